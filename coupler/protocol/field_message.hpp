// Grid fields on the wire (a Field message): what a participant's fields() gives, in
// arrays that name themselves. First the grid, per axis a Text "x", "y", "z" and a Field of
// 1 x nodes; then per field a Text with its name and a Field of cells x components.
#pragma once

#include <vector>

#include "output/field_frame.hpp"
#include "protocol/message.hpp"

namespace cosim::protocol {

// No fields: no arrays at all, not even the grid.
std::vector<Array> field_arrays(output::FieldFrame frame);  // moves the values into the arrays
// The frame back; ProtocolError for arrays that do not make one (an axis missing or out of
// order, a name without its array, a field whose rows are not the grid's cells).
output::FieldFrame field_frame(Message m);  // moves them back out

}  // namespace cosim::protocol
