#include "coupler/study/key_path.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <utility>
#include <vector>

#include "coupler/study/argument_error.hpp"

namespace cosim::study {
namespace {

std::vector<std::string> steps_of(const std::string& path, const std::string& argument) {
  std::vector<std::string> steps;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    steps.push_back(path.substr(start, dot - start));
    if (steps.back().empty())
      throw ArgumentError(
          fmt::format("{}: '{}' is not a key path (keys joined by dots: coupling.window)", argument, path));
    if (dot == std::string::npos) return steps;
    start = dot + 1;
  }
}

std::vector<std::string> keys_of(const YAML::Node& map) {
  std::vector<std::string> keys;
  for (const auto& entry : map) keys.push_back(entry.first.Scalar());
  return keys;
}

}  // namespace

void set_at(YAML::Node root, const std::string& path, const YAML::Node& value, const std::string& argument) {
  const std::vector<std::string> steps = steps_of(path, argument);
  // reset(), not assignment: assigning to a yaml-cpp handle overwrites the node it refers to.
  YAML::Node node;
  node.reset(root);
  std::string walked = "the scene";
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::string& step = steps[i];
    const bool last = i + 1 == steps.size();
    if (node.IsSequence()) {
      std::size_t index = 0;
      const auto [end, ec] = std::from_chars(step.data(), step.data() + step.size(), index);
      if (ec != std::errc() || end != step.data() + step.size() || index >= node.size())
        throw ArgumentError(fmt::format("{}: {} is a list of {} entries: expected an index from 0 to {}, not '{}'",
                                        argument, walked, node.size(), node.size() - 1, step));
      if (last) {
        node[index] = value;
        return;
      }
      node.reset(node[index]);
    } else if (node.IsMap()) {
      if (last) {
        node[step] = value;
        return;
      }
      const YAML::Node child = std::as_const(node)[step];
      if (!child.IsDefined())
        throw ArgumentError(
            fmt::format("{}: {} has no key '{}' (it has: {})", argument, walked, step, fmt::join(keys_of(node), ", ")));
      node.reset(child);
    } else {
      throw ArgumentError(
          fmt::format("{}: {} is a value, not a mapping or list: no '{}' in it", argument, walked, step));
    }
    walked = fmt::format("{}", fmt::join(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(i) + 1, "."));
  }
}

}  // namespace cosim::study
