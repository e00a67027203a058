// The lead and its followers (participant/mpi_team.hpp) on two ranks: every call reaches
// every rank with the lead's arguments (a forwarded frame's point sets too), the state
// gathers into one array with its layout and scatters back, and a state from another rank
// count is refused without leaving the followers behind. Run under `mpirun -n 2`.
#include <gtest/gtest.h>
#include <mpi.h>

#include "coupler/participant/mpi_team.hpp"

namespace cosim::participant {
namespace {

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// Rank r holds r + 1 values; advance() sums the window's end time and a pose value over the
// ranks, so a rank that missed the call or its inputs shows in the result.
class RankSolver final : public Solver {
 public:
  Outputs initialise(const scene::Scene&, const std::string&, const std::vector<PoseRow>&,
                     const std::vector<double>& state) override {
    values_ = state.empty() ? std::vector<double>(static_cast<std::size_t>(rank() + 1), 10.0 * rank()) : state;
    return {};
  }
  Outputs advance(const Window& w, const Inputs& in) override {
    double local = w.t1 + in.poses_start.at(0).position.x(), sum = 0;
    MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    for (double& v : values_) v += 1;
    return {{}, {ForceRow{{sum, 0, 0}, Eigen::Vector3d::Zero()}}, 1};
  }
  std::vector<double> state() const override { return values_; }
  void restore(const std::vector<double>& state) override { values_ = state; }

 private:
  std::vector<double> values_;
};

const scene::Scene& tiny_scene() {
  static const scene::Scene s = scene::load_scene_from_string(
      "time: {end: 1}\ncoupling: {window: 0.5}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "participants:\n  spring: {command: [x], provides: [forces], needs: [], dt: 0.5}\n");
  return s;
}

TEST(MpiTeam, CallsReachEveryRankAndTheStateRoundTrips) {
  RankSolver local;
  const int code = run_on_ranks(local, MPI_COMM_WORLD, [](Solver& lead) {
    lead.initialise(tiny_scene(), "spring", {}, {});
    EXPECT_EQ(lead.state(), (std::vector<double>{2, 1, 2, 0, 10, 10}));  // ranks, sizes, values
    Inputs in;
    in.poses_start.emplace_back().position.x() = 0.25;
    EXPECT_EQ(lead.advance({0, 1, 0.0, 0.5}, in).forces.at(0).force.x(), 1.5);  // 2 x (0.5 + 0.25)
    const std::vector<double> saved = lead.state();
    EXPECT_EQ(saved, (std::vector<double>{2, 1, 2, 1, 11, 11}));
    lead.advance({1, 1, 0.5, 1.0}, in);
    lead.restore(saved);
    EXPECT_EQ(lead.state(), saved);
    return 7;
  });
  EXPECT_EQ(code, 7);  // the followers return the lead's code
}

TEST(MpiTeam, AStateOfAnotherRankCountIsRefusedAndTheTeamGoesOn) {
  RankSolver local;
  run_on_ranks(local, MPI_COMM_WORLD, [](Solver& lead) {
    lead.initialise(tiny_scene(), "spring", {}, {});
    try {
      lead.restore({3, 1, 1, 1, 0, 0, 0});
      ADD_FAILURE() << "restored a state of 3 ranks on 2";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "the state was written by 3 ranks, this run has 2: resume on 3");
    }
    EXPECT_THROW(lead.restore({2, 1, 2, 0, 0}), std::runtime_error);  // shorter than it says
    EXPECT_EQ(lead.state(), (std::vector<double>{2, 1, 2, 0, 10, 10}));
    return 0;
  });
}

// Sums over the ranks the z of the first point of the first point set it was forwarded, and
// that point's first attribute value.
class PointSetSolver final : public Solver {
 public:
  Outputs initialise(const scene::Scene&, const std::string&, const std::vector<PoseRow>&,
                     const std::vector<double>&) override {
    return {};
  }
  Outputs advance(const Window&, const Inputs& in) override {
    const field::PointSet* set = in.fields ? &in.fields->point_sets.at(0) : nullptr;
    double local = set ? set->points.at(2) + set->attributes.at(0).values.at(0) : -100.0, sum = 0;
    MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return {{}, {ForceRow{{sum, 0, 0}, Eigen::Vector3d::Zero()}}, 1};
  }
  std::vector<double> state() const override { return {}; }
  void restore(const std::vector<double>&) override {}
};

// A frame forwarded in an Advance reaches every rank whole, its point sets and their
// attributes too.
TEST(MpiTeam, AForwardedFrameReachesEveryRankWithItsPointSets) {
  PointSetSolver local;
  run_on_ranks(local, MPI_COMM_WORLD, [](Solver& lead) {
    lead.initialise(tiny_scene(), "spring", {}, {});
    Inputs in;
    in.fields = field::FieldFrame{field::RectilinearGrid{{{{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}}}},
                                  {{"p", 1, {1.0}}},
                                  {{"ball", {0.5, 0.5, 2.5}, {{"id", 1, {4.0}, true}}}}};
    EXPECT_EQ(lead.advance({0, 1, 0.0, 0.5}, in).forces.at(0).force.x(), 13.0);  // 2 x (2.5 + 4)
    return 0;
  });
}

}  // namespace
}  // namespace cosim::participant
