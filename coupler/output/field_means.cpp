#include "coupler/output/field_means.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/in_file.hpp"
#include "coupler/output/journal_driver.hpp"

namespace cosim::output {
namespace {

// An axis's weights: each cell's length within [lo, hi], or, for lo == hi, 1 for the one cell
// holding lo (the last cell takes its upper node too). All zero when the interval misses.
std::vector<double> weights(hid_t grid, const std::string& axis, double lo, double hi) {
  const std::vector<double> nodes = read_array(grid, axis);
  std::vector<double> out;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const bool last = i + 1 == nodes.size();
    if (lo == hi)
      out.push_back(lo >= nodes[i - 1] && (lo < nodes[i] || (last && lo == nodes[i])) ? 1.0 : 0.0);
    else
      out.push_back(std::max(0.0, std::min(hi, nodes[i]) - std::max(lo, nodes[i - 1])));
  }
  return out;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

FieldMeans field_means(const std::filesystem::path& path, const std::string& participant, const std::string& field,
                       const Region& region) {
  return in_file(path, [&] {
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, journaled_access().get()), H5Fclose, "open file");
    const Handle fields = open_group(file.get(), "fields");
    const Handle group = open_group(fields.get(), participant);
    const Handle grid = open_group(group.get(), "grid");
    if (!has_link(grid.get(), "x"))
      fail("/fields/" + participant + "/grid is polyhedral: the run file holds no cell volumes to weigh a mean by");
    const std::vector<double> dx = weights(grid.get(), "x", region.lo[0], region.hi[0]);
    const std::vector<double> dy = weights(grid.get(), "y", region.lo[1], region.hi[1]);
    const std::vector<double> dz = weights(grid.get(), "z", region.lo[2], region.hi[2]);
    const double volume = sum(dx) * sum(dy) * sum(dz);
    if (volume == 0)
      fail(fmt::format("/fields/{}/grid: no cell lies in [{}, {}] x [{}, {}] x [{}, {}]", participant, region.lo[0],
                       region.hi[0], region.lo[1], region.hi[1], region.lo[2], region.hi[2]));
    std::vector<std::pair<double, std::vector<double>>> frames;
    FieldMeans out;
    for (const std::string& name : link_names(group.get())) {
      if (name == "grid" || !is_group(group.get(), name)) continue;
      const Handle frame = open_group(group.get(), name);
      const std::vector<hsize_t> dims = array_dims(frame.get(), field);
      const std::string where = "/fields/" + participant + "/" + name + "/" + field;
      if ((dims.size() != 3 && dims.size() != 4) || dims[0] != dz.size() || dims[1] != dy.size() ||
          dims[2] != dx.size())
        fail(where + ": its shape is not the grid's (nz, ny, nx) or (nz, ny, nx, c)");
      const std::size_t columns = dims.size() == 4 ? dims[3] : 1;
      const std::vector<double> values = read_array(frame.get(), field);
      std::vector<double> mean(columns, 0.0);
      std::size_t at = 0;
      for (double wz : dz)
        for (double wy : dy)
          for (double wx : dx) {
            for (std::size_t c = 0; c < columns; ++c) mean[c] += wx * wy * wz * values[at + c];
            at += columns;
          }
      for (double& m : mean) m /= volume;
      out.columns = columns;
      frames.emplace_back(read_attribute<double>(frame.get(), "time"), std::move(mean));
    }
    if (frames.empty()) fail("/fields/" + participant + ": no frame holds " + field);
    std::sort(frames.begin(), frames.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [t, mean] : frames) {
      out.time.push_back(t);
      out.values.insert(out.values.end(), mean.begin(), mean.end());
    }
    return out;
  });
}

}  // namespace cosim::output
