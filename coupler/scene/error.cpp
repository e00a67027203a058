#include "scene/error.hpp"

#include <fmt/format.h>

namespace cosim::scene {
namespace {

std::string message(const std::string& file, int line, const std::string& key, const std::string& value,
                    const std::string& problem) {
  const std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  if (key.empty()) return fmt::format("{}: {}", where, problem);
  if (value.empty()) return fmt::format("{}: {}: {}", where, key, problem);
  return fmt::format("{}: {} = {}: {}", where, key, value, problem);
}

}  // namespace

SceneError::SceneError(std::string file, int line, std::string key, std::string value, const std::string& problem)
    : std::runtime_error(message(file, line, key, value, problem)),
      file(std::move(file)),
      line(line),
      key(std::move(key)),
      value(std::move(value)) {}

}  // namespace cosim::scene
