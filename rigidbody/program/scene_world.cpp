#include "rigidbody/program/scene_world.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "coupler/scene/geometry_shape.hpp"
#include "coupler/scene/eigen.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/reader.hpp"

namespace cosim::rigidbody::program {
namespace {

using Eigen::Vector3d;

const scene::Participant& section(const scene::Scene& scene) {
  const auto* p = scene.participant("rigidbody");
  if (p == nullptr)
    throw scene::SceneError(scene.file.string(), 0, "participants.rigidbody", "",
                            "missing: cosim-rigidbody reads its dt and options there");
  return *p;
}

// A mesh listed in convex_hulls collides as the hull of its body-frame vertices. A convex
// mesh's hull has the same centre of mass; any other's moves by the hull's own com_shift.
geometry::Shape hull_of(const geometry::Shape& mesh) {
  return geometry::ConvexHull(std::get<geometry::TriangleMesh>(mesh).vertices());
}

// The option names mesh bodies only, so a misspelt or non-mesh name is an error that lists
// the meshes.
std::vector<std::size_t> convex_hulls(const scene::Scene& scene, const scene::Reader& options) {
  std::vector<std::size_t> meshes;
  std::vector<const char*> names;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].shape.type == scene::ShapeType::Mesh) {
      meshes.push_back(i);
      names.push_back(scene.bodies[i].name.c_str());
    }
  if (!options.has("convex_hulls")) return {};
  std::vector<std::size_t> bodies;
  for (std::size_t k : options.choices("convex_hulls", names)) bodies.push_back(meshes[k]);
  return bodies;
}

// Face f of the domain (x_min, x_max, y_min, ...) as a half-space whose normal points
// into the domain, with the bodies' default material.
std::vector<world::BodyDesc> walls(const scene::Scene& scene, const scene::Reader& options, bool friction) {
  constexpr std::array face_names{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  if (!options.has("walls")) return {};
  std::vector<world::BodyDesc> out;
  for (std::size_t f : options.choices("walls", face_names)) {
    const int axis = static_cast<int>(f / 2);
    const bool upper = f % 2 == 1;
    Vector3d normal = Vector3d::Zero();
    normal[axis] = upper ? -1.0 : 1.0;
    world::BodyDesc d{.shape = geometry::HalfSpace(normal), .name = face_names[f]};
    d.state.position = scene::to_eigen(scene.domain.min);
    d.state.position[axis] = upper ? scene.domain.max[axis] : scene.domain.min[axis];
    if (!friction) d.material.friction = 0.0;
    d.fixed = true;
    out.push_back(std::move(d));
  }
  return out;
}

// The gap the fluid resolves, in its widest cells. The immersed boundary (Roma's kernel)
// follows Brenner's drag of a sphere closing on a wall to a fraction of a cell; the range
// is where the leading-order correction added to its drag comes nearest Brenner's at every
// gap, calibrated at d/h 6 and Re 0.1 and 0.5, checked at d/h 8 (fluid_accuracy
// --wall-approach; bench/fluid_accuracy/README.md "Sphere closing on a wall"). The staircase's surfaces
// sit on cell faces, so it loses the whole film below a cell (not measured).
constexpr double kResolvedFilmCellsIbm = 0.4, kResolvedFilmCellsStaircase = 1.0;

// lubrication: auto: the film of the scene's cosim-fluid, its Newtonian viscosity below the
// gap its grid resolves, a fraction of the widest of its cells along the axes that have more
// than one.
solver::LubricationOptions lubrication_of_the_fluid(const scene::Scene& scene, const scene::Reader& options) {
  const scene::Participant* fluid = scene.participant("fluid");
  if (fluid == nullptr)
    options.fail("lubrication",
                 "auto takes the viscosity and the cell size from participants.fluid, which this scene lacks");
  const scene::Reader fluid_options = scene::options_of(scene, *fluid);
  const scene::Reader viscosity = fluid_options.map("viscosity");
  if (viscosity.string("model") != "newtonian")
    options.fail("lubrication", "auto needs a Newtonian fluid: give viscosity and range for " +
                                    fluid_options.where("viscosity") + " = " + viscosity.string("model"));
  std::array<double, 3> cells{};
  fluid_options.map("grid").numbers("cells", cells, scene::Range::at_least(1));
  solver::LubricationOptions l;
  l.viscosity = viscosity.number("mu", scene::Range::above(0));
  for (int a = 0; a < 3; ++a)
    if (cells[a] > 1) l.range = std::max(l.range, (scene.domain.max[a] - scene.domain.min[a]) / cells[a]);
  const bool staircase =
      fluid_options.has("bodies") && fluid_options.map("bodies").string("method", "ibm") == "staircase";
  l.range *= staircase ? kResolvedFilmCellsStaircase : kResolvedFilmCellsIbm;
  l.roughness = 1e-3 * l.range;
  return l;
}

// lubrication: {viscosity: mu, range: gap the fluid resolves, roughness: gap where it stops}, or auto
solver::LubricationOptions lubrication(const scene::Scene& scene, const scene::Reader& options, bool contact) {
  if (!options.has("lubrication")) return {};
  solver::LubricationOptions l;
  if (options.node("lubrication").IsScalar()) {
    if (options.string("lubrication") != "auto")
      options.fail("lubrication", "expected auto or {viscosity, range, roughness}");
    l = lubrication_of_the_fluid(scene, options);
  } else {
    const scene::Reader r = options.map("lubrication");
    l.viscosity = r.number("viscosity", scene::Range::above(0));
    l.range = r.number("range", scene::Range::above(0));
    l.roughness = r.number("roughness", 1e-3 * l.range, scene::Range::above(0));
    if (l.roughness >= l.range) r.fail("roughness", "must be below range (" + std::to_string(l.range) + " m)");
    r.finish();
  }
  // The film acts on the pairs the contact pipeline finds; without it there are none.
  if (!contact) {
    spdlog::warn("{}: no contact effect in effects, so the lubrication force is not applied",
                 options.where("lubrication"));
    return {};
  }
  return l;
}

// What the soft step trades time for accuracy with (solver/README.md "Soft step"); the
// other solvers have no use for them.
void soft_step_options(const scene::Reader& options, world::Settings& s) {
  s.soft.substeps = options.integer("substeps", s.soft.substeps, scene::Range::at_least(1));
  s.soft.relax_iterations = options.integer("relax_iterations", s.soft.relax_iterations, scene::Range::at_least(0));
  s.soft.hertz = options.number("contact_hertz", s.soft.hertz, scene::Range::above(0));
  if (const double runs = s.soft.spring_hertz(s.dt / s.soft.substeps);
      s.solver == world::SolverKind::soft && options.has("contact_hertz") && runs < s.soft.hertz)
    spdlog::warn(
        "{}: {} Hz is stiffer than {} substeps of dt = {} s resolve; the springs run at {} Hz (a quarter of "
        "the substep rate)",
        options.where("contact_hertz"), s.soft.hertz, s.soft.substeps, s.dt, runs);
  if (s.solver == world::SolverKind::soft) return;
  for (const char* key : {"substeps", "relax_iterations", "contact_hertz"})
    if (options.has(key))
      spdlog::warn("{}: only the soft step uses it, so it is ignored with this solver", options.where(key));
}

}  // namespace

ProgramOptions program_options(const scene::Scene& scene) {
  const auto& p = section(scene);
  const auto options = scene::options_of(scene, p);
  ProgramOptions out;
  world::Settings& s = out.settings;
  s.dt = p.dt;

  constexpr std::array solver_names{"soft", "sequential-impulses", "pgs", "jacobi", "dem"};
  constexpr std::array solvers{world::SolverKind::soft, world::SolverKind::sequential_impulses, world::SolverKind::pgs,
                               world::SolverKind::jacobi, world::SolverKind::dem};
  s.solver = solvers[options.choice("solver", solver_names, 0)];
  s.iterations = options.integer("iterations", s.iterations, scene::Range::at_least(0));
  s.tolerance = options.number("tolerance", s.tolerance, scene::Range::above(0));
  s.contact_margin = options.number("contact_margin", s.contact_margin, scene::Range::at_least(0));
  soft_step_options(options, s);
  constexpr std::array restitution_names{"simultaneous", "sequential"};
  constexpr std::array restitutions{solver::Restitution::simultaneous, solver::Restitution::sequential};
  s.restitution = restitutions[options.choice("restitution", restitution_names, 0)];

  s.body_forces.gravity = scene.has_effect(scene::Effect::Gravity);
  s.body_forces.g = scene::to_eigen(scene.gravity);
  s.body_forces.buoyancy = scene.has_effect(scene::Effect::Buoyancy);
  // Hydrostatic buoyancy needs the fluid's density, which the scene has nowhere else; without
  // the effect the key may stay, so switching effects needs no other edit.
  if (s.body_forces.buoyancy || options.has("fluid_density"))
    s.body_forces.fluid_density = options.number("fluid_density", scene::Range::above(0));
  s.contact = scene.has_effect(scene::Effect::Contact);
  out.virtual_mass = options.number("virtual_mass", 0.0, scene::Range::at_least(0));
  if (out.virtual_mass > 0 && !options.has("fluid_density"))
    options.fail("virtual_mass", "needs fluid_density, the density of the fluid whose mass it borrows");

  constexpr std::array law_names{"linear", "hertz"};
  constexpr std::array laws{solver::NormalLaw::linear, solver::NormalLaw::hertz};
  s.dem.law = laws[options.choice("dem_law", law_names, 0)];
  s.dem.normal_stiffness = options.number("normal_stiffness", s.dem.normal_stiffness, scene::Range::above(0));
  s.lubrication = lubrication(scene, options, s.contact);
  out.convex_hulls = convex_hulls(scene, options);
  out.walls = walls(scene, options, scene.has_effect(scene::Effect::Friction));
  options.finish();
  return out;
}

world::Settings settings_of(const scene::Scene& scene) { return program_options(scene).settings; }

world::BodyDesc body_of(const scene::Body& b, bool friction, bool convex_hull) {
  world::BodyDesc d{.shape = scene::shape_of(b.shape), .name = b.name};
  d.state.orientation = scene::to_eigen(b.orientation);
  d.state.position = scene::to_eigen(b.position) + d.state.orientation * scene::com_shift(d.shape);
  if (convex_hull) {
    d.shape = hull_of(d.shape);
    d.state.position += d.state.orientation * scene::com_shift(d.shape);
  }
  d.state.velocity = scene::to_eigen(b.velocity);
  d.state.angular_velocity = scene::to_eigen(b.angular_velocity);
  d.density = b.material.density;
  d.material = {.friction = friction ? b.material.friction : 0.0, .restitution = b.material.restitution};
  d.fixed = b.fixed;
  return d;
}

std::unique_ptr<world::World> make_world(const scene::Scene& scene) {
  return make_world(scene, program_options(scene));
}

std::unique_ptr<world::World> make_world(const scene::Scene& scene, const ProgramOptions& options) {
  auto w = std::make_unique<world::World>(options.settings);
  const bool friction = scene.has_effect(scene::Effect::Friction);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const bool hull =
        std::find(options.convex_hulls.begin(), options.convex_hulls.end(), i) != options.convex_hulls.end();
    w->add(body_of(scene.bodies[i], friction, hull));
  }
  for (const world::BodyDesc& wall : options.walls) w->add(wall);
  return w;
}

}  // namespace cosim::rigidbody::program
