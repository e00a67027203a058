// Fixed-point problems x = H(x) with known answers, and the window loop the coupler runs
// over them, so the accelerators can be checked against exact solutions.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "coupler/coupling/acceleration.hpp"

namespace cosim::coupling::test {

struct Problem {
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> h;
  Eigen::VectorXd solution;
};

// H(x) = A x + b with A symmetric and the given eigenvalues (random eigenvectors), so the
// spectrum, and with it contraction or divergence of the plain iteration, is chosen exactly.
Problem linear(const Eigen::VectorXd& eigenvalues, unsigned seed);
// H(x) = b - c tanh(x) componentwise: for c > 1 the slope -c sech^2 makes it unstable near
// 0 and contractive far out, a nonlinear stand-in for added mass.
Problem tanh_problem(const Eigen::VectorXd& b, double c);

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed);

// Stopping rule of the loop below: |H(x) - x| at most this. The problems here have
// |(I - H')^{-1}| <= 2, so it puts x within 1e-10 of the solution.
constexpr double residual_tolerance = 1e-11;

struct Window {
  int updates = 0;  // calls to next() before x passed the test
  bool converged = false;
  std::vector<Eigen::VectorXd> iterates;  // x_0, x_1, ... as evaluated
  const Eigen::VectorXd& x() const { return iterates.back(); }
};

// One coupling window: starts with new_window(), then evaluates and accelerates until the
// residual passes or max_updates is reached.
Window iterate(Accelerator& accelerator, const Problem& problem, const Eigen::VectorXd& x0, int max_updates);

// Prints the updates each method needed in one comparison ("unconverged" if it never
// passed) and records them in the test's XML output.
void report(const std::string& problem, const std::vector<std::pair<std::string, Window>>& windows);

}  // namespace cosim::coupling::test
