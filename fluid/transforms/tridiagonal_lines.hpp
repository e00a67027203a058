#pragma once
// Tridiagonal systems along z for a whole row of modes at once (the transform solvers'
// last stage): the same couplings between neighbouring layers for every mode i, a
// diagonal per layer and mode. Thomas' algorithm across all i at once, so the inner loop
// runs over contiguous modes; on a periodic axis the corners are folded in by
// Sherman-Morrison.
#include <petscsys.h>

#include <vector>

namespace cosim::fluid::transforms {

// Solves, for each i in 0 .. nx, diagonal(k, i) x_k + sub(k) x_{k-1} + super(k) x_{k+1} = f_k
// for k in 0 .. n, in place: element (i, k) at row[k k_stride + i]. Without `cyclic` sub(0)
// and super(n - 1) are ignored; with it, row 0 reaches k = n - 1 by sub(0) and row n - 1
// reaches 0 by super(n - 1). work holds (2 n + 1) nx doubles.
template <typename Sub, typename Super, typename Diagonal>
void solve_tridiagonal_lines(double* row, PetscInt n, PetscInt nx, PetscInt k_stride, const Sub& sub,
                             const Super& super, const Diagonal& diagonal, bool cyclic, std::vector<double>& work) {
  double* w = work.data();
  double* v = work.data() + n * nx;  // Sherman-Morrison's second right-hand side
  double* gamma = v + n * nx;        // and its free parameter, minus row 0's diagonal
  // The corners of a cyclic line: row 0 reaches k = n - 1 (beta), row n - 1 reaches 0 (alpha).
  const double alpha = super(n - 1), beta = sub(0);
  for (PetscInt i = 0; i < nx; ++i) {
    w[i] = diagonal(0, i);
    if (cyclic) {
      gamma[i] = -w[i];
      w[i] -= gamma[i];
      v[i] = gamma[i];
    }
  }
  if (cyclic)
    for (PetscInt k = 1; k < n; ++k)
      for (PetscInt i = 0; i < nx; ++i) v[k * nx + i] = k == n - 1 ? alpha : 0;
  // Forward elimination, with the cyclic line's last diagonal modified.
  for (PetscInt k = 1; k < n; ++k) {
    double* f = row + k * k_stride;
    const double* f_prev = row + (k - 1) * k_stride;
    const double a = sub(k), c_prev = super(k - 1);
    for (PetscInt i = 0; i < nx; ++i) {
      double d = diagonal(k, i);
      if (cyclic && k == n - 1) d -= alpha * beta / gamma[i];
      const double m = a / w[(k - 1) * nx + i];
      w[k * nx + i] = d - m * c_prev;
      f[i] -= m * f_prev[i];
      if (cyclic) v[k * nx + i] -= m * v[(k - 1) * nx + i];
    }
  }
  // Back substitution.
  for (PetscInt i = 0; i < nx; ++i) {
    row[(n - 1) * k_stride + i] /= w[(n - 1) * nx + i];
    if (cyclic) v[(n - 1) * nx + i] /= w[(n - 1) * nx + i];
  }
  for (PetscInt k = n - 2; k >= 0; --k) {
    double* f = row + k * k_stride;
    const double* f_next = row + (k + 1) * k_stride;
    const double c = super(k);
    for (PetscInt i = 0; i < nx; ++i) {
      f[i] = (f[i] - c * f_next[i]) / w[k * nx + i];
      if (cyclic) v[k * nx + i] = (v[k * nx + i] - c * v[(k + 1) * nx + i]) / w[k * nx + i];
    }
  }
  if (cyclic)
    for (PetscInt i = 0; i < nx; ++i) {
      double* first = row + i;
      const double* last = row + (n - 1) * k_stride + i;
      const double fact = (*first + beta * *last / gamma[i]) / (1 + v[i] + beta * v[(n - 1) * nx + i] / gamma[i]);
      for (PetscInt k = 0; k < n; ++k) row[k * k_stride + i] -= fact * v[k * nx + i];
    }
}

}  // namespace cosim::fluid::transforms
