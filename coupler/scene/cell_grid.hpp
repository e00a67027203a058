// Solids sorted into the cubic cells of a hash grid, so that what overlaps a solid is looked
// for among its neighbours only: checking or placing N bodies of similar size costs O(N),
// not O(N^2). A solid is listed in every cell its bounding box touches; one that would
// touch very many (much larger than a cell) is kept aside and tried against every query.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

#include "coupler/scene/solid.hpp"

namespace cosim::scene {

class CellGrid {
 public:
  explicit CellGrid(double cell);  // edge of a cell, > 0

  void add(const Solid& s);  // as index size(), the next one
  std::size_t size() const { return solids_.size(); }

  // The smallest index of a solid added before that overlaps `s` (solid.hpp) and that
  // `counts` accepts (all of them without it); nullopt if there is none.
  std::optional<std::size_t> first_overlap(const Solid& s, const std::function<bool(std::size_t)>& counts = {}) const;

 private:
  using Cell = std::array<std::int64_t, 3>;
  struct Hash {
    std::size_t operator()(const Cell& c) const;
  };
  struct Span {  // the cells a solid's box touches, per axis inclusive
    Cell lo, hi;
    std::uint64_t cells() const;
  };
  Span span_of(const Solid& s) const;

  double cell_;
  std::vector<Solid> solids_;
  std::unordered_map<Cell, std::vector<std::size_t>, Hash> cells_;
  std::vector<std::size_t> large_;
};

}  // namespace cosim::scene
