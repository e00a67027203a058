#include "tracker/parallel/migration.hpp"

#include <climits>
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

std::size_t migrate(Swarm& swarm, std::span<const int> owner, const Ranks& ranks) {
  if (ranks.size() == 1) return 0;
  const auto n = static_cast<std::size_t>(ranks.size());
  const int me = ranks.rank();
  const std::size_t size = record_bytes(swarm.objects());
  const auto owner_of = [&](std::size_t i) { return owner[static_cast<std::size_t>(swarm.cell(i))]; };

  std::vector<std::size_t> leaving(n, 0);
  for (std::size_t i = 0; i < swarm.size(); ++i) ++leaving[static_cast<std::size_t>(owner_of(i))];
  leaving[static_cast<std::size_t>(me)] = 0;
  std::vector<int> send_bytes(n), send_at(n), receive_bytes(n), receive_at(n);
  std::size_t total = 0;
  for (std::size_t r = 0; r < n; ++r) {
    send_at[r] = bytes_count(total);
    send_bytes[r] = bytes_count(leaving[r] * size);
    total += leaving[r] * size;
  }
  std::vector<std::byte> out(total);
  std::vector<std::size_t> filled(send_at.begin(), send_at.end());
  for (std::size_t i = 0; i < swarm.size(); ++i)
    if (const auto r = static_cast<std::size_t>(owner_of(i)); r != static_cast<std::size_t>(me)) {
      pack(swarm, i, std::span(out).subspan(filled[r], size));
      filled[r] += size;
    }
  swarm.remove_if([&](std::size_t i) { return owner_of(i) != me; });

  MPI_Alltoall(send_bytes.data(), 1, MPI_INT, receive_bytes.data(), 1, MPI_INT, ranks.comm());
  std::size_t received = 0;
  for (std::size_t r = 0; r < n; ++r) {
    receive_at[r] = bytes_count(received);
    received += static_cast<std::size_t>(receive_bytes[r]);
  }
  std::vector<std::byte> in(received);
  MPI_Alltoallv(out.data(), send_bytes.data(), send_at.data(), MPI_BYTE, in.data(), receive_bytes.data(),
                receive_at.data(), MPI_BYTE, ranks.comm());
  unpack(in, swarm);
  return total / size;
}

}  // namespace cosim::tracker
