// cosim-drag: a participant of its own, built against an installed cosim (README.md). It
// provides forces and needs poses: a linear drag -c v on every body, c from its section's
// options (`coefficient`, kg/s). With cosim-rigidbody and gravity a body of mass m falls at
// m g / c in the end.
#include <iostream>

#include "coupler/participant/run_participant.hpp"
#include "coupler/scene/reader.hpp"

namespace {

using namespace cosim;

class Drag final : public participant::Solver {
 public:
  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<participant::PoseRow>& poses, const std::vector<double>&) override {
    // The same reader as the built-ins': a bad or unknown key is refused naming file and line.
    const scene::Reader options = scene::options_of(scene, *scene.participant(name));
    c_ = options.number("coefficient", scene::Range::above(0));
    options.finish();
    return {{}, drag(poses, poses), 0};
  }

  // Forces are the window's mean (docs/protocol.md): the velocity goes linearly from the
  // start pose to the end one, so the mean drag is that of their mean.
  participant::Outputs advance(const participant::Window&, const participant::Inputs& in) override {
    return {{}, drag(in.poses_start, in.poses_end), 1};
  }

  // The force follows from the poses alone: nothing to save for rollback or checkpoints.
  std::vector<double> state() const override { return {}; }
  void restore(const std::vector<double>&) override {}

 private:
  std::vector<participant::ForceRow> drag(const std::vector<participant::PoseRow>& start,
                                          const std::vector<participant::PoseRow>& end) const {
    std::vector<participant::ForceRow> forces(start.size());
    for (std::size_t b = 0; b < start.size(); ++b) forces[b].force = -c_ * 0.5 * (start[b].velocity + end[b].velocity);
    return forces;
  }

  double c_ = 0.0;
};

}  // namespace

int main() {
  auto client = cosim::protocol::Client::from_environment();
  if (!client) {
    std::cerr << "cosim-drag is a participant: start it through cosim run\n";
    return 2;
  }
  Drag drag;
  using cosim::scene::Data;
  return cosim::participant::run_participant(*client, drag, static_cast<std::uint32_t>(Data::Forces),
                                             static_cast<std::uint32_t>(Data::Poses));
}
