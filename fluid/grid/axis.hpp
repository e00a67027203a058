#pragma once
// One coordinate direction of the structured grid: the cell faces, uniform or stretched.
#include <vector>

namespace cosim::fluid::grid {

class Axis {
 public:
  static Axis uniform(int cells, double lo, double hi, bool periodic);
  // Cells cluster towards both ends with a tanh map; beta > 0 sets how strongly (the
  // ratio of end to middle cell width is about 1/cosh^2(beta)).
  static Axis stretched(int cells, double lo, double hi, double beta, bool periodic);
  // Explicit node coordinates, strictly increasing, at least two cells.
  static Axis from_faces(std::vector<double> faces, bool periodic);

  int cells() const { return cells_; }
  bool periodic() const { return periodic_; }
  double lo() const { return face(0); }
  double hi() const { return face(cells_); }
  // Valid for i in [-2, cells + 2]: outside the domain faces continue periodically, or
  // mirror at the boundary, so ghost cells sit where a ghost-cell closure expects them.
  double face(int i) const { return faces_[static_cast<std::size_t>(i + kGhost)]; }
  double centre(int i) const { return 0.5 * (face(i) + face(i + 1)); }
  double width(int i) const { return face(i + 1) - face(i); }
  double max_width() const { return max_width_; }
  // The cell holding x: face(i) <= x < face(i + 1), clamped to the axis; on a periodic axis
  // x is first wrapped into the period.
  int cell_at(double x) const;
  // A periodic axis of one cell carries no variation: its derivative terms vanish and are
  // skipped (a two-dimensional problem is one cell layer thick and periodic).
  bool degenerate() const { return periodic_ && cells_ == 1; }

 private:
  static constexpr int kGhost = 2;
  Axis(std::vector<double> faces, bool periodic);
  std::vector<double> faces_;  // faces -kGhost .. cells + kGhost
  int cells_ = 0;
  bool periodic_ = false;
  double max_width_ = 0;
};

}  // namespace cosim::fluid::grid
