#include "tracker/parallel/migration.hpp"

#include <climits>
#include <map>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace cosim::tracker {
namespace {

// The swarm's own record (swarm.hpp): float velocities cross as they are stored.
struct Record {
  double x[3];
  float v[3];
  Index cell;
};
static_assert(sizeof(Record) == 40);

// Two tags, alternating with the round: ranks are at most one migration apart.
constexpr int kMigrationTags[2] = {7301, 7302};

int bytes_count(std::size_t n) {
  if (n > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("a rank sends more than 2 GB of particles in one step");
  return static_cast<int>(n);
}

}  // namespace

std::size_t record_bytes(int objects) { return sizeof(Record) + static_cast<std::size_t>(objects) * sizeof(csg::State); }

void pack(const Swarm& swarm, std::size_t i, std::span<std::byte> record) {
  const Particle p = swarm.particle(i);
  const Record r{{p.x[0], p.x[1], p.x[2]},
                 {static_cast<float>(p.v[0]), static_cast<float>(p.v[1]), static_cast<float>(p.v[2])},
                 p.cell};
  std::memcpy(record.data(), &r, sizeof r);
  const std::span<const csg::State> states = swarm.states(i);
  std::memcpy(record.data() + sizeof r, states.data(), states.size_bytes());
}

void unpack(std::span<const std::byte> records, Swarm& swarm) {
  const std::size_t size = record_bytes(swarm.objects());
  if (records.size() % size != 0)
    throw std::invalid_argument("unpack: " + std::to_string(records.size()) + " bytes are not whole records of " +
                                std::to_string(size));
  std::vector<csg::State> states(static_cast<std::size_t>(swarm.objects()));
  for (std::size_t at = 0; at < records.size(); at += size) {
    Record r;
    std::memcpy(&r, records.data() + at, sizeof r);
    std::memcpy(states.data(), records.data() + at + sizeof r, states.size() * sizeof(csg::State));
    swarm.add({{r.x[0], r.x[1], r.x[2]}, {r.v[0], r.v[1], r.v[2]}, r.cell}, states);
  }
}

std::size_t migrate(Swarm& swarm, std::span<const int> owner, const Ranks& ranks, std::uint64_t round) {
  if (ranks.size() == 1) return 0;
  const int me = ranks.rank();
  const std::size_t size = record_bytes(swarm.objects());
  const auto owner_of = [&](std::size_t i) { return owner[static_cast<std::size_t>(swarm.cell(i))]; };

  // One buffer per rank sent to, in rank order.
  std::map<int, std::vector<std::byte>> out;
  std::size_t left = 0;
  for (std::size_t i = 0; i < swarm.size(); ++i)
    if (const int r = owner_of(i); r != me) {
      std::vector<std::byte>& to = out[r];
      to.resize(to.size() + size);
      pack(swarm, i, std::span(to).last(size));
      ++left;
    }
  swarm.remove_if([&](std::size_t i) { return owner_of(i) != me; });

  // NBX: synchronous sends complete only once received; a rank whose sends are all received
  // enters a non-blocking barrier and keeps receiving until every rank is in it.
  const int tag = kMigrationTags[round % 2];
  for (const auto& [rank, bytes] : out) bytes_count(bytes.size());  // every size checked before a send is posted
  std::vector<MPI_Request> sends;
  for (auto& [rank, bytes] : out) {
    sends.emplace_back();
    MPI_Issend(bytes.data(), bytes_count(bytes.size()), MPI_BYTE, rank, tag, ranks.comm(), &sends.back());
  }
  MPI_Request barrier = MPI_REQUEST_NULL;
  // Unpacked by sender once all have come, not as they arrive: a cell's particles then
  // stand in the same order in every run, and so draw the same random numbers.
  std::map<int, std::vector<std::byte>> in;
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
  for (const auto& [rank, bytes] : in) unpack(bytes, swarm);
  return left;
}

}  // namespace cosim::tracker
