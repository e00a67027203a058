#include "fluid/grid/axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::fluid::grid {

Axis Axis::uniform(int cells, double lo, double hi, bool periodic) { return stretched(cells, lo, hi, 0.0, periodic); }

Axis Axis::stretched(int cells, double lo, double hi, double beta, bool periodic) {
  if (cells < 1) throw std::invalid_argument("axis: need at least one cell");
  if (beta < 0) throw std::invalid_argument("axis: stretching factor must be >= 0");
  std::vector<double> faces(static_cast<std::size_t>(cells) + 1);
  for (int i = 0; i <= cells; ++i) {
    const double s = static_cast<double>(i) / cells;
    const double mapped = beta == 0 ? s : 0.5 * (1 + std::tanh(beta * (2 * s - 1)) / std::tanh(beta));
    faces[static_cast<std::size_t>(i)] = lo + (hi - lo) * mapped;
  }
  faces.back() = hi;
  return Axis(std::move(faces), periodic);
}

Axis Axis::from_faces(std::vector<double> faces, bool periodic) { return Axis(std::move(faces), periodic); }

Axis::Axis(std::vector<double> faces, bool periodic) : cells_(static_cast<int>(faces.size()) - 1), periodic_(periodic) {
  if (cells_ < 1) throw std::invalid_argument("axis: need at least two face coordinates");
  for (int i = 0; i < cells_; ++i)
    if (!(faces[static_cast<std::size_t>(i) + 1] > faces[static_cast<std::size_t>(i)]))
      throw std::invalid_argument("axis: face coordinates must increase strictly (at index " + std::to_string(i + 1) +
                                  ")");
  if (!periodic_ && cells_ < 2)
    throw std::invalid_argument("axis: a bounded axis needs at least two cells for its wall closure");
  const double length = faces.back() - faces.front();
  for (int i = 0; i < cells_; ++i)
    max_width_ = std::max(max_width_, faces[static_cast<std::size_t>(i) + 1] - faces[static_cast<std::size_t>(i)]);
  faces_.resize(faces.size() + 2 * kGhost);
  for (int i = 0; i <= cells_; ++i) faces_[static_cast<std::size_t>(i + kGhost)] = faces[static_cast<std::size_t>(i)];
  for (int g = 1; g <= kGhost; ++g) {
    const auto at = [&](int i) -> double& { return faces_[static_cast<std::size_t>(i + kGhost)]; };
    // Periodic faces repeat with the period (this also covers a single-cell axis); bounded
    // ones mirror at the end face.
    if (periodic_) {
      const auto wrapped = [&](int i) {
        const int turns = i >= 0 ? i / cells_ : -((-i + cells_ - 1) / cells_);
        return faces[static_cast<std::size_t>(i - turns * cells_)] + turns * length;
      };
      at(-g) = wrapped(-g);
      at(cells_ + g) = wrapped(cells_ + g);
    } else {
      at(-g) = 2 * at(0) - at(g);
      at(cells_ + g) = 2 * at(cells_) - at(cells_ - g);
    }
  }
}

int Axis::cell_at(double x) const {
  if (periodic_) {
    const double period = hi() - lo();
    x -= std::floor((x - lo()) / period) * period;
  }
  int lo_cell = 0, hi_cell = cells_;  // face(lo_cell) <= x < face(hi_cell), or clamped
  while (hi_cell - lo_cell > 1) {
    const int mid = (lo_cell + hi_cell) / 2;
    (face(mid) <= x ? lo_cell : hi_cell) = mid;
  }
  return lo_cell;
}

}  // namespace cosim::fluid::grid
