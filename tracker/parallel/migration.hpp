// Particles that crossed into another rank's cells go to that rank: each as one record of
// bytes (its stored 40 bytes, then its logical state per obstacle), all of a step's for one
// rank in one message. Only ranks that exchange particles talk (mostly the owners of
// neighbouring cells): a sparse exchange by the NBX protocol (Hoefler, Siebert & Lumsdaine,
// "Scalable communication protocols for dynamic sparse data exchange", PPoPP 2010), whose
// cost does not grow with the rank count as an all-to-all's does. Records carry the whole
// mesh's cell numbers, so a rank that has only its part of the mesh (mesh/part.hpp) takes
// them in its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "tracker/mesh/part.hpp"
#include "tracker/parallel/owners.hpp"
#include "tracker/parallel/ranks.hpp"
#include "tracker/tracking/handover.hpp"

namespace cosim::tracker::parallel {

// A rank's cell numbers against the whole mesh's: the identity when it has the whole mesh.
struct Numbering {
  const mesh::Mesh* part = nullptr;
  const mesh::PartCells* cells = nullptr;  // the part's numbers back
  Index global(Index cell) const { return part ? part->global_cell(cell) : cell; }
  // std::logic_error if the part does not have the cell (a particle sent to the wrong rank).
  Index local(Index global) const;
};

// Messages of bytes by rank, in rank order.
using Messages = std::map<int, std::vector<std::byte>>;
// Collective, the sparse exchange itself: `out` to their ranks, and what came here by sender.
// `round`: as for migrate().
Messages exchange(const Messages& out, const Ranks& ranks, std::uint64_t round);

// Collective: every particle whose cell (in the whole mesh) `owner` gives to another rank
// leaves the swarm for that rank, and what the others send here is appended. Returns how
// many left. Received particles are appended in the order of their senders' ranks. `round`
// counts the migrations on the communicator: a rank may start the next one before another
// has seen this one end, and the round's parity keeps their messages apart, so consecutive
// migrations on one communicator must differ in parity (one Decomposition at a time per
// communicator, or a collective between two that start their counts afresh).
std::size_t migrate(tracking::Swarm& swarm, const Owners& owner, const Ranks& ranks, std::uint64_t round,
                    const Numbering& numbering = {});
// The same for moves handed over (each particle in another rank's cell, with the rest of
// its move): the handover then holds what the others sent here.
std::size_t migrate(tracking::Handover& handover, const Owners& owner, const Ranks& ranks, std::uint64_t round,
                    const Numbering& numbering);

}  // namespace cosim::tracker::parallel
