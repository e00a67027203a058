#include "tracker/program/adapter.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "coupler/participant/poses_at.hpp"
#include "tracker/program/cell_fields.hpp"
#include "tracker/program/particle_dump.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/velocity_input.hpp"

namespace cosim::tracker::program {
namespace {

Eigen::Isometry3d pose_of(const participant::PoseRow& row) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(row.position);
  pose.rotate(row.orientation.normalized());
  return pose;
}

}  // namespace

participant::Outputs TrackerSolver::initialise(const scene::Scene& scene, const std::string&,
                                               const std::vector<participant::PoseRow>& poses,
                                               const std::vector<double>& state) {
  bodies_ = scene.bodies.size();
  windows_ = scene.windows();
  check_size(poses);
  // The coupler's poses (the rigid-body program's) win over the scene's.
  std::vector<Eigen::Isometry3d> placed;
  for (const participant::PoseRow& row : poses) placed.push_back(pose_of(row));
  TrackerScene setup = read_tracker(scene, ranks_);
  place_bound_obstacles(setup, placed);
  obstacle_body_ = setup.obstacle_body;
  particle_output_ = setup.particle_output;
  gas_ = std::make_unique<step::Simulation>(std::move(setup), ranks_);
  if (ranks_.lead()) grid_ = output_grid(*gas_);
  if (!state.empty()) restore(state);
  return {{}, std::vector<participant::ForceRow>(bodies_), 0};
}

void TrackerSolver::check_size(const std::vector<participant::PoseRow>& poses) const {
  if (!poses.empty() && poses.size() != bodies_)
    throw std::runtime_error("poses for " + std::to_string(poses.size()) + " bodies, the scene has " +
                             std::to_string(bodies_));
}

participant::Outputs TrackerSolver::advance(const participant::Window& w, const participant::Inputs& in) {
  if (draws_ == Draws::per_window) gas_->reseed(w.index);
  done_ = w.index + 1;
  if (in.fields) gas_->set_velocity(velocity_of(*in.fields));
  const std::vector<tracking::ObstacleTally> before = gas_->tallies();
  const std::vector<int>& body_of = obstacle_body_;
  const int steps = gas_->advance(w.t0, w.t1, [&](double t, double h) {
    if (in.poses_start.empty()) return;
    const std::vector<participant::PoseRow> poses = participant::poses_at(in, w, t);
    check_size(poses);
    for (std::size_t i = 0; i < body_of.size(); ++i)
      if (body_of[i] >= 0)
        gas_->move_obstacle(static_cast<int>(i), pose_of(poses[static_cast<std::size_t>(body_of[i])]), h);
  });
  if (const long long lost = gas_->moves().lost; lost > 0)
    throw std::runtime_error(std::to_string(lost) + " particles lost (outside their cells) by t = " +
                             std::to_string(w.t1) + " s: a tracking bug");

  // Per unit particle mass in the tallies; times mass and weight is momentum.
  const double scale = gas_->setup().particles.mass * gas_->setup().particles.weight / (w.t1 - w.t0);
  std::vector<participant::ForceRow> on(bodies_);  // the obstacles bound to a body add up
  const std::vector<tracking::ObstacleTally> after = gas_->tallies();
  for (std::size_t i = 0; i < body_of.size(); ++i) {
    if (body_of[i] < 0) continue;
    participant::ForceRow& row = on[static_cast<std::size_t>(body_of[i])];
    row.force += scale * (after[i].impulse - before[i].impulse);
    row.torque += scale * (after[i].angular_impulse - before[i].angular_impulse);
  }
  return {{}, on, static_cast<double>(steps)};
}

field::FieldFrame TrackerSolver::fields() const {
  // Taking the moments starts a new average: the next frame averages the windows since.
  if (std::optional<FieldBlocks> blocks = field_blocks()) {
    // The coupler takes the whole frame: rank 0 puts the blocks together.
    if (!ranks_.lead()) {
      blocks->each({});
      return {};
    }
    field::FieldFrame frame = std::move(blocks->frame);
    const std::array<std::size_t, 3> cells = std::get<field::RectilinearGrid>(grid_.grid).cells();
    for (field::CellField& f : frame.fields)
      f.values.assign(cells[0] * cells[1] * cells[2] * static_cast<std::size_t>(f.components), 0.0);
    blocks->each([&](const field::CellBlock& b) { field::place(b, cells, frame.fields); });
    return frame;
  }
  const std::vector<double> count = gas_->counts();
  const std::vector<tracking::CellMoments> moments = gas_->take_moments();
  std::optional<field::PointSet> particles;
  if (particle_output_ && particle_output_->at(done_, windows_)) particles = particle_set(*gas_, *particle_output_);
  if (!ranks_.lead()) return {};  // rank 0 answers the coupler: only it has every cell's values
  field::FieldFrame frame{grid_.grid, cell_fields(moments, count)};
  if (particles) frame.point_sets.push_back(std::move(*particles));
  return frame;
}

std::optional<TrackerSolver::FieldBlocks> TrackerSolver::field_blocks() const {
  if (!gas_->brick()) return std::nullopt;
  const step::Simulation::BrickSamples mine = gas_->take_brick();
  std::optional<field::PointSet> particles;
  if (particle_output_ && particle_output_->at(done_, windows_)) particles = particle_set(*gas_, *particle_output_);
  FieldBlocks blocks;
  // A block on the wire: its lo and hi, then each field's values.
  std::vector<double> sent;
  for (const std::array<int, 3>& corner : {mine.brick.lo, mine.brick.hi})
    sent.insert(sent.end(), corner.begin(), corner.end());
  std::vector<field::CellField> layout;
  for (field::CellField& f : cell_fields(mine.moments, mine.count)) {
    sent.insert(sent.end(), f.values.begin(), f.values.end());
    layout.push_back({std::move(f.name), f.components, {}});
  }
  if (ranks_.lead()) {
    blocks.frame = {grid_.grid, layout};
    if (particles) blocks.frame.point_sets.push_back(std::move(*particles));
  }
  blocks.each = [ranks = ranks_, layout = std::move(layout), sent = std::move(sent)](const auto& take) {
    ranks.gather_each(sent, [&](std::span<const double> values) {
      field::CellBlock b;
      for (std::size_t a = 0; a < 3; ++a) {
        b.lo[a] = static_cast<std::size_t>(values[a]);
        b.hi[a] = static_cast<std::size_t>(values[3 + a]);
      }
      const std::size_t n = (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]);
      const double* at = values.data() + 6;
      for (const field::CellField& f : layout) {
        const std::size_t count = n * static_cast<std::size_t>(f.components);
        b.fields.push_back({f.name, f.components, {at, at + count}});
        at += count;
      }
      take(b);
    });
  };
  return blocks;
}

std::vector<std::string> TrackerSolver::wanted_fields() const { return {"velocity"}; }

std::vector<double> TrackerSolver::state() const { return gas_->state(); }

void TrackerSolver::restore(const std::vector<double>& state) { gas_->restore(state); }

}  // namespace cosim::tracker::program
