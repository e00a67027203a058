#include "run/peers.hpp"

#include <algorithm>
#include <set>

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "run/failure.hpp"
#include "run/interrupt.hpp"

namespace cosim::run {
namespace {

using clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kTick(50);  // how often liveness and Ctrl-C are checked

std::string text_of(const protocol::Message& m) {
  const auto* t = m.find(protocol::Tag::Text);
  return t ? t->bytes : std::string();
}

}  // namespace

Peers::Peers(protocol::Server& server, std::chrono::milliseconds timeout)
    : server_(server), timeout_(timeout) {}

Peers::~Peers() {
  for (auto& [name, p] : processes_) p.stop(std::chrono::milliseconds(0));
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

void Peers::send(const std::string& name, protocol::Message m) {
  m.header.participant = name;
  server_.send(name, m);
}

std::map<std::string, protocol::Message> Peers::gather(const std::vector<std::string>& names,
                                                       protocol::Type type,
                                                       std::uint64_t window) {
  std::set<std::string> pending(names.begin(), names.end());
  std::map<std::string, protocol::Message> replies;
  const auto deadline = clock::now() + timeout_;
  while (!pending.empty()) {
    if (interrupted()) throw Interrupted();
    std::optional<protocol::Message> m;
    try {
      m = server_.receive(kTick);
    } catch (const protocol::ProtocolError& e) {
      throw ParticipantFailure(*pending.begin(), window,
                               std::string("sent a message the coupler cannot read (") +
                                   e.what() + ")");
    }
    if (m) {
      const auto& from = m->header.participant;
      if (m->header.type == protocol::Type::Error)
        throw ParticipantFailure(from, window, "reported an error: " + text_of(*m));
      if (m->header.type != type || !pending.contains(from))
        throw ParticipantFailure(from, window,
                                 std::string("sent ") + protocol::to_string(m->header.type) +
                                     " while the coupler waited for " +
                                     protocol::to_string(type));
      pending.erase(from);
      if (type == protocol::Type::Bye) said_bye_.insert(from);
      replies.emplace(from, std::move(*m));
      continue;
    }
    for (auto& [name, p] : processes_)
      if (auto ended = p.poll(); ended && !said_bye_.contains(name))
        throw ParticipantFailure(name, window, *ended);
    if (clock::now() > deadline)
      throw ParticipantFailure(*pending.begin(), window,
                               "did not answer " + std::string(protocol::to_string(type)) +
                                   " within " + std::to_string(timeout_.count() / 1000.0) +
                                   " s (coupling.timeout)");
  }
  return replies;
}

std::map<std::string, protocol::Message> Peers::exchange(
    std::map<std::string, protocol::Message> requests, protocol::Type reply,
    std::uint64_t window) {
  std::vector<std::string> names;
  for (auto& [name, m] : requests) {
    send(name, std::move(m));
    names.push_back(name);
  }
  return gather(names, reply, window);
}

void Peers::stop_all(std::uint64_t window) {
  protocol::Message stop;
  stop.header.type = protocol::Type::Stop;
  for (const auto& name : names()) send(name, stop);
  gather(names(), protocol::Type::Bye, window);
  for (auto& [name, p] : processes_) p.stop(std::chrono::seconds(10));
}

void Peers::abort_all(const std::string& reason) {
  protocol::Message abort;
  abort.header.type = protocol::Type::Abort;
  abort.arrays.push_back(protocol::Array::text(reason));
  for (auto& [name, p] : processes_) {
    if (p.poll()) continue;
    try {
      send(name, abort);
    } catch (const std::exception&) {
      // It is being ended below anyway; a dead peer cannot take the message.
    }
  }
  for (auto& [name, p] : processes_) p.stop(std::chrono::seconds(2));
}

}  // namespace cosim::run
