#include "tracker/mesh/validate.hpp"

#include "tracker/mesh/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cosim::tracker::mesh {
namespace {

constexpr double relative_tolerance = 1e-9;

std::string str(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

class CellCheck {
 public:
  CellCheck(const Mesh& mesh, Index cell, std::vector<Problem>& problems)
      : mesh_(mesh), cell_(cell), first_(mesh.cell_faces[cell]), last_(mesh.cell_faces[cell + 1]), problems_(problems) {
    size_ = cell_box(mesh, cell).diagonal().norm();
    tolerance_ = relative_tolerance * size_;
  }

  void run() {
    closed_and_sized();
    for (Index f = first_; f < last_; ++f) {
      neighbours(f);
      orientation(f);
    }
    planarity_and_convexity();
  }

 private:
  void report(bool error, Defect defect, Index face, std::string what) {
    problems_.push_back({error, defect, cell_, face, std::move(what)});
  }

  void closed_and_sized() {
    Vec3 sum = Vec3::Zero();
    double area = 0.0;
    for (Index f = first_; f < last_; ++f) {
      const Vec3 a = area_vector(mesh_, f);
      sum += a;
      area += a.norm();
      // Zero area within the length tolerance: the face is no wider than the tolerance
      // across its longest chord (area <= tolerance * diameter / 2; a triangle's height
      // over that chord). Comparing the area with tolerance * cell size instead would
      // reject genuine small faces of 1e-5 of the cell (random Voronoi points have them).
      const double chord = diameter(f);
      if (2.0 * a.norm() <= tolerance_ * chord)
        report(true, Defect::degenerate, f,
               "face has zero area (width " + str(chord > 0.0 ? 2.0 * a.norm() / chord : 0.0) + ")");
    }
    if (sum.norm() > relative_tolerance * area)
      report(true, Defect::open_cell, -1,
             "open cell: outward area vectors sum to " + str(sum.norm()) + " of total area " + str(area));
    if (!(mesh_.volume[cell_] > 0.0))
      report(true, Defect::degenerate, -1, "volume " + str(mesh_.volume[cell_]) + " is not positive");
  }

  void neighbours(Index f) {
    const Face& face = mesh_.faces[f];
    if (face.neighbour < 0) {
      if (patch_of(face.neighbour) >= static_cast<Index>(mesh_.patches.size()))
        report(true, Defect::missing_twin, f, "boundary code " + std::to_string(face.neighbour) + " names no patch");
      return;
    }
    const Index other = face.neighbour;
    const bool twin_ok = other < mesh_.cell_count() && face.twin >= mesh_.cell_faces[other] &&
                         face.twin < mesh_.cell_faces[other + 1] && mesh_.faces[face.twin].neighbour == cell_ &&
                         mesh_.faces[face.twin].twin == f;
    if (!twin_ok) {
      report(true, Defect::missing_twin, f,
             "neighbour " + std::to_string(other) + " has no face back to cell " + std::to_string(cell_));
      return;
    }
    const double cosine = face.normal.dot(mesh_.faces[face.twin].normal);
    if (cosine > -1.0 + relative_tolerance)
      report(
          true, Defect::normals_not_opposite, f,
          "normal and neighbour " + std::to_string(other) + "'s normal are not opposite (cosine " + str(cosine) + ")");
  }

  void orientation(Index f) {
    const Face& face = mesh_.faces[f];
    if (face.normal.dot(mesh_.centroid[cell_] - face.point) <= 0.0)
      report(true, Defect::inverted_face, f, "normal points out of the cell");
  }

  double diameter(Index f) const {
    double longest = 0.0;
    const Index n = mesh_.vertex_count(f);
    for (Index i = 0; i < n; ++i)
      for (Index j = i + 1; j < n; ++j)
        longest = std::max(longest, (mesh_.face_vertex(f, i) - mesh_.face_vertex(f, j)).norm());
    return longest;
  }

  double off_plane(Index f, const Vec3& x) const { return mesh_.faces[f].normal.dot(x - mesh_.faces[f].point); }

  void planarity_and_convexity() {
    double allowance = 0.0;
    for (Index f = first_; f < last_; ++f) {
      double worst = 0.0;
      for (Index k = 0; k < mesh_.vertex_count(f); ++k)
        worst = std::max(worst, std::abs(off_plane(f, mesh_.face_vertex(f, k))));
      if (worst > tolerance_)
        report(false, Defect::non_planar_face, f, "non-planar: a vertex is " + str(worst) + " off the face plane");
      allowance = std::max(allowance, worst);
    }
    for (Index f = first_; f < last_; ++f) {
      double worst = 0.0;
      for (Index g = first_; g < last_; ++g)
        for (Index k = 0; k < mesh_.vertex_count(g); ++k)
          worst = std::min(worst, off_plane(f, mesh_.face_vertex(g, k)));
      if (worst < -(tolerance_ + 2.0 * allowance))
        report(true, Defect::non_convex, f,
               "non-convex: a vertex of the cell is " + str(-worst) + " outside this face's plane");
    }
  }

  const Mesh& mesh_;
  Index cell_, first_, last_;
  std::vector<Problem>& problems_;
  double size_ = 0.0, tolerance_ = 0.0;
};

}  // namespace

std::vector<Problem> validate(const Mesh& mesh) {
  std::vector<Problem> problems;
  for (Index c = 0; c < mesh.cell_count(); ++c) CellCheck(mesh, c, problems).run();
  return problems;
}

bool has_errors(const std::vector<Problem>& problems) {
  return std::any_of(problems.begin(), problems.end(), [](const Problem& p) { return p.error; });
}

std::string describe(const std::vector<Problem>& problems, std::size_t limit) {
  std::string text;
  for (std::size_t i = 0; i < std::min(limit, problems.size()); ++i) {
    const Problem& p = problems[i];
    text += std::string(p.error ? "error" : "warning") + ": cell " + std::to_string(p.cell);
    if (p.face >= 0) text += " face " + std::to_string(p.face);
    text += ": " + p.what + "\n";
  }
  if (problems.size() > limit) text += "... and " + std::to_string(problems.size() - limit) + " more\n";
  return text;
}

void require_valid(const Mesh& mesh) {
  std::vector<Problem> errors = validate(mesh);
  std::erase_if(errors, [](const Problem& p) { return !p.error; });
  if (!errors.empty())
    throw std::invalid_argument(mesh.source + ": invalid mesh, " + std::to_string(errors.size()) + " errors:\n" +
                                describe(errors));
}

}  // namespace cosim::tracker::mesh
