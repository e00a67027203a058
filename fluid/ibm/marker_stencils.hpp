#pragma once
// The markers that take part in a step on this rank (those whose kernels touch its faces),
// and their kernels' points on this rank flattened once: the forcing assembles its system
// from them, and the step and the no-slip corrections spread onto and interpolate from
// them. A point is its offset from the owned box's first face, the same in every global
// vector of that component's DMDA.
#include <petscdmda.h>

#include <Eigen/Core>

#include <array>
#include <span>
#include <vector>

#include "fluid/grid/grid.hpp"
#include "fluid/ibm/kernel_stencil.hpp"
#include "fluid/ibm/marker_sharing.hpp"

namespace cosim::fluid::ibm {

struct ActiveMarker {
  std::size_t body = 0, marker = 0;
  std::size_t id = 0;                // its number among all bodies' markers
  Eigen::Vector3d position, target;  // where it is, and the body's velocity there
  double volume = 0;
  std::array<KernelStencil, 3> stencil;
  std::array<bool, 3> local{};  // the stencil meets this rank's faces of the component
};

// Owned faces of the three components, as DMDA arrays.
using FaceArrays = std::array<PetscScalar***, 3>;

class MarkerStencils {
 public:
  // `roots`: the values whose roots this rank keeps (marker_sharing.hpp; collective).
  MarkerStencils(const grid::Grid& grid, std::span<const ActiveMarker> markers, PetscInt roots);

  // field += sum_l g_l w_l / dV, g holding 3 values (x, y, z) per marker.
  void spread(const FaceArrays& field, const std::vector<double>& g) const;
  // out_l = sum_x w_l field, summed over the ranks that hold marker l (collective).
  void interpolate(const FaceArrays& field, std::vector<double>& out) const;
  // The entries of B = I S, interpolating with these kernels what is spread with those of
  // `spreading` (the same markers, elsewhere: symmetric where they are these), that this
  // rank's faces make: sum_x w_i(x) s_j(x) / dV_x over them for each pair of values of one
  // component it holds, rows and columns by the values' global numbers, in the order of the
  // values this rank holds and then of the columns. A value's row of B is the sum of its
  // entries over the ranks.
  struct Product {
    PetscInt row, column;
    double value;
  };
  std::vector<Product> products(const MarkerStencils& spreading) const;
  const MarkerSharing& sharing() const { return sharing_; }

 private:
  struct Touch {
    std::ptrdiff_t offset;
    double weight;
    double spread;  // weight / dV of the face
  };
  std::array<PetscScalar*, 3> origins(const FaceArrays& field) const;

  const grid::Grid& grid_;
  std::array<grid::Box, 3> owned_;
  std::vector<Touch> touches_;
  std::vector<std::size_t> first_;  // value i's touches: first_[i] .. first_[i + 1]
  std::vector<PetscInt> ids_;       // value i's global number
  MarkerSharing sharing_;
};

}  // namespace cosim::fluid::ibm
