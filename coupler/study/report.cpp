#include "coupler/study/report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace cosim::study {
namespace {

namespace fs = std::filesystem;

std::string number(std::optional<double> v, const char* format = "{:.8g}") {
  return v && std::isfinite(*v) ? fmt::format(fmt::runtime(format), *v) : "";
}

// Quoted when it holds a comma or a quote (list values, expressions).
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::optional<double> error_of(const Quantity& q, std::size_t level) {
  if (!q.values[level] || !q.reference) return std::nullopt;
  return *q.values[level] - *q.reference;
}

std::string error_header(const Results& r, const Quantity& q) {
  return q.against_extrapolate ? "value − extrapolate" : fmt::format("value − level {}", r.levels.size());
}

std::string table(const Results& r, const Quantity& q) {
  std::vector<std::string> header{"level"};
  header.insert(header.end(), r.keys.begin(), r.keys.end());
  header.insert(header.end(), {"value", error_header(r, q), "p", "wall s", "CPU s", "peak MB"});
  std::string out = fmt::format("| {} |\n|{}\n", fmt::join(header, " | "),
                                fmt::join(std::vector<std::string>(header.size(), "---|"), ""));
  for (std::size_t k = 0; k < r.levels.size(); ++k) {
    const Level& l = r.levels[k];
    std::vector<std::string> row{std::to_string(k + 1)};
    row.insert(row.end(), l.values.begin(), l.values.end());
    row.push_back(q.values[k] ? number(q.values[k]) : "— (" + q.problems[k] + ")");
    row.push_back(number(error_of(q, k), "{:.3g}"));
    row.push_back(q.estimates[k] ? number(q.estimates[k]->order, "{:.3g}") : "");
    row.push_back(fmt::format("{:.2f}", l.usage.wall_seconds));
    row.push_back(fmt::format("{:.2f}", l.usage.cpu_seconds));
    row.push_back(fmt::format("{:.0f}", l.usage.peak_mb));
    out += fmt::format("| {} |\n", fmt::join(row, " | "));
  }
  return out;
}

std::string findings(const Results& r, const Quantity& q) {
  const std::size_t n = r.levels.size();
  const auto& last = q.estimates[n - 1];
  std::string out;
  if (last && last->order) {
    out += fmt::format("- observed order p = {:.3g}, from levels {}, {} and {} (r21 = {:.4g}, r32 = {:.4g})\n",
                       *last->order, n - 2, n - 1, n, r.ratios.r[n - 2], r.ratios.r[n - 3]);
    out +=
        fmt::format("- extrapolate {:.8g} (Richardson, from levels {} and {} with p)\n", last->extrapolate, n - 1, n);
    out += fmt::format("- GCI_fine {:.3g}", last->gci_fine_abs);
    if (std::isfinite(last->gci_fine)) out += fmt::format(" ({:.3g} % of level {}'s value)", 100 * last->gci_fine, n);
    out += "\n";
  } else if (n == 2 && q.values[0] && q.values[1]) {
    const double d = *q.values[1] - *q.values[0];
    out += fmt::format("- two levels: the value changes by {:.3g}", d);
    if (*q.values[1] != 0) out += fmt::format(" ({:.3g} %)", 100 * d / std::abs(*q.values[1]));
    out += " from level 1 to level 2; a third level gives the order\n";
  }
  if (!q.finding.empty()) out += "- " + q.finding + "\n";
  return out;
}

}  // namespace

void write_csv(const Results& r, const fs::path& file) {
  std::ofstream out(file);
  std::vector<std::string> header{"quantity", "expression", "level"};
  header.insert(header.end(), r.keys.begin(), r.keys.end());
  header.insert(header.end(), {"value", "error", "p", "extrapolate", "gci", "wall_s", "cpu_s", "peak_mb"});
  std::vector<std::string> fields;
  for (const auto& h : header) fields.push_back(csv_field(h));
  out << fmt::format("{}\n", fmt::join(fields, ","));
  for (const Quantity& q : r.quantities) {
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
      const Level& l = r.levels[k];
      const auto& e = q.estimates[k];
      fields = {csv_field(q.measure.name), csv_field(q.measure.text), std::to_string(k + 1)};
      for (const auto& v : l.values) fields.push_back(csv_field(v));
      fields.push_back(number(q.values[k], "{:.17g}"));
      fields.push_back(number(error_of(q, k), "{:.17g}"));
      fields.push_back(e ? number(e->order, "{:.17g}") : "");
      fields.push_back(e && e->order ? number(e->extrapolate, "{:.17g}") : "");
      fields.push_back(e && e->order ? number(e->gci_fine_abs, "{:.17g}") : "");
      fields.push_back(fmt::format("{:.3f}", l.usage.wall_seconds));
      fields.push_back(fmt::format("{:.3f}", l.usage.cpu_seconds));
      fields.push_back(fmt::format("{:.1f}", l.usage.peak_mb));
      out << fmt::format("{}\n", fmt::join(fields, ","));
    }
  }
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

void write_costs_csv(const Results& r, const fs::path& file) {
  std::ofstream out(file);
  out << "level,program,share,peak_mb\n";
  for (std::size_t k = 0; k < r.levels.size(); ++k)
    for (const output::ProgramCost& p : r.levels[k].programs)
      out << fmt::format("{},{},{:.4f},{}\n", k + 1, csv_field(p.name), p.share,
                         p.peak_bytes >= 0 ? fmt::format("{:.1f}", p.peak_bytes / 1e6) : "");
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::string costs_section(const Results& r) {
  std::vector<std::string> programs;  // every program any level has, in its first order
  for (const Level& l : r.levels)
    for (const output::ProgramCost& p : l.programs)
      if (std::find(programs.begin(), programs.end(), p.name) == programs.end()) programs.push_back(p.name);
  if (programs.empty()) return {};
  std::vector<std::string> header{"level", "wall s"};
  header.insert(header.end(), programs.begin(), programs.end());
  std::string out = fmt::format(
      "\n## What each level cost\n\nEach program's share of the windows' wall time and its "
      "peak resident set (one process: a rank), from the run file; the coupler's share "
      "is what is left of the windows, the wire included.\n\n| {} |\n|{}\n",
      fmt::join(header, " | "), fmt::join(std::vector<std::string>(header.size(), "---|"), ""));
  for (std::size_t k = 0; k < r.levels.size(); ++k) {
    const Level& l = r.levels[k];
    std::vector<std::string> row{std::to_string(k + 1), fmt::format("{:.2f}", l.usage.wall_seconds)};
    for (const std::string& name : programs) {
      const auto p = std::find_if(l.programs.begin(), l.programs.end(),
                                  [&](const output::ProgramCost& c) { return c.name == name; });
      if (p == l.programs.end())
        row.emplace_back();
      else
        row.push_back(p->peak_bytes >= 0 ? fmt::format("{:.0f} %, {:.0f} MB", 100 * p->share, p->peak_bytes / 1e6)
                                         : fmt::format("{:.0f} %", 100 * p->share));
    }
    out += fmt::format("| {} |\n", fmt::join(row, " | "));
  }
  return out;
}

std::string quantity_sections(const Results& r, bool plots) {
  std::string out;
  for (const Quantity& q : r.quantities) {
    out += fmt::format("\n## {} = `{}`\n\n{}\n{}", q.measure.name, q.measure.text, table(r, q), findings(r, q));
    if (plots) out += "\n" + q.plot + "\n";
  }
  return out;
}

void write_report(const Results& r, const fs::path& file) {
  std::ofstream out(file);
  out << fmt::format("# Study of {}\n\n```\n{}\n```\n\n", r.scene.string(), r.command);
  out << fmt::format("{} levels, level 1 the coarsest, varying {}.", r.levels.size(), fmt::join(r.keys, ", "));
  if (!r.ratios.r.empty())
    out << fmt::format(" Refinement ratios from level to level: {:.4g}, from {}{}.", fmt::join(r.ratios.r, ", "),
                       r.keys.front(), r.keys.size() > 1 ? " (the first varied key)" : "");
  else
    out << " No refinement ratio, so no order: " << r.ratios.why_none << ".";
  out << (r.expected_order ? fmt::format(" Expected order: {:g}.", *r.expected_order) : std::string());
  if (!r.set.empty()) out << fmt::format(" Set on every level: {}.", fmt::join(r.set, ", "));
  out << "\n\n";
  out << (r.jobs > 1 ? fmt::format("Up to {} runs went side by side, each on its share of the cores, so their wall "
                                   "times are longer than alone.",
                                   r.jobs)
                     : std::string("The runs went one at a time."))
      << " CPU s is the user and system time of `cosim run` and every participant; peak MB the largest peak resident "
         "set among those processes. Each level's scene, run file and log are `level_<k>.yaml`, `.h5` and `.log` "
         "beside this report.\n";
  for (std::size_t k = 0; k < r.levels.size(); ++k)
    if (!r.levels[k].usage.ended.empty())
      out << fmt::format("\nLevel {} failed: `cosim run` {} (see {}).\n", k + 1, r.levels[k].usage.ended,
                         r.levels[k].log.filename().string());
  out << quantity_sections(r, true) << costs_section(r);
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace cosim::study
