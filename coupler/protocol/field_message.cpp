#include "protocol/field_message.hpp"

#include <string>
#include <utility>

namespace cosim::protocol {
namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

std::uint32_t rows_of(std::size_t n) { return static_cast<std::uint32_t>(n); }

}  // namespace

std::vector<Array> field_arrays(output::FieldFrame frame) {
  std::vector<Array> arrays;
  if (frame.fields.empty()) return arrays;
  for (std::size_t a = 0; a < 3; ++a) {
    auto& nodes = frame.grid.nodes[a];
    const std::uint32_t count = rows_of(nodes.size());  // before the values move out
    arrays.push_back(Array::text(kAxes[a]));
    arrays.push_back(Array::of(Tag::Field, 1, count, std::move(nodes)));
  }
  for (output::CellField& f : frame.fields) {
    const auto components = static_cast<std::uint32_t>(f.components);
    const std::uint32_t rows = rows_of(f.values.size() / components);  // before the values move out
    arrays.push_back(Array::text(f.name));
    arrays.push_back(Array::of(Tag::Field, rows, components, std::move(f.values)));
  }
  return arrays;
}

output::FieldFrame field_frame(Message m) {
  output::FieldFrame frame;
  if (m.arrays.empty()) return frame;
  if (m.arrays.size() % 2 != 0 || m.arrays.size() < 6)
    throw ProtocolError("Field message of '" + m.header.participant + "' has " + std::to_string(m.arrays.size()) +
                        " arrays: expected name and values for x, y, z and each field");
  for (std::size_t i = 0; i < m.arrays.size(); i += 2) {
    const Array& name = m.arrays[i];
    Array& values = m.arrays[i + 1];
    if (name.tag != Tag::Text || values.tag != Tag::Field)
      throw ProtocolError("Field message of '" + m.header.participant + "': array " + std::to_string(i) +
                          " must be a name (Text) followed by a Field array");
    if (i < 6) {
      if (name.bytes != kAxes[i / 2] || values.rows != 1 || values.cols < 2)
        throw ProtocolError("Field message of '" + m.header.participant + "': grid axis " + kAxes[i / 2] +
                            " missing or without nodes (array " + std::to_string(i) + ")");
      frame.grid.nodes[i / 2] = std::move(values.values);
      continue;
    }
    const auto n = frame.grid.cells();
    if (values.rows != n[0] * n[1] * n[2])
      throw ProtocolError("Field message of '" + m.header.participant + "': field " + name.bytes + " has " +
                          std::to_string(values.rows) + " rows, the grid has " + std::to_string(n[0] * n[1] * n[2]) +
                          " cells");
    frame.fields.push_back({name.bytes, static_cast<int>(values.cols), std::move(values.values)});
  }
  return frame;
}

}  // namespace cosim::protocol
