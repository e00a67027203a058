#include "cosim_git_hash.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::output {

RunInfo RunInfo::of_this_build(std::string scene_text, std::string scene_file) {
  return {std::move(scene_text), std::move(scene_file), COSIM_GIT_HASH, COSIM_VERSION, protocol::kVersion};
}

}  // namespace cosim::output
