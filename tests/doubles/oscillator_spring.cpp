// Test double in the fluid role: owns the second mass and both springs and returns the
// spring force on the first dynamic body. See README.md.
#include <cmath>

#include "tests/doubles/double_common.hpp"

namespace cosim::doubles {
namespace {

class SpringSolver final : public participant::Solver {
 public:
  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<participant::PoseRow>& poses,
                                  const std::vector<double>& state) override {
    const auto& p = section(scene, name);
    const auto options = scene::options_of(scene, p);
    common_ = Common::read(scene, p, options);
    k_ = options.number("stiffness");
    k2_ = options.number("wall_stiffness", 0.0);
    m2_ = options.number("mass");
    rest_ = options.number("rest_length", 0.0);
    anchor_ = options.number("anchor", 0.0);
    x2_ = options.number("position");
    v2_ = options.number("velocity", 0.0);
    extra_rows_ = options.integer("extra_force_rows", 0);
    if (k_ <= 0) options.fail("stiffness", "must be > 0");
    if (m2_ <= 0) options.fail("mass", "must be > 0");
    options.finish();
    bodies_ = scene.bodies.size();
    for (body_ = 0; body_ < bodies_ && scene.bodies[body_].fixed; ++body_) {
    }
    if (body_ == bodies_) throw std::runtime_error("the spring needs a dynamic body to pull");
    if (!state.empty()) restore(state);
    return {{}, force_on_body(poses[body_].position.x()), 0};
  }

  participant::Outputs advance(const participant::Window& w, const participant::Inputs& in) override {
    common_.on_window(w);
    const auto n = static_cast<int>(std::lround((w.t1 - w.t0) / common_.dt));
    const double h = (w.t1 - w.t0) / n;
    const double x1_start = in.poses_start[body_].position.x(), x1_end = in.poses_end[body_].position.x();
    const auto x1 = [&](double s) { return participant::lerp(x1_start, x1_end, w, s); };
    const auto accel = [&](double x2, double s) { return (-k_ * (x2 - x1(s) - rest_) - k2_ * (x2 - anchor_)) / m2_; };
    for (int i = 0; i < n; ++i) step(common_.integrator, x2_, v2_, w.t0 + i * h, h, accel);
    return {{}, force_on_body(x1_end), static_cast<double>(n)};
  }

  std::vector<double> state() const override { return {x2_, v2_}; }
  void restore(const std::vector<double>& state) override {
    if (state.size() != 2) throw std::runtime_error("restart state has the wrong size");
    x2_ = state[0];
    v2_ = state[1];
  }

 private:
  std::vector<participant::ForceRow> force_on_body(double x1) const {
    std::vector<participant::ForceRow> forces(bodies_ + static_cast<std::size_t>(extra_rows_));
    forces[body_].force.x() = k_ * (x2_ - x1 - rest_);
    return forces;
  }

  Common common_;
  double k_ = 0, k2_ = 0, m2_ = 0, rest_ = 0, anchor_ = 0;
  double x2_ = 0, v2_ = 0;
  std::size_t bodies_ = 0, body_ = 0;
  int extra_rows_ = 0;  // > 0: a broken participant, for the coupler's tests
};

}  // namespace
}  // namespace cosim::doubles

int main() {
  cosim::doubles::SpringSolver solver;
  using cosim::scene::Data;
  return cosim::doubles::serve("cosim-test-oscillator-spring", solver, Data::Forces, Data::Poses);
}
