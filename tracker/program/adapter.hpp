// cosim-tracker as a participant: the gas of the scene's tracker section, advanced window
// by window. It needs the bodies' poses (obstacles bound to a body move with it) and
// provides the gas's force and torque on each body (protocol::kForceWidth values per body,
// zero for a body no obstacle is bound to). Over several ranks every rank runs one
// (participant/mpi_team.hpp): its calls are collective and the forces are the sums over the
// ranks, on every rank. It provides its sampled fields for the run file too. In tracer mode
// it needs the fluid's velocity: the coupler forwards the fluid's field at each window's
// start, and the tracers are carried by it, held, through the window.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "coupler/participant/solver.hpp"
#include "tracker/program/output_grid.hpp"
#include "tracker/program/scene_particle_output.hpp"
#include "tracker/step/simulation.hpp"

namespace cosim::tracker::program {

class TrackerSolver final : public participant::Solver {
 public:
  // Where a window's random draws come from: coupled, from the window's own stream
  // (Simulation::reseed), so a repeated window with the same inputs gives the same forces;
  // standalone, where no window is repeated, on from the stream the gas started with.
  enum class Draws { per_window, one_stream };

  explicit TrackerSolver(parallel::Ranks ranks = {}, Draws draws = Draws::per_window) : ranks_(ranks), draws_(draws) {}

  participant::Outputs initialise(const scene::Scene& scene, const std::string& name,
                                  const std::vector<participant::PoseRow>& poses,
                                  const std::vector<double>& state) override;
  // Subcycles to exactly w.t1 in equal steps of at most the participant's dt; before each
  // step the bound obstacles move to their body's pose at the step's end (inputs
  // interpolated in the window); forwarded fields replace the tracers' velocity field
  // first; random draws as Draws says. Lost particles (a tracking bug) throw
  // std::runtime_error. The forces are the momentum and its moment the hits gave each body
  // in the window, over the window's length: the window's mean.
  participant::Outputs advance(const participant::Window& w, const participant::Inputs& in) override;
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;
  // The per-cell samples averaged since the last call (or the start) on the tracker's
  // output grid (cell_fields.hpp, output_grid.hpp); collective, the whole frame on rank 0
  // (the others' is empty). After the
  // windows particle_output names (counted from the last advance()) the particles too, on
  // rank 0 (particle_dump.hpp).
  field::FieldFrame fields() const override;
  // fields() in blocks, one per rank, for a writer that never holds every cell's values (a
  // box of hexahedra over several ranks, Simulation::brick()); nullopt otherwise. Collective.
  struct FieldBlocks {
    field::FieldFrame frame;  // rank 0's: the grid, the fields' names and components, the particles
    // Hands take() each rank's block on rank 0, rank after rank; collective: every rank
    // calls it once (the others with a take() that is not called).
    std::function<void(const std::function<void(const field::CellBlock&)>& take)> each;
  };
  std::optional<FieldBlocks> field_blocks() const;
  // Tracers need only the fluid's velocity of its frame.
  std::vector<std::string> wanted_fields() const override;

  // For a standalone run's file and summary.
  const step::Simulation& gas() const { return *gas_; }
  const OutputGrid& grid() const { return grid_; }  // rank 0's; empty on the others

 private:
  void check_size(const std::vector<participant::PoseRow>& poses) const;

  parallel::Ranks ranks_;
  Draws draws_;
  std::unique_ptr<step::Simulation> gas_;
  std::vector<int> obstacle_body_;                 // TrackerScene's
  std::optional<ParticleOutput> particle_output_;  // TrackerScene's
  OutputGrid grid_;                                // rank 0's: built once, its grid sent with every frame
  std::size_t bodies_ = 0;
  std::uint64_t windows_ = 0;  // of the run
  std::uint64_t done_ = 0;     // windows advanced through: the last one's index + 1
};

}  // namespace cosim::tracker::program
