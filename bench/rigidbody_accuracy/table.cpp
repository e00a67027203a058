#include "bench/rigidbody_accuracy/table.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace cosim::bench {
std::string solver_label(const rigidbody::world::Settings& s) {
  switch (s.solver) {
    case rigidbody::world::SolverKind::soft:
      return "soft";
    case rigidbody::world::SolverKind::pgs:
      return "pgs";
    case rigidbody::world::SolverKind::jacobi:
      return "jacobi";
    case rigidbody::world::SolverKind::sequential_impulses:
      return "si";
    case rigidbody::world::SolverKind::dem: {
      char label[32];
      std::snprintf(label, sizeof label, "dem k=%.0e", s.dem.normal_stiffness);
      return label;
    }
  }
  return "?";
}

namespace {

bool is_dem(const Run& run) { return run.spec.settings.solver == rigidbody::world::SolverKind::dem; }

// Empty when the solver has no iterations (DEM) or the run no reference.
std::string cell(bool present, const char* format, double value) {
  if (!present) return "";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string iterations(const Run& r) {
  const rigidbody::world::Settings& s = r.spec.settings;
  const int n =
      s.solver == rigidbody::world::SolverKind::soft ? s.soft_options().iterations : s.impulse_options().max_iterations;
  return cell(!is_dem(r), "%.0f", static_cast<double>(n));
}
std::string error(const Run& r) { return cell(r.metrics.error.has_value(), "%.2e", r.metrics.error.value_or(0)); }
std::string converged(const Run& r) { return cell(!is_dem(r), "%.2f", r.metrics.converged); }
std::string mean_iterations(const Run& r) { return cell(!is_dem(r), "%.1f", r.metrics.mean_iterations); }
std::string stable_dt(const Run& r) {
  return cell(r.metrics.dem_stable_dt.has_value(), "%.2e", r.metrics.dem_stable_dt.value_or(0));
}

}  // namespace

void print_header() {
  std::printf(
      "Lengths in units of the sphere radius (pyramid) or box half size (stack); energies in\n"
      "units of the initial potential energy (floor at z = 0). pen: deepest contact; drift:\n"
      "largest horizontal displacement; error: largest distance of an end position from the\n"
      "reference (pyramid) or the start (stack); E rise: largest rise of kinetic + potential\n"
      "energy above its running minimum; KE end: kinetic energy at the end; conv: fraction of\n"
      "steps that met the tolerance; wall: stepping only. DEM: fraction of steps with the\n"
      "solver's unstable-dt warning and its stable estimate.\n\n");
  std::printf("%-13s %-10s %5s %8s %9s %9s %9s %9s %9s %5s %6s %8s %11s %6s %9s\n", "scene", "solver", "iters", "dt",
              "pen", "drift", "error", "E rise", "KE end", "conv", "iters", "wall s", "body-st/s", "warn", "stable dt");
}

void print_row(const Run& r) {
  const Metrics& m = r.metrics;
  std::printf("%-13s %-10s %5s %8.1e %9.2e %9.2e %9s %9.2e %9.2e %5s %6s %8.3f %11.3e %6s %9s\n", r.scene.name.c_str(),
              solver_label(r.spec.settings).c_str(), iterations(r).c_str(), r.spec.settings.dt, m.penetration, m.drift,
              error(r).c_str(), m.energy_rise, m.kinetic_end, converged(r).c_str(), mean_iterations(r).c_str(),
              m.wall_seconds, m.body_steps_per_second, cell(is_dem(r), "%.2f", m.dem_warned).c_str(),
              stable_dt(r).c_str());
  std::fflush(stdout);
}

void write_csv(const std::string& path, const std::vector<Run>& runs) {
  std::ofstream out(path);
  out << "scene,solver,iterations,dt,penetration,drift,error,energy_rise,kinetic_end,converged,"
         "mean_iterations,wall_seconds,body_steps_per_second,dem_warned,dem_stable_dt\n";
  for (const Run& r : runs) {
    const Metrics& m = r.metrics;
    out << r.scene.name << ',' << solver_label(r.spec.settings) << ',' << iterations(r) << ',' << r.spec.settings.dt
        << ',' << m.penetration << ',' << m.drift << ',' << error(r) << ',' << m.energy_rise << ',' << m.kinetic_end
        << ',' << converged(r) << ',' << mean_iterations(r) << ',' << m.wall_seconds << ',' << m.body_steps_per_second
        << ',' << cell(is_dem(r), "%.4f", m.dem_warned) << ',' << stable_dt(r) << '\n';
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + path);
}

}  // namespace cosim::bench
