#include "rigidbody/world/tunnelling.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "rigidbody/geometry/convex_hull.hpp"

namespace cosim::world {
namespace {

double width(const geometry::Shape& shape, const Eigen::Vector3d& n) {
  return n.dot(geometry::support(shape, n) - geometry::support(shape, -n));
}

}  // namespace

double thinnest_extent(const geometry::Shape& shape) {
  if (!geometry::is_bounded(shape)) return std::numeric_limits<double>::infinity();
  // Every analytic shape is symmetric about its body axes, so its thinnest width is along
  // one of them. A hull's may lie between two edges; its faces give a close upper bound.
  double w = std::min({width(shape, Eigen::Vector3d::UnitX()), width(shape, Eigen::Vector3d::UnitY()),
                       width(shape, Eigen::Vector3d::UnitZ())});
  if (const auto* hull = std::get_if<geometry::ConvexHull>(&shape))
    for (const geometry::Plane& p : hull->planes()) w = std::min(w, width(shape, p.normal));
  return w;
}

std::vector<TunnellingRisk> tunnelling_risks(std::span<const double> thinnest,
                                             std::span<const dynamics::BodyState> states,
                                             std::span<const dynamics::BodyInertia> inertias, double dt,
                                             double margin, double speed_gain) {
  std::vector<TunnellingRisk> risks;
  for (std::uint32_t i = 0; i < thinnest.size(); ++i) {
    if (inertias[i].is_fixed()) continue;
    const double travel = (states[i].velocity.norm() + speed_gain) * dt;
    if (travel > margin || travel > 0.5 * thinnest[i]) risks.push_back({i, travel, thinnest[i], margin});
  }
  return risks;
}

std::string describe(const TunnellingRisk& risk, const std::string& name, double dt) {
  const double half = 0.5 * risk.thinnest;
  std::string limits;
  if (risk.travel > risk.margin) limits = fmt::format("the contact margin {:.3g} m", risk.margin);
  if (risk.travel > half) limits += fmt::format("{}half its thinnest extent {:.3g} m", limits.empty() ? "" : " and ", half);
  // Travel is proportional to dt, so the dt that keeps it within both limits follows.
  const double safe_dt = dt * std::min(risk.margin, half) / risk.travel;
  std::string fix = fmt::format("lower the rigidbody dt to {:.3g} s", safe_dt);
  if (risk.travel <= half)
    fix += fmt::format(" or raise participants.rigidbody.options.contact_margin above {:.3g} m", risk.travel);
  return fmt::format("body {}{} may move {:.3g} m per substep (dt = {:.3g} s), more than {}: it can pass "
                     "through thin bodies or planes; {}",
                     risk.body, name.empty() ? "" : " (" + name + ")", risk.travel, dt, limits, fix);
}

void TunnellingWarnings::add(std::string name, const geometry::Shape& shape) {
  names_.push_back(std::move(name));
  thinnest_.push_back(thinnest_extent(shape));
  warned_.push_back(0);
}

void TunnellingWarnings::warn(std::span<const TunnellingRisk> risks, double dt) {
  std::vector<TunnellingRisk> fresh;
  for (const TunnellingRisk& r : risks)
    if (!std::exchange(warned_[r.body], 1)) fresh.push_back(r);
  const auto named = std::min(fresh.size(), kNamedPerWindow);
  std::partial_sort(fresh.begin(), fresh.begin() + static_cast<std::ptrdiff_t>(named), fresh.end(),
                    [](const TunnellingRisk& x, const TunnellingRisk& y) { return x.travel > y.travel; });
  for (std::size_t i = 0; i < named; ++i) spdlog::warn("{}", describe(fresh[i], names_[fresh[i].body], dt));
  if (fresh.size() > named)
    spdlog::warn("{} more bodies may move farther per substep than the contact margin or half their thinnest extent",
                 fresh.size() - named);
}

}  // namespace cosim::world
