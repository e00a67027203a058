#include "fluid/navier_stokes/step_stages.hpp"

namespace cosim::fluid::navier_stokes {
namespace {

struct LogEvents {
  std::array<PetscLogEvent, kStageNames.size()> stages{};
  PetscLogEvent pressure_solve{};
  PetscLogEvent forcing_iteration{};
};

const LogEvents& log_events() {
  static const LogEvents events = [] {
    PetscClassId id;
    LogEvents e;
    COSIM_PETSC(PetscClassIdRegister("cosim fluid", &id));
    const std::array<const char*, kStageNames.size()> names{"FluidMomentumRHS", "FluidBodyForcing", "FluidViscousSolve",
                                                            "FluidProjection", "FluidNoSlip"};
    for (std::size_t s = 0; s < names.size(); ++s) COSIM_PETSC(PetscLogEventRegister(names[s], id, &e.stages[s]));
    COSIM_PETSC(PetscLogEventRegister("FluidPressureSolve", id, &e.pressure_solve));
    COSIM_PETSC(PetscLogEventRegister("FluidForcingIteration", id, &e.forcing_iteration));
    return e;
  }();
  return events;
}

}  // namespace

PetscLogEvent log_event(Stage stage) { return log_events().stages[static_cast<std::size_t>(stage)]; }

PetscLogEvent pressure_solve_event() { return log_events().pressure_solve; }

PetscLogEvent forcing_iteration_event() { return log_events().forcing_iteration; }

}  // namespace cosim::fluid::navier_stokes
