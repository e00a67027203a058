#include "coupler/protocol/field_message.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>
#include <variant>

#include "coupler/protocol/point_set_arrays.hpp"

namespace cosim::protocol {
namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};
// Every integer below 2^53 is a float64, and a topology's entries are such integers.
constexpr double kExactIntegers = 9007199254740992.0;

std::uint32_t rows_of(std::size_t n) { return static_cast<std::uint32_t>(n); }

std::vector<std::int64_t> topology_entries(const std::vector<double>& values, const std::string& who) {
  std::vector<std::int64_t> out;
  out.reserve(values.size());
  for (const double v : values) {
    if (!(v >= 0.0 && v < kExactIntegers && v == std::floor(v)))  // NaN fails too
      throw ProtocolError(who + ": topology entry " + std::to_string(v) + " is not a whole number within [0, 2^53)");
    out.push_back(static_cast<std::int64_t>(v));
  }
  return out;
}

void push_grid(std::vector<Array>& arrays, field::RectilinearGrid& grid) {
  for (std::size_t a = 0; a < 3; ++a) {
    auto& nodes = grid.nodes[a];
    const std::uint32_t count = rows_of(nodes.size());  // before the values move out
    arrays.push_back(Array::text(kAxes[a]));
    arrays.push_back(Array::of(Tag::Field, 1, count, std::move(nodes)));
  }
}

void push_grid(std::vector<Array>& arrays, field::PolyhedralGrid& grid) {
  const std::uint32_t vertices = rows_of(grid.vertices.size() / 3);  // before the values move out
  arrays.push_back(Array::text("vertices"));
  arrays.push_back(Array::of(Tag::Field, vertices, 3, std::move(grid.vertices)));
  arrays.push_back(Array::text("topology"));
  // Exact as float64: grid_problem() has bounded every entry by the vertex count or the
  // topology's length.
  std::vector<double> topology(grid.topology.begin(), grid.topology.end());
  const std::uint32_t entries = rows_of(topology.size());  // before the values move out
  arrays.push_back(Array::of(Tag::Field, 1, entries, std::move(topology)));
}

// Moves the grid out of the leading arrays into frame; returns the index of the first field's name.
std::size_t take_grid(std::vector<Array>& a, field::FieldFrame& frame, const std::string& who) {
  if (a[0].bytes == "vertices") {
    if (a.size() < 6 || a[1].cols != 3 || a[2].bytes != "topology" || a[3].rows != 1)
      throw ProtocolError(who + ": vertices (v x 3) must be followed by the topology (1 x n) and a field");
    field::PolyhedralGrid grid;
    grid.vertices = std::move(a[1].values);
    grid.topology = topology_entries(a[3].values, who);
    grid.cells = a[5].rows;  // every field has a row per cell
    frame.grid = std::move(grid);
    return 4;
  }
  if (a.size() < 6)
    throw ProtocolError(who + " has " + std::to_string(a.size()) +
                        " arrays: expected name and values for x, y, z and each field");
  field::RectilinearGrid grid;
  for (std::size_t i = 0; i < 6; i += 2) {
    if (a[i].bytes != kAxes[i / 2] || a[i + 1].rows != 1 || a[i + 1].cols < 2)
      throw ProtocolError(who + ": grid axis " + kAxes[i / 2] + " missing or without nodes (array " +
                          std::to_string(i) + ")");
    grid.nodes[i / 2] = std::move(a[i + 1].values);
  }
  frame.grid = std::move(grid);
  return 6;
}

}  // namespace

std::vector<Array> field_arrays(field::FieldFrame frame) {
  std::vector<Array> arrays;
  if (frame.fields.empty()) return arrays;
  for (const std::string& problem : {field::grid_problem(frame.grid), field::point_sets_problem(frame.point_sets)})
    if (!problem.empty()) throw ProtocolError("Field arrays: " + problem);
  std::visit([&](auto& grid) { push_grid(arrays, grid); }, frame.grid);
  for (field::CellField& f : frame.fields) {
    const auto components = static_cast<std::uint32_t>(f.components);
    const std::uint32_t rows = rows_of(f.values.size() / components);  // before the values move out
    arrays.push_back(Array::text(f.name));
    arrays.push_back(Array::of(Tag::Field, rows, components, std::move(f.values)));
  }
  push_point_sets(arrays, frame.point_sets);
  return arrays;
}

field::FieldFrame field_frame(Message m) {
  return field_frame(std::move(m.arrays), "Field message of '" + m.header.participant + "'");
}

field::FieldFrame field_frame(std::vector<Array> arrays, const std::string& who) {
  field::FieldFrame frame;
  if (arrays.empty()) return frame;
  frame.point_sets = take_point_sets(arrays, who);
  if (arrays.empty()) throw ProtocolError(who + ": point sets without a grid and cell fields");
  if (arrays.size() % 2 != 0)
    throw ProtocolError(who + " has " + std::to_string(arrays.size()) + " arrays: expected pairs of a name and values");
  for (std::size_t i = 0; i < arrays.size(); i += 2)
    if (arrays[i].tag != Tag::Text || arrays[i + 1].tag != Tag::Field)
      throw ProtocolError(who + ": array " + std::to_string(i) + " must be a name (Text) followed by a Field array");
  const std::size_t first_field = take_grid(arrays, frame, who);
  if (const std::string problem = field::grid_problem(frame.grid); !problem.empty())
    throw ProtocolError(who + ": " + problem);
  const std::size_t cells = field::cell_count(frame.grid);
  for (std::size_t i = first_field; i < arrays.size(); i += 2) {
    const Array& name = arrays[i];
    Array& values = arrays[i + 1];
    if (values.rows != cells)
      throw ProtocolError(who + ": field " + name.bytes + " has " + std::to_string(values.rows) +
                          " rows, the grid has " + std::to_string(cells) + " cells");
    frame.fields.push_back({name.bytes, static_cast<int>(values.cols), std::move(values.values)});
  }
  return frame;
}

std::vector<Array> take_field_arrays(std::vector<Array>& arrays) {
  const auto first = std::find_if(arrays.begin(), arrays.end(), [](const Array& a) { return a.tag == Tag::Text; });
  std::vector<Array> fields(std::make_move_iterator(first), std::make_move_iterator(arrays.end()));
  arrays.erase(first, arrays.end());
  return fields;
}

std::size_t payload_bytes(const std::vector<Array>& arrays) {
  std::size_t bytes = 0;
  for (const Array& a : arrays) bytes += a.values.size() * sizeof(double) + a.bytes.size();
  return bytes;
}

}  // namespace cosim::protocol
