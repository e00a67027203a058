#include "tests/coupling/problems.hpp"

#include <iomanip>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

namespace cosim::coupling::test {

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (auto& value : v) value = uniform(engine);
  return v;
}

Problem linear(const Eigen::VectorXd& eigenvalues, unsigned seed) {
  const Eigen::Index n = eigenvalues.size();
  Eigen::MatrixXd m(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    m.col(j) = random_vector(n, seed + 1 + static_cast<unsigned>(j));
  }
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(m).householderQ();
  const Eigen::MatrixXd a = q * eigenvalues.asDiagonal() * q.transpose();
  const Eigen::VectorXd b = random_vector(n, seed);
  const Eigen::MatrixXd i = Eigen::MatrixXd::Identity(n, n);
  return {[a, b](const Eigen::VectorXd& x) -> Eigen::VectorXd { return a * x + b; }, (i - a).partialPivLu().solve(b)};
}

Problem tanh_problem(const Eigen::VectorXd& b, double c) {
  // x + c tanh(x) = b is monotone in x, so Newton from x = b / (1 + c) finds its one root.
  Eigen::VectorXd solution = b / (1.0 + c);
  for (int k = 0; k < 50; ++k) {
    const Eigen::ArrayXd t = solution.array().tanh();
    solution.array() -= (solution.array() + c * t - b.array()) / (1.0 + c * (1.0 - t * t));
  }
  return {[b, c](const Eigen::VectorXd& x) -> Eigen::VectorXd { return b.array() - c * x.array().tanh(); }, solution};
}

Window iterate(Accelerator& accelerator, const Problem& problem, const Eigen::VectorXd& x0, int max_updates) {
  accelerator.new_window();
  Window window;
  window.iterates.push_back(x0);
  for (;;) {
    const Eigen::VectorXd& x = window.iterates.back();
    const Eigen::VectorXd hx = problem.h(x);
    window.converged = (hx - x).norm() <= residual_tolerance;
    if (window.converged || window.updates == max_updates) return window;
    window.iterates.push_back(accelerator.next(x, hx));
    ++window.updates;
  }
}

void report(const std::string& problem, const std::vector<std::pair<std::string, Window>>& windows) {
  std::cout << "[iterations] " << std::left << std::setw(40) << problem;
  for (const auto& [method, window] : windows) {
    const std::string updates = window.converged ? std::to_string(window.updates) : "unconverged";
    std::cout << "  " << method << ' ' << std::setw(11) << updates;
    ::testing::Test::RecordProperty(method, updates);
  }
  std::cout << '\n';
}

}  // namespace cosim::coupling::test
