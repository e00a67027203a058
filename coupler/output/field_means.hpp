// A grid field's volume-weighted mean over the whole grid, a box of it or the cell holding a
// point, at each frame of a run file: what `cosim study` measures a field by.
#pragma once

#include <array>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace cosim::output {

// Where a mean is taken: the cells' overlaps with the box [lo, hi] weigh them. An axis with
// lo == hi takes the one cell holding that coordinate, so a point takes its cell's value.
struct Region {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{-inf, -inf, -inf}, hi{inf, inf, inf};  // the whole grid
};

struct FieldMeans {
  std::vector<double> time;    // s, each frame's time attribute, increasing
  std::vector<double> values;  // time.size() x columns, row-major
  std::size_t columns = 0;     // 1 for a scalar field, its components otherwise
};

// /fields/<participant>/<frame>/<field> over every frame, each cell weighted by its volume
// within `region` from grid/x, y, z. Throws std::runtime_error naming the file and the object
// when the file has no such field, its grid is polyhedral (the file holds no cell volumes for
// it), or the region meets no cell.
FieldMeans field_means(const std::filesystem::path& path, const std::string& participant, const std::string& field,
                       const Region& region = {});

}  // namespace cosim::output
