#include "fluid/program/scene_fluid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coupler/scene/geometry_shape.hpp"
#include "coupler/scene/eigen.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/sections.hpp"
#include "coupler/scene/reader.hpp"
#include "fluid/program/confined_inflow.hpp"
#include "geometry/aabb.hpp"
#include "geometry/shape.hpp"

namespace cosim::fluid::program {
namespace {

using fluid::grid::Boundary;
using scene::Range;
using scene::Reader;

constexpr std::array face_names{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
constexpr std::array boundary_names{"wall", "inflow", "outflow", "periodic"};
constexpr std::array profile_names{"uniform", "parabolic"};
constexpr std::array pressure_update_names{"standard", "rotational", "exact"};
constexpr std::array viscosity_names{"newtonian", "power-law", "carreau"};
constexpr std::array method_names{"ibm", "staircase"};
constexpr std::array kernel_names{"roma3", "peskin4", "bao6"};

const scene::Participant& section(const scene::Scene& scene) {
  const auto* p = scene.participant("fluid");
  if (p == nullptr)
    throw scene::SceneError(scene.file.string(), 0, "participants.fluid", "",
                            "missing: cosim-fluid reads its dt and options there");
  return *p;
}

fluid::grid::Point point(const scene::Vec3& v) { return {v[0], v[1], v[2]}; }

// Whole numbers per axis under `key`, from 1 to each axis's `most`.
std::array<int, 3> whole_per_axis(const Reader& grid, const char* key, const std::array<double, 3>& most,
                                  const std::string& limit) {
  std::array<double, 3> n{};
  grid.numbers(key, n, Range::at_least(1));
  std::array<int, 3> out{};
  for (std::size_t a = 0; a < 3; ++a) {
    if (n[a] != std::floor(n[a]) || n[a] > most[a]) grid.fail(key, "expected whole numbers, each at most " + limit);
    out[a] = static_cast<int>(n[a]);
  }
  return out;
}

// Cells per axis (a one-cell periodic axis is a 2D problem).
std::array<int, 3> cells(const Reader& grid) { return whole_per_axis(grid, "cells", {1e8, 1e8, 1e8}, "1e8"); }

// How many of the participant's ranks share each axis: whole numbers, at most the axis's
// cells, their product the participant's `ranks` where the scene gives more than one
// (standalone, mpirun's count rules: the grid checks it then).
std::array<int, 3> rank_layout(const Reader& grid, const std::array<int, 3>& cells, int ranks) {
  const std::array<int, 3> out =
      whole_per_axis(grid, "ranks", {double(cells[0]), double(cells[1]), double(cells[2])}, "the axis's cells");
  const long long product = static_cast<long long>(out[0]) * out[1] * out[2];
  if (ranks > 1 && product != ranks)
    grid.fail("ranks", "their product is " + std::to_string(product) + ", the participant runs on " +
                           std::to_string(ranks) + " (participants.fluid.ranks)");
  return out;
}

fluid::viscous::ViscosityModel viscosity(const Reader& r) {
  fluid::viscous::ViscosityModel model = fluid::viscous::ViscosityModel::newtonian(1);
  switch (r.choice("model", viscosity_names)) {
    case 0:
      model = fluid::viscous::ViscosityModel::newtonian(r.number("mu", Range::above(0)));
      break;
    case 1: {
      const double k = r.number("consistency", Range::above(0)), n = r.number("index", Range::above(0));
      const double lo = r.number("mu_min", Range::above(0)), hi = r.number("mu_max", Range::above(0));
      if (hi < lo) r.fail("mu_max", "must be >= mu_min");
      model = fluid::viscous::ViscosityModel::power_law(k, n, lo, hi);
      break;
    }
    default: {
      const double mu0 = r.number("mu_zero", Range::above(0)), mu_inf = r.number("mu_infinity", Range::at_least(0));
      model = fluid::viscous::ViscosityModel::carreau(mu0, mu_inf, r.number("time_constant", Range::above(0)),
                                                      r.number("index", Range::above(0)));
    }
  }
  r.finish();
  return model;
}

// Peak velocity `u`, times prod 4 s (1 - s) over the face's bounded tangential axes when
// parabolic (s the position across the axis).
fluid::grid::VelocityFunction inflow(fluid::grid::Point u, bool parabolic, int axis, const scene::Domain& d,
                                     const std::array<bool, 3>& periodic) {
  return [=](const fluid::grid::Point& x, double) {
    double f = 1;
    for (int t = 0; t < 3; ++t)
      if (parabolic && t != axis && !periodic[t]) {
        const double s = (x[t] - d.min[t]) / (d.max[t] - d.min[t]);
        f *= 4 * s * (1 - s);
      }
    return fluid::grid::Point{f * u[0], f * u[1], f * u[2]};
  };
}

// An inflow face that feeds only the inside of the container named by its `within`.
struct Confinement {
  std::size_t face;
  std::string body;
  Reader keys;  // the face's, for errors
};

// Faces not listed are no-slip walls; periodic must hold for both faces of an axis. Returns
// the inflow faces confined to a container, applied once the grid and the bodies are read.
std::vector<Confinement> read_boundaries(const Reader& options, const scene::Domain& domain, FluidSetup& s,
                                         std::array<bool, 3>& periodic) {
  s.boundaries.fill(Boundary::no_slip());
  std::vector<Confinement> confined;
  if (!options.has("boundaries")) return confined;
  std::array<std::size_t, 6> kind{};
  const Reader list = options.map("boundaries");
  for (std::size_t f = 0; f < 6; ++f)
    if (list.has(face_names[f])) kind[f] = list.map(face_names[f]).choice("type", boundary_names);
  for (int a = 0; a < 3; ++a) {
    const bool lo = kind[2 * a] == 3, hi = kind[2 * a + 1] == 3;
    if (lo != hi) list.fail(face_names[lo ? 2 * a + 1 : 2 * a], "the opposite face is periodic: both faces must be");
    periodic[a] = lo;
  }
  for (std::size_t f = 0; f < 6; ++f) {
    if (!list.has(face_names[f])) continue;
    const Reader r = list.map(face_names[f]);
    r.choice("type", boundary_names);
    const int axis = static_cast<int>(f / 2);
    switch (kind[f]) {
      case 0:
        s.boundaries[f] = Boundary::moving_wall(point(r.vec3("velocity", {0, 0, 0})));
        break;
      case 1: {
        const fluid::grid::Point u = point(r.vec3("velocity"));
        const bool parabolic = r.choice("profile", profile_names, 0) == 1;
        s.boundaries[f] = Boundary::inflow(inflow(u, parabolic, axis, domain, periodic));
        if (r.has("within")) {
          if (parabolic) r.fail("within", "takes profile uniform: a parabola across the box is not the container's");
          confined.push_back({f, r.string("within"), r});
        }
        break;
      }
      case 2:
        s.boundaries[f] = Boundary::outflow();
        break;
      default:
        s.boundaries[f] = Boundary::periodic();
    }
    r.finish();
  }
  list.finish();
  return confined;
}

void confine_inflows(const std::vector<Confinement>& confined, FluidSetup& s) {
  for (const Confinement& c : confined) {
    const auto named = std::find(s.body_names.begin(), s.body_names.end(), c.body);
    if (named == s.body_names.end()) c.keys.fail("within", "no body of that name");
    const fluid::bodies::RigidBody& body = s.bodies[static_cast<std::size_t>(named - s.body_names.begin())];
    const auto* container = std::get_if<geometry::Container>(&body.shape);
    if (container == nullptr) c.keys.fail("within", "not a container (a fixed body with shape: {container: true})");
    const int axis = static_cast<int>(c.face / 2);
    const auto side = c.face % 2 == 0 ? fluid::grid::Side::lower : fluid::grid::Side::upper;
    try {
      s.boundaries[c.face] =
          Boundary::inflow(confined_inflow(s.boundaries[c.face].velocity, *container, body.pose, axis, side, s.axes));
    } catch (const std::invalid_argument& e) {
      c.keys.fail("within", e.what());
    }
  }
}

// bodies: {method: ibm, kernel, sweeps, corrections, no_slip_tolerance, tolerance,
// retraction, curvature_retraction, marker_spacing, spread_at_theta} or
// {method: staircase, subsamples, surface_offset}; a key of the other method is refused.
fluid::BodyOptions read_body_method(const Reader& options) {
  const fluid::staircase::FbmOptions staircase{.offset = fluid::staircase::kCalibratedSurfaceOffset};
  fluid::ibm::IbmOptions defaults;
  defaults.retraction = fluid::ibm::calibrated_retraction(defaults.kernel);
  if (!options.has("bodies")) return defaults;
  const Reader r = options.map("bodies");
  const bool ibm = r.choice("method", method_names, 0) == 0;
  for (const char* key : ibm ? std::array{"subsamples", "surface_offset", "", "", "", "", "", "", ""}
                             : std::array{"kernel", "sweeps", "corrections", "no_slip_tolerance", "tolerance",
                                          "retraction", "curvature_retraction", "marker_spacing", "spread_at_theta"})
    if (*key && r.has(key)) r.fail(key, std::string("applies to method ") + (ibm ? "staircase" : "ibm") + " only");
  fluid::BodyOptions out;
  if (ibm) {
    fluid::ibm::IbmOptions o;
    o.kernel =
        static_cast<fluid::ibm::DeltaKernel>(r.choice("kernel", kernel_names, static_cast<std::size_t>(o.kernel)));
    o.sweeps = r.integer("sweeps", o.sweeps, Range::at_least(1));
    o.corrections = r.integer("corrections", o.corrections, Range::at_least(0));
    o.no_slip_tolerance = r.number("no_slip_tolerance", o.no_slip_tolerance, Range::open(0, 1));
    o.tolerance = r.number("tolerance", o.tolerance, Range::open(0, 1));
    const fluid::ibm::Retraction calibrated = fluid::ibm::calibrated_retraction(o.kernel);
    o.retraction = fluid::ibm::Retraction{r.number("retraction", calibrated.constant, Range::closed(0, 2)),
                                          r.number("curvature_retraction", calibrated.curvature, Range::closed(-2, 2)),
                                          calibrated.concave};
    o.spacing = r.number("marker_spacing", o.spacing, Range::closed(0.25, 2));
    o.spread_at_theta = r.boolean("spread_at_theta", o.spread_at_theta);
    out = o;
  } else {
    fluid::staircase::FbmOptions o = staircase;
    o.subsamples = r.integer("subsamples", o.subsamples, Range::at_least(1));
    o.offset = r.number("surface_offset", o.offset, Range::at_least(0));
    out = o;
  }
  r.finish();
  return out;
}

// Body b's entry in the scene file's `bodies` list, as a key: a generated body's is its
// generator's.
std::string entry_key(const scene::Scene& scene, std::size_t b) {
  std::size_t entry = b;
  for (const scene::BodyGenerator& g : scene.generators) {
    if (b >= g.first && b < g.first + g.count) return "bodies[" + std::to_string(g.entry) + "].generate";
    if (b >= g.first + g.count) entry = entry + 1 - g.count;
  }
  return "bodies[" + std::to_string(entry) + "].position";
}

// A fixed body may reach across a periodic face (the scene lets fixed bodies reach out of the
// domain): the immersed boundary wraps its markers and volume fractions round. The staircase
// does not, cosim-rigidbody does not wrap bodies, so its moving bodies would pass through
// the part beyond the face, and a body as long as the period would meet itself.
void check_wrapping(const scene::Scene& scene, const FluidSetup& s) {
  const auto moving = std::find_if(scene.bodies.begin(), scene.bodies.end(), [](const auto& o) { return !o.fixed; });
  const bool rigid = std::any_of(scene.participants.begin(), scene.participants.end(),
                                 [](const scene::Participant& p) { return p.name == "rigidbody"; });
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (!geometry::is_bounded(s.bodies[b].shape)) continue;
    const geometry::Aabb box = geometry::world_aabb(s.bodies[b].shape, s.bodies[b].pose);
    for (std::size_t a = 0; a < 3; ++a) {
      const fluid::grid::Axis& axis = s.axes[a];
      if (!axis.periodic() || axis.degenerate() || (box.min[a] >= axis.lo() && box.max[a] <= axis.hi())) continue;
      const auto fail = [&](const std::string& why) {
        const scene::Body& body = scene.bodies[b];
        throw scene::SceneError(
            scene.file.string(), body.material_line, entry_key(scene, b), scene::text(body.position),
            fmt::format("body '{}' reaches across the periodic {} faces: {}", body.name, "xyz"[a], why));
      };
      if (box.max[a] - box.min[a] >= axis.hi() - axis.lo())
        fail("it is as long as the period or longer, and would meet itself");
      if (std::holds_alternative<fluid::staircase::FbmOptions>(s.body_method))
        fail("the staircase does not wrap bodies round (participants.fluid.options.bodies.method: ibm does)");
      if (rigid && moving != scene.bodies.end())
        fail("cosim-rigidbody does not wrap it round, so body '" + moving->name +
             "' would pass through its part beyond");
    }
  }
}

// Neither method holds a half-space.
void read_bodies(const scene::Scene& scene, const scene::Participant& p, FluidSetup& s) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const scene::Body& body = scene.bodies[b];
    const std::string key = "bodies[" + std::to_string(b) + "].shape.type";
    if (body.shape.type == scene::ShapeType::Plane)
      throw scene::SceneError(scene.file.string(), p.line, key, "plane",
                              "cosim-fluid cannot hold a plane body: make it a wall boundary (participants.fluid)");
    fluid::bodies::RigidBody r{.shape = scene::shape_of(body.shape), .pose = {}};
    const Eigen::Quaterniond q = scene::to_eigen(body.orientation);
    const Eigen::Vector3d x = scene::to_eigen(body.position) + q * scene::com_shift(r.shape);
    r.pose = geometry::Pose(x, q);
    s.bodies.push_back(std::move(r));
    s.body_names.push_back(body.name);
    Motion m;
    m.position = x;
    m.orientation = q;
    s.motions.push_back(m);
  }
}

}  // namespace

FluidSetup fluid_setup(const scene::Scene& scene) {
  const scene::Participant& p = section(scene);
  const Reader options = scene::options_of(scene, p);
  FluidSetup s;

  std::array<bool, 3> periodic{};
  const std::vector<Confinement> confined = read_boundaries(options, scene.domain, s, periodic);
  const Reader grid = options.map("grid");
  const std::array<int, 3> n = cells(grid);
  std::array<double, 3> beta{};
  if (grid.has("stretching")) grid.numbers("stretching", beta, Range::at_least(0));
  if (grid.has("ranks")) s.ranks = rank_layout(grid, n, p.ranks);
  grid.finish();
  for (int a = 0; a < 3; ++a) {
    const double lo = scene.domain.min[a], hi = scene.domain.max[a];
    s.axes.push_back(beta[a] > 0 ? fluid::grid::Axis::stretched(n[a], lo, hi, beta[a], periodic[a])
                                 : fluid::grid::Axis::uniform(n[a], lo, hi, periodic[a]));
  }

  s.properties.density = options.number("density", Range::above(0));
  s.properties.viscosity = viscosity(options.map("viscosity"));
  // A driving pressure gradient over rho, never gravity: with effect buoyancy cosim-rigidbody
  // adds the hydrostatic force, and a fluid gravity would count it twice.
  s.properties.body_force = point(options.vec3("body_force", {0, 0, 0}));
  s.initial_velocity = point(options.vec3("initial_velocity", {0, 0, 0}));
  s.steps.dt_max = p.dt;
  s.steps.cfl = options.number("cfl", s.steps.cfl, Range::above(0));
  s.steps.dt_initial = options.number("dt_initial", std::min(s.steps.dt_initial, p.dt), Range::left_open(0, p.dt));
  s.steps.theta = options.number("theta", s.steps.theta, Range::closed(0.5, 1));
  s.steps.pressure_update =
      static_cast<fluid::navier_stokes::PressureUpdate>(options.choice("pressure_update", pressure_update_names, 0));
  s.steps.convection = options.boolean("convection", true);
  s.body_method = read_body_method(options);
  if (s.steps.pressure_update == fluid::navier_stokes::PressureUpdate::exact &&
      std::holds_alternative<fluid::staircase::FbmOptions>(s.body_method))
    options.fail("pressure_update",
                 "exact needs bodies: {method: ibm}: the staircase's imposed faces take the "
                 "standard projection");
  try {
    s.petsc = parse_petsc_flags(options.string("petsc", ""));
  } catch (const std::invalid_argument& e) {
    options.fail("petsc", e.what());
  }
  read_bodies(scene, p, s);
  confine_inflows(confined, s);
  s.motions = read_motions(scene, options, std::move(s.motions));
  check_wrapping(scene, s);
  options.finish();
  return s;
}

}  // namespace cosim::fluid::program
