#include "tracker/parallel/migration.hpp"

#include <climits>
#include <map>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace cosim::tracker::parallel {
namespace {

// The swarm's own record (swarm.hpp): float velocities cross as they are stored.
struct Record {
  double x[3];
  float v[3];
  Index cell;
};
static_assert(sizeof(Record) == 40);

// A move handed over: the particle as the move has it, and the rest of the move.
struct FlightRecord {
  double x[3];
  double v[3];
  double remaining;
  Index cell;
  std::int32_t entered;
  std::int32_t streak;
  std::int32_t unused = 0;
};
static_assert(sizeof(FlightRecord) == 72);

// Two tags, alternating with the round: ranks are at most one migration apart.

int bytes_count(std::size_t n) {
  if (n > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("a rank sends more than 2 GB of particles in one step");
  return static_cast<int>(n);
}

}  // namespace

// NBX: synchronous sends complete only once received; a rank whose sends are all received
// enters a non-blocking barrier and keeps receiving until every rank is in it. Returns what
// came, by sender: unpacked in that order, not as they arrive, a cell's particles stand in
// the same order in every run, and so draw the same random numbers.
Messages exchange(const Messages& out, const Ranks& ranks, std::uint64_t round) {
  const int tag = kMigrationTags[round % 2];
  for (const auto& [rank, bytes] : out) bytes_count(bytes.size());  // every size checked before a send is posted
  std::vector<MPI_Request> sends;
  for (const auto& [rank, bytes] : out) {
    sends.emplace_back();
    MPI_Issend(bytes.data(), bytes_count(bytes.size()), MPI_BYTE, rank, tag, ranks.comm(), &sends.back());
  }
  MPI_Request barrier = MPI_REQUEST_NULL;
  Messages in;
  for (bool sent = false;;) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, ranks.comm(), &arrived, &status);
    if (arrived) {
      int bytes = 0;
      MPI_Get_count(&status, MPI_BYTE, &bytes);
      std::vector<std::byte>& from = in[status.MPI_SOURCE];
      from.resize(static_cast<std::size_t>(bytes));
      MPI_Recv(from.data(), bytes, MPI_BYTE, status.MPI_SOURCE, tag, ranks.comm(), MPI_STATUS_IGNORE);
    }
    int done = 0;
    if (!sent) {
      MPI_Testall(static_cast<int>(sends.size()), sends.data(), &done, MPI_STATUSES_IGNORE);
      if (done) {
        MPI_Ibarrier(ranks.comm(), &barrier);
        sent = true;
      }
    } else {
      MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
      if (done) break;
    }
  }
  return in;
}

namespace {

// Appends `record` (a record, then the states) to the message for `rank`.
template <typename R>
void append(Messages& out, int rank, const R& record, std::span<const csg::State> states) {
  std::vector<std::byte>& to = out[rank];
  const std::size_t at = to.size();
  to.resize(at + sizeof record + states.size_bytes());
  std::memcpy(to.data() + at, &record, sizeof record);
  // Without obstacles there are no states, and memcpy of a null pointer is undefined.
  if (!states.empty()) std::memcpy(to.data() + at + sizeof record, states.data(), states.size_bytes());
}

// Calls take(record, states) for each whole record of `records`.
template <typename R, typename Take>
void for_each_record(std::span<const std::byte> records, int objects, const Take& take) {
  const std::size_t size = sizeof(R) + static_cast<std::size_t>(objects) * sizeof(csg::State);
  if (records.size() % size != 0)
    throw std::invalid_argument("unpack: " + std::to_string(records.size()) + " bytes are not whole records of " +
                                std::to_string(size));
  std::vector<csg::State> states(static_cast<std::size_t>(objects));
  for (std::size_t at = 0; at < records.size(); at += size) {
    R r;
    std::memcpy(&r, records.data() + at, sizeof r);
    if (!states.empty()) std::memcpy(states.data(), records.data() + at + sizeof r, states.size() * sizeof(csg::State));
    take(r, std::span<const csg::State>(states));
  }
}

Record record_of(const tracking::Particle& p, const Numbering& numbering) {
  return {{p.x[0], p.x[1], p.x[2]},
          {static_cast<float>(p.v[0]), static_cast<float>(p.v[1]), static_cast<float>(p.v[2])},
          numbering.global(p.cell)};
}

}  // namespace

Index Numbering::local(Index global) const {
  if (cells == nullptr) return global;
  const Index c = cells->local(global);
  if (c < 0) throw std::logic_error("a particle in cell " + std::to_string(global) + ", which this rank does not have");
  return c;
}

namespace {

// Adds the particle of every record (as migrate() sends them) to the swarm, bit for bit.
void unpack(std::span<const std::byte> records, tracking::Swarm& swarm, const Numbering& numbering) {
  for_each_record<Record>(records, swarm.objects(), [&](const Record& r, std::span<const csg::State> states) {
    swarm.add({{r.x[0], r.x[1], r.x[2]}, {r.v[0], r.v[1], r.v[2]}, numbering.local(r.cell)}, states);
  });
}

}  // namespace

std::size_t migrate(tracking::Swarm& swarm, const Owners& owner, const Ranks& ranks, std::uint64_t round,
                    const Numbering& numbering) {
  if (ranks.size() == 1) return 0;
  const int me = ranks.rank();
  const auto owner_of = [&](std::size_t i) { return owner(numbering.global(swarm.cell(i))); };
  Messages out;
  std::size_t left = 0;
  for (std::size_t i = 0; i < swarm.size(); ++i)
    if (const int r = owner_of(i); r != me) {
      append(out, r, record_of(swarm.particle(i), numbering), swarm.states(i));
      ++left;
    }
  swarm.remove_if([&](std::size_t i) { return owner_of(i) != me; });
  for (const auto& [rank, bytes] : exchange(out, ranks, round)) unpack(bytes, swarm, numbering);
  return left;
}

std::size_t migrate(tracking::Handover& handover, const Owners& owner, const Ranks& ranks, std::uint64_t round,
                    const Numbering& numbering) {
  if (ranks.size() == 1) return 0;
  Messages out;
  for (std::size_t i = 0; i < handover.size(); ++i) {
    const tracking::Particle& p = handover.particle(i);
    const tracking::Flight& f = handover.flight(i);
    const Index cell = numbering.global(p.cell);
    const FlightRecord r{{p.x[0], p.x[1], p.x[2]}, {p.v[0], p.v[1], p.v[2]}, f.remaining, cell, f.entered, f.streak};
    append(out, owner(cell), r, handover.states(i));
  }
  const std::size_t left = handover.size();
  handover.clear();
  for (const auto& [rank, bytes] : exchange(out, ranks, round))
    for_each_record<FlightRecord>(
        bytes, handover.objects(), [&](const FlightRecord& r, std::span<const csg::State> states) {
          handover.add({{r.x[0], r.x[1], r.x[2]}, {r.v[0], r.v[1], r.v[2]}, numbering.local(r.cell)}, states,
                       {r.remaining, r.entered, r.streak});
        });
  return left;
}

}  // namespace cosim::tracker::parallel
