#include "coupler/output/field_writer.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <utility>
#include <variant>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_values.hpp"

namespace cosim::output {
namespace {

// Zero-padded so that the groups list in time order wherever names are sorted.
std::string step_name(std::uint64_t window) {
  char text[24];
  std::snprintf(text, sizeof text, "%06llu", static_cast<unsigned long long>(window));
  return text;
}

bool has_attributes(const field::FieldFrame& frame) {
  return std::any_of(frame.point_sets.begin(), frame.point_sets.end(),
                     [](const field::PointSet& p) { return !p.attributes.empty(); });
}

// `cells`: how many cells' values each field holds (the grid's, or none when the values
// come in blocks).
void check_frame(const field::FieldFrame& frame, const std::string& participant, std::size_t cells) {
  for (const std::string& problem : {field::grid_problem(frame.grid), field::point_sets_problem(frame.point_sets)})
    if (!problem.empty()) throw ObjectError("fields of " + participant + ": " + problem);
  for (const field::CellField& f : frame.fields) {
    if (f.components < 1 || f.values.size() != cells * static_cast<std::size_t>(f.components))
      throw ObjectError("field " + f.name + " of " + participant + ": " + std::to_string(f.values.size()) +
                        " values do not fit " + (cells > 0 ? "the grid" : "a frame whose values come in blocks"));
    if (f.name == kPointSetGroup && !frame.point_sets.empty())
      throw ObjectError("field " + f.name + " of " + participant +
                        ": the step's group of that name holds the point sets");
    if (f.name == kPointAttributeGroup && has_attributes(frame))
      throw ObjectError("field " + f.name + " of " + participant +
                        ": the step's group of that name holds the point sets' attributes");
  }
}

// A series without steps on the participant's grid: its shape is what a later frame's grid
// is compared with, as the grid is written once.
XdmfSeries series_of(const std::string& participant, const field::Grid& grid) {
  XdmfSeries s{participant, "/fields/" + participant + "/grid", {}, {}};
  if (const auto* p = std::get_if<field::PolyhedralGrid>(&grid))
    s.polyhedra = {p->cells, p->vertices.size() / 3, p->topology.size()};
  else
    s.cells = std::get<field::RectilinearGrid>(grid).cells();
  return s;
}

bool same_grid(const XdmfSeries& a, const XdmfSeries& b) { return a.cells == b.cells && a.polyhedra == b.polyhedra; }

// The cells part of a field's dataset shape, slowest first.
std::vector<hsize_t> cell_dims(const XdmfSeries& s) {
  if (s.polyhedra.cells > 0) return {s.polyhedra.cells};
  return {s.cells[2], s.cells[1], s.cells[0]};
}

void write_grid(hid_t participant_group, const field::Grid& grid) {
  Handle group = create_group(participant_group, "grid");
  if (const auto* p = std::get_if<field::PolyhedralGrid>(&grid)) {
    write_array(group.get(), "vertices", {p->vertices.size() / 3, 3}, p->vertices.data());
    write_array(group.get(), "topology", {p->topology.size()}, p->topology.data());
    // Readers (and resume()) then need not walk the topology to size the fields.
    write_attribute(group.get(), "cells", std::uint64_t{p->cells});
    return;
  }
  const auto& nodes = std::get<field::RectilinearGrid>(grid).nodes;
  for (std::size_t a = 0; a < 3; ++a)
    write_array(group.get(), std::string(1, "xyz"[a]), {nodes[a].size()}, nodes[a].data());
}

// The set's attributes beside its points: (n) for one component, (n, c) for c, int64 if integer.
void write_point_attributes(hid_t group, const field::PointSet& p, XdmfPointSet& entry) {
  if (p.attributes.empty()) return;
  Handle set = create_group(group, p.name);
  const hsize_t n = p.points.size() / 3;
  for (const field::PointAttribute& a : p.attributes) {
    std::vector<hsize_t> dims{n};
    if (a.components > 1) dims.push_back(static_cast<hsize_t>(a.components));
    if (a.integer) {
      // Exact: field::point_sets_problem() has bounded them by 2^53.
      const std::vector<std::int64_t> whole(a.values.begin(), a.values.end());
      write_array(set.get(), a.name, dims, whole.data());
    } else {
      write_array(set.get(), a.name, dims, a.values.data());
    }
    entry.attributes.push_back({a.name, a.components, a.integer});
  }
}

void write_point_sets(hid_t step, const field::FieldFrame& frame, XdmfStep& entry) {
  if (frame.point_sets.empty()) return;
  Handle points = create_group(step, kPointSetGroup);
  Handle attributes = has_attributes(frame) ? create_group(step, kPointAttributeGroup) : Handle();
  for (const field::PointSet& p : frame.point_sets) {
    write_array(points.get(), p.name, {p.points.size() / 3, 3}, p.points.data());
    entry.point_sets.push_back({p.name, p.points.size() / 3});
    write_point_attributes(attributes.get(), p, entry.point_sets.back());
  }
}

// The point sets of a step already in the file, in name order, their attributes too.
std::vector<XdmfPointSet> stored_point_sets(hid_t step) {
  std::vector<XdmfPointSet> sets;
  Handle points = open_group(step, kPointSetGroup);
  // Without attributes the name may be a cell field's.
  const bool attributes = has_link(step, kPointAttributeGroup) && is_group(step, kPointAttributeGroup);
  Handle all = attributes ? open_group(step, kPointAttributeGroup) : Handle();
  for (const std::string& name : link_names(points.get())) {
    XdmfPointSet set{name, array_dims(points.get(), name).at(0)};
    if (attributes && has_link(all.get(), name)) {
      Handle group = open_group(all.get(), name);
      for (const std::string& a : link_names(group.get())) {
        const auto dims = array_dims(group.get(), a);
        set.attributes.push_back({a, dims.size() > 1 ? static_cast<int>(dims[1]) : 1, integer_array(group.get(), a)});
      }
    }
    sets.push_back(std::move(set));
  }
  return sets;
}

// The series of a grid already in the file, as series_of() described it when it was written.
XdmfSeries stored_series(hid_t participant_group, const std::string& participant) {
  XdmfSeries s{participant, "/fields/" + participant + "/grid", {}, {}};
  Handle grid = open_group(participant_group, "grid");
  if (has_link(grid.get(), "topology")) {
    s.polyhedra = {read_attribute<std::uint64_t>(grid.get(), "cells"), array_dims(grid.get(), "vertices").at(0),
                   array_dims(grid.get(), "topology").at(0)};
  } else {
    for (std::size_t a = 0; a < 3; ++a) s.cells[a] = array_dims(grid.get(), std::string(1, "xyz"[a])).at(0) - 1;
  }
  return s;
}

}  // namespace

FieldWriter::FieldWriter(std::filesystem::path h5_path) : h5_path_(std::move(h5_path)) {}

std::pair<Handle, XdmfStep> FieldWriter::open_step(hid_t file, const std::string& participant, std::uint64_t window,
                                                   double time, const field::FieldFrame& frame) {
  Handle fields = open_or_create_group(file, "fields");
  Handle group = open_or_create_group(fields.get(), participant);
  const XdmfSeries shape = series_of(participant, frame.grid);
  const auto [it, first] = series_.try_emplace(participant, shape);
  if (first && !has_link(group.get(), "grid")) write_grid(group.get(), frame.grid);
  if (!same_grid(it->second, shape)) throw ObjectError("fields of " + participant + ": the grid changed");
  const std::string name = step_name(window);
  Handle step = create_group(group.get(), name);
  write_attribute(step.get(), "time", time);
  return {std::move(step), XdmfStep{"/fields/" + participant + "/" + name, time, {}}};
}

void FieldWriter::write(hid_t file, const std::string& participant, std::uint64_t window, double time,
                        const field::FieldFrame& frame) {
  check_frame(frame, participant, field::cell_count(frame.grid));
  auto [step, entry] = open_step(file, participant, window, time, frame);
  const XdmfSeries& series = series_.at(participant);
  for (const field::CellField& f : frame.fields) {
    std::vector<hsize_t> dims = cell_dims(series);
    if (f.components > 1) dims.push_back(static_cast<hsize_t>(f.components));
    write_array(step.get(), f.name, dims, f.values.data());
    entry.fields.push_back({f.name, f.components});
  }
  write_point_sets(step.get(), frame, entry);
  series_.at(participant).steps.push_back(std::move(entry));
}

void FieldWriter::write(hid_t file, const std::string& participant, std::uint64_t window, double time,
                        const field::FieldFrame& frame, const std::function<void(const BlockSink&)>& blocks) {
  const auto* grid = std::get_if<field::RectilinearGrid>(&frame.grid);
  if (!grid) throw ObjectError("fields of " + participant + ": blocks of cells need a rectilinear grid");
  check_frame(frame, participant, 0);
  auto [step, entry] = open_step(file, participant, window, time, frame);
  const std::array<std::size_t, 3> cells = grid->cells();
  for (const field::CellField& f : frame.fields) {
    std::vector<hsize_t> dims = cell_dims(series_.at(participant));
    if (f.components > 1) dims.push_back(static_cast<hsize_t>(f.components));
    create_array(step.get(), f.name, dims);
    entry.fields.push_back({f.name, f.components});
  }
  // One bit a cell: the datasets are not filled beforehand, so every cell must be written
  // exactly once.
  std::vector<bool> written(field::cell_count(frame.grid), false);
  std::size_t count = 0;
  // Clang before 16, the fuzz preset's, cannot capture a structured binding in a lambda.
  const auto step_id = step.get();
  blocks([&](const field::CellBlock& b) {
    if (const std::string problem = field::block_problem(b, cells, frame.fields); !problem.empty())
      throw ObjectError("fields of " + participant + ": " + problem);
    for (std::size_t z = b.lo[2]; z < b.hi[2]; ++z)
      for (std::size_t y = b.lo[1]; y < b.hi[1]; ++y)
        for (std::size_t x = b.lo[0]; x < b.hi[0]; ++x) {
          const std::size_t c = (z * cells[1] + y) * cells[0] + x;
          if (written[c])
            throw ObjectError("fields of " + participant + ": cell (" + std::to_string(x) + ", " + std::to_string(y) +
                              ", " + std::to_string(z) + ") in two blocks");
          written[c] = true;
          ++count;
        }
    if ((b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]) == 0) return;
    for (const field::CellField& f : b.fields) {
      std::vector<hsize_t> start{b.lo[2], b.lo[1], b.lo[0]};
      std::vector<hsize_t> extent{b.hi[2] - b.lo[2], b.hi[1] - b.lo[1], b.hi[0] - b.lo[0]};
      if (f.components > 1) {
        start.push_back(0);
        extent.push_back(static_cast<hsize_t>(f.components));
      }
      write_block(step_id, f.name, start, extent, f.values.data());
    }
  });
  if (count != written.size())
    throw ObjectError("fields of " + participant + ": blocks of " + std::to_string(count) + " cells for a grid of " +
                      std::to_string(written.size()));
  write_point_sets(step.get(), frame, entry);
  series_.at(participant).steps.push_back(std::move(entry));
}

void FieldWriter::resume(hid_t file, std::uint64_t next_window) {
  if (!has_link(file, "fields")) return;
  Handle fields = open_group(file, "fields");
  for (const std::string& participant : link_names(fields.get())) {
    Handle group = open_group(fields.get(), participant);
    XdmfSeries series = stored_series(group.get(), participant);
    const std::size_t scalar_rank = cell_dims(series).size();
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
      XdmfStep entry{"/fields/" + participant + "/" + name, read_attribute<double>(step.get(), "time"), {}};
      for (const std::string& field : link_names(step.get())) {
        // A cell field may have a group's name in a step without point sets (or attributes).
        if (field == kPointSetGroup && is_group(step.get(), field)) {
          entry.point_sets = stored_point_sets(step.get());
          continue;
        }
        if (field == kPointAttributeGroup && is_group(step.get(), field)) continue;  // read with the sets
        const auto dims = array_dims(step.get(), field);
        entry.fields.push_back({field, dims.size() > scalar_rank ? static_cast<int>(dims.back()) : 1});
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
