#include "coupler/output/body_series.hpp"

#include <algorithm>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/in_file.hpp"
#include "coupler/output/journal_driver.hpp"
#include "coupler/output/series.hpp"

namespace cosim::output {

BodySeries body_series(const std::filesystem::path& path, const std::string& body, const std::string& series) {
  return in_file(path, [&] {
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, journaled_access().get()), H5Fclose, "open file");
    const Handle bodies = open_group(file.get(), "bodies");
    const Handle group = open_group(bodies.get(), body);
    const Series time = Series::open(group.get(), "time");
    const Series values = Series::open(group.get(), series);
    const hsize_t rows = std::min(time.rows(), values.rows());
    BodySeries out;
    out.columns = values.columns();
    out.time = time.read_all();
    out.values = values.read_all();
    out.time.resize(rows);
    out.values.resize(rows * out.columns);
    return out;
  });
}

}  // namespace cosim::output
