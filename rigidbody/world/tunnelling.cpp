#include "rigidbody/world/tunnelling.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "geometry/convex_hull.hpp"

namespace cosim::rigidbody::world {
namespace {

double width(const geometry::Shape& shape, const Eigen::Vector3d& n) {
  return n.dot(geometry::support(shape, n) - geometry::support(shape, -n));
}

std::string name_of(std::span<const NamedBody> names, std::uint32_t body) {
  const auto it = std::lower_bound(names.begin(), names.end(), body,
                                   [](const NamedBody& n, std::uint32_t b) { return n.body < b; });
  return it != names.end() && it->body == body ? it->name : std::string();
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
                                             std::span<const dynamics::BodyInertia> inertias, double dt, double margin,
                                             double speed_gain) {
  std::vector<TunnellingRisk> risks;
  for (std::uint32_t i = 0; i < thinnest.size(); ++i) {
    if (inertias[i].is_fixed()) continue;
    const double travel = (states[i].velocity.norm() + speed_gain) * dt;
    if (travel > margin || travel > 0.5 * thinnest[i]) risks.push_back({i, travel, thinnest[i], margin});
  }
  return risks;
}

double excess(const TunnellingRisk& risk) { return risk.travel / std::min(risk.margin, 0.5 * risk.thinnest); }

std::string describe(const TunnellingRisk& risk, const std::string& name, double dt) {
  const double half = 0.5 * risk.thinnest;
  std::string limits;
  if (risk.travel > risk.margin) limits = fmt::format("the contact margin {:.3g} m", risk.margin);
  if (risk.travel > half)
    limits += fmt::format("{}half its thinnest extent {:.3g} m", limits.empty() ? "" : " and ", half);
  // Travel is proportional to dt, so the dt that keeps it within both limits follows.
  const double factor = excess(risk);
  std::string fix = fmt::format("lower the rigidbody dt by a factor {:.3g}, to {:.3g} s", factor, dt / factor);
  if (risk.travel <= half)
    fix += fmt::format(" or raise participants.rigidbody.options.contact_margin above {:.3g} m", risk.travel);
  return fmt::format(
      "body {}{} may move {:.3g} m per substep (dt = {:.3g} s), more than {}: it can pass "
      "through thin bodies or planes; {}",
      risk.body, name.empty() ? "" : " (" + name + ")", risk.travel, dt, limits, fix);
}

std::string summarise(std::span<const TunnellingRisk> risks, std::span<const NamedBody> names, double dt) {
  const auto worst = std::max_element(risks.begin(), risks.end(), [](const TunnellingRisk& x, const TunnellingRisk& y) {
    return excess(x) < excess(y);
  });
  const std::string message = describe(*worst, name_of(names, worst->body), dt);
  if (risks.size() == 1) return message;
  return fmt::format(
      "{} bodies may move farther per substep than the contact margin or half their thinnest extent; "
      "the worst: {}",
      risks.size(), message);
}

void TunnellingWarnings::add(std::string name, const geometry::Shape& shape) {
  if (!name.empty()) names_.push_back({static_cast<std::uint32_t>(thinnest_.size()), std::move(name)});
  thinnest_.push_back(thinnest_extent(shape));
}

std::optional<std::string> TunnellingWarnings::warning(std::span<const TunnellingRisk> risks, double dt) {
  if (risks.empty()) return std::nullopt;
  double worst = 0.0;
  for (const TunnellingRisk& r : risks) worst = std::max(worst, excess(r));
  if (warned_count_ > 0 && risks.size() < 2 * warned_count_ && worst < 2 * warned_excess_) return std::nullopt;
  warned_count_ = risks.size();
  warned_excess_ = worst;
  return summarise(risks, names_, dt);
}

}  // namespace cosim::rigidbody::world
