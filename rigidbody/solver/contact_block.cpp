#include "rigidbody/solver/contact_block.hpp"

#include <algorithm>

namespace cosim::rigidbody::solver {

namespace {

// How a unit impulse along a row moves one of its bodies: sign (-1 on a, +1 on b) times the
// body's inverse mass along the row's direction d and its inverse inertia on r x d.
struct Side {
  std::uint32_t body;
  double sign;
  Eigen::Vector3d direction;
  Eigen::Vector3d arm;   // r x d
  Eigen::Vector3d turn;  // I^-1 (r x d)
};

}  // namespace

ContactBlock::ContactBlock(std::span<const ContactFrame> frames, int axes, std::span<const Mobility> mobility,
                           std::span<const double> compliance)
    : axes_(axes), compliance_(Eigen::Map<const Eigen::VectorXd>(compliance.data(), compliance.size())) {
  std::vector<Side> sides;  // two per row
  for (const ContactFrame& f : frames)
    for (int axis = 0; axis < axes; ++axis) {
      const Eigen::Vector3d d = f.basis.row(axis).transpose();
      for (const auto& [body, sign, r] : {std::tuple{f.a, -1.0, f.ra}, std::tuple{f.b, 1.0, f.rb}}) {
        const Eigen::Vector3d arm = r.cross(d);
        sides.push_back({body, sign, d, arm, mobility[body].turn(arm)});
      }
    }
  const auto n = static_cast<Eigen::Index>(sides.size() / 2);
  w_ = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i; j < n; ++j) {
      double wij = 0.0;
      for (const Side& p : {sides[2 * i], sides[2 * i + 1]})
        for (const Side& q : {sides[2 * j], sides[2 * j + 1]})
          if (p.body == q.body)
            wij += p.sign * q.sign * (mobility[p.body].inverse_mass * p.direction.dot(q.direction) + p.turn.dot(q.arm));
      w_(i, j) = w_(j, i) = wij;
    }
}

void ContactBlock::factorize(const std::vector<int>& active) {
  if (active == factorized_) return;
  const auto k = static_cast<Eigen::Index>(active.size());
  Eigen::MatrixXd m(k, k);
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j) m(i, j) = w_(active[i], active[j]) + (i == j ? compliance_[active[i]] : 0.0);
  ldlt_.compute(m);
  factorized_ = active;
}

// A convex quadratic programme, min 1/2 x.K x + q.x over x_normal >= 0 (K is positive definite
// thanks to the compliance), solved as Lawson and Hanson solve non-negative least squares:
// a point joins the free set when its constraint is violated the most, and a step that
// would turn a free impulse negative stops where the first reaches zero and frees it. The
// objective falls at every step, so no set repeats and it ends after finitely many; warm
// started from the last impulses, a resting group needs one factorization.
void ContactBlock::solve(std::span<const double> u, std::span<const double> target, std::span<double> lambda) {
  const auto n = static_cast<Eigen::Index>(lambda.size());
  const Eigen::Map<const Eigen::VectorXd> u_now(u.data(), n);
  const Eigen::Map<const Eigen::VectorXd> wanted(target.data(), n);
  Eigen::Map<Eigen::VectorXd> impulse(lambda.data(), n);
  // The constraint's excess w = K x + q must be >= 0, and 0 where x > 0.
  const Eigen::VectorXd q = u_now - w_ * impulse - wanted;
  const double tolerance = 1e-9 * (q.cwiseAbs().maxCoeff() + 1e-300);
  const auto excess = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return w_ * x + compliance_.cwiseProduct(x) + q;
  };

  const auto bounded = [&](Eigen::Index i) { return i % axes_ == 0; };  // a normal row
  Eigen::VectorXd x = impulse;
  std::vector<int> free;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (bounded(i)) x[i] = std::max(0.0, x[i]);
    if (x[i] > 0.0 || !bounded(i)) free.push_back(static_cast<int>(i));
  }
  for (Eigen::Index round = 0; round < 3 * n + 3; ++round) {
    const Eigen::VectorXd z = free_solution(free, q);
    Eigen::Index blocking = -1;
    double step = 1.0;
    for (const int i : free)
      if (bounded(i) && z[i] <= 0.0 && x[i] - z[i] > 0.0 && x[i] / (x[i] - z[i]) < step)
        step = x[blocking = i] / (x[i] - z[i]);
    x += step * (z - x);
    if (blocking >= 0) {
      x[blocking] = 0.0;
      std::erase_if(free, [&](int i) { return bounded(i) && x[i] <= 0.0; });
      continue;
    }
    const Eigen::VectorXd w = excess(x);
    Eigen::Index worst = -1;
    double most = -tolerance;
    for (Eigen::Index i = 0; i < n; ++i)
      if (w[i] < most && std::find(free.begin(), free.end(), i) == free.end()) most = w[worst = i];
    if (worst < 0) break;
    free.insert(std::upper_bound(free.begin(), free.end(), static_cast<int>(worst)), static_cast<int>(worst));
  }
  impulse = x;
}

// x with K_FF x_F = -q_F on the free set F and zero elsewhere.
Eigen::VectorXd ContactBlock::free_solution(const std::vector<int>& free, const Eigen::VectorXd& q) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(q.size());
  if (free.empty()) return z;
  factorize(free);
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(free.size()));
  for (std::size_t i = 0; i < free.size(); ++i) rhs[static_cast<Eigen::Index>(i)] = -q[free[i]];
  const Eigen::VectorXd solved = ldlt_.solve(rhs);
  for (std::size_t i = 0; i < free.size(); ++i) z[free[i]] = solved[static_cast<Eigen::Index>(i)];
  return z;
}

}  // namespace cosim::rigidbody::solver
