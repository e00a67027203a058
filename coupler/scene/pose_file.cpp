#include "coupler/scene/pose_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "coupler/output/last_poses.hpp"
#include "coupler/scene/sections.hpp"

namespace cosim::scene {
namespace {

namespace fs = std::filesystem;

// The widths a line may have: position, with velocity, with orientation, with both.
constexpr std::array widths{3, 6, 7, 10};
constexpr const char* widths_text = "3, 6, 7 or 10 numbers (x,y,z[,qw,qx,qy,qz][,vx,vy,vz])";

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::optional<double> number(std::string_view s) {
  double value = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (error != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

FilePose pose_of(const Reader& r, const std::vector<double>& v, std::string where) {
  FilePose p;
  p.where = std::move(where);
  std::copy_n(v.begin(), 3, p.position.begin());
  std::size_t next = 3;
  if (v.size() >= 7) {
    Quat q{};
    std::copy_n(v.begin() + 3, 4, q.begin());
    if (const auto problem = make_unit(q)) r.fail("file", p.where + ": qw,qx,qy,qz " + *problem);
    p.orientation = q;
    next = 7;
  }
  if (v.size() > next) {
    Vec3 velocity{};
    std::copy_n(v.begin() + static_cast<std::ptrdiff_t>(next), 3, velocity.begin());
    p.velocity = velocity;
  }
  return p;
}

std::vector<FilePose> csv_poses(const Reader& r, const fs::path& file) {
  std::ifstream in(file);
  if (!in) r.fail("file", "cannot open " + file.string());
  std::vector<FilePose> poses;
  std::size_t width = 0;  // of the first line of numbers; every line must have it
  bool first = true;      // the first line that is neither blank nor a comment may be a header
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const std::string_view content = trim(text);
    if (content.empty() || content.front() == '#') continue;
    const std::vector<std::string_view> fields = split(content);
    // A header has no number in it; a first line with a typo in one number is no header.
    const bool header =
        first && std::none_of(fields.begin(), fields.end(), [](std::string_view f) { return number(f).has_value(); });
    first = false;
    if (header) continue;
    const std::string where = fmt::format("line {}", line);
    std::vector<double> values;
    for (const std::string_view field : fields) {
      const std::optional<double> value = number(field);
      if (!value) r.fail("file", fmt::format("{}: '{}' is not a number", where, field));
      values.push_back(*value);
    }
    if (std::find(widths.begin(), widths.end(), static_cast<int>(values.size())) == widths.end())
      r.fail("file", fmt::format("{}: {} numbers; expected {}", where, values.size(), widths_text));
    if (width == 0) width = values.size();
    if (values.size() != width)
      r.fail("file", fmt::format("{}: {} numbers where the lines before have {}", where, values.size(), width));
    poses.push_back(pose_of(r, values, where));
  }
  if (poses.empty()) r.fail("file", "no bodies in the file (no line of numbers)");
  return poses;
}

std::vector<FilePose> run_file_poses(const Reader& r, const fs::path& file) {
  std::vector<output::LastPose> last;
  try {
    last = output::last_poses(file);
  } catch (const std::runtime_error& e) {
    r.fail("file", e.what());
  }
  if (last.empty()) r.fail("file", "the run file has no bodies");
  std::vector<FilePose> poses;
  for (const output::LastPose& l : last) {
    std::vector<double> values(l.position.begin(), l.position.end());
    values.insert(values.end(), l.orientation.begin(), l.orientation.end());
    poses.push_back(pose_of(r, values, fmt::format("body '{}'", l.body)));
  }
  return poses;
}

}  // namespace

std::vector<FilePose> read_pose_file(const Reader& r, const fs::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".csv") return csv_poses(r, file);
  if (extension == ".h5" || extension == ".hdf5") return run_file_poses(r, file);
  r.fail("file", "expected a .csv table or a cosim run file (.h5)");
}

}  // namespace cosim::scene
