// The one exception a bad scene raises. Its fields let tools point at the spot (an editor
// jumping to file:line, a test asserting the key) without parsing what().
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace cosim::scene {

struct SceneError : std::runtime_error {
  // what() is "<file>:<line>: <key> = <value>: <problem>"; an empty value drops " = <value>",
  // an empty key drops the key part, line 0 (no line, e.g. a missing file) drops ":<line>".
  SceneError(std::string file, int line, std::string key, std::string value, const std::string& problem);

  std::string file;
  int line;
  std::string key;    // dotted path with list indices: bodies[0].shape.radius
  std::string value;  // as written in the file, shortened
};

// A program's exit code for `body`: its own, or 2 for a SceneError ("<program>: invalid
// scene: ..." on stderr) and 1 for any other exception ("<program>: ..."), so every program
// tells a bad scene from a failed run the same way.
int exit_code(const std::string& program, const std::function<int()>& body);

}  // namespace cosim::scene
