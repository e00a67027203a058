#pragma once
// Velocity unknowns whose value is prescribed rather than solved for: the faces inside
// fictitious-boundary bodies. The viscous solve turns their rows into Dirichlet rows, and
// the projection treats them like wall faces (no pressure coupling across them, no
// correction of their velocity), so a body is a no-slip obstacle as exact as a wall.
#include <array>
#include <cstdint>
#include <vector>

#include "fluid/grid/grid.hpp"

namespace cosim::fluid::bodies {

struct ImposedFace {
  grid::Index at{};
  double value = 0;
};

class ImposedFaces {
 public:
  explicit ImposedFaces(const grid::Grid& grid);

  // Rebuilding: clear(), add() every imposed face this rank sees (owned or ghost), then
  // finish(), which is collective.
  void clear();
  void add(int c, const grid::Index& p, double value);
  void finish();

  // This rank's rows, each with its value.
  const std::vector<ImposedFace>& owned(int c) const { return owned_[static_cast<std::size_t>(c)]; }
  // p within the ghosted range of component c.
  bool contains(int c, const grid::Index& p) const { return mask_[static_cast<std::size_t>(c)][offset(c, p)] != 0; }
  // Advances, on all ranks at once, whenever the set of imposed faces changes anywhere.
  int generation() const { return generation_; }

 private:
  std::size_t offset(int c, const grid::Index& p) const;

  const grid::Grid& grid_;
  std::array<grid::Box, 3> ghosted_, owned_box_;
  std::array<std::vector<std::uint8_t>, 3> mask_;
  std::array<std::vector<grid::Index>, 3> seen_, previous_;  // every face set in the mask
  std::array<std::vector<ImposedFace>, 3> owned_;
  int generation_ = 0;
};

}  // namespace cosim::fluid::bodies
