#include "tracker/program/polyhedra_xdmf.hpp"

#include <sstream>

#include "output/text.hpp"

namespace cosim::tracker {
namespace {

constexpr std::int64_t kPolyhedron = 16;  // XDMF's type code in a Mixed topology

std::string item(const std::string& dims, const char* type, const std::string& where) {
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"8\" Format=\"HDF\">" + where +
         "</DataItem>";
}

}  // namespace

std::vector<std::int64_t> mixed_topology(const Mesh& mesh) {
  std::vector<std::int64_t> out;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    out.push_back(kPolyhedron);
    out.push_back(mesh.cell_faces[c + 1] - mesh.cell_faces[c]);
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f) {
      out.push_back(mesh.vertex_count(f));
      for (Index k = mesh.face_vertex_begin[f]; k < mesh.face_vertex_begin[f + 1]; ++k)
        out.push_back(mesh.face_vertex_index[k]);
    }
  }
  return out;
}

std::string polyhedra_xdmf(const std::string& h5_file, const PolyhedraSeries& s) {
  // The file name is the user's; group and field names are ours, without XML specials.
  const std::string at = output::xml_escaped(h5_file) + ":";
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
      << "    <Grid Name=\"" << s.name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const output::XdmfStep& step : s.steps) {
    out << "      <Grid Name=\"" << step.group << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << output::exact(step.time) << "\"/>\n"
        << "        <Topology TopologyType=\"Mixed\" NumberOfElements=\"" << s.cells << "\">\n          "
        << item(std::to_string(s.topology_size), "Int", at + s.mesh_group + "/topology") << "\n        </Topology>\n"
        << "        <Geometry GeometryType=\"XYZ\">\n          "
        << item(std::to_string(s.vertices) + " 3", "Float", at + s.mesh_group + "/vertices")
        << "\n        </Geometry>\n";
    for (const output::XdmfField& f : step.fields) {
      const bool vector = f.components > 1;
      const std::string dims = std::to_string(s.cells) + (vector ? " " + std::to_string(f.components) : "");
      out << "        <Attribute Name=\"" << f.name << "\" AttributeType=\"" << (vector ? "Vector" : "Scalar")
          << "\" Center=\"Cell\">\n          " << item(dims, "Float", at + step.group + "/" + f.name)
          << "\n        </Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out.str();
}

}  // namespace cosim::tracker
