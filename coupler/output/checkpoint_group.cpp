#include "output/checkpoint_group.hpp"

#include <cstdint>

#include "output/h5_groups.hpp"
#include "output/h5_values.hpp"
#include "output/record_shape.hpp"

namespace cosim::output {
namespace {

constexpr const char* kName = "checkpoint";
constexpr const char* kNewName = "checkpoint_new";

}  // namespace

void write_checkpoint(hid_t file, const Checkpoint& c, std::size_t bodies,
                      const std::vector<std::string>& participants) {
  const std::string what = "checkpoint for window " + std::to_string(c.next_window);
  check_body_rows(what, c.poses, c.forces, bodies);
  check_participants(what, c.states, participants);
  // Left over if an earlier write failed part-way.
  if (has_link(file, kNewName)) remove_link(file, kNewName);
  {
    Handle group = create_group(file, kNewName);
    write_attribute(group.get(), "window", c.next_window);
    write_attribute(group.get(), "time", c.time);
    write_doubles(group.get(), "poses", c.poses, kPoseWidth);
    write_doubles(group.get(), "forces", c.forces, kForceWidth);
    Handle states = create_group(group.get(), "participants");
    for (const auto& [name, state] : c.states) {
      Handle p = create_group(states.get(), name);
      write_doubles(p.get(), "state", state, 1);
    }
  }
  flush(file);
  if (has_link(file, kName)) remove_link(file, kName);
  move_link(file, kNewName, kName);
  flush(file);
}

std::optional<Checkpoint> read_checkpoint(hid_t file,
                                          const std::vector<std::string>& participants) {
  if (!has_link(file, kName)) return std::nullopt;
  Handle group = open_group(file, kName);
  Checkpoint c;
  c.next_window = read_attribute<std::uint64_t>(group.get(), "window");
  c.time = read_attribute<double>(group.get(), "time");
  c.poses = read_doubles(group.get(), "poses");
  c.forces = read_doubles(group.get(), "forces");
  Handle states = open_group(group.get(), "participants");
  for (const std::string& name : participants) {
    if (has_link(states.get(), name)) {
      Handle p = open_group(states.get(), name);
      c.states[name] = read_doubles(p.get(), "state");
    }
  }
  return c;
}

}  // namespace cosim::output
