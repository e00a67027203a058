#include "tests/tracker/mesh/checks.hpp"

#include "tracker/mesh/validate.hpp"

#include <gtest/gtest.h>

#include <numeric>

namespace cosim::tracker::mesh::test {

double total_volume(const Mesh& mesh) { return std::accumulate(mesh.volume.begin(), mesh.volume.end(), 0.0); }

Index boundary_faces(const Mesh& mesh) {
  Index count = 0;
  for (const Face& face : mesh.faces) count += face.neighbour < 0;
  return count;
}

void expect_consistent(const Mesh& mesh) {
  const auto problems = validate(mesh);
  EXPECT_FALSE(has_errors(problems)) << describe(problems);
  for (Index c = 0; c < mesh.cell_count(); ++c)
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f) {
      const Face& face = mesh.faces[f];
      ASSERT_NEAR(face.normal.norm(), 1.0, 1e-12);
      ASSERT_GT(face.normal.dot(mesh.centroid[c] - face.point), 0.0) << "cell " << c << " face " << f;
      if (face.neighbour < 0) continue;
      const Face& twin = mesh.faces[face.twin];
      ASSERT_EQ(twin.neighbour, c);
      ASSERT_EQ(twin.twin, f);
      ASSERT_NEAR(face.normal.dot(twin.normal), -1.0, 1e-12);
    }
}

}  // namespace cosim::tracker::mesh::test
