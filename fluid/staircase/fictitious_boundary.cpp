#include "fluid/staircase/fictitious_boundary.hpp"

#include <stdexcept>

namespace cosim::fluid::staircase {

using bodies::HydrodynamicLoad;
using bodies::IndicatorPatch;
using bodies::RigidBody;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::kCellCentre;
using grid::Point;
using navier_stokes::NavierStokes;

FictitiousBoundary::FictitiousBoundary(const Grid& grid, FbmOptions options)
    : grid_(grid), options_(options), imposed_(grid) {
  if (options.subsamples < 1) throw std::invalid_argument("fictitious boundary: subsamples must be >= 1");
  if (options.offset < 0) throw std::invalid_argument("fictitious boundary: the surface offset must be >= 0");
}

std::size_t FictitiousBoundary::add(RigidBody body) {
  if (geometry::kind(body.shape) == geometry::ShapeKind::HalfSpace)
    throw std::invalid_argument("fictitious boundary: a half-space is not a body (use a wall boundary)");
  bodies_.push_back({std::move(body), {}});
  build(bodies_.back());
  collect_imposed_faces();
  return bodies_.size() - 1;
}

void FictitiousBoundary::move(std::size_t i, const geometry::Pose& pose, const Eigen::Vector3d& velocity,
                              const Eigen::Vector3d& angular_velocity) {
  Entry& e = bodies_.at(i);
  const bool moved =
      pose.position() != e.body.pose.position() || pose.orientation().coeffs() != e.body.pose.orientation().coeffs();
  // A body placed where it is, at the velocity it has (a fixed one: every step), changes
  // neither its indicator nor the imposed values. Every rank gets the same poses, so all
  // skip the collective collect_imposed_faces() together.
  if (!moved && velocity == e.body.velocity && angular_velocity == e.body.angular_velocity) return;
  e.body.pose = pose;
  e.body.velocity = velocity;
  e.body.angular_velocity = angular_velocity;
  if (moved) build(e);
  collect_imposed_faces();
}

// Faces with the ghost layers: the projection asks whether a ghost cell is enclosed, and
// the force integral differences alpha_i across the rank's lowest owned cells and edges.
void FictitiousBoundary::build(Entry& e) const {
  e.patches.clear();
  for (int c = 0; c < 3; ++c)
    e.patches.push_back(indicator(grid_, c, e.body, options_, grid_.ghosted(grid_.velocity_dm(c))));
  e.patches.push_back(
      indicator(grid_, kCellCentre, e.body, {.subsamples = options_.subsamples}, grid_.owned(grid_.cell_dm())));
}

void FictitiousBoundary::collect_imposed_faces() {
  imposed_.clear();
  for (const Entry& e : bodies_)
    for (int c = 0; c < 3; ++c) {
      const IndicatorPatch& alpha = e.patches[static_cast<std::size_t>(c)];
      for_each_index(alpha.range(), [&](const Index& p) {
        if (alpha(p) < 0.5) return;
        const Point x = grid_.position(c, p);
        imposed_.add(c, p, e.body.velocity_at(Eigen::Vector3d(x[0], x[1], x[2]))[c]);
      });
    }
  imposed_.finish();
}

std::vector<HydrodynamicLoad> FictitiousBoundary::loads(const NavierStokes& flow) const {
  std::vector<HydrodynamicLoad> out;
  for (const Entry& e : bodies_)
    out.push_back(hydrodynamic_load(flow, {&e.patches[0], &e.patches[1], &e.patches[2]}, e.body.pose.position()));
  return out;
}

double FictitiousBoundary::grid_volume(std::size_t i) const {
  const IndicatorPatch& alpha = bodies_.at(i).patches[kCellPatch];
  double volume = 0;
  for_each_index(alpha.range(), [&](const Index& m) { volume += alpha(m) * grid_.cell_volume(m); });
  MPI_Allreduce(MPI_IN_PLACE, &volume, 1, MPI_DOUBLE, MPI_SUM, grid_.comm());
  return volume;
}

std::size_t FictitiousBoundary::points_tested(std::size_t i) const {
  std::size_t n = 0;
  for (const IndicatorPatch& p : bodies_.at(i).patches) n += p.tested();
  return n;
}

}  // namespace cosim::fluid::staircase
