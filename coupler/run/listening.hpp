// Where the coupler listens and who may connect: an ipc socket in the run's private folder,
// or tcp on 127.0.0.1 or coupling.interface with CURVE keys made for this run.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "coupler/protocol/server.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::run {

struct Listening {
  std::string endpoint;  // to bind: "ipc://...", "tcp://127.0.0.1:*", "tcp://ib0:*"
  protocol::ServerOptions options;
  // What each participant finds in its environment besides the endpoint and its name: its
  // CURVE keys.
  std::map<std::string, std::map<std::string, std::string>> environment;
};

// Over tcp, makes the run's keys: the coupler's pair goes to run_dir/coupler.key (0600),
// each participant's pair to its environment only.
Listening listening(const scene::Coupling& coupling, const std::vector<std::string>& participants,
                    const std::filesystem::path& run_dir);

}  // namespace cosim::run
