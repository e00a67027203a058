#include "tracker/program/velocity_input.hpp"

#include <algorithm>
#include <stdexcept>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_values.hpp"

namespace cosim::tracker::program {

tracers::VelocityField velocity_of(const field::FieldFrame& frame) {
  const auto field = std::find_if(frame.fields.begin(), frame.fields.end(),
                                  [](const field::CellField& f) { return f.name == "velocity"; });
  if (field == frame.fields.end() || field->components != 3)
    throw std::runtime_error("the fields have no 3-component velocity");
  const auto* grid = std::get_if<field::RectilinearGrid>(&frame.grid);
  if (grid == nullptr) throw std::runtime_error("the fields are not on a rectilinear grid");
  std::array<std::vector<double>, 3> centres;
  std::size_t cells = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    const std::vector<double>& nodes = grid->nodes[a];
    if (nodes.size() < 2) throw std::runtime_error("the fields' grid has fewer than 2 nodes along an axis");
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) centres[a].push_back(0.5 * (nodes[i] + nodes[i + 1]));
    cells *= centres[a].size();
  }
  if (field->values.size() != 3 * cells)
    throw std::runtime_error("velocity has " + std::to_string(field->values.size() / 3) + " cells, the grid " +
                             std::to_string(cells));
  return tracers::VelocityField(std::move(centres), field->values);
}

tracers::VelocityField read_velocity(const std::filesystem::path& file, const std::string& participant) {
  try {
    if (!std::filesystem::exists(file)) throw std::runtime_error("no such file");
    output::Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + file.string());
    const std::string base = "/fields/" + participant;
    if (!output::has_link(h5.get(), "fields") ||
        !output::has_link(output::open_group(h5.get(), "fields").get(), participant))
      throw std::runtime_error("no fields of '" + participant + "'");
    std::vector<std::string> steps = output::link_names(output::open_group(h5.get(), base).get());
    std::erase(steps, "grid");
    if (steps.empty()) throw std::runtime_error("no field steps of '" + participant + "'");
    // Names are window numbers padded to the same width, so name order is time order.
    const std::string last = *std::max_element(
        steps.begin(), steps.end(),
        [](const std::string& a, const std::string& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; });
    field::RectilinearGrid grid;
    for (std::size_t a = 0; a < 3; ++a)
      grid.nodes[a] = output::read_array(h5.get(), base + "/grid/" + std::string(1, "xyz"[a]));
    field::FieldFrame frame{grid, {}};
    if (!output::has_link(output::open_group(h5.get(), base + "/" + last).get(), "velocity"))
      throw std::runtime_error("no velocity in " + base + "/" + last);
    frame.fields.push_back({"velocity", 3, output::read_array(h5.get(), base + "/" + last + "/velocity")});
    return velocity_of(frame);
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

}  // namespace cosim::tracker::program
