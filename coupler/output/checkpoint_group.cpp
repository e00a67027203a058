#include "coupler/output/checkpoint_group.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/record_shape.hpp"
#include "coupler/output/series.hpp"

namespace cosim::output {
namespace {

constexpr const char* kGroup = "checkpoint";
constexpr const char* kCurrent = "current";
constexpr const char* kLength = "length";
// Chunks of about the first value's size within these bounds: a pose table is not one big,
// mostly empty chunk, and a solver state of megabytes is not thousands of chunks.
constexpr hsize_t kMinChunkBytes = 4 << 10;
constexpr hsize_t kMaxChunkBytes = 256 << 10;

hsize_t chunk_rows(hsize_t rows, hsize_t columns) {
  const hsize_t row_bytes = columns * sizeof(double);
  return std::max<hsize_t>(1, std::clamp(rows, kMinChunkBytes / row_bytes, kMaxChunkBytes / row_bytes));
}

// {rows, columns} of a 1-d (columns 1) or 2-d dataset.
std::array<hsize_t, 2> extent(hid_t ds, const std::string& where) {
  Handle space(H5Dget_space(ds), H5Sclose, "dataspace of " + where);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != 1 && rank != 2) throw ObjectError(where + " is not a 1-d or 2-d dataset");
  std::array<hsize_t, 2> dims{0, 1};
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

// The first `rows` rows of a dataset, and a memory dataspace of that shape.
struct FirstRows {
  Handle file;
  Handle memory;
};
FirstRows first_rows(hid_t ds, hsize_t rows, hsize_t columns, const std::string& where) {
  const hsize_t start[2] = {0, 0};
  const hsize_t count[2] = {rows, columns};
  Handle file(H5Dget_space(ds), H5Sclose, "dataspace of " + where);
  check(H5Sselect_hyperslab(file.get(), H5S_SELECT_SET, start, nullptr, count, nullptr), "select rows of " + where);
  Handle memory(H5Screate_simple(H5Sget_simple_extent_ndims(file.get()), count, nullptr), H5Sclose,
                "make memory dataspace for " + where);
  return {std::move(file), std::move(memory)};
}

// Overwrites the array `name` (rows x columns doubles, row-major; 1-d if columns == 1) in
// place, creating it on first use. It is only ever grown: shrinking a chunked dataset frees
// its chunks, so a shorter value leaves the rows after it and says its length in `length`.
void write_rows(hid_t group, const std::string& name, const std::vector<double>& values, hsize_t columns) {
  const std::string where = "dataset " + child_path(group, name);
  const hsize_t rows = values.size() / columns;
  Handle ds = has_link(group, name)
                  ? Handle(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where)
                  : create_extendible(group, name, H5T_NATIVE_DOUBLE, columns, chunk_rows(rows, columns));
  std::array<hsize_t, 2> dims = extent(ds.get(), where);
  if (dims[1] != columns) {
    throw ObjectError(where + " has rows of " + std::to_string(dims[1]) + " values, not " + std::to_string(columns));
  }
  if (rows > dims[0]) {
    dims[0] = rows;
    check(H5Dset_extent(ds.get(), dims.data()), "grow " + where);
  }
  if (rows > 0) {
    const FirstRows sel = first_rows(ds.get(), rows, columns, where);
    check(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, sel.memory.get(), sel.file.get(), H5P_DEFAULT, values.data()),
          "write " + where);
  }
  write_attribute(ds.get(), kLength, std::uint64_t{rows});
}

std::vector<double> read_rows(hid_t group, const std::string& name) {
  const std::string where = "dataset " + child_path(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  const std::array<hsize_t, 2> dims = extent(ds.get(), where);
  const auto rows = read_attribute<std::uint64_t>(ds.get(), kLength);
  if (rows > dims[0]) {
    throw ObjectError(where + ": length " + std::to_string(rows) + " exceeds its " + std::to_string(dims[0]) + " rows");
  }
  std::vector<double> values(rows * dims[1]);
  if (!values.empty()) {
    const FirstRows sel = first_rows(ds.get(), rows, dims[1], where);
    check(H5Dread(ds.get(), H5T_NATIVE_DOUBLE, sel.memory.get(), sel.file.get(), H5P_DEFAULT, values.data()),
          "read " + where);
  }
  return values;
}

// Writes c into one slot, creating what it lacks. Every run participant gets a state
// dataset, with or without a state, so that only the first checkpoint creates objects.
void write_slot(hid_t checkpoint, const std::string& slot_name, const Checkpoint& c,
                const std::vector<std::string>& participants) {
  static const std::vector<double> kNoState;
  Handle slot = open_or_create_group(checkpoint, slot_name);
  write_attribute(slot.get(), "window", c.next_window);
  write_attribute(slot.get(), "time", c.time);
  write_rows(slot.get(), "poses", c.poses, kPoseWidth);
  write_rows(slot.get(), "forces", c.forces, kForceWidth);
  write_rows(slot.get(), "responses", c.responses, kResponseWidth);
  Handle states = open_or_create_group(slot.get(), "participants");
  for (const std::string& name : participants) {
    const auto state = c.states.find(name);
    const bool present = state != c.states.end();
    Handle p = open_or_create_group(states.get(), name);
    write_attribute(p.get(), "present", int{present});
    write_rows(p.get(), "state", present ? state->second : kNoState, 1);
  }
}

}  // namespace

void write_checkpoint(hid_t file, const Checkpoint& c, std::size_t bodies,
                      const std::vector<std::string>& participants) {
  const std::string what = "checkpoint for window " + std::to_string(c.next_window);
  check_body_rows(what, c.poses, c.forces, bodies);
  if (!c.responses.empty() && c.responses.size() != bodies * kResponseWidth)
    throw ObjectError(what + ": " + std::to_string(c.responses.size()) + " response values for " +
                      std::to_string(bodies) + " bodies (" + std::to_string(kResponseWidth) + " each, or none)");
  check_participants(what, c.states, participants);
  Handle group = open_or_create_group(file, kGroup);
  const char* next = "a";
  if (has_attribute(group.get(), kCurrent)) {
    if (read_attribute<std::string>(group.get(), kCurrent) == "a") next = "b";
  } else {
    // The first checkpoint (or a retry of one that failed) lays out both slots, b with the
    // same value, so that from now on writes only overwrite and grow.
    write_slot(group.get(), "b", c, participants);
  }
  write_slot(group.get(), next, c, participants);
  flush(file);
  // The commit point: one attribute overwritten in place, after the slot is in the file.
  write_fixed_string_attribute(group.get(), kCurrent, next);
  flush(file);
}

std::optional<Checkpoint> read_checkpoint(hid_t file, const std::vector<std::string>& participants) {
  if (!has_link(file, kGroup)) return std::nullopt;
  Handle group = open_group(file, kGroup);
  if (!has_attribute(group.get(), kCurrent)) return std::nullopt;
  const auto current = read_attribute<std::string>(group.get(), kCurrent);
  if (current != "a" && current != "b") {
    throw ObjectError("attribute current of /checkpoint names no slot: '" + current + "'");
  }
  Handle slot = open_group(group.get(), current);
  Checkpoint c;
  c.next_window = read_attribute<std::uint64_t>(slot.get(), "window");
  c.time = read_attribute<double>(slot.get(), "time");
  c.poses = read_rows(slot.get(), "poses");
  c.forces = read_rows(slot.get(), "forces");
  if (has_link(slot.get(), "responses")) c.responses = read_rows(slot.get(), "responses");
  Handle states = open_group(slot.get(), "participants");
  for (const std::string& name : participants) {
    if (!has_link(states.get(), name)) continue;
    Handle p = open_group(states.get(), name);
    if (read_attribute<int>(p.get(), "present") != 0) c.states[name] = read_rows(p.get(), "state");
  }
  return c;
}

}  // namespace cosim::output
