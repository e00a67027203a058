// The forcing's matrix from entries several ranks give for one row: each row the sum of
// every rank's entries, in any order the ranks give them, with its diagonal, 1 on a row no
// rank gives entries for. Runs on one rank and, in fluid.suite_on_two_ranks, on two.
#include <gtest/gtest.h>

#include <vector>

#include "fluid/ibm/summed_rows.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid {

using ibm::MarkerStencils;
using ibm::summed_rows;

namespace {

TEST(IbmSummedRows, EachRowIsTheSumOfEveryRanksEntries) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const PetscInt rows = 5 + rank, total = 5 * size + size * (size - 1) / 2;
  // Every rank gives every even row: 1 on its diagonal and rank + 1 two columns on, the
  // last row first (not by ascending row); odd rows get nothing.
  std::vector<MarkerStencils::Product> entries;
  for (PetscInt r = total - 1; r >= 0; --r)
    if (r % 2 == 0) {
      entries.push_back({r, r, 1.0});
      entries.push_back({r, (r + 2) % total, rank + 1.0});
    }
  Mat B = summed_rows(PETSC_COMM_WORLD, rows, entries);
  PetscInt first = 0, end = 0, global = 0;
  COSIM_PETSC(MatGetOwnershipRange(B, &first, &end));
  COSIM_PETSC(MatGetSize(B, &global, nullptr));
  EXPECT_EQ(end - first, rows);
  EXPECT_EQ(global, total);
  for (PetscInt r = first; r < end; ++r) {
    PetscInt count = 0;
    const PetscInt* columns = nullptr;
    const PetscScalar* values = nullptr;
    COSIM_PETSC(MatGetRow(B, r, &count, &columns, &values));
    std::vector<std::pair<PetscInt, double>> row;
    for (PetscInt k = 0; k < count; ++k) row.emplace_back(columns[k], values[k]);
    COSIM_PETSC(MatRestoreRow(B, r, &count, &columns, &values));
    using Row = std::vector<std::pair<PetscInt, double>>;
    if (r % 2 == 1) {
      EXPECT_EQ(row, (Row{{r, 1.0}})) << "row " << r;
    } else if (const PetscInt next = (r + 2) % total; next == r) {
      EXPECT_EQ(row, (Row{{r, size + size * (size + 1) / 2.0}})) << "row " << r;
    } else {
      Row expected{{r, double(size)}, {next, size * (size + 1) / 2.0}};
      if (next < r) std::swap(expected[0], expected[1]);
      EXPECT_EQ(row, expected) << "row " << r;
    }
  }
  MatDestroy(&B);
}

}  // namespace
}  // namespace cosim::fluid
