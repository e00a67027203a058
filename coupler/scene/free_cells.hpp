// The cells of a box where the centre of one more body may still go. Random addition draws
// from these only and drops a cell as soon as a single placed body rules out all of it.
// Drawing uniformly from equal cells and refusing what overlaps leaves each new centre
// uniform over the space still free, so the packings are those of plain random sequential
// addition; only far fewer draws are refused near jamming, where most of the box is ruled
// out. Spheres in a box 24 radii wide, given up after 10000 refused draws in a row: plain
// drawing stops at solid fraction 0.30, drawing from free cells at 0.34.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "coupler/scene/scene.hpp"
#include "coupler/scene/solid.hpp"
#include "coupler/scene/uniform.hpp"

namespace cosim::scene {

class FreeCells {
 public:
  // Cells about `edge` wide tiling `box` (coarser when there would be too many).
  FreeCells(const Domain& box, double edge);

  bool empty() const { return free_.empty(); }
  Vec3 draw(Uniform& random) const;  // uniformly from the free cells
  // Drops the cells where `body` centred anywhere would overlap `placed`.
  void exclude(const Solid& body, const Solid& placed);
  // Drops the cells where `body` centred anywhere would reach beyond a wall: `room(x)` is
  // the distance from x to the nearest wall, positive on the free side.
  void keep_within(const Solid& body, const std::function<double(const Vec3&)>& room);

 private:
  using Index = std::array<std::int64_t, 3>;
  std::size_t id(const Index& i) const;
  Index index(std::size_t id) const;

  Vec3 origin_{};
  Vec3 edge_{};
  Index n_{};
  std::vector<std::uint32_t> free_;  // ids of the free cells, in no order
  std::vector<std::uint32_t> slot_;  // cell id -> its place in free_, or none
};

}  // namespace cosim::scene
