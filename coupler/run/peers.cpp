#include "coupler/run/peers.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <thread>

#include "coupler/protocol/messages.hpp"
#include "coupler/run/failure.hpp"
#include "coupler/run/interrupt.hpp"

namespace cosim::run {
namespace {

using clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kTick(50);  // how often liveness and Ctrl-C are checked

std::string text_of(const protocol::Message& m) {
  const auto* t = m.find(protocol::Tag::Text);
  return t ? t->bytes : std::string();
}

}  // namespace

std::string in_window(std::uint64_t k, double t0, double t1) {
  return fmt::format("in window {} (t = {} .. {} s)", k, t0, t1);
}

Peers::Peers(protocol::Server& server, std::chrono::milliseconds timeout, std::chrono::milliseconds heartbeat)
    : server_(server), timeout_(timeout), heartbeat_(heartbeat) {}

Peers::~Peers() {
  for (const auto& held : refusals_.held_back()) spdlog::warn("{}", held);
  for (auto& [name, p] : processes_) p.stop(std::chrono::milliseconds(0));
  launcher::end_orphans();
}

void Peers::start(const std::string& name, const std::vector<std::string>& command,
                  const std::map<std::string, std::string>& env) {
  const auto& p = processes_.emplace(name, launcher::Process(name, command, env)).first->second;
  spdlog::info("started {} (pid {}): {}", name, p.pid(), fmt::join(command, " "));
}

std::vector<std::string> Peers::names() const {
  std::vector<std::string> out;
  for (const auto& [name, p] : processes_) out.push_back(name);
  return out;
}

// A participant that cannot be reached has usually just died: say how, if it did.
void Peers::fail(const std::string& name, const std::string& problem, const std::string& when) {
  auto it = processes_.find(name);
  if (it != processes_.end()) {
    const auto deadline = clock::now() + std::chrono::milliseconds(200);
    while (!it->second.poll() && clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (auto ended = it->second.poll()) throw ParticipantFailure(name, *ended, when);
  }
  throw ParticipantFailure(name, problem, when);
}

void Peers::watch_connections() {
  for (const auto& refusal : server_.refusals())
    if (const auto line = refusals_.admit(refusal)) spdlog::warn("{}", *line);
  for (auto& name : server_.lost())
    if (processes_.contains(name)) lost_.insert(std::move(name));
}

std::string Peers::lost_connection() const {
  return fmt::format(
      "lost its connection to the coupler (closed, or no answer to heartbeats for {} s: "
      "coupling.heartbeat)",
      heartbeat_.count() / 1000.0);
}

void Peers::check_connections(const std::string& when) {
  for (const auto& name : lost_)
    if (!said_bye_.contains(name)) fail(name, lost_connection(), when);
}

void Peers::send(const std::string& name, protocol::Message m, const std::string& when) {
  try {
    server_.send(name, m);
  } catch (const protocol::PeerError& e) {
    watch_connections();
    fail(name, lost_.contains(name) ? lost_connection() : e.problem, when);
  }
}

std::map<std::string, protocol::Message> Peers::gather(const std::vector<std::string>& names, protocol::Type type,
                                                       const std::string& when) {
  std::set<std::string> pending(names.begin(), names.end());
  std::map<std::string, protocol::Message> replies;
  const auto deadline = clock::now() + timeout_;
  while (!pending.empty()) {
    if (interrupted()) throw Interrupted();
    std::optional<protocol::Message> m;
    try {
      m = server_.receive(kTick);
    } catch (const protocol::PeerError& e) {
      if (processes_.contains(e.peer)) fail(e.peer, e.problem, when);
      spdlog::warn("ignored a client calling itself '{}', which is not a participant of this run: it {}", e.peer,
                   e.problem);
    }
    watch_connections();
    if (m) {
      const auto& from = m->header.participant;
      if (!processes_.contains(from)) {
        spdlog::warn("ignored {} from '{}', which is not a participant of this run",
                     protocol::to_string(m->header.type), from);
        continue;
      }
      // What it reports is the cause; its exit right after is only the consequence.
      if (m->header.type == protocol::Type::Error)
        throw ParticipantFailure(from, "reported an error: " + text_of(*m), when);
      if (m->header.type != type)
        fail(from,
             fmt::format("sent {} while the coupler waited for {}", protocol::to_string(m->header.type),
                         protocol::to_string(type)),
             when);
      if (!pending.contains(from)) fail(from, fmt::format("sent {} twice", protocol::to_string(type)), when);
      pending.erase(from);
      if (type == protocol::Type::Bye) said_bye_.insert(from);
      replies.emplace(from, std::move(*m));
      continue;
    }
    for (auto& [name, p] : processes_)
      if (auto ended = p.poll(); ended && !said_bye_.contains(name)) throw ParticipantFailure(name, *ended, when);
    // Only now, with no message waiting: what a participant sent before its connection
    // ended has been read.
    check_connections(when);
    if (clock::now() > deadline)
      throw ParticipantFailure(*pending.begin(),
                               fmt::format("did not answer {} within {} s (coupling.timeout)",
                                           protocol::to_string(type), timeout_.count() / 1000.0),
                               when);
  }
  return replies;
}

std::map<std::string, protocol::Message> Peers::exchange(std::map<std::string, protocol::Message> requests,
                                                         protocol::Type reply, const std::string& when) {
  std::vector<std::string> names;
  for (auto& [name, m] : requests) {
    send(name, std::move(m), when);
    names.push_back(name);
  }
  return gather(names, reply, when);
}

std::map<std::string, double> Peers::peak_bytes() const {
  std::map<std::string, double> out;
  for (const auto& [name, p] : processes_) out[name] = p.peak_bytes();
  return out;
}

void Peers::stop_all() {
  const protocol::Message stop = protocol::messages::stop();
  for (const auto& name : names()) send(name, stop, "while stopping");
  gather(names(), protocol::Type::Bye, "while stopping");
  for (auto& [name, p] : processes_) p.stop(std::chrono::seconds(10));
}

void Peers::abort_all(const std::string& reason) {
  const protocol::Message abort = protocol::messages::abort(reason);
  for (auto& [name, p] : processes_) {
    if (p.poll()) continue;
    try {
      server_.send(name, abort);
    } catch (const protocol::ProtocolError&) {
      // It is being ended below anyway; a dead peer cannot take the message.
    }
  }
  for (auto& [name, p] : processes_) p.stop(std::chrono::seconds(2));
}

}  // namespace cosim::run
