// A frame's point sets (field::PointSet) on the wire, after its cell fields in a Field
// message: three arrays however many sets there are, so that a fluid with hundreds of
// bodies stays within kMaxArrays. A Text of the names, each followed by a NUL (names have
// no control characters: field::point_sets_problem()); a Field of 1 x k, each set's point
// count as float64; a Points array of n x 3, every set's points, one set after the other.
// Then, if any set has attributes, three more: a Text of their names, each followed by a
// NUL (the sets in order, each set's attributes in order); a Field of 3 x a, per attribute
// the index of its set, its components and 1 if it is integer (else 0); a PointAttributes
// array of 1 x m, every attribute's points x components values, one after the other.
// No point sets: none of the arrays; sets without attributes: the first three only.
#pragma once

#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::protocol {

// Appends the arrays (the points and the attributes' values copied into one each); nothing
// for no sets.
void push_point_sets(std::vector<Array>& arrays, const std::vector<field::PointSet>& sets);
// If the last array is a Points or PointAttributes array, takes the point sets' arrays off
// the end of `arrays` and returns their sets; ProtocolError naming `who` for arrays that do
// not make them (names and counts that do not pair up, a count that is not a whole number,
// counts that are not the points sent, attributes without sets, an attribute's set index,
// components or integer flag that is not one, values that are not what the attributes
// take, a name or value point_sets_problem() refuses).
std::vector<field::PointSet> take_point_sets(std::vector<Array>& arrays, const std::string& who);

}  // namespace cosim::protocol
