#include "coupler/output/program_costs.hpp"

#include <algorithm>
#include <cmath>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_values.hpp"
#include "coupler/output/in_file.hpp"
#include "coupler/output/journal_driver.hpp"
#include "coupler/output/series.hpp"

namespace cosim::output {

std::vector<ProgramCost> program_costs(const std::filesystem::path& path, bool serial) {
  return in_file(path, [&] {
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, journaled_access().get()), H5Fclose, "open file");
    const auto names =
        read_attribute<std::vector<std::string>>(open_group(file.get(), "run").get(), "participant_names");
    const Handle coupling = open_group(file.get(), "coupling");
    const std::vector<double> windows = Series::open(coupling.get(), "wall_seconds").read_all();
    std::vector<double> taken(windows.size(), 0.0);  // the participants' part of each window
    const Handle participants = open_group(coupling.get(), "participants");
    std::vector<ProgramCost> out;
    double total = 0;
    for (double w : windows) total += w;
    for (const std::string& name : names) {
      const Handle group = open_group(participants.get(), name);
      const std::vector<double> seconds = Series::open(group.get(), "wall_seconds").read_all();
      ProgramCost cost{.name = name};
      for (std::size_t k = 0; k < std::min(seconds.size(), windows.size()); ++k) {
        if (std::isnan(seconds[k])) continue;  // a window with no record of it
        cost.share += seconds[k];
        taken[k] = serial ? taken[k] + seconds[k] : std::max(taken[k], seconds[k]);
      }
      cost.share = total > 0 ? cost.share / total : 0.0;
      if (has_attribute(group.get(), "peak_bytes")) cost.peak_bytes = read_attribute<double>(group.get(), "peak_bytes");
      out.push_back(cost);
    }
    double rest = 0;
    for (std::size_t k = 0; k < windows.size(); ++k) rest += std::max(0.0, windows[k] - taken[k]);
    out.push_back({.name = "coupler", .share = total > 0 ? rest / total : 0.0});
    return out;
  });
}

}  // namespace cosim::output
