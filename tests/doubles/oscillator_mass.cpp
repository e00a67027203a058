// Test double in the rigid-body role: moves every dynamic sphere of the scene under the
// force the coupler gives it (translation only). See README.md.
#include <cmath>
#include <numbers>

#include "tests/doubles/double_common.hpp"

namespace cosim::doubles {
namespace {

class MassSolver final : public participant::Solver {
 public:
  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<participant::PoseRow>& poses,
                                  const std::vector<double>& state) override {
    const auto& p = section(scene, name);
    const auto options = scene::options_of(scene, p);
    common_ = Common::read(scene, p, options);
    options.finish();
    for (const auto& b : scene.bodies) {
      if (!b.fixed && b.shape.type != scene::ShapeType::Sphere)
        throw std::runtime_error("body '" + b.name + "': the oscillator double moves spheres only");
      const double r = b.shape.radius;
      mass_.push_back(b.fixed ? 0.0 : b.material.density * 4.0 / 3.0 * std::numbers::pi * r * r * r);
    }
    poses_ = poses;
    if (!state.empty()) restore(state);
    return {poses_, {}, 0};
  }

  participant::Outputs advance(const participant::Window& w, const participant::Inputs& in) override {
    common_.on_window(w);
    const auto n = static_cast<int>(std::lround((w.t1 - w.t0) / common_.dt));
    const double h = (w.t1 - w.t0) / n;
    for (std::size_t b = 0; b < mass_.size(); ++b) {
      if (mass_[b] == 0.0) continue;
      for (int axis = 0; axis < 3; ++axis) {
        double& x = poses_[b].position[axis];
        double& v = poses_[b].velocity[axis];
        const auto force = [&](double, double s) {
          return participant::lerp(in.forces_start[b].force[axis], in.forces_end[b].force[axis], w, s) / mass_[b];
        };
        for (int i = 0; i < n; ++i) step(common_.integrator, x, v, w.t0 + i * h, h, force);
      }
    }
    return {poses_, {}, static_cast<double>(n)};
  }

  std::vector<double> state() const override { return participant::values_of(poses_); }
  void restore(const std::vector<double>& state) override {
    if (state.size() != protocol::kPoseWidth * poses_.size())
      throw std::runtime_error("restart state has the wrong size");
    poses_ = participant::pose_rows(state);
  }

 private:
  Common common_;
  std::vector<double> mass_;  // 0 for fixed bodies
  std::vector<participant::PoseRow> poses_;
};

}  // namespace
}  // namespace cosim::doubles

int main() {
  cosim::doubles::MassSolver solver;
  using cosim::scene::Data;
  return cosim::doubles::serve("cosim-test-oscillator-mass", solver, Data::Poses, Data::Forces);
}
