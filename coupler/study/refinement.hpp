// The refinement ratio between consecutive levels, from the values of the first varied key.
#pragma once

#include <string>
#include <vector>

#include "coupler/study/levels.hpp"

namespace cosim::study {

struct Ratios {
  std::vector<double> r;  // r[k]: from level k to level k + 1 (0-based), > 1; empty: none
  std::string why_none;   // when empty
};

// Values that shrink from level to level are steps or windows: r = coarse / fine. Values that
// grow are counts, such as cells: r = fine / coarse. A list (cells per axis) counts by the
// geometric mean of the entries that change between levels, Celik et al.'s h = (1 / N)^(1/d)
// for N cells in the d dimensions refined.
Ratios refinement_ratios(const Varied& key);

}  // namespace cosim::study
