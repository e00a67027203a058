#pragma once
// Faces of the standard cell kinds in Gmsh's corner order, counter-clockwise seen from
// outside a positively oriented element.

#include <vector>

namespace cosim::tracker::mesh::element_faces {

// Corners 0, 1, 2 counter-clockwise seen from corner 3.
inline const std::vector<std::vector<int>> tetrahedron{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
// Bottom 0-1-2-3 and top 4-5-6-7, both counter-clockwise seen from above.
inline const std::vector<std::vector<int>> hexahedron{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
// Bottom triangle 0-1-2 and top 3-4-5, counter-clockwise seen from above.
inline const std::vector<std::vector<int>> prism{{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
// Base 0-1-2-3 counter-clockwise seen from the apex 4.
inline const std::vector<std::vector<int>> pyramid{{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

}  // namespace cosim::tracker::mesh::element_faces
