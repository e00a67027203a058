#include "coupler/run/session.hpp"

#include <spdlog/spdlog.h>
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "coupler/launcher/command.hpp"
#include "coupler/protocol/client.hpp"
#include "coupler/protocol/field_message.hpp"
#include "coupler/protocol/messages.hpp"
#include "coupler/run/failure.hpp"
#include "coupler/run/listening.hpp"
#include "coupler/run/progress.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/unused_materials.hpp"

namespace cosim::run {
namespace fs = std::filesystem;
namespace {

using clock = std::chrono::steady_clock;

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// A private folder for the ipc socket, removed when the run ends.
struct RunDirectory {
  RunDirectory() {
    std::string pattern = (fs::temp_directory_path() / "cosim-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a run folder");
    path = pattern;
  }
  ~RunDirectory() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  fs::path path;
};

// A participant's own fields are not its input (the tracker provides its samples for the
// run file), and frames of two others would have to be told apart on the wire.
std::string field_source(const scene::Scene& scene, const scene::Plan& plan, const scene::Participant& consumer) {
  std::vector<std::string> others;
  for (const auto& p : plan.start)
    if (p.name != consumer.name && scene::has(p.provides, scene::Data::Fields)) others.push_back(p.name);
  if (others.size() != 1)
    throw scene::SceneError(scene.file.string(), consumer.line, "participants." + consumer.name, "",
                            others.empty()
                                ? "needs fields, but no other participant provides them"
                                : "needs fields from one participant, but " + join(others) + " provide them");
  return others.front();
}

// The frame with only the `wanted` fields, in that order (all if none are named, and only
// then its point sets: a consumer that names fields uses those), copied out of the source's.
field::FieldFrame pick(const field::FieldFrame& frame, const std::vector<std::string>& wanted,
                       const std::string& source, const std::string& consumer, const std::string& when) {
  if (wanted.empty()) return frame;
  field::FieldFrame out{frame.grid, {}};
  for (const auto& name : wanted) {
    const auto f =
        std::find_if(frame.fields.begin(), frame.fields.end(), [&](const auto& field) { return field.name == name; });
    if (f == frame.fields.end())
      throw ParticipantFailure(source, "sends no field '" + name + "', which '" + consumer + "' needs", when);
    out.fields.push_back(*f);
  }
  return out;
}

}  // namespace

Session::Session(scene::Scene scene)
    : scene_(std::move(scene)), plan_(scene::plan_participants(scene_)), roles_(plan_.start) {
  for (const auto& p : plan_.start) {
    if (scene::has(p.needs, scene::Data::Fields)) field_source_[p.name] = field_source(scene_, plan_, p);
    commands_.push_back(launcher::participant_command(scene_, p, launcher::own_directory()));
  }
}

void Session::attach(output::RunFile file, std::optional<output::Checkpoint> resume_from, bool progress) {
  file_.emplace(std::move(file));
  resume_ = std::move(resume_from);
  progress_ = progress;
}

void Session::execute() {
  announce();
  RunDirectory dir;
  auto listen = listening(scene_.coupling, roles_.all(), dir.path);
  const bool curve = listen.options.curve.has_value();
  const auto heartbeat = listen.options.heartbeat;
  std::optional<protocol::Server> server;
  try {
    server.emplace(listen.endpoint, std::move(listen.options));
  } catch (const protocol::ProtocolError& e) {
    if (scene_.coupling.interface.empty()) throw;
    throw std::runtime_error(scene_.file.string() + ": coupling.interface = " + scene_.coupling.interface + ": " +
                             e.what());
  }
  spdlog::info("listening on {}{}", server->endpoint(), curve ? " (CURVE, keys of this run)" : "");
  Peers peers(*server, std::chrono::milliseconds(static_cast<long>(scene_.coupling.timeout * 1000.0)), heartbeat);
  for (std::size_t i = 0; i < plan_.start.size(); ++i) {
    const auto& name = plan_.start[i].name;
    auto env = launcher::mpi_environment(!plan_.start[i].placement.local());
    env[protocol::kEndpointEnv] = server->endpoint();
    env[protocol::kParticipantEnv] = name;
    env[protocol::kHeartbeatEnv] = fmt::format("{}", scene_.coupling.heartbeat);
    env.merge(listen.environment[name]);
    peers.start(name, commands_[i], env);
  }
  try {
    handshake(peers);
    windows(peers);
    peers.stop_all();
    totals_.peak_bytes = peers.peak_bytes();
  } catch (const Interrupted&) {
    peers.abort_all("the coupler was interrupted");
    throw;
  } catch (const std::exception& e) {
    peers.abort_all(e.what());
    throw;
  }
}

void Session::announce() const {
  std::vector<std::string> effects, started;
  for (auto e : scene_.effects) effects.emplace_back(scene::to_string(e));
  for (const auto& p : plan_.start)
    started.push_back(p.name + " (provides " + scene::describe(p.provides) + ", needs " + scene::describe(p.needs) +
                      ")");
  spdlog::info("effects: {}", effects.empty() ? "none" : join(effects));
  spdlog::info("participants: {}", join(started));
  for (const auto& s : plan_.skipped) spdlog::info("not started: {}", s);
  spdlog::info("{} windows of {} s, {}", scene_.windows(), scene_.coupling.window,
               scene::to_string(scene_.coupling.scheme));
  for (const auto& w : scene::unused_materials(scene_)) spdlog::warn("{}", w);
}

std::uint64_t Session::first_window() const { return resume_ ? resume_->next_window : 0; }

double Session::window_start(std::uint64_t k) const { return static_cast<double>(k) * scene_.coupling.window; }

void Session::handshake(Peers& peers) {
  const auto w = first_window();
  const std::string when = "during start-up";
  for (const auto& [name, hello] : peers.gather(roles_.all(), protocol::Type::Hello, when)) {
    const auto& planned =
        *std::find_if(plan_.start.begin(), plan_.start.end(), [&](const auto& s) { return s.name == name; });
    // Hello says what a program can exchange; the scene decides what it will. A program
    // announces its roles before it has seen the scene, so the planned roles must only be
    // within what it can do (the rigid bodies can take forces even when no one sends any).
    const auto within = [](scene::DataSet planned, scene::DataSet offered) { return (planned & ~offered) == 0; };
    if (!within(planned.provides, hello.header.provides) || !within(planned.needs, hello.header.needs))
      throw ParticipantFailure(name,
                               "can provide " + scene::describe(hello.header.provides) + " and take " +
                                   scene::describe(hello.header.needs) + ", but the scene needs it to provide " +
                                   scene::describe(planned.provides) + " and take " + scene::describe(planned.needs),
                               when);
    if (static_cast<int>(hello.header.ranks) != planned.ranks)
      throw ParticipantFailure(name,
                               "runs on " + std::to_string(hello.header.ranks) + " ranks, the scene asks for " +
                                   std::to_string(planned.ranks),
                               when);
    if (hello.header.version < protocol::kVersion)
      spdlog::info("{} speaks protocol version {} (the coupler {}): answered in its version", name,
                   hello.header.version, protocol::kVersion);
  }

  // A resumed run starts from exactly what was committed: the participants' Ready answers
  // would recompute the forces from the committed poses, which in parallel schemes is not
  // what the committed forces were computed from.
  const auto b = static_cast<Eigen::Index>(scene_.bodies.size());
  current_ = resume_ ? Exchange{Eigen::Map<const Eigen::VectorXd>(resume_->poses.data(), b * kPoseSize),
                                Eigen::Map<const Eigen::VectorXd>(resume_->forces.data(), b * kForceSize),
                                Eigen::Map<const Eigen::VectorXd>(resume_->responses.data(),
                                                                  static_cast<Eigen::Index>(resume_->responses.size()))}
                     : Exchange{initial_poses(scene_), Eigen::VectorXd::Zero(b * kForceSize), {}};
  std::map<std::string, protocol::Message> inits;
  for (const auto& name : roles_.all()) {
    inits.emplace(name, protocol::messages::init(w, window_start(w), scene_.time.end, scene_.file.string(), scene_.text,
                                                 poses_array(current_.poses),
                                                 resume_ ? std::optional(resume_->states.at(name)) : std::nullopt));
  }
  const auto ready = peers.exchange(std::move(inits), protocol::Type::Ready, when);
  for (const auto& [name, source] : field_source_)
    for (const protocol::Array* field : ready.at(name).all(protocol::Tag::Text))
      wanted_fields_[name].push_back(field->bytes);
  committed_ = w;
  if (resume_) {
    checkpointed_ = w;
    return;
  }
  for (const auto& name : roles_.pose_providers)
    current_.poses = take(ready.at(name), protocol::Tag::Poses, b * kPoseSize, when);
  for (const auto& name : roles_.force_providers) {
    const protocol::Message& m = ready.at(name);
    current_.forces += take(m, protocol::Tag::Forces, b * kForceSize, when);
    if (m.find(protocol::Tag::Responses) == nullptr) continue;
    if (current_.responses.size() == 0) current_.responses = Eigen::VectorXd::Zero(b * kResponseSize);
    current_.responses += take(m, protocol::Tag::Responses, b * kResponseSize, when);
  }
  record(0, 0.0, WindowResult{current_, 0, 0.0, true, {}, {}, {}}, 0.0);
  write_fields(peers, 0);
  checkpoint(peers, 0);
}

void Session::windows(Peers& peers) {
  WindowRunner runner(peers, roles_, scene_.coupling);
  const auto n = scene_.windows();
  Progress progress(first_window(), n, scene_.time.end, progress_);
  for (auto k = first_window(); k < n; ++k) {
    const auto started = clock::now();
    const double t1 = window_start(k + 1);
    WindowResult r = runner.advance(k, window_start(k), t1, current_, forwarded_fields(peers, k));
    for (const auto& [name, bytes] : r.field_bytes) forwarded_bytes_ += bytes;
    count(r);
    if (!r.converged)
      spdlog::warn("window {} (t = {} s): not converged after {} iterations, residual {:.3g}", k, t1, r.iterations,
                   r.residual);
    const protocol::Message commit = protocol::messages::commit(k);
    for (const auto& name : roles_.all()) peers.send(name, commit, in_window(k, window_start(k), t1));
    current_ = r.end;
    committed_ = k + 1;
    const double wall = std::chrono::duration<double>(clock::now() - started).count();
    if (scene_.output.row_at(k + 1, n)) record(k + 1, t1, r, wall);
    write_fields(peers, k + 1);
    if (scene_.output.checkpoint_at(k + 1, n)) checkpoint(peers, k + 1);
    progress.update(k, t1, r.iterations);
  }
  progress.finish();
  if (!field_source_.empty() && n > first_window())
    spdlog::info("forwarded {:.0f} bytes of fields ({:.0f} per window)", forwarded_bytes_,
                 forwarded_bytes_ / static_cast<double>(n - first_window()));
}

void Session::count(const WindowResult& r) {
  totals_.windows += 1;
  totals_.iterations += r.iterations;
  for (const auto& [name, s] : r.wall_seconds) totals_.seconds[name] += s;
  for (const auto& [name, n] : r.substeps) totals_.steps[name] += n;
}

void Session::record(std::uint64_t window, double time, const WindowResult& r, double wall) {
  output::WindowRecord rec;
  rec.window = window;
  rec.time = time;
  rec.iterations = r.iterations;
  rec.residual = r.residual;
  rec.wall_seconds = wall;
  rec.poses.assign(r.end.poses.data(), r.end.poses.data() + r.end.poses.size());
  rec.forces.assign(r.end.forces.data(), r.end.forces.data() + r.end.forces.size());
  for (const auto& name : roles_.all()) {
    rec.participant_wall_seconds[name] = r.wall_seconds.contains(name) ? r.wall_seconds.at(name) : 0.0;
    rec.participant_substeps[name] = r.substeps.contains(name) ? r.substeps.at(name) : 0.0;
    rec.participant_field_bytes[name] = r.field_bytes.contains(name) ? r.field_bytes.at(name) : 0.0;
  }
  file_->append(rec);
}

std::map<std::string, field::FieldFrame> Session::request_fields(Peers& peers, const std::set<std::string>& providers,
                                                                 std::uint64_t window, const std::string& when) {
  std::map<std::string, protocol::Message> requests;
  for (const auto& name : providers)
    requests.emplace(name, protocol::messages::field_request(window, window_start(window)));
  std::map<std::string, field::FieldFrame> frames;
  for (auto& [name, m] : peers.exchange(std::move(requests), protocol::Type::Field, when)) {
    try {
      frames.emplace(name, protocol::field_frame(std::move(m)));
    } catch (const protocol::ProtocolError& e) {
      throw ParticipantFailure(name, e.what(), when);
    }
  }
  return frames;
}

void Session::write_fields(Peers& peers, std::uint64_t windows_done) {
  if (!scene_.output.fields_at(windows_done, scene_.windows())) return;
  std::set<std::string> providers;
  for (const auto& [name, provides] : roles_.provides)
    if (scene::has(provides, scene::Data::Fields)) providers.insert(name);
  if (providers.empty()) return;
  const double time = window_start(windows_done);
  const auto when = fmt::format("while writing fields at t = {} s", time);
  written_fields_ = {windows_done, request_fields(peers, providers, windows_done, when)};
  for (const auto& [name, frame] : written_fields_.frames)
    if (!frame.fields.empty()) file_->write_fields(name, windows_done, time, frame);
}

FieldArrays Session::forwarded_fields(Peers& peers, std::uint64_t window) {
  FieldArrays out;
  if (field_source_.empty()) return out;
  // A source that has just sent its fields for the run file at this instant is not asked again.
  const bool written = written_fields_.window == window;
  std::set<std::string> sources;
  for (const auto& [consumer, source] : field_source_)
    if (!written || !written_fields_.frames.contains(source)) sources.insert(source);
  const auto when = fmt::format("while taking the fields to forward at t = {} s", window_start(window));
  auto frames = request_fields(peers, sources, window, when);
  if (written) frames.insert(written_fields_.frames.begin(), written_fields_.frames.end());
  for (const auto& [consumer, source] : field_source_)
    out.emplace(consumer,
                protocol::field_arrays(pick(frames.at(source), wanted_fields_[consumer], source, consumer, when)));
  return out;
}

void Session::checkpoint(Peers& peers, std::uint64_t next_window) {
  std::map<std::string, protocol::Message> requests;
  for (const auto& name : roles_.all()) requests.emplace(name, protocol::messages::checkpoint(next_window));
  output::Checkpoint c;
  c.next_window = next_window;
  c.time = window_start(next_window);
  c.poses.assign(current_.poses.data(), current_.poses.data() + current_.poses.size());
  c.forces.assign(current_.forces.data(), current_.forces.data() + current_.forces.size());
  c.responses.assign(current_.responses.data(), current_.responses.data() + current_.responses.size());
  const auto when = fmt::format("while checkpointing at t = {} s", c.time);
  for (auto& [name, m] : peers.exchange(std::move(requests), protocol::Type::State, when)) {
    const auto* state = m.find(protocol::Tag::State);
    if (state == nullptr) throw ParticipantFailure(name, "sent State without its state", when);
    c.states[name] = state->values;
  }
  file_->write_checkpoint(c);
  checkpointed_ = next_window;
}

}  // namespace cosim::run
