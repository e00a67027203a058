#include "tracker/dsmc/species.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

namespace cosim::tracker::dsmc {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const YAML::Mark& mark, const std::string& key,
                       const std::string& value, const std::string& problem) {
  std::ostringstream out;
  out << file.string();
  if (!mark.is_null()) out << ':' << mark.line + 1;
  out << ": ";
  if (!key.empty()) out << "key '" << key << "'";
  if (!value.empty()) out << " = '" << value << "'";
  if (!key.empty() || !value.empty()) out << ": ";
  out << problem;
  throw SpeciesError(out.str());
}

struct Reader {
  const std::filesystem::path& file;
  const YAML::Node& node;
  std::string prefix;

  double number(const std::string& key, double lo, double hi, bool lo_open, const std::string& range) const {
    const YAML::Node v = node[key];
    if (!v) fail(file, node.Mark(), prefix + key, "", "missing");
    if (!v.IsScalar()) fail(file, v.Mark(), prefix + key, "", "must be a number");
    const std::string text = v.Scalar();
    double x = 0;
    try {
      std::size_t used = 0;
      x = std::stod(text, &used);
      if (used != text.size()) throw std::invalid_argument(text);
    } catch (const std::exception&) {
      fail(file, v.Mark(), prefix + key, text, "not a number");
    }
    if (!std::isfinite(x) || x < lo || x > hi || (lo_open && x == lo))
      fail(file, v.Mark(), prefix + key, text, "must lie in " + range);
    return x;
  }
};

}  // namespace

const Species& SpeciesTable::at(const std::string& name) const& {
  const auto it = species_.find(name);
  if (it == species_.end()) {
    std::string known;
    for (const auto& [n, s] : species_) known += (known.empty() ? "" : ", ") + n;
    throw SpeciesError(file_.string() + ": no species '" + name + "' (the file has " + known + ")");
  }
  return it->second;
}

SpeciesTable read_species(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail(file, YAML::Mark::null_mark(), "", "", "cannot open the species file");
  YAML::Node root;
  try {
    root = YAML::Load(in);
  } catch (const YAML::ParserException& e) {
    fail(file, e.mark, "", "", "invalid YAML: " + e.msg);
  }
  if (!root.IsMap()) fail(file, root.Mark(), "", "", "expected a map with the key 'species'");
  for (const auto& kv : root)
    if (kv.first.Scalar() != "species") fail(file, kv.first.Mark(), kv.first.Scalar(), "", "unknown key");
  const YAML::Node list = root["species"];
  if (!list) fail(file, root.Mark(), "species", "", "missing");
  if (!list.IsMap() || list.size() == 0)
    fail(file, list.Mark(), "species", "", "must be a map of species name -> properties");

  static const std::array<const char*, 8> keys = {"mass",  "diameter_vhs", "diameter_vss",  "omega",
                                                  "alpha", "T_ref",        "viscosity_ref", "rotational_dof"};
  SpeciesTable table;
  table.file_ = file;
  for (const auto& kv : list) {
    const std::string name = kv.first.Scalar();
    const YAML::Node& node = kv.second;
    const std::string prefix = "species." + name + ".";
    if (!node.IsMap()) fail(file, node.Mark(), "species." + name, "", "must be a map of properties");
    if (table.species_.contains(name)) fail(file, kv.first.Mark(), "species." + name, "", "defined twice");
    for (const auto& p : node) {
      const std::string key = p.first.Scalar();
      bool known = false;
      for (const char* k : keys) known = known || key == k;
      if (!known)
        fail(file, p.first.Mark(), prefix + key, "",
             "unknown key (expected mass, diameter_vhs, diameter_vss, omega, alpha, T_ref, viscosity_ref, "
             "rotational_dof)");
    }
    const Reader r{file, node, prefix};
    const double inf = HUGE_VAL;
    Species s;
    s.name = name;
    s.mass = r.number("mass", 0, inf, true, "(0, inf) kg");
    s.diameter_vhs = r.number("diameter_vhs", 0, inf, true, "(0, inf) m");
    s.diameter_vss = r.number("diameter_vss", 0, inf, true, "(0, inf) m");
    s.omega = r.number("omega", 0.5, 1.0, false, "[0.5, 1]");
    s.alpha = r.number("alpha", 1.0, 2.0, false, "[1, 2]");
    s.T_ref = r.number("T_ref", 0, inf, true, "(0, inf) K");
    s.viscosity_ref = r.number("viscosity_ref", 0, inf, true, "(0, inf) Pa s");
    const double dof = r.number("rotational_dof", 0, 3, false, "{0, 2, 3}");
    if (dof != 0 && dof != 2 && dof != 3)
      fail(file, node["rotational_dof"].Mark(), prefix + "rotational_dof", node["rotational_dof"].Scalar(),
           "must be 0 (atoms), 2 (linear molecules) or 3");
    s.rotational_dof = static_cast<int>(dof);
    table.species_.emplace(name, s);
  }
  return table;
}

std::filesystem::path default_species_file() { return COSIM_DSMC_SPECIES_FILE; }

}  // namespace cosim::tracker::dsmc
