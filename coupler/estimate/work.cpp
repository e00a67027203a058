#include "coupler/estimate/work.hpp"

#include <yaml-cpp/yaml.h>

#include <stdexcept>

namespace cosim::estimate {
namespace {

Units units(const YAML::Node& node) {
  Units out;
  if (!node) return out;
  for (const auto& entry : node) out[entry.first.as<std::string>()] = entry.second.as<double>();
  return out;
}

}  // namespace

ProgramWork read_work(const std::filesystem::path& file) {
  try {
    const YAML::Node doc = YAML::LoadFile(file.string());
    ProgramWork out;
    out.program = doc["program"].as<std::string>();
    out.per_step = units(doc["per_step"]);
    out.held = units(doc["held"]);
    out.frame_bytes = doc["frame_bytes"] ? doc["frame_bytes"].as<double>() : 0.0;
    out.state_bytes = doc["state_bytes"] ? doc["state_bytes"].as<double>() : 0.0;
    out.dt = doc["dt"] ? doc["dt"].as<double>() : 0.0;
    out.grows = doc["grows"] && doc["grows"].as<bool>();
    return out;
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(file.string() + ": not a work report: " + e.what());
  }
}

}  // namespace cosim::estimate
