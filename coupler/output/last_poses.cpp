#include "coupler/output/last_poses.hpp"

#include <algorithm>
#include <limits>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/in_file.hpp"
#include "coupler/output/journal_driver.hpp"
#include "coupler/output/run_file.hpp"
#include "coupler/output/series.hpp"

namespace cosim::output {
namespace {

template <std::size_t N>
std::array<double, N> row_of(const Series& series, hsize_t row) {
  if (series.columns() != N) {
    throw ObjectError("series " + series.path() + " has " + std::to_string(series.columns()) + " columns, not " +
                      std::to_string(N));
  }
  const std::vector<double> values = series.read_row(row);
  std::array<double, N> out{};
  std::copy(values.begin(), values.end(), out.begin());
  return out;
}

}  // namespace

std::vector<LastPose> last_poses(const std::filesystem::path& path) {
  // peek() says what is wrong with a file that is no run file, and gives the body order.
  const std::vector<std::string> bodies = RunFile::peek(path).bodies;
  return in_file(path, [&] {
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, journaled_access().get()), H5Fclose, "open file");
    const Handle group = open_group(file.get(), "bodies");
    std::vector<Series> positions, orientations;
    hsize_t rows = std::numeric_limits<hsize_t>::max();
    for (const std::string& name : bodies) {
      const Handle body = open_group(group.get(), name);
      positions.push_back(Series::open(body.get(), "position"));
      orientations.push_back(Series::open(body.get(), "orientation"));
      rows = std::min({rows, positions.back().rows(), orientations.back().rows()});
    }
    if (rows == 0) throw ObjectError("no row written yet");
    std::vector<LastPose> poses;
    for (std::size_t i = 0; i < bodies.size(); ++i)
      poses.push_back({bodies[i], row_of<3>(positions[i], rows - 1), row_of<4>(orientations[i], rows - 1)});
    return poses;
  });
}

}  // namespace cosim::output
