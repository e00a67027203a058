#include "coupler/estimate/cost_model.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>

namespace cosim::estimate {
namespace {

double dot(double constant, const Units& coefficients, double one, const Units& counts) {
  double sum = constant * one;
  for (const auto& [unit, c] : coefficients) {
    const auto it = counts.find(unit);
    if (it != counts.end()) sum += c * it->second;
  }
  return sum;
}

// Least squares min |A x - b| over x >= 0 for the few columns a cost model has: every set of
// free columns is tried, and the best fit whose free coefficients are all non-negative wins
// (the others held at zero), which is the exact answer for so few columns.
Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const auto n = a.cols();
  // A model has a constant and a few counts (the coupler's: three and a start-up per
  // built-in program); 2^n subsets stay cheap well beyond that.
  if (n > 16) throw std::runtime_error(fmt::format("a cost model of {} coefficients is beyond its fit", n));
  Eigen::VectorXd best = Eigen::VectorXd::Zero(n);
  double best_residual = b.squaredNorm();
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    std::vector<Eigen::Index> free;
    for (Eigen::Index j = 0; j < n; ++j)
      if (mask & (1u << j)) free.push_back(j);
    Eigen::MatrixXd sub(a.rows(), static_cast<Eigen::Index>(free.size()));
    for (std::size_t k = 0; k < free.size(); ++k) sub.col(static_cast<Eigen::Index>(k)) = a.col(free[k]);
    const Eigen::VectorXd x = sub.colPivHouseholderQr().solve(b);
    if ((x.array() < 0).any()) continue;
    const double residual = (sub * x - b).squaredNorm();
    if (residual >= best_residual) continue;
    best_residual = residual;
    best.setZero();
    for (std::size_t k = 0; k < free.size(); ++k) best[free[k]] = x[static_cast<Eigen::Index>(k)];
  }
  return best;
}

// Fits `constant` + sum of per-unit coefficients: rows are the observations' counts over
// their measured value (`measured` > 0 only), then the prior's rows.
void fit_linear(const std::vector<Observation>& observations,
                const std::function<const Units&(const Observation&)>& counts,
                const std::function<double(const Observation&)>& measured, double prior_constant, const Units& prior,
                double prior_weight, double& constant, Units& coefficients) {
  std::vector<std::string> units;
  for (const auto& [unit, c] : prior) units.push_back(unit);
  for (const auto& o : observations)
    for (const auto& [unit, n] : counts(o))
      if (!prior.contains(unit) && std::find(units.begin(), units.end(), unit) == units.end()) units.push_back(unit);
  const auto columns = static_cast<Eigen::Index>(units.size() + 1);
  std::vector<Eigen::VectorXd> rows;
  std::vector<double> rhs;
  for (const auto& o : observations) {
    const double y = measured(o);
    if (!(y > 0)) continue;
    Eigen::VectorXd row(columns);
    row[0] = 1 / y;
    for (std::size_t j = 0; j < units.size(); ++j) {
      const auto it = counts(o).find(units[j]);
      row[static_cast<Eigen::Index>(j + 1)] = it == counts(o).end() ? 0.0 : it->second / y;
    }
    rows.push_back(row);
    rhs.push_back(1);
  }
  const auto prior_row = [&](Eigen::Index column, double value) {
    if (!(value > 0)) return;
    Eigen::VectorXd row = Eigen::VectorXd::Zero(columns);
    row[column] = prior_weight / value;
    rows.push_back(row);
    rhs.push_back(prior_weight);
  };
  prior_row(0, prior_constant);
  for (std::size_t j = 0; j < units.size(); ++j)
    prior_row(static_cast<Eigen::Index>(j + 1), prior.contains(units[j]) ? prior.at(units[j]) : 0.0);
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), columns);
  Eigen::VectorXd b(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    a.row(static_cast<Eigen::Index>(i)) = rows[i];
    b[static_cast<Eigen::Index>(i)] = rhs[i];
  }
  const Eigen::VectorXd x = rows.empty() ? Eigen::VectorXd::Zero(columns) : non_negative_least_squares(a, b);
  constant = x[0];
  coefficients.clear();
  for (std::size_t j = 0; j < units.size(); ++j) coefficients[units[j]] = x[static_cast<Eigen::Index>(j + 1)];
}

}  // namespace

double step_seconds(const Coefficients& c, const Units& per_step) {
  return dot(c.seconds_per_step, c.seconds_per_unit, 1.0, per_step);
}

double memory_bytes(const Coefficients& c, const Units& held) { return dot(c.base_bytes, c.bytes_per_unit, 1.0, held); }

Coefficients fit(const std::vector<Observation>& observations, const Coefficients& prior, double prior_weight) {
  Coefficients out;
  fit_linear(
      observations, [](const Observation& o) -> const Units& { return o.per_step; },
      [](const Observation& o) { return o.steps > 0 ? o.seconds / o.steps : 0.0; }, prior.seconds_per_step,
      prior.seconds_per_unit, prior_weight, out.seconds_per_step, out.seconds_per_unit);
  fit_linear(
      observations, [](const Observation& o) -> const Units& { return o.held; },
      [](const Observation& o) { return o.peak_bytes; }, prior.base_bytes, prior.bytes_per_unit, prior_weight,
      out.base_bytes, out.bytes_per_unit);
  return out;
}

}  // namespace cosim::estimate
