#include "coupler/estimate/cost_store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace cosim::estimate {
namespace fs = std::filesystem;
namespace {

// Enough for every shipped scene a few times over and a calibration, small enough to read
// in milliseconds before each run.
constexpr std::size_t kMaxRecords = 400;

void emit(YAML::Emitter& out, const Units& units) {
  out << YAML::Flow << YAML::BeginMap;
  for (const auto& [unit, n] : units) out << YAML::Key << unit << YAML::Value << n;
  out << YAML::EndMap;
}

Units units(const YAML::Node& node) {
  Units out;
  if (node)
    for (const auto& entry : node) out[entry.first.as<std::string>()] = entry.second.as<double>();
  return out;
}

}  // namespace

fs::path CostStore::default_path() {
  if (const char* file = std::getenv("COSIM_COST_FILE"); file != nullptr && *file != '\0') return file;
  char host[256] = "host";
  gethostname(host, sizeof host - 1);
  fs::path dir;
  if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache != nullptr && *cache != '\0')
    dir = cache;
  else if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    dir = fs::path(home) / ".cache";
  else
    dir = fs::temp_directory_path();
  return dir / "cosim" / (std::string("cost-") + host + ".yaml");
}

CostStore CostStore::load(const fs::path& path) {
  CostStore store;
  store.path_ = path;
  if (!fs::exists(path)) return store;
  try {
    for (const auto& r : YAML::LoadFile(path.string())["runs"]) {
      RunRecord record;
      record.scene = r["scene"].as<std::string>();
      record.build = r["build"].as<std::string>();
      record.calibration = r["calibration"].as<bool>(false);
      record.windows = r["windows"].as<double>();
      record.iterations = r["iterations"].as<double>();
      record.wall_seconds = r["wall_seconds"].as<double>();
      record.disk_bytes = r["disk_bytes"].as<double>(0.0);
      for (const auto& p : r["programs"]) {
        Observation o;
        o.per_step = units(p.second["per_step"]);
        o.held = units(p.second["held"]);
        o.steps = p.second["steps"].as<double>();
        o.seconds = p.second["seconds"].as<double>();
        o.peak_bytes = p.second["peak_bytes"].as<double>(0.0);
        record.programs[p.first.as<std::string>()] = o;
      }
      store.records_.push_back(std::move(record));
    }
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path.string() + ": cannot read the measured costs (" + e.what() +
                             "); remove the file and run `cosim calibrate`");
  }
  return store;
}

void CostStore::save() const {
  YAML::Emitter out;
  out << YAML::Comment("What runs measured on this host: cosim fits its cost estimates to it (cosim calibrate)");
  out << YAML::BeginMap << YAML::Key << "runs" << YAML::Value << YAML::BeginSeq;
  for (const auto& r : records_) {
    out << YAML::BeginMap;
    out << YAML::Key << "scene" << YAML::Value << r.scene << YAML::Key << "build" << YAML::Value << r.build;
    out << YAML::Key << "calibration" << YAML::Value << r.calibration;
    out << YAML::Key << "windows" << YAML::Value << r.windows << YAML::Key << "iterations" << YAML::Value
        << r.iterations;
    out << YAML::Key << "wall_seconds" << YAML::Value << r.wall_seconds << YAML::Key << "disk_bytes" << YAML::Value
        << r.disk_bytes;
    out << YAML::Key << "programs" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, o] : r.programs) {
      out << YAML::Key << name << YAML::Value << YAML::BeginMap;
      out << YAML::Key << "per_step" << YAML::Value;
      emit(out, o.per_step);
      out << YAML::Key << "held" << YAML::Value;
      emit(out, o.held);
      out << YAML::Key << "steps" << YAML::Value << o.steps << YAML::Key << "seconds" << YAML::Value << o.seconds;
      out << YAML::Key << "peak_bytes" << YAML::Value << o.peak_bytes << YAML::EndMap;
    }
    out << YAML::EndMap << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  fs::create_directories(path_.parent_path().empty() ? fs::path(".") : path_.parent_path());
  const fs::path temporary = path_.string() + "." + std::to_string(getpid());
  std::ofstream file(temporary);
  file << out.c_str() << "\n";
  file.close();
  if (!file) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(temporary.string() + ": cannot write the measured costs");
  }
  fs::rename(temporary, path_);
}

void CostStore::update(const fs::path& path, const std::function<void(CostStore&)>& change) {
  fs::create_directories(path.parent_path().empty() ? fs::path(".") : path.parent_path());
  const std::string lock_path = path.string() + ".lock";
  const int lock = open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock < 0) throw std::runtime_error(lock_path + ": cannot open the lock of the measured costs");
  // Released when the descriptor closes, also if change() or save() throws.
  const std::unique_ptr<int, void (*)(int*)> closer(new int(lock), [](int* fd) {
    close(*fd);
    delete fd;
  });
  while (flock(lock, LOCK_EX) != 0)
    if (errno != EINTR) throw std::runtime_error(lock_path + ": cannot lock the measured costs");
  CostStore store = load(path);
  change(store);
  store.save();
}

void CostStore::add(RunRecord record) {
  records_.push_back(std::move(record));
  if (records_.size() > kMaxRecords) records_.erase(records_.begin(), records_.end() - kMaxRecords);
}

void CostStore::drop_calibration() {
  std::erase_if(records_, [](const RunRecord& r) { return r.calibration; });
}

std::vector<Observation> CostStore::observations(const std::string& program, const std::string& build) const {
  std::vector<Observation> same, any;
  for (const auto& r : records_) {
    const auto it = r.programs.find(program);
    if (it == r.programs.end()) continue;
    any.push_back(it->second);
    if (r.build == build) same.push_back(it->second);
  }
  return same.empty() ? any : same;
}

const RunRecord* CostStore::last_run_of(const std::string& scene) const {
  for (auto it = records_.rbegin(); it != records_.rend(); ++it)
    if (it->scene == scene) return &*it;
  return nullptr;
}

}  // namespace cosim::estimate
