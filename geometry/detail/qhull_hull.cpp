#include "geometry/detail/qhull_hull.hpp"

#include <libqhullcpp/Qhull.h>
#include <libqhullcpp/QhullError.h>
#include <libqhullcpp/QhullFacetList.h>
#include <libqhullcpp/QhullVertexSet.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace cosim::geometry::detail {

QhullFacets qhull_convex_hull(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 4)
    throw std::invalid_argument("convex hull: needs at least 4 points, got " + std::to_string(points.size()));
  std::vector<double> coordinates;
  coordinates.reserve(3 * points.size());
  for (const auto& p : points) {
    if (!p.allFinite()) throw std::invalid_argument("convex hull: a point is not finite");
    coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  }

  orgQhull::Qhull qhull;
  std::ostringstream log;  // qhull would otherwise print its diagnosis to stderr
  qhull.setErrorStream(&log);
  qhull.setOutputStream(&log);
  try {
    qhull.runQhull("", 3, static_cast<int>(points.size()), coordinates.data(), "");
  } catch (const orgQhull::QhullError& e) {
    const std::string what = log.str().empty() ? e.what() : log.str();
    throw std::invalid_argument("convex hull: qhull failed (are the points coplanar?): " +
                                what.substr(0, what.find('\n')));
  }

  QhullFacets out;
  for (const auto& vertex : qhull.vertexList()) out.vertices.push_back(static_cast<std::uint32_t>(vertex.point().id()));
  for (const auto& facet : qhull.facetList()) {
    std::vector<std::uint32_t> ids;
    for (const auto& vertex : facet.vertices()) ids.push_back(static_cast<std::uint32_t>(vertex.point().id()));
    const double* n = facet.hyperplane().coordinates();
    out.facets.push_back(std::move(ids));
    out.normals.emplace_back(n[0], n[1], n[2]);
  }
  return out;
}

}  // namespace cosim::geometry::detail
