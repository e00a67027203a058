// The participant side of a run, the same for every program: handshake, then answer the
// coupler until Stop. Rollback for implicit schemes happens here (state saved at the
// window start and restored when the window is repeated), so solvers need not know.
#pragma once

#include "coupler/participant/solver.hpp"
#include "coupler/protocol/client.hpp"

namespace cosim::participant {

// Returns the process exit code. Solver exceptions are reported to the coupler (which
// names this participant to the user) and end the process with 1. `ranks`: the MPI size
// announced in Hello (the solver spreads its calls over them itself, mpi_team.hpp).
// Field requests are answered with solver.fields() (field_message.hpp).
// A participant that needs fields names the ones it uses (solver.wanted_fields()) in Text
// arrays of its Ready.
int run_participant(protocol::Client& client, Solver& solver, std::uint32_t provides, std::uint32_t needs,
                    std::uint32_t ranks = 1);

// An Advance's inputs: the rows of each tag in order (start, then end), and the field
// frame after them (field_message.hpp). ProtocolError for Poses or Forces arrays whose
// rows are not a body's (protocol::kPoseWidth, kForceWidth) and for fields that are not a
// frame.
Inputs inputs_of(protocol::Message advance);

}  // namespace cosim::participant
