#include "output/xdmf.hpp"

#include "output/text.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace cosim::output {
namespace {

void data_item(std::ostream& out, const std::string& dims, const std::string& h5_file,
               const std::string& dataset, const char* indent, const char* type = "Float") {
  out << indent << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type
      << "\" Precision=\"8\" Format=\"HDF\">" << xml_escaped(h5_file + ":" + dataset) << "</DataItem>\n";
}

// The grid's topology and geometry; returns the dimensions of a cell field.
std::string write_grid(std::ostream& out, const std::string& h5_file, const XdmfSeries& s) {
  if (const XdmfPolyhedra& p = s.polyhedra; p.cells > 0) {
    out << "        <Topology TopologyType=\"Mixed\" NumberOfElements=\"" << p.cells << "\">\n";
    data_item(out, std::to_string(p.topology_size), h5_file, s.grid_group + "/topology", "          ", "Int");
    out << "        </Topology>\n        <Geometry GeometryType=\"XYZ\">\n";
    data_item(out, std::to_string(p.vertices) + " 3", h5_file, s.grid_group + "/vertices", "          ");
    out << "        </Geometry>\n";
    return std::to_string(p.cells);
  }
  const auto& n = s.cells;
  // XDMF orders dimensions slowest first: z, y, x.
  const std::string nodes = std::to_string(n[2] + 1) + " " + std::to_string(n[1] + 1) + " " + std::to_string(n[0] + 1);
  out << "        <Topology TopologyType=\"3DRectMesh\" Dimensions=\"" << nodes << "\"/>\n"
      << "        <Geometry GeometryType=\"VXVYVZ\">\n";
  for (int a = 0; a < 3; ++a)
    data_item(out, std::to_string(n[static_cast<std::size_t>(a)] + 1), h5_file,
              s.grid_group + "/" + "xyz"[a], "          ");
  out << "        </Geometry>\n";
  return std::to_string(n[2]) + " " + std::to_string(n[1]) + " " + std::to_string(n[0]);
}

void write_step(std::ostream& out, const std::string& h5_file, const XdmfSeries& s, const XdmfStep& step) {
  out << "      <Grid Name=\"" << xml_escaped(step.group) << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << exact(step.time) << "\"/>\n";
  const std::string cells = write_grid(out, h5_file, s);
  for (const XdmfField& f : step.fields) {
    const bool vector = f.components > 1;
    out << "        <Attribute Name=\"" << xml_escaped(f.name) << "\" AttributeType=\"" << (vector ? "Vector" : "Scalar")
        << "\" Center=\"Cell\">\n";
    data_item(out, vector ? cells + " " + std::to_string(f.components) : cells, h5_file, step.group + "/" + f.name,
              "          ");
    out << "        </Attribute>\n";
  }
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
    for (const XdmfStep& step : s.steps) write_step(out, h5_file, s, step);
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
