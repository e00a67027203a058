// One of a body's series over the run, with its times: what `cosim study` measures on.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cosim::output {

struct BodySeries {
  std::vector<double> time;    // s, the end of each written window
  std::vector<double> values;  // time.size() x columns, row-major
  std::size_t columns = 0;
};

// /bodies/<body>/<series> (position, velocity, force, ...) and /bodies/<body>/time, cut to
// the rows both have (a crash inside a write can leave one a row longer). Throws
// std::runtime_error naming the file and the object if it is not a run file or has no such
// body or series.
BodySeries body_series(const std::filesystem::path& path, const std::string& body, const std::string& series);

}  // namespace cosim::output
