// The participant side of a run, the same for every program: handshake, then answer the
// coupler until Stop. Rollback for implicit schemes happens here (state saved at the
// window start and restored when the window is repeated), so solvers need not know.
#pragma once

#include "participant/solver.hpp"
#include "protocol/client.hpp"

namespace cosim::participant {

// Returns the process exit code. Solver exceptions are reported to the coupler (which
// names this participant to the user) and end the process with 1. `ranks`: the MPI size
// announced in Hello (the solver spreads its calls over them itself, mpi_team.hpp).
// Field requests are answered with solver.fields() (field_message.hpp).
int run_participant(protocol::Client& client, Solver& solver, std::uint32_t provides,
                    std::uint32_t needs, std::uint32_t ranks = 1);

}  // namespace cosim::participant
