// Grid fields on the wire (a Field message): what a participant's fields() gives, in
// arrays that name themselves. First the grid: a rectilinear one per axis as a Text "x",
// "y", "z" and a Field of 1 x nodes; a polyhedral one as a Text "vertices" and a Field of
// vertices x 3, then a Text "topology" and a Field of 1 x entries, the int64 Mixed topology
// (field::PolyhedralGrid) as float64, exact as its entries are below 2^53. Then per field
// a Text with its name and a Field of cells x components; the cell count of a polyhedral
// grid is not sent apart, it is the fields' rows. Then the frame's point sets, if it has
// any, in three arrays (point_set_arrays.hpp), the last one tagged Points, and their
// attributes, if any, in three more, the last one tagged PointAttributes.
// An Advance to a participant that needs fields carries the same arrays after its inputs
// (Poses and Forces arrays, none of them Text): the first Text array starts the frame.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::protocol {

// No fields: no arrays at all, not even the grid or the point sets. ProtocolError for a grid
// that is not one (field::grid_problem()) or point sets that are not
// (field::point_sets_problem()), so that a bad frame fails at its sender.
std::vector<Array> field_arrays(field::FieldFrame frame);  // moves the values into the arrays
// The frame back; ProtocolError for arrays that do not make one (an axis missing or out of
// order, vertices without the topology, a topology entry that is not a whole number, a
// topology that is not the fields' cells, a name without its array, a field whose rows
// are not the grid's cells, point sets that are not: take_point_sets()).
field::FieldFrame field_frame(Message m);  // moves them back out
// The same from the field arrays alone; `who` names their sender in errors.
field::FieldFrame field_frame(std::vector<Array> arrays, const std::string& who);
// Moves the field arrays (from the first Text on) out of an Advance's arrays.
std::vector<Array> take_field_arrays(std::vector<Array>& arrays);
// What the arrays' payloads weigh on the wire (float64 values and text bytes).
std::size_t payload_bytes(const std::vector<Array>& arrays);

}  // namespace cosim::protocol
