#include "coupler/run/listening.hpp"

#include <cmath>

namespace cosim::run {

Listening listening(const scene::Coupling& coupling, const std::vector<std::string>& participants,
                    const std::filesystem::path& run_dir) {
  Listening l;
  l.options.heartbeat = std::chrono::milliseconds(std::lround(coupling.heartbeat * 1000.0));
  if (coupling.transport == scene::Transport::Ipc) {
    l.endpoint = "ipc://" + (run_dir / "coupler").string();
    return l;
  }
  const std::string& at = coupling.interface;
  l.endpoint = at.empty()                          ? "tcp://127.0.0.1:*"
               : at.find(':') != std::string::npos ? "tcp://[" + at + "]:*"  // an IPv6 address
                                                   : "tcp://" + at + ":*";
  // Even on 127.0.0.1 another user of this host could connect: every tcp run has keys.
  protocol::curve::ServerKeys keys{protocol::curve::make_keypair(), {}};
  protocol::curve::write_keypair(run_dir / "coupler.key", keys.own);
  for (const auto& name : participants) {
    const protocol::curve::ClientKeys own{keys.own.public_key, protocol::curve::make_keypair()};
    keys.participants.emplace(own.own.public_key, name);
    l.environment[name] = protocol::curve::environment(own);
  }
  l.options.curve = std::move(keys);
  return l;
}

}  // namespace cosim::run
