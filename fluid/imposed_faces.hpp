#pragma once
// Velocity unknowns whose value is prescribed rather than solved for: the faces inside
// fictitious-boundary bodies. The viscous solve turns their rows into Dirichlet rows, and
// the projection treats them like wall faces (no pressure coupling across them, no
// correction of their velocity), so a body is a no-slip obstacle as exact as a wall.
#include <array>
#include <cstdint>
#include <vector>

#include "fluid/grid.hpp"

namespace cosim::fluid {

struct ImposedFace {
  Index at{};
  double value = 0;
};

class ImposedFaces {
 public:
  explicit ImposedFaces(const Grid& grid);

  // Rebuilding: clear(), add() every imposed face this rank sees (owned or ghost), then
  // finish(), which is collective.
  void clear();
  void add(int c, const Index& p, double value);
  void finish();

  // This rank's rows, each with its value.
  const std::vector<ImposedFace>& owned(int c) const { return owned_[static_cast<std::size_t>(c)]; }
  // p within the ghosted range of component c.
  bool contains(int c, const Index& p) const { return mask_[static_cast<std::size_t>(c)][offset(c, p)] != 0; }
  // Advances, on all ranks at once, whenever the set of imposed faces changes anywhere.
  int generation() const { return generation_; }

 private:
  std::size_t offset(int c, const Index& p) const;

  const Grid& grid_;
  std::array<Box, 3> ghosted_, owned_box_;
  std::array<std::vector<std::uint8_t>, 3> mask_;
  std::array<std::vector<Index>, 3> seen_, previous_;  // every face set in the mask
  std::array<std::vector<ImposedFace>, 3> owned_;
  int generation_ = 0;
};

}  // namespace cosim::fluid
