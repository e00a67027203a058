#include "coupler/output/xdmf.hpp"

#include "coupler/output/text.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace cosim::output {
namespace {

void data_item(std::ostream& out, const std::string& dims, const std::string& h5_file, const std::string& dataset,
               const std::string& pad, const char* type = "Float") {
  out << pad << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\"8\" Format=\"HDF\">"
      << xml_escaped(h5_file + ":" + dataset) << "</DataItem>\n";
}

// The grid's topology and geometry, indented by `pad`; returns the dimensions of a cell field.
std::string write_grid(std::ostream& out, const std::string& h5_file, const XdmfSeries& s, const std::string& pad) {
  const std::string inner = pad + "  ";
  if (const XdmfPolyhedra& p = s.polyhedra; p.cells > 0) {
    out << pad << "<Topology TopologyType=\"Mixed\" NumberOfElements=\"" << p.cells << "\">\n";
    data_item(out, std::to_string(p.topology_size), h5_file, s.grid_group + "/topology", inner, "Int");
    out << pad << "</Topology>\n" << pad << "<Geometry GeometryType=\"XYZ\">\n";
    data_item(out, std::to_string(p.vertices) + " 3", h5_file, s.grid_group + "/vertices", inner);
    out << pad << "</Geometry>\n";
    return std::to_string(p.cells);
  }
  const auto& n = s.cells;
  // XDMF orders dimensions slowest first: z, y, x.
  const std::string nodes = std::to_string(n[2] + 1) + " " + std::to_string(n[1] + 1) + " " + std::to_string(n[0] + 1);
  out << pad << "<Topology TopologyType=\"3DRectMesh\" Dimensions=\"" << nodes << "\"/>\n"
      << pad << "<Geometry GeometryType=\"VXVYVZ\">\n";
  for (int a = 0; a < 3; ++a)
    data_item(out, std::to_string(n[static_cast<std::size_t>(a)] + 1), h5_file, s.grid_group + "/" + "xyz"[a], inner);
  out << pad << "</Geometry>\n";
  return std::to_string(n[2]) + " " + std::to_string(n[1]) + " " + std::to_string(n[0]);
}

// XDMF's types by component count: ParaView takes a Vector for 3 components only.
const char* attribute_type(int components) {
  return components == 1 ? "Scalar" : components == 3 ? "Vector" : "Matrix";
}

// An Attribute of `count` (cells or points) rows at `center`, indented by `pad`.
void write_attribute(std::ostream& out, const std::string& h5_file, const XdmfField& f, const std::string& center,
                     const std::string& count, const std::string& dataset, const std::string& pad) {
  out << pad << "<Attribute Name=\"" << xml_escaped(f.name) << "\" AttributeType=\"" << attribute_type(f.components)
      << "\" Center=\"" << center << "\">\n";
  data_item(out, f.components > 1 ? count + " " + std::to_string(f.components) : count, h5_file, dataset, pad + "  ",
            f.integer ? "Int" : "Float");
  out << pad << "</Attribute>\n";
}

// The children of the step's cell grid, indented by `pad`: the grid and the step's cell fields.
void write_cells(std::ostream& out, const std::string& h5_file, const XdmfSeries& s, const XdmfStep& step,
                 const std::string& pad) {
  const std::string cells = write_grid(out, h5_file, s, pad);
  for (const XdmfField& f : step.fields)
    write_attribute(out, h5_file, f, "Cell", cells, step.group + "/" + f.name, pad);
}

// The set's Polyvertex grid with its attributes, indented by `pad`.
void write_point_set(std::ostream& out, const std::string& h5_file, const XdmfStep& step, const XdmfPointSet& p,
                     const std::string& pad) {
  const std::string n = std::to_string(p.points);
  out << pad << "<Grid Name=\"" << xml_escaped(p.name) << "\" GridType=\"Uniform\">\n"
      << pad << "  <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\"/>\n"
      << pad << "  <Geometry GeometryType=\"XYZ\">\n";
  data_item(out, n + " 3", h5_file, step.group + "/" + kPointSetGroup + "/" + p.name, pad + "    ");
  out << pad << "  </Geometry>\n";
  const std::string attributes = step.group + "/" + kPointAttributeGroup + "/" + p.name + "/";
  for (const XdmfField& a : p.attributes) write_attribute(out, h5_file, a, "Node", n, attributes + a.name, pad + "  ");
  out << pad << "</Grid>\n";
}

void write_step(std::ostream& out, const std::string& h5_file, const XdmfSeries& s, const XdmfStep& step,
                bool spatial) {
  const std::string time = "        <Time Value=\"" + exact(step.time) + "\"/>\n";
  if (!spatial) {
    out << "      <Grid Name=\"" << xml_escaped(step.group) << "\" GridType=\"Uniform\">\n" << time;
    write_cells(out, h5_file, s, step, "        ");
    out << "      </Grid>\n";
    return;
  }
  out << "      <Grid Name=\"" << xml_escaped(step.group) << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << time << "        <Grid Name=\"cells\" GridType=\"Uniform\">\n";
  write_cells(out, h5_file, s, step, "          ");
  out << "        </Grid>\n";
  for (const XdmfPointSet& p : step.point_sets)
    if (p.points > 0) write_point_set(out, h5_file, step, p, "        ");
  out << "      </Grid>\n";
}

}  // namespace

std::string xdmf_document(const std::string& h5_file, const std::vector<XdmfSeries>& series) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\">\n"
      << "  <Domain>\n";
  for (const XdmfSeries& s : series) {
    out << "    <Grid Name=\"" << xml_escaped(s.name) << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    const bool spatial =
        std::any_of(s.steps.begin(), s.steps.end(), [](const XdmfStep& step) { return !step.point_sets.empty(); });
    for (const XdmfStep& step : s.steps) write_step(out, h5_file, s, step, spatial);
    out << "    </Grid>\n";
  }
  out << "  </Domain>\n"
      << "</Xdmf>\n";
  return out.str();
}

void write_replacing(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path partial = path;
  partial += ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw std::runtime_error(partial.string() + ": cannot write");
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) throw std::runtime_error(path.string() + ": cannot replace: " + error.message());
}

}  // namespace cosim::output
