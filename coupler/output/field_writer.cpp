#include "output/field_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "output/h5_groups.hpp"
#include "output/h5_handle.hpp"
#include "output/h5_values.hpp"

namespace cosim::output {
namespace {

// Zero-padded so that the groups list in time order wherever names are sorted.
std::string step_name(std::uint64_t window) {
  char text[24];
  std::snprintf(text, sizeof text, "%06llu", static_cast<unsigned long long>(window));
  return text;
}

void check_frame(const FieldFrame& frame, const std::string& participant) {
  for (const auto& nodes : frame.grid.nodes)
    if (nodes.size() < 2) throw ObjectError("fields of " + participant + ": an axis with fewer than 2 nodes");
  const auto n = frame.grid.cells();
  for (const CellField& f : frame.fields)
    if (f.components < 1 || f.values.size() != n[0] * n[1] * n[2] * static_cast<std::size_t>(f.components))
      throw ObjectError("field " + f.name + " of " + participant + ": " + std::to_string(f.values.size()) +
                        " values do not fit the grid");
}

void write_grid(hid_t participant_group, const RectilinearGrid& grid) {
  Handle group = create_group(participant_group, "grid");
  for (std::size_t a = 0; a < 3; ++a)
    write_array(group.get(), std::string(1, "xyz"[a]), {grid.nodes[a].size()}, grid.nodes[a].data());
}

}  // namespace

FieldWriter::FieldWriter(std::filesystem::path h5_path) : h5_path_(std::move(h5_path)) {}

void FieldWriter::write(hid_t file, const std::string& participant, std::uint64_t window, double time,
                        const FieldFrame& frame) {
  check_frame(frame, participant);
  Handle fields = open_or_create_group(file, "fields");
  Handle group = open_or_create_group(fields.get(), participant);
  const std::string base = "/fields/" + participant;
  auto [it, first] = series_.try_emplace(participant, XdmfSeries{participant, base + "/grid", frame.grid.cells(), {}});
  XdmfSeries& series = it->second;
  if (first && !has_link(group.get(), "grid")) write_grid(group.get(), frame.grid);
  if (series.cells != frame.grid.cells()) throw ObjectError("fields of " + participant + ": the grid changed");

  const std::string name = step_name(window);
  Handle step = create_group(group.get(), name);
  write_attribute(step.get(), "time", time);
  const auto n = frame.grid.cells();
  XdmfStep entry{base + "/" + name, time, {}};
  for (const CellField& f : frame.fields) {
    std::vector<hsize_t> dims{n[2], n[1], n[0]};
    if (f.components > 1) dims.push_back(static_cast<hsize_t>(f.components));
    write_array(step.get(), f.name, dims, f.values.data());
    entry.fields.push_back({f.name, f.components});
  }
  series.steps.push_back(std::move(entry));
}

void FieldWriter::resume(hid_t file, std::uint64_t next_window) {
  if (!has_link(file, "fields")) return;
  Handle fields = open_group(file, "fields");
  for (const std::string& participant : link_names(fields.get())) {
    Handle group = open_group(fields.get(), participant);
    const std::string base = "/fields/" + participant;
    Handle grid = open_group(group.get(), "grid");
    std::array<std::size_t, 3> cells{};
    for (std::size_t a = 0; a < 3; ++a) cells[a] = array_dims(grid.get(), std::string(1, "xyz"[a])).at(0) - 1;
    XdmfSeries series{participant, base + "/grid", cells, {}};
    std::vector<std::pair<std::uint64_t, std::string>> steps;
    for (const std::string& name : link_names(group.get()))
      if (name != "grid") steps.emplace_back(std::stoull(name), name);
    std::sort(steps.begin(), steps.end());  // more than 6 digits sort after 6 by name
    for (const auto& [window, name] : steps) {
      if (window > next_window) {
        delete_link(group.get(), name);
        continue;
      }
      Handle step = open_group(group.get(), name);
      XdmfStep entry{base + "/" + name, read_attribute<double>(step.get(), "time"), {}};
      for (const std::string& field : link_names(step.get())) {
        const auto dims = array_dims(step.get(), field);
        entry.fields.push_back({field, dims.size() > 3 ? static_cast<int>(dims[3]) : 1});
      }
      series.steps.push_back(std::move(entry));
    }
    series_.insert_or_assign(participant, std::move(series));
  }
}

void FieldWriter::write_sidecar() const {
  if (series_.empty()) return;  // a run without fields has no sidecar
  std::vector<XdmfSeries> all;
  for (const auto& [_, s] : series_) all.push_back(s);
  std::filesystem::path sidecar = h5_path_;
  sidecar.replace_extension(".xmf");
  write_replacing(sidecar, xdmf_document(h5_path_.filename().string(), all));
}

}  // namespace cosim::output
