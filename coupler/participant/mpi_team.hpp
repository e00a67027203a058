// A participant on several MPI ranks. Rank 0 alone talks to the coupler (or runs the
// standalone loop), through a LeadSolver: before each call on its own share of the work it
// tells the other ranks which call follows and with what arguments, and they make the same
// call on theirs (follow()). The solver's calls are collective, so the ranks stay in step.
//
// The state crosses as one array on rank 0: [ranks, size on rank 0, ..., size on rank
// ranks-1, then each rank's values in turn]. A checkpoint restores only on as many ranks
// as wrote it; any other count is refused with both numbers named.
#pragma once

#include <mpi.h>

#include <functional>

#include "coupler/participant/solver.hpp"

namespace cosim::participant {

class LeadSolver final : public Solver {
 public:
  LeadSolver(Solver& local, MPI_Comm comm);
  ~LeadSolver() override;  // releases the followers if finish() was not called

  Outputs initialise(const scene::Scene& scene, const std::string& name, const std::vector<PoseRow>& poses,
                     const std::vector<double>& state) override;
  Outputs advance(const Window& w, const Inputs& in) override;
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;
  // Each rank's share gathered by the solver's own fields() (rank 0 gets the whole frame):
  // rank 0's frame alone is returned, so rank 0 alone fills the point sets, with every
  // rank's points. A frame forwarded in an Advance reaches every rank whole, point sets too.
  field::FieldFrame fields() const override;
  std::vector<std::string> wanted_fields() const override;  // rank 0's: every rank runs the same solver

  // Lets the followers return `exit_code` from follow().
  void finish(int exit_code);

 private:
  void announce(int call) const;

  Solver& local_;
  MPI_Comm comm_;
  bool finished_ = false;
};

// Ranks other than 0: make the lead's calls on `local` until it finishes; returns the exit
// code it finished with. A call that throws here but not on rank 0 would leave rank 0
// waiting in a collective, so an exception aborts the whole job (MPI_Abort) after
// printing what it was.
int follow(Solver& local, MPI_Comm comm);

// The program's body on every rank: rank 0 runs `lead` with a LeadSolver over `local` and
// finishes it with the code `lead` returns (1 if it throws, after which it rethrows); the
// others follow. One rank too goes through a LeadSolver, so its state has the same layout.
int run_on_ranks(Solver& local, MPI_Comm comm, const std::function<int(Solver&)>& lead);

}  // namespace cosim::participant
