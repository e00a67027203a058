// A grid field's volume-weighted mean over the whole grid at each frame of a run file: what
// `cosim study` measures a field by.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cosim::output {

struct FieldMeans {
  std::vector<double> time;    // s, each frame's time attribute, increasing
  std::vector<double> values;  // time.size() x columns, row-major
  std::size_t columns = 0;     // 1 for a scalar field, its components otherwise
};

// /fields/<participant>/<frame>/<field> over every frame, each cell weighted by its volume
// from grid/x, y, z. Throws std::runtime_error naming the file and the object when the file
// has no such field, or its grid is polyhedral (the file holds no cell volumes for it).
FieldMeans field_means(const std::filesystem::path& path, const std::string& participant, const std::string& field);

}  // namespace cosim::output
