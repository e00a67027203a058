#include "fluid/ibm/immersed_boundary.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "fluid/ibm/marker_stencils.hpp"
#include "fluid/ibm/volume_fraction.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/navier_stokes/step_stages.hpp"
#include "fluid/petsc_check.hpp"
#include "geometry/queries.hpp"
#include "geometry/surface_sampling.hpp"

namespace cosim::fluid::ibm {

using bodies::ForcingArrays;
using bodies::HydrodynamicLoad;
using bodies::IndicatorPatch;
using bodies::RigidBody;
using bodies::StepResponse;
using grid::Axes;
using grid::Axis;
using grid::Box;
using grid::finest_width_at;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::kCellCentre;
using grid::Point;
using navier_stokes::NavierStokes;

namespace {

constexpr std::size_t kInnerWidth = 6;  // momentum and angular momentum
constexpr double kSamplingGap = 0.8;    // geometry::sample_surface's least distance, in spacings

// The only axis of one periodic cell (a two-dimensional grid), or -1.
int flat_axis(const Axes& axes) {
  int flat = -1;
  for (int d = 0; d < 3; ++d)
    if (axes[static_cast<std::size_t>(d)].degenerate()) {
      if (flat >= 0) throw std::invalid_argument("immersed boundary: at most one axis may be a single periodic cell");
      flat = d;
    }
  return flat;
}

bool overlap(const geometry::Aabb& a, const geometry::Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

// Whether `box` comes within `reach` of the largest cell width of the cells `cells` on
// every axis (on a periodic axis also whole periods away): a body that does not has no
// marker whose kernel touches them.
bool near(const Grid& grid, const Box& cells, const geometry::Aabb& box, double reach) {
  geometry::Aabb target;
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = grid.axis(d);
    const double margin = reach * axis.max_width();
    target.min[d] = axis.face(static_cast<int>(cells.lo[d])) - margin;
    target.max[d] = axis.face(static_cast<int>(cells.hi[d])) + margin;
  }
  return !periodic_shifts(grid, box, target).empty();
}

// The retraction's law was calibrated at h kappa = 1/3 and 1/2 (spheres of twelve and eight
// cells across) and holds at 2/3 (six: the Hasimoto error +0.3 %, bench/fluid_accuracy/README.md); it is
// held at a sphere of four cells across, beyond which (small or sharp features) the markers
// would meet the opposite side's kernels.
constexpr double kLargestCurvature = 1.0;  // times 1 / h

// kappa_1 + kappa_2 at surface point x: the Laplacian of the signed distance, by central
// differences a quarter cell wide.
double curvature_in_space(const geometry::Shape& shape, const geometry::Pose& pose, const Eigen::Vector3d& x,
                          double h) {
  const double e = h / 4;
  double laplacian = 0;
  for (int d = 0; d < 3; ++d) {
    const Eigen::Vector3d step = e * Eigen::Vector3d::Unit(d);
    laplacian += geometry::signed_distance(shape, pose, x + step) + geometry::signed_distance(shape, pose, x - step);
  }
  laplacian = (laplacian - 6 * geometry::signed_distance(shape, pose, x)) / (e * e);
  return std::clamp(laplacian, -kLargestCurvature / h, kLargestCurvature / h);
}

// The curvature of a section's curve at sample i: of the circle through it and its two
// nearest neighbours, positive where the curve bends away from its normal (convex).
double curvature_in_plane(const std::vector<geometry::SurfaceSample>& curve, std::size_t i, double h) {
  std::size_t a = i, b = i;
  double da = std::numeric_limits<double>::infinity(), db = da;
  for (std::size_t k = 0; k < curve.size(); ++k) {
    if (k == i) continue;
    const double d = (curve[k].point - curve[i].point).norm();
    if (d < da) {
      b = a;
      db = da;
      a = k;
      da = d;
    } else if (d < db) {
      b = k;
      db = d;
    }
  }
  if (a == i || b == i) return 0;
  const Eigen::Vector3d u = curve[a].point - curve[i].point, v = curve[b].point - curve[i].point;
  const double chord = (u - v).norm(), area2 = u.cross(v).norm();  // twice the triangle's area
  const double kappa = 2 * area2 / (u.norm() * v.norm() * chord);  // 1 / circumradius
  const bool convex = (u + v).dot(curve[i].normal) < 0;            // the neighbours fall behind the normal
  return std::clamp(convex ? kappa : -kappa, -kLargestCurvature / h, kLargestCurvature / h);
}

// Markers moved in along their normals crowd together where the surface curves (a sphere
// of 3.75 cells across retracted by 0.4 of a cell: 1.6 times as many per area), and markers
// much closer than a cell make the forcing's system nearly singular: its sweeps stall, the
// forces turn noisy, and an implicitly coupled window no longer converges (30 iterations a
// window in ten Cate's quick scene, 3.4 with them thinned). So a marker closer than `gap`
// (the sampling's own minimum distance) to one kept before it is dropped, and its area goes
// to that one.
template <typename Marker>
void thin_out(std::vector<Marker>& markers, double gap) {
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  const auto key = [&](const Eigen::Vector3d& x, int a, int b, int c) {
    const auto at = [&](int d, int o) { return (static_cast<std::int64_t>(std::floor(x[d] / gap)) + o) & 0x1fffff; };
    return at(0, a) | (at(1, b) << 21) | (at(2, c) << 42);
  };
  std::vector<Marker> kept;
  for (const Marker& m : markers) {
    std::size_t nearest = kept.size();
    double best = gap * gap;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          const auto it = cells.find(key(m.position, a, b, c));
          if (it == cells.end()) continue;
          for (std::size_t k : it->second)
            if ((kept[k].position - m.position).squaredNorm() < best) {
              best = (kept[k].position - m.position).squaredNorm();
              nearest = k;
            }
        }
    if (nearest < kept.size()) {
      kept[nearest].area += m.area;
      continue;
    }
    cells[key(m.position, 0, 0, 0)].push_back(kept.size());
    kept.push_back(m);
  }
  markers = std::move(kept);
}

void require_body(const RigidBody& body) {
  if (geometry::kind(body.shape) == geometry::ShapeKind::HalfSpace)
    throw std::invalid_argument("immersed boundary: a half-space is not a body (use a wall boundary)");
}

// Whether body o may cover a marker of body b: their boxes overlap, or for a container
// (whose box is everything), the other comes within its bounding radius of the wall.
bool may_cover(const RigidBody& b, const geometry::Aabb& box_b, const RigidBody& o, const geometry::Aabb& box_o) {
  const auto near_wall = [](const RigidBody& container, const RigidBody& other) {
    return !geometry::is_bounded(other.shape) ||
           geometry::signed_distance(container.shape, container.pose, other.pose.position()) +
                   geometry::bounding_radius(other.shape) >=
               0;
  };
  if (geometry::kind(b.shape) == geometry::ShapeKind::Container) return near_wall(b, o);
  if (geometry::kind(o.shape) == geometry::ShapeKind::Container) return near_wall(o, b);
  return overlap(box_b, box_o);
}

IbmOptions resolved(IbmOptions options) {
  if (!options.retraction) options.retraction = calibrated_retraction(options.kernel);
  return options;
}

}  // namespace

Retraction calibrated_retraction(DeltaKernel kernel) {
  switch (kernel) {
    case DeltaKernel::roma3:
      return {0.2985, 0.2274, -0.796};
    case DeltaKernel::peskin4:
      return {0.4363, 0.4458, -1.439};
    default:
      return {0.3969, 0.8484, -2.852};
  }
}

ImmersedBoundary::ImmersedBoundary(const Grid& grid, IbmOptions options) : grid_(grid), options_(resolved(options)) {
  check(grid.axes(), options);
}

void ImmersedBoundary::check(const Axes& axes, const IbmOptions& options) {
  if (options.sweeps < 1) throw std::invalid_argument("immersed boundary: sweeps must be >= 1");
  if (options.corrections < 0) throw std::invalid_argument("immersed boundary: corrections must be >= 0");
  if (!(options.no_slip_tolerance > 0 && options.no_slip_tolerance < 1))
    throw std::invalid_argument("immersed boundary: no_slip_tolerance must be in (0, 1)");
  if (!(options.tolerance > 0)) throw std::invalid_argument("immersed boundary: the tolerance must be > 0");
  if (!(options.spacing > 0)) throw std::invalid_argument("immersed boundary: the marker spacing must be > 0");
  flat_axis(axes);
  const int reach = static_cast<int>(std::ceil(support_radius(options.kernel)));
  for (const Axis& a : axes)
    if (a.periodic() && !a.degenerate() && a.cells() < 2 * reach)
      throw std::invalid_argument("immersed boundary: a periodic axis needs at least " + std::to_string(2 * reach) +
                                  " cells for the " + std::string(name(options.kernel)) + " kernel");
}

std::size_t ImmersedBoundary::marker_count(const Axes& axes, const IbmOptions& options,
                                           std::span<const RigidBody> bodies) {
  check(axes, options);
  const IbmOptions placing = resolved(options);
  geometry::SampledShapes sampled;
  std::size_t count = 0;
  for (const RigidBody& body : bodies) {
    require_body(body);
    count += place_markers(axes, placing, body, BodyDistance(axes, body), sampled).size();
  }
  return count;
}

std::size_t ImmersedBoundary::add(RigidBody body) {
  require_body(body);
  Entry e(grid_, std::move(body));
  e.markers = place_markers(grid_.axes(), options_, e.body, e.distance, sampled_);
  first_marker_.push_back(first_marker_.back() + e.markers.size());
  bodies_.push_back(std::move(e));
  return bodies_.size() - 1;
}

std::vector<ImmersedBoundary::Marker> ImmersedBoundary::place_markers(const Axes& axes, const IbmOptions& options,
                                                                      const RigidBody& body,
                                                                      const BodyDistance& distance,
                                                                      geometry::SampledShapes& sampled) {
  // Markers about one cell apart where the body is: the smallest width of its cell on the
  // axes that carry variation.
  const int flat = flat_axis(axes);
  const Eigen::Vector3d& at = body.pose.position();
  const double h = finest_width_at(axes, {at[0], at[1], at[2]});
  const Axis* layer = flat < 0 ? nullptr : &axes[static_cast<std::size_t>(flat)];
  const std::vector<geometry::SurfaceSample> samples =
      flat < 0 ? sampled.at(body.shape, body.pose, options.spacing * h)
               : geometry::sample_section(body.shape, body.pose, flat, layer->centre(0), options.spacing * h);
  // On a two-dimensional grid a marker stands for its length of curve times the layer.
  const double thickness = flat < 0 ? 1.0 : layer->width(0);
  std::vector<Marker> markers;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const geometry::SurfaceSample& s = samples[i];
    const double kappa =
        flat < 0 ? curvature_in_space(body.shape, body.pose, s.point, h) : curvature_in_plane(samples, i, h);
    const Retraction& law = *options.retraction;
    const double depth = h * (law.constant + (kappa < 0 ? law.concave : law.curvature) * h * kappa);
    const Eigen::Vector3d x = s.point - depth * s.normal;
    const double inside = distance.at(body, x);
    if (!(inside < 0)) continue;
    // The moved surface's share: the area shrinks by (1 - depth kappa_i) along each
    // principal direction (taken as equal in space).
    const double shrink = flat < 0 ? std::pow(1 - depth * kappa / 2, 2) : 1 - depth * kappa;
    markers.push_back(
        {body.pose.to_body(x), body.pose.direction_to_body(s.normal), s.area * thickness * std::max(shrink, 0.1)});
  }
  thin_out(markers, kSamplingGap * options.spacing * h);
  if (markers.empty())
    throw std::invalid_argument("immersed boundary: no marker stays inside the body once retracted by " +
                                std::to_string(options.retraction->constant) +
                                " cell widths: it is thinner than twice that" +
                                (flat < 0 ? std::string() : std::string(" or misses the grid's plane")));
  return markers;
}

void ImmersedBoundary::move(std::size_t i, const geometry::Pose& pose, const Eigen::Vector3d& velocity,
                            const Eigen::Vector3d& angular_velocity) {
  RigidBody& b = bodies_.at(i).body;
  b.pose = pose;
  b.velocity = velocity;
  b.angular_velocity = angular_velocity;
}

std::vector<HydrodynamicLoad> ImmersedBoundary::loads(const NavierStokes&) const {
  std::vector<HydrodynamicLoad> out;
  for (const Entry& e : bodies_) out.push_back(e.load);
  return out;
}

std::vector<IndicatorPatch> ImmersedBoundary::cell_fractions(std::size_t i) const {
  const Entry& e = bodies_.at(i);
  std::vector<IndicatorPatch> out;
  for (FractionImage& image : volume_fractions(grid_, kCellCentre, e.body, e.distance, grid_.owned(grid_.cell_dm())))
    out.push_back(std::move(image.patch));
  return out;
}

std::vector<Eigen::Vector3d> ImmersedBoundary::markers(std::size_t i) const {
  const Entry& e = bodies_.at(i);
  std::vector<Eigen::Vector3d> out;
  for (const Marker& m : e.markers) out.push_back(e.body.pose.to_world(m.position));
  return out;
}

// Per body: the inner momenta, whether they are known, then 3 per marker: the force its
// holders agree on (collective; every marker's, once per checkpoint).
std::vector<double> ImmersedBoundary::state() const {
  std::vector<double> forces(3 * total_markers(), 0.0), holders(total_markers(), 0.0);
  for (const auto& [b, k] : held_) {
    const Marker& m = bodies_[b].markers[k];
    const std::size_t id = first_marker_[b] + k;
    for (int c = 0; c < 3; ++c) forces[3 * id + static_cast<std::size_t>(c)] = m.force[c];
    holders[id] = 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, forces.data(), static_cast<int>(forces.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
  MPI_Allreduce(MPI_IN_PLACE, holders.data(), static_cast<int>(holders.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
  std::vector<double> out;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Entry& e = bodies_[b];
    out.insert(out.end(), e.inner.begin(), e.inner.end());
    out.push_back(e.inner_known ? 1 : 0);
    for (std::size_t id = first_marker_[b]; id < first_marker_[b + 1]; ++id)
      for (std::size_t c = 0; c < 3; ++c) out.push_back(holders[id] > 0 ? forces[3 * id + c] / holders[id] : 0.0);
  }
  return out;
}

void ImmersedBoundary::restore(std::span<const double> state) {
  std::size_t expected = 0;
  for (const Entry& e : bodies_) expected += kInnerWidth + 1 + 3 * e.markers.size();
  if (state.size() != expected)
    throw std::invalid_argument("immersed boundary state has " + std::to_string(state.size()) + " values, its " +
                                std::to_string(bodies_.size()) + " bodies need " + std::to_string(expected));
  auto at = state.begin();
  held_.clear();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    Entry& e = bodies_[b];
    std::copy_n(at, kInnerWidth, e.inner.begin());
    at += kInnerWidth;
    e.inner_known = *at++ != 0;
    for (std::size_t k = 0; k < e.markers.size(); ++k) {
      e.markers[k].force = Eigen::Vector3d(at[0], at[1], at[2]);
      e.markers[k].known = true;
      held_.emplace_back(b, k);
      at += 3;
    }
  }
}

// Markers inside the domain's bounded extent and outside every other body (where bodies
// touch, the other's surface holds the fluid there), with their kernels on the grid and
// touching this rank's faces where they are or `lag` earlier, when they spread.
void ImmersedBoundary::collect_active_markers(double lag) {
  active_.clear();
  spreading_.clear();
  std::vector<geometry::Aabb> boxes;
  for (const Entry& e : bodies_) boxes.push_back(geometry::world_aabb(e.body.shape, e.body.pose));
  std::array<Box, 3> owned;
  for (int c = 0; c < 3; ++c) owned[static_cast<std::size_t>(c)] = grid_.owned(grid_.velocity_dm(c));
  const Box cells = grid_.owned(grid_.cell_dm());
  // A face's kernel reaches support_radius widths; a face lies half a cell outside its cell.
  const double reach = support_radius(options_.kernel) + 1;
  // On a periodic axis a bounded body's markers beyond the domain stand for the part of it
  // that wraps round; a container (a pipe along the axis) is longer than the period, and
  // only its markers within one period are its own.
  const auto inside_domain = [&](const Eigen::Vector3d& x, bool bounded) {
    for (int d = 0; d < 3; ++d) {
      const Axis& axis = grid_.axis(d);
      if (axis.degenerate() || (axis.periodic() && bounded)) continue;
      if (axis.periodic() ? !(x[d] >= axis.lo() && x[d] < axis.hi()) : !(x[d] > axis.lo() && x[d] < axis.hi()))
        return false;
    }
    return true;
  };
  // The kernels at x, and whether they meet this rank's faces; false where a kernel is off
  // the grid.
  const auto place = [&](const Eigen::Vector3d& x, ActiveMarker& a) {
    const Point p{x[0], x[1], x[2]};
    a.position = x;
    for (std::size_t c = 0; c < 3; ++c) {
      a.stencil[c] = kernel_stencil(grid_, static_cast<int>(c), options_.kernel, p);
      if (a.stencil[c].empty()) return false;
      a.local[c] = a.stencil[c].meets(owned[c]);
    }
    return true;
  };
  const auto local = [](const ActiveMarker& a) { return a.local[0] || a.local[1] || a.local[2]; };
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& body = bodies_[b].body;
    const bool bounded = geometry::is_bounded(body.shape);
    // The box the body sweeps over the lag.
    geometry::Aabb swept = boxes[b];
    // A container's box is infinite: spin times its size would be 0 x inf.
    const double spin = body.angular_velocity.norm();
    const double sweep = lag * (body.velocity.norm() + (spin > 0 ? spin * (swept.max - swept.min).norm() / 2 : 0.0));
    swept.min.array() -= sweep;
    swept.max.array() += sweep;
    if (!near(grid_, cells, swept, reach)) continue;
    // The bodies that may cover b's markers, each by every image of it (across periodic
    // faces) whose box meets b's.
    std::vector<std::pair<std::size_t, Eigen::Vector3d>> touching;
    for (std::size_t o = 0; o < bodies_.size(); ++o) {
      if (o == b) continue;
      for (const Eigen::Vector3d& shift : periodic_shifts(grid_, boxes[o], boxes[b])) {
        const geometry::Aabb image{boxes[o].min + shift, boxes[o].max + shift};
        if (may_cover(body, boxes[b], bodies_[o].body, image)) touching.emplace_back(o, shift);
      }
    }
    for (std::size_t k = 0; k < bodies_[b].markers.size(); ++k) {
      const Marker& m = bodies_[b].markers[k];
      ActiveMarker a;
      a.body = b;
      a.marker = k;
      const Eigen::Vector3d x = body.pose.to_world(m.position);
      if (!inside_domain(x, bounded)) continue;
      const bool covered = std::any_of(touching.begin(), touching.end(), [&](const auto& other) {
        const auto& [o, shift] = other;
        const Eigen::Vector3d at = x - shift;
        return boxes[o].contains(at) && geometry::signed_distance(bodies_[o].body.shape, bodies_[o].body.pose, at) < 0;
      });
      if (covered || !place(x, a)) continue;
      a.id = first_marker_[b] + k;
      a.target = body.velocity_at(x);
      // dV = area times the width across the surface.
      const Eigen::Vector3d normal = body.pose.direction_to_world(m.normal);
      double across = 0;
      for (int d = 0; d < 3; ++d)
        across += normal[d] * normal[d] * a.stencil[0].axes[static_cast<std::size_t>(d)].width;
      a.volume = m.area * across;
      // Where it spreads from: `lag` back along its velocity, or where it is if that is off
      // the domain.
      ActiveMarker earlier = a;
      if (lag > 0) {
        const Eigen::Vector3d back = x - lag * a.target;
        if (!inside_domain(back, true) || !place(back, earlier)) earlier = a;
      }
      if (!local(a) && !local(earlier)) continue;
      active_.push_back(a);
      spreading_.push_back(earlier);
    }
  }
}

namespace {

// residual = target - interpolated at each marker; returns the largest of both over every
// rank, the scale of the forcing's tolerance.
double slip_against(std::span<const ActiveMarker> active, const MarkerSharing& sharing, std::vector<double>& residual) {
  double scale = 0;
  for (std::size_t l = 0; l < active.size(); ++l)
    for (std::size_t c = 0; c < 3; ++c) {
      const double target = active[l].target[static_cast<Eigen::Index>(c)];
      scale = std::max({scale, std::abs(target), std::abs(residual[3 * l + c])});
      residual[3 * l + c] = target - residual[3 * l + c];
    }
  return sharing.largest(scale);
}

// The root mean square of values held across the ranks.
double root_mean_square(const MarkerSharing& sharing, const std::vector<double>& a) {
  const std::array<double, 3> squares = sharing.dot(a, a);
  return sharing.count() > 0 ? std::sqrt((squares[0] + squares[1] + squares[2]) / sharing.count()) : 0.0;
}

}  // namespace

// The markers' impulses g_l = dt F_l dV_l (velocity times volume, per component) are those
// whose spread brings the interpolated velocity to the body's: B g = U - I[u~], where
// B = I S, B_lm = sum_x w_l(x) s_m(x) / dV_x with s_m the kernel the marker spreads with,
// is symmetric positive definite where that is its own (forcing_system.hpp), solved from
// the last step's impulses.
void ImmersedBoundary::force(const NavierStokes& flow, double dt, const ForcingArrays& arrays) {
  const double lag = options_.spread_at_theta && bodies_move() ? (1 - flow.time_step_options().theta) * dt : 0.0;
  collect_active_markers(lag);
  update_fractions();
  // A body's inner momentum is carried from step to step; at the first step (or a body's
  // first) it is taken from the flow as it is, with the body where it will be.
  if (std::any_of(bodies_.begin(), bodies_.end(), [](const Entry& e) { return !e.inner_known; })) {
    const std::vector<double> momenta = inner_momenta(flow);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      if (!bodies_[b].inner_known) {
        std::copy_n(momenta.begin() + static_cast<std::ptrdiff_t>(kInnerWidth * b), kInnerWidth,
                    bodies_[b].inner.begin());
        bodies_[b].inner_known = true;
      }
  }
  const std::size_t n = active_.size();
  // Built once for the step: the corrections after the projection use the same markers.
  system_.reset();
  const PetscInt roots = roots_by_body(grid_.comm(), first_marker_);
  const MarkerStencils& stencils = stencils_.emplace(grid_, active_, roots);
  spread_stencils_.reset();
  if (lag > 0) spread_stencils_.emplace(grid_, spreading_, roots);
  const ForcingSystem& system = system_.emplace(stencils, spreading(), first_marker_, block_solvers_);
  std::vector<double> g = last_impulses(stencils.sharing(), dt), residual(3 * n);
  stencils.interpolate(arrays.predicted, residual);
  const double scale = slip_against(active_, stencils.sharing(), residual);
  sweeps_ = system.solve(g, residual, options_.tolerance * scale, options_.sweeps);
  slip_ = stencils.sharing().largest(residual);
  spreading().spread(arrays.rhs, g);
  for (Entry& e : bodies_) e.forcing = e.forcing_moment = Eigen::Vector3d::Zero();
  // Markers that leave this rank, or every body, start afresh when they come back.
  for (const auto& [b, k] : held_) {
    bodies_[b].markers[k].force = Eigen::Vector3d::Zero();
    bodies_[b].markers[k].known = false;
  }
  held_.clear();
  for (const ActiveMarker& a : active_) {
    bodies_[a.body].markers[a.marker].force = Eigen::Vector3d::Zero();
    held_.emplace_back(a.body, a.marker);
  }
  add_impulses(g, dt, stencils.sharing());
  hold_solid(dt, arrays);
}

void ImmersedBoundary::hold_solid(double dt, const ForcingArrays& arrays) {
  for (Entry& e : bodies_)
    for (int c = 0; c < 3; ++c)
      for (const Index& p : e.held[static_cast<std::size_t>(c)]) {
        const Point at = grid_.position(c, p);
        const Eigen::Vector3d x(at[0], at[1], at[2]);
        const double push = e.body.velocity_at(x)[c] - arrays.predicted[static_cast<std::size_t>(c)][p[2]][p[1]][p[0]];
        arrays.rhs[static_cast<std::size_t>(c)][p[2]][p[1]][p[0]] += push;
        Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
        impulse[c] = push * grid_.face_volume(c, p) / dt;
        e.forcing += impulse;
        e.forcing_moment += (x - e.body.pose.position()).cross(impulse);
      }
}

// A rank that did not hold a marker in the last step does not know its force: the holders
// that did agree on it (their mean, the same value on each), the others start from zero.
std::vector<double> ImmersedBoundary::last_impulses(const MarkerSharing& sharing, double dt) const {
  const std::size_t n = active_.size();
  std::vector<double> g(3 * n), holders(3 * n);
  for (std::size_t l = 0; l < n; ++l) {
    const Marker& m = bodies_[active_[l].body].markers[active_[l].marker];
    for (std::size_t c = 0; c < 3; ++c) {
      g[3 * l + c] = m.known ? m.force[static_cast<Eigen::Index>(c)] : 0.0;
      holders[3 * l + c] = m.known ? 1.0 : 0.0;
    }
  }
  sharing.sum(g);
  sharing.sum(holders);
  for (std::size_t i = 0; i < 3 * n; ++i) g[i] = holders[i] > 0 ? dt * active_[i / 3].volume * g[i] / holders[i] : 0.0;
  return g;
}

double ImmersedBoundary::slip_in(const NavierStokes& flow, const MarkerStencils& stencils,
                                 std::vector<double>& residual) const {
  residual.assign(3 * active_.size(), 0.0);
  FaceArrays u{};
  // interpolate() only reads the velocity it is given.
  for (int c = 0; c < 3; ++c) {
    const PetscScalar*** read = nullptr;
    COSIM_PETSC(DMDAVecGetArrayRead(grid_.velocity_dm(c), flow.velocity(c), &read));
    u[static_cast<std::size_t>(c)] = const_cast<PetscScalar***>(read);
  }
  stencils.interpolate(u, residual);
  for (int c = 0; c < 3; ++c) {
    const PetscScalar*** read = const_cast<const PetscScalar***>(u[static_cast<std::size_t>(c)]);
    COSIM_PETSC(DMDAVecRestoreArrayRead(grid_.velocity_dm(c), flow.velocity(c), &read));
  }
  return slip_against(active_, stencils.sharing(), residual);
}

namespace {

// What the correction's Krylov solve reads through PETSc's callbacks.
struct Correction {
  const MarkerStencils* stencils;
  const MarkerStencils* spreading;
  StepResponse* response;
  std::function<std::vector<double>(std::vector<double>&)> precondition;
  std::vector<double> image;
};

// y = the interpolated change of the step's velocity that impulses x cause. An exception
// must not cross PETSc's C frames: it becomes PETSc's error, which KSPSolve returns.
PetscErrorCode respond(Mat A, Vec x, Vec y) {
  PetscFunctionBeginUser;
  Correction* k = nullptr;
  PetscCall(MatShellGetContext(A, &k));
  try {
    const MarkerSharing& sharing = k->stencils->sharing();
    std::vector<double> impulses(k->image.size());
    sharing.from_roots(x, impulses);
    k->spreading->spread(k->response->rhs(), impulses);
    k->stencils->interpolate(k->response->change(), k->image);
    sharing.to_roots(k->image, y);
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  PetscFunctionReturn(0);
}

// y = the impulses that the forcing's own system (no solve, no projection) maps to slip x.
PetscErrorCode precondition(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  Correction* k = nullptr;
  PetscCall(PCShellGetContext(pc, &k));
  try {
    const MarkerSharing& sharing = k->stencils->sharing();
    std::vector<double> slip(k->image.size());
    sharing.from_roots(x, slip);
    sharing.to_roots(k->precondition(slip), y);
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  PetscFunctionReturn(0);
}

// The Krylov solve's PETSc objects, destroyed however correct() leaves.
struct KrylovObjects {
  Vec rhs = nullptr, g = nullptr;
  Mat A = nullptr;
  KSP ksp = nullptr;
  ~KrylovObjects() {
    KSPDestroy(&ksp);
    MatDestroy(&A);
    VecDestroy(&g);
    VecDestroy(&rhs);
  }
};

}  // namespace

// The slip left in the step's final velocity, r = U - I[u], is cancelled by impulses g with
// I[R S g] = r, R the viscous solve and projection: FGMRES on the markers' values (each held
// once, by the root of marker_sharing.hpp), right-preconditioned by the forcing's system
// I S g = r, which it is where R is the identity.
int ImmersedBoundary::correct(const NavierStokes& flow, double dt, StepResponse& response) {
  if (!stencils_ || stencils_->sharing().count() == 0) return 0;
  const std::size_t n = active_.size();
  const MarkerStencils& stencils = *stencils_;
  const MarkerSharing& sharing = stencils.sharing();
  std::vector<double> residual;
  const double scale = slip_in(flow, stencils, residual);
  final_slip_ = sharing.largest(residual);
  if (options_.corrections == 0 || root_mean_square(sharing, residual) <= options_.no_slip_tolerance * scale) return 0;
  const auto forcing_solve = [&](std::vector<double>& r) {
    std::vector<double> g(r.size(), 0.0);
    system_->solve(g, r, options_.tolerance * scale, options_.sweeps);
    return g;
  };
  Correction k{&stencils, &spreading(), &response, forcing_solve, std::vector<double>(3 * n)};
  const PetscInt roots = sharing.roots();
  KrylovObjects o;
  COSIM_PETSC(VecCreateMPI(grid_.comm(), roots, PETSC_DETERMINE, &o.rhs));
  COSIM_PETSC(VecDuplicate(o.rhs, &o.g));
  sharing.to_roots(residual, o.rhs);
  COSIM_PETSC(MatCreateShell(grid_.comm(), roots, roots, PETSC_DETERMINE, PETSC_DETERMINE, &k, &o.A));
  COSIM_PETSC(MatShellSetOperation(o.A, MATOP_MULT, reinterpret_cast<void (*)(void)>(respond)));
  COSIM_PETSC(KSPCreate(grid_.comm(), &o.ksp));
  KSP ksp = o.ksp;
  COSIM_PETSC(KSPSetOptionsPrefix(ksp, "no_slip_"));
  COSIM_PETSC(KSPSetType(ksp, KSPFGMRES));
  COSIM_PETSC(KSPGMRESSetRestart(ksp, options_.corrections));
  COSIM_PETSC(KSPSetOperators(ksp, o.A, o.A));
  PC pc;
  COSIM_PETSC(KSPGetPC(ksp, &pc));
  COSIM_PETSC(PCSetType(pc, PCSHELL));
  COSIM_PETSC(PCShellSetContext(pc, &k));
  COSIM_PETSC(PCShellSetApply(pc, precondition));
  // Converged where the root mean square slip is no_slip_tolerance of the velocity scale.
  const double rms = options_.no_slip_tolerance * scale * std::sqrt(sharing.count());
  COSIM_PETSC(KSPSetTolerances(ksp, 1e-12, rms, PETSC_DEFAULT, options_.corrections));
  COSIM_PETSC(KSPSetFromOptions(ksp));
  COSIM_PETSC(KSPSolve(ksp, o.rhs, o.g));
  PetscInt iterations = 0;
  COSIM_PETSC(KSPGetIterationNumber(ksp, &iterations));
  if (iterations == 0) return 0;
  std::vector<double> impulses_found(3 * n);
  sharing.from_roots(o.g, impulses_found);
  spreading().spread(response.rhs(), impulses_found);
  response.apply();
  add_impulses(impulses_found, dt, sharing);
  slip_in(flow, stencils, residual);
  final_slip_ = sharing.largest(residual);
  return static_cast<int>(iterations) + 1;
}

bool ImmersedBoundary::bodies_move() const {
  return std::any_of(bodies_.begin(), bodies_.end(),
                     [](const Entry& e) { return !e.body.velocity.isZero(0) || !e.body.angular_velocity.isZero(0); });
}

void ImmersedBoundary::add_impulses(const std::vector<double>& g, double dt, const MarkerSharing& sharing) {
  for (std::size_t l = 0; l < active_.size(); ++l) {
    Entry& e = bodies_[active_[l].body];
    const Eigen::Vector3d impulse(g[3 * l], g[3 * l + 1], g[3 * l + 2]);
    Marker& m = e.markers[active_[l].marker];
    m.force += impulse / (dt * active_[l].volume);
    m.known = true;
    const Eigen::Vector3d share = sharing.once(3 * l) * impulse / dt;
    e.forcing += share;
    e.forcing_moment += (active_[l].position - e.body.pose.position()).cross(share);
  }
}

void ImmersedBoundary::finish_step(const NavierStokes& flow, double dt) {
  const std::vector<double> momenta = inner_momenta(flow);
  const double rho = flow.fluid().density;
  // Each rank summed its share of the markers' forcing.
  std::vector<double> forcing;
  for (const Entry& e : bodies_) {
    forcing.insert(forcing.end(), e.forcing.data(), e.forcing.data() + 3);
    forcing.insert(forcing.end(), e.forcing_moment.data(), e.forcing_moment.data() + 3);
  }
  MPI_Allreduce(MPI_IN_PLACE, forcing.data(), static_cast<int>(forcing.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    Entry& e = bodies_[b];
    e.forcing = Eigen::Vector3d(forcing[6 * b], forcing[6 * b + 1], forcing[6 * b + 2]);
    e.forcing_moment = Eigen::Vector3d(forcing[6 * b + 3], forcing[6 * b + 4], forcing[6 * b + 5]);
    const double* now = momenta.data() + kInnerWidth * b;
    const Eigen::Vector3d momentum(now[0], now[1], now[2]), angular(now[3], now[4], now[5]);
    const Eigen::Vector3d momentum_before(e.inner[0], e.inner[1], e.inner[2]);
    const Eigen::Vector3d angular_before(e.inner[3], e.inner[4], e.inner[5]);
    e.load.force = -rho * e.forcing + rho * (momentum - momentum_before) / dt;
    e.load.torque = -rho * e.forcing_moment + rho * (angular - angular_before) / dt;
    std::copy_n(now, kInnerWidth, e.inner.begin());
  }
}

void ImmersedBoundary::update_fractions() {
  for (Entry& e : bodies_) {
    // A body where it was (a fixed one: every step, a container over the whole domain) has
    // the fractions it had.
    const geometry::Pose& now = e.body.pose;
    if (e.fraction_pose && e.fraction_pose->position() == now.position() &&
        e.fraction_pose->orientation().coeffs() == now.orientation().coeffs())
      continue;
    e.fraction_pose = now;
    for (int c = 0; c < 3; ++c)
      e.fraction[static_cast<std::size_t>(c)] =
          volume_fractions(grid_, c, e.body, e.distance, grid_.owned(grid_.velocity_dm(c)));
    if (geometry::is_bounded(e.body.shape)) continue;
    // Beyond the markers' kernels: their depth and reach, and half a face's width.
    double widest = 0;
    for (int d = 0; d < 3; ++d)
      if (!grid_.axis(d).degenerate()) widest = std::max(widest, grid_.axis(d).max_width());
    const double beyond = (options_.retraction->constant + support_radius(options_.kernel) + 0.5) * widest;
    for (int c = 0; c < 3; ++c) {
      std::vector<Index>& held = e.held[static_cast<std::size_t>(c)];
      held.clear();
      for_each_index(grid_.owned(grid_.velocity_dm(c)), [&](const Index& p) {
        const Point at = grid_.position(c, p);
        if (!grid_.on_boundary(c, p) &&
            geometry::signed_distance(e.body.shape, e.body.pose, Eigen::Vector3d(at[0], at[1], at[2])) < -beyond)
          held.push_back(p);
      });
    }
  }
}

std::vector<double> ImmersedBoundary::inner_momenta(const NavierStokes& flow) const {
  std::vector<double> out(kInnerWidth * bodies_.size(), 0.0);
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    const PetscScalar*** u = nullptr;
    COSIM_PETSC(DMDAVecGetArrayRead(dm, flow.velocity(c), &u));
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      const RigidBody& body = bodies_[b].body;
      Eigen::Vector3d momentum = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero();
      for (const FractionImage& image : bodies_[b].fraction[static_cast<std::size_t>(c)]) {
        const IndicatorPatch& alpha = image.patch;
        const Eigen::Vector3d centre = body.pose.position() + image.shift;
        for_each_index(alpha.range(), [&](const Index& p) {
          const double a = alpha(p);
          if (a == 0 || grid_.on_boundary(c, p)) return;
          const Point x = grid_.position(c, p);
          Eigen::Vector3d m = Eigen::Vector3d::Zero();
          m[c] = a * u[p[2]][p[1]][p[0]] * grid_.face_volume(c, p);
          momentum += m;
          angular += (Eigen::Vector3d(x[0], x[1], x[2]) - centre).cross(m);
        });
      }
      for (int d = 0; d < 3; ++d) {
        out[kInnerWidth * b + static_cast<std::size_t>(d)] += momentum[d];
        out[kInnerWidth * b + 3 + static_cast<std::size_t>(d)] += angular[d];
      }
    }
    COSIM_PETSC(DMDAVecRestoreArrayRead(dm, flow.velocity(c), &u));
  }
  MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(out.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
  return out;
}

}  // namespace cosim::fluid::ibm
