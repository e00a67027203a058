// Particles that crossed into another rank's cells go to that rank: each as one record of
// bytes (its stored 40 bytes, then its logical state per obstacle), all of a step's in one
// MPI_Alltoallv.
#pragma once

#include <cstddef>
#include <span>

#include "tracker/parallel/ranks.hpp"
#include "tracker/tracking/swarm.hpp"

namespace cosim::tracker {

// Bytes of one particle's record with `objects` obstacles.
std::size_t record_bytes(int objects);
// Particle i of the swarm into `record` (record_bytes(swarm.objects()) long).
void pack(const Swarm& swarm, std::size_t i, std::span<std::byte> record);
// Adds the particle of every record in `records` (whole records, as pack() wrote them) to
// the swarm, bit for bit as it was packed.
void unpack(std::span<const std::byte> records, Swarm& swarm);

// Collective: every particle whose cell `owner` gives to another rank leaves the swarm
// for that rank, and what the others send here is appended. Returns how many left.
std::size_t migrate(Swarm& swarm, std::span<const int> owner, const Ranks& ranks);

}  // namespace cosim::tracker
