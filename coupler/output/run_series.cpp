#include "coupler/output/run_series.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/record_shape.hpp"

namespace cosim::output {
namespace {

struct Spec {
  const char* name;
  hsize_t columns;
  hid_t (*type)();
};

constexpr Spec kCoupling[] = {{"window", 1, &native_type<std::uint64_t>},
                              {"time", 1, &native_type<double>},
                              {"iterations", 1, &native_type<int>},
                              {"residual", 1, &native_type<double>},
                              {"wall_seconds", 1, &native_type<double>}};
enum CouplingIndex { kWindow, kTime, kIterations, kResidual, kWallSeconds };

constexpr Spec kParticipant[] = {{"wall_seconds", 1, &native_type<double>},
                                 {"substeps", 1, &native_type<double>},
                                 {"field_bytes", 1, &native_type<double>}};
enum ParticipantIndex { kParticipantWallSeconds, kSubsteps, kFieldBytes };

constexpr Spec kBodyTime{"time", 1, &native_type<double>};
// A body's series past `time` are column slices of its row in WindowRecord poses/forces.
struct Slice {
  Spec spec;
  bool of_forces;
  std::size_t offset;
};
constexpr Slice kBodySlices[] = {
    {{"position", 3, &native_type<double>}, false, 0}, {{"orientation", 4, &native_type<double>}, false, 3},
    {{"velocity", 3, &native_type<double>}, false, 7}, {{"angular_velocity", 3, &native_type<double>}, false, 10},
    {{"force", 3, &native_type<double>}, true, 0},     {{"torque", 3, &native_type<double>}, true, 3}};

Handle group(hid_t parent, const std::string& name, bool create) {
  return create ? create_group(parent, name) : open_group(parent, name);
}

Series series(hid_t group, const Spec& spec, bool create) {
  if (create) return Series::create(group, spec.name, spec.columns, spec.type());
  Series s = Series::open(group, spec.name);
  if (s.columns() != spec.columns) {
    throw ObjectError("series " + s.path() + " has " + std::to_string(s.columns()) + " columns, expected " +
                      std::to_string(spec.columns));
  }
  return s;
}

template <std::size_t N>
std::vector<Series> series_of(hid_t group, const Spec (&specs)[N], bool create) {
  std::vector<Series> out;
  for (const Spec& spec : specs) out.push_back(series(group, spec, create));
  return out;
}

double value_or_nan(const std::map<std::string, double>& values, const std::string& name) {
  const auto it = values.find(name);
  return it == values.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

}  // namespace

RunSeries RunSeries::create(hid_t file, const std::vector<std::string>& bodies,
                            const std::vector<std::string>& participants) {
  return make(file, bodies, participants, Mode::Create);
}

RunSeries RunSeries::open(hid_t file, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& participants) {
  return make(file, bodies, participants, Mode::Open);
}

RunSeries RunSeries::make(hid_t file, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& participants, Mode mode) {
  const bool create = mode == Mode::Create;
  RunSeries rs;
  rs.participant_names_ = participants;

  Handle bodies_group = group(file, "bodies", create);
  for (const std::string& name : bodies) {
    Handle body = group(bodies_group.get(), name, create);
    Body b{series(body.get(), kBodyTime, create), {}};
    for (const Slice& slice : kBodySlices) b.slices.push_back(series(body.get(), slice.spec, create));
    rs.bodies_.push_back(std::move(b));
  }

  Handle coupling = group(file, "coupling", create);
  rs.coupling_ = series_of(coupling.get(), kCoupling, create);
  Handle participants_group = group(coupling.get(), "participants", create);
  for (const std::string& name : participants) {
    Handle p = group(participants_group.get(), name, create);
    rs.participants_.push_back(series_of(p.get(), kParticipant, create));
  }
  return rs;
}

hsize_t RunSeries::windows() const { return coupling_[kTime].rows(); }

void RunSeries::append(const WindowRecord& w) {
  const std::string what = "window " + std::to_string(w.window);
  check_body_rows(what, w.poses, w.forces, bodies_.size());
  check_participants(what, w.participant_wall_seconds, participant_names_);
  check_participants(what, w.participant_substeps, participant_names_);
  check_participants(what, w.participant_field_bytes, participant_names_);
  coupling_[kWindow].append(&w.window);
  coupling_[kTime].append(&w.time);
  coupling_[kIterations].append(&w.iterations);
  coupling_[kResidual].append(&w.residual);
  coupling_[kWallSeconds].append(&w.wall_seconds);

  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    bodies_[b].time.append(&w.time);
    for (std::size_t k = 0; k < std::size(kBodySlices); ++k) {
      const Slice& slice = kBodySlices[k];
      const double* row = slice.of_forces ? &w.forces[b * kForceWidth] : &w.poses[b * kPoseWidth];
      bodies_[b].slices[k].append(row + slice.offset);
    }
  }

  for (std::size_t p = 0; p < participants_.size(); ++p) {
    const std::string& name = participant_names_[p];
    const double wall = value_or_nan(w.participant_wall_seconds, name);
    const double substeps = value_or_nan(w.participant_substeps, name);
    participants_[p][kParticipantWallSeconds].append(&wall);
    participants_[p][kSubsteps].append(&substeps);
    const double field_bytes = value_or_nan(w.participant_field_bytes, name);
    participants_[p][kFieldBytes].append(&field_bytes);
  }
}

std::vector<Series*> RunSeries::all() {
  std::vector<Series*> out;
  for (Series& s : coupling_) out.push_back(&s);
  for (Body& b : bodies_) {
    out.push_back(&b.time);
    for (Series& s : b.slices) out.push_back(&s);
  }
  for (auto& p : participants_) {
    for (Series& s : p) out.push_back(&s);
  }
  return out;
}

void RunSeries::cut_after(double time) {
  const std::vector<double> times = coupling_[kTime].read_all();
  // Window end times and the checkpoint time come from the same arithmetic; the relative
  // slack only absorbs last-digit rounding, never a whole window.
  const double limit = time + 1e-12 * std::abs(time);
  hsize_t keep = 0;
  while (keep < times.size() && times[keep] <= limit) ++keep;
  for (Series* s : all()) s->truncate(keep);
}

}  // namespace cosim::output
