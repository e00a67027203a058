#include "coupler/scene/error.hpp"

#include <fmt/format.h>

#include <iostream>

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

int exit_code(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const SceneError& e) {
    std::cerr << program << ": invalid scene: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace cosim::scene
