#pragma once
// What one step of NavierStokes takes from the bodies, as an argument of the step so that a
// reader of the step sees every input: the staircase's faces, whose velocity the step
// prescribes, or the immersed boundary's forcing, which the step asks for its force.
#include "fluid/bodies/body_forcing.hpp"
#include "fluid/bodies/imposed_faces.hpp"

namespace cosim::fluid::bodies {

// At most one of the two: the forcing needs the operators of the fluid alone.
struct StepBodies {
  // Dirichlet rows of the implicit viscous solve and walls for the projection; null for none.
  const ImposedFaces* imposed = nullptr;
  // Asked for its force between the right-hand side and the viscous solve; null for none.
  BodyForcing* forcing = nullptr;
};

}  // namespace cosim::fluid::bodies
