#include "tests/doubles/double_common.hpp"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "coupler/participant/run_participant.hpp"
#include <thread>

namespace cosim::doubles {

const scene::Participant& section(const scene::Scene& scene, const std::string& name) {
  const auto* p = scene.participant(name);
  if (p == nullptr) throw std::runtime_error("no section participants." + name + " in the scene");
  return *p;
}

int serve(const char* program, participant::Solver& solver, scene::Data provides, scene::Data needs) {
  auto client = protocol::Client::from_environment();
  if (!client) {
    std::cerr << program << " is a test participant: start it through cosim run\n";
    return 2;
  }
  return participant::run_participant(*client, solver, static_cast<std::uint32_t>(provides),
                                      static_cast<std::uint32_t>(needs));
}

Common Common::read(const scene::Scene&, const scene::Participant& p, const scene::Reader& options) {
  Common c;
  const auto integrator = options.string("integrator", "verlet");
  if (integrator == "euler")
    c.integrator = Integrator::Euler;
  else if (integrator != "verlet")
    options.fail("integrator", "expected verlet or euler");
  c.dt = p.dt;
  c.delay = options.number("delay", 0.0);
  c.kill_at = options.number("kill_at", c.kill_at);
  c.hang_at = options.number("hang_at", c.hang_at);
  c.kill_marker = options.string("kill_marker", "");
  return c;
}

void Common::on_window(const participant::Window& w) const {
  if (w.t0 >= kill_at && (kill_marker.empty() || !std::filesystem::exists(kill_marker))) {
    if (!kill_marker.empty()) std::ofstream(kill_marker) << "killed\n";
    std::raise(SIGKILL);
  }
  if (w.t0 >= hang_at)
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  if (delay > 0) std::this_thread::sleep_for(std::chrono::duration<double>(delay));
}

}  // namespace cosim::doubles
