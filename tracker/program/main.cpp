// cosim-tracker: the tracker program.
//   started by `cosim run` (COSIM_ENDPOINT set)         a coupled participant (adapter.hpp)
//   cosim-tracker --standalone scene.yaml [-o f.h5]     particles among the scene's obstacles
//   cosim-tracker --check scene.yaml [--work FILE]      read the tracker section only (cosim check),
//                                                       and write the work it gives (tracker_work.hpp)
// Under mpirun the gas is spread over the ranks (tracker/parallel): rank 0 talks to the
// coupler or writes the run file, the others follow (participant/mpi_team.hpp).
#include <CLI/CLI.hpp>
#include <mpi.h>

#include <fmt/format.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "coupler/participant/mpi_team.hpp"
#include "coupler/participant/program_args.hpp"
#include "coupler/participant/run_participant.hpp"
#include "coupler/participant/stage_summary.hpp"
#include "coupler/protocol/client.hpp"
#include "coupler/scene/error.hpp"
#include "tracker/program/adapter.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/standalone.hpp"
#include "tracker/program/tracker_work.hpp"

namespace {

int coupled() {
  cosim::tracker::program::TrackerSolver solver(cosim::tracker::parallel::Ranks(MPI_COMM_WORLD));
  return cosim::participant::run_on_ranks(solver, MPI_COMM_WORLD, [](cosim::participant::Solver& lead) {
    using cosim::scene::Data;
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    auto client = cosim::protocol::Client::from_environment();
    // Able to take poses and fields (tracer mode) and give forces and fields; the coupler's
    // plan decides what flows.
    return cosim::participant::run_participant(
        *client, lead, static_cast<std::uint32_t>(Data::Forces) | static_cast<std::uint32_t>(Data::Fields),
        static_cast<std::uint32_t>(Data::Poses) | static_cast<std::uint32_t>(Data::Fields),
        static_cast<std::uint32_t>(ranks));
  });
}

int standalone(const std::string& scene, const std::string& output) {
  const cosim::tracker::parallel::Ranks ranks(MPI_COMM_WORLD);
  const int code = cosim::scene::exit_code("cosim-tracker", [&] {
    const cosim::tracker::program::RunSummary s =
        cosim::tracker::program::run_tracker(cosim::scene::load_scene(scene), output, ranks);
    // Each rank's setup time and peak memory, for the scaling of a run over ranks.
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double mine[2] = {s.setup_seconds, static_cast<double>(usage.ru_maxrss) / 1024.0};
    std::vector<double> all(2 * static_cast<std::size_t>(ranks.size()));
    MPI_Gather(mine, 2, MPI_DOUBLE, all.data(), 2, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (!ranks.lead()) return 0;
    std::fprintf(stderr,
                 "cosim-tracker: %llu steps, %zu particles seeded, %zu entered, %zu remain, %lld collisions, "
                 "%.2f s (setup %.2f s)\n  %s\n  steps%s: %s\n",
                 static_cast<unsigned long long>(s.steps), s.seeded, s.injected, s.remaining,
                 static_cast<long long>(s.collisions), s.wall_seconds, s.setup_seconds,
                 cosim::tracker::tracking::summary(s.moves).c_str(), ranks.size() > 1 ? " on rank 0" : "",
                 cosim::participant::stage_summary(cosim::tracker::step::kStageNames, s.stages.all()).c_str());
    if (ranks.size() > 1)
      std::fprintf(stderr, "cosim-tracker: %d ranks, %zu particles moved between them, %llu re-partitions\n",
                   ranks.size(), s.migrated, static_cast<unsigned long long>(s.rebalances));
    std::string setup, peak;
    for (int r = 0; r < ranks.size(); ++r) {
      setup += fmt::format(" {:.2f}", all[2 * static_cast<std::size_t>(r)]);
      peak += fmt::format(" {:.0f}", all[2 * static_cast<std::size_t>(r) + 1]);
    }
    std::fprintf(stderr, "cosim-tracker: by rank: setup [s]%s; peak memory [MB]%s\n", setup.c_str(), peak.c_str());
    return 0;
  });
  // A bad scene stops every rank alike (2); an error on one rank alone would leave the
  // others waiting in a collective.
  if (code != 0 && code != 2 && ranks.size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  int code = 0;
  MPI_Init(&argc, &argv);
  if (std::getenv(cosim::protocol::kEndpointEnv) != nullptr) {
    code = coupled();
  } else {
    CLI::App app{"cosim-tracker: ballistic particles through polyhedral meshes among CSG obstacles"};
    cosim::participant::ProgramArgs args;
    cosim::participant::add_program_args(app, args, "Run this scene's tracker alone", "tracker section");
    try {
      app.parse(argc, argv);
      code =
          args.check.empty() ? standalone(args.standalone, args.output) : cosim::scene::exit_code("cosim-tracker", [&] {
            const cosim::scene::Scene scene = cosim::scene::load_scene(args.check);
            const cosim::tracker::program::TrackerScene setup = cosim::tracker::program::read_tracker(scene);
            if (!args.work.empty())
              cosim::participant::write_work(args.work, cosim::tracker::program::tracker_work(scene, setup));
            return 0;
          });
    } catch (const CLI::ParseError& e) {
      code = app.exit(e);
    }
  }
  MPI_Finalize();
  return code;
}
