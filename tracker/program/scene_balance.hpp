// How the ranks' particle loads are kept even (participants.tracker.options.balance),
// optional, as SPARTA's `fix balance` does:
//
//   balance:
//     every: 10        # steps between checks; 0: never re-partition. Default 10
//     threshold: 1.2   # re-partition when the most particles a rank holds exceed the
//                      # mean by this factor. Default 1.2, at least 1
//
// On one rank nothing is checked. A re-partition weights every cell by its particles
// (Simulation::step, tracker/parallel/README.md).
#pragma once

#include "coupler/scene/reader.hpp"
#include "tracker/step/gas_setup.hpp"

namespace cosim::tracker::program {

step::Balance read_balance(const scene::Reader& options);

}  // namespace cosim::tracker::program
