// A frame's point sets (output::PointSet) on the wire, after its cell fields in a Field
// message: three arrays however many sets there are, so that a fluid with hundreds of
// bodies stays within kMaxArrays. A Text of the names, each followed by a NUL (names have
// no control characters: output::point_sets_problem()); a Field of 1 x k, each set's point
// count as float64; a Points array of n x 3, every set's points, one set after the other.
// No point sets: none of the three.
#pragma once

#include <string>
#include <vector>

#include "output/field_frame.hpp"
#include "protocol/message.hpp"

namespace cosim::protocol {

// Appends the three arrays (the points copied into one); nothing for no sets.
void push_point_sets(std::vector<Array>& arrays, const std::vector<output::PointSet>& sets);
// If the last array is a Points array, takes the three off the end of `arrays` and returns
// their sets; ProtocolError naming `who` for arrays that do not make them (names and counts
// that do not pair up, a count that is not a whole number, counts that are not the points
// sent, a name point_sets_problem() refuses).
std::vector<output::PointSet> take_point_sets(std::vector<Array>& arrays, const std::string& who);

}  // namespace cosim::protocol
