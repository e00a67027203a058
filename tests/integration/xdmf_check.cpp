#include "tests/integration/xdmf_check.hpp"

#include <iterator>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace cosim::testing {
namespace {

std::string attribute(const std::string& tag, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(tag, m, std::regex(" " + name + "=\"([^\"]*)\""))) return "";
  return m[1];
}

// Element names open and close in order; processing instructions stand alone.
void check_nesting(const std::string& text) {
  std::vector<std::string> open;
  const std::regex tag("<(/?)([A-Za-z?!][^ />]*)[^>]*?(/?)>");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), tag); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::string name = m[2];
    if (name[0] == '?' || name[0] == '!' || m[3] == "/") continue;
    if (m[1] == "") {
      open.push_back(name);
    } else if (open.empty() || open.back() != name) {
      throw std::runtime_error("unexpected </" + name + ">");
    } else {
      open.pop_back();
    }
  }
  if (!open.empty()) throw std::runtime_error("<" + open.back() + "> is not closed");
  if (text.find("<Xdmf") == std::string::npos) throw std::runtime_error("no Xdmf element");
}

XdmfDataItem data_item(const std::string& attributes, const std::string& where) {
  XdmfDataItem d;
  std::istringstream dims(attribute(attributes, "Dimensions"));
  for (std::size_t n = 0; dims >> n;) d.dims.push_back(n);
  const std::size_t colon = where.find(':');
  if (colon == std::string::npos) throw std::runtime_error("DataItem without file:dataset: " + where);
  d.file = where.substr(0, colon);
  d.dataset = where.substr(colon + 1);
  return d;
}

// The Attribute elements of `block`, each of one DataItem.
std::vector<XdmfAttribute> attributes(const std::string& block) {
  std::vector<XdmfAttribute> out;
  const std::regex element("<Attribute([^>]*)>\\s*<DataItem([^>]*)>([^<]*)</DataItem>\\s*</Attribute>");
  for (auto it = std::sregex_iterator(block.begin(), block.end(), element); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out.push_back({attribute(m[1], "Name"), attribute(m[1], "AttributeType"), attribute(m[1], "Center"),
                   attribute(m[2], "NumberType"), data_item(m[2], m[3])});
  }
  return out;
}

std::vector<XdmfPolyvertex> polyvertices(const std::string& text) {
  std::vector<XdmfPolyvertex> out;
  const std::regex grid(
      "<Grid Name=\"([^\"]*)\"[^>]*>\\s*<Topology TopologyType=\"Polyvertex\"([^>]*)/>"
      "\\s*<Geometry GeometryType=\"XYZ\">\\s*<DataItem([^>]*)>([^<]*)</DataItem>\\s*</Geometry>"
      "((?:\\s*<Attribute[^>]*>\\s*<DataItem[^>]*>[^<]*</DataItem>\\s*</Attribute>)*)\\s*</Grid>");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), grid); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    XdmfPolyvertex p{m[1], std::stoul(attribute(m[2], "NumberOfElements")), data_item(m[3], m[4]), attributes(m[5])};
    if (p.points.dims != std::vector<std::size_t>{p.elements, 3})
      throw std::runtime_error("Polyvertex grid " + p.name + " of " + std::to_string(p.elements) +
                               " elements has points of other Dimensions");
    for (const XdmfAttribute& a : p.attributes)
      if (a.center != "Node" || a.item.dims.empty() || a.item.dims[0] != p.elements)
        throw std::runtime_error("attribute " + a.name + " of Polyvertex grid " + p.name +
                                 " is not node-centred with a row per point");
    out.push_back(p);
  }
  const std::regex topology("TopologyType=\"Polyvertex\"");
  if (out.size() != static_cast<std::size_t>(std::distance(std::sregex_iterator(text.begin(), text.end(), topology),
                                                           std::sregex_iterator())))
    throw std::runtime_error("a Polyvertex topology without its XYZ geometry of one DataItem");
  return out;
}

}  // namespace

XdmfContents read_xdmf(const std::string& text) {
  check_nesting(text);
  XdmfContents c;
  const std::regex time("<Time ([^>]*)/>");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), time); it != std::sregex_iterator(); ++it)
    c.times.push_back(std::stod(attribute(" " + (*it)[1].str(), "Value")));
  const std::regex item("<DataItem([^>]*)>([^<]*)</DataItem>");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), item); it != std::sregex_iterator(); ++it)
    c.items.push_back(data_item((*it)[1], (*it)[2]));
  c.polyvertices = polyvertices(text);
  return c;
}

}  // namespace cosim::testing
