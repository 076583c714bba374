// Dense linear systems A x = b over any scalar type T, by Gaussian elimination with row pivoting,
// reporting the rank and consistency instead of assuming a square regular matrix.
//
// The kinematic systems of a mechanism are rectangular in general (2 rows per loop and 1 per
// prismatic pair, against one unknown per moving link and per prismatic pair, plus the input
// rows), and can be rank deficient (redundant constraints, too few inputs). So:
//   rank        the rank of A;
//   consistent  b lies in the range of A (no row reduces to 0 = non-zero);
//   x           the solution when rank == columns and consistent (empty otherwise).
// Exact arithmetic (Rational): pivots are exactly non-zero, the rank is exact. The elimination is
// sparse (core/row_echelon.h: a reduced basis built one row at a time, each subtraction touching
// only the non-zero entries): a mechanism's rows read the few links of one loop, and a chain of
// loops keeps its basis rows short, so the cost grows about linearly with the loops instead of
// the cube of the unknowns (dense elimination on rationals). Same rank, consistency and x.
// Floating point: a pivot counts as zero when |p| <= max(m, n) * u * max|A_ij| (the usual
// numerical-rank threshold: the size of the backward error of elimination), u = unit roundoff.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/row_echelon.h"
#include "core/scalar.h"

namespace linkproof {

template <class T>
struct LinearSolution {
  int rank = 0;
  bool consistent = true;
  std::vector<T> x;
};

template <class T>
using DenseMatrix = std::vector<std::vector<T>>;

/// The exact route: sparse reduced row echelon form (rank, consistency, the unique solution).
template <class T>
LinearSolution<T> solve_linear_system_sparse(const DenseMatrix<T>& A, const std::vector<T>& b) {
  const size_t m = A.size();
  const size_t n = m == 0 ? 0 : A[0].size();
  RowEchelon<T> e(static_cast<int>(n));
  for (size_t r = 0; r < m; ++r) {
    SparseRow<T> row;
    for (size_t c = 0; c < n; ++c)
      if (!is_zero(A[r][c])) row.emplace_back(static_cast<int>(c), A[r][c]);
    e.add(row, b[r]);
  }
  LinearSolution<T> out;
  out.rank = e.rank();
  out.consistent = e.is_consistent();
  if (out.consistent && out.rank == static_cast<int>(n)) {
    out.x.reserve(n);
    for (size_t c = 0; c < n; ++c) out.x.push_back(*e.determined_value(static_cast<int>(c)));
  }
  return out;
}

template <class T>
LinearSolution<T> solve_linear_system(DenseMatrix<T> A, std::vector<T> b) {
  if constexpr (ScalarTraits<T>::is_exact) return solve_linear_system_sparse(A, b);
  const size_t m = A.size();
  const size_t n = m == 0 ? 0 : A[0].size();
  double threshold = 0;
  if constexpr (!ScalarTraits<T>::is_exact) {
    double amax = 0;
    for (const auto& row : A)
      for (const auto& v : row) amax = std::max(amax, std::abs(ScalarTraits<T>::to_double(v)));
    threshold = static_cast<double>(std::max(m, n)) * std::numeric_limits<double>::epsilon() / 2 * amax;
  }
  const auto negligible = [&](const T& v) {
    if constexpr (ScalarTraits<T>::is_exact) return is_zero(v);
    else return std::abs(ScalarTraits<T>::to_double(v)) <= threshold;
  };
  LinearSolution<T> out;
  std::vector<size_t> pivot_col;
  size_t row = 0;
  for (size_t col = 0; col < n && row < m; ++col) {
    size_t best = m;
    double best_mag = -1;
    for (size_t r = row; r < m; ++r) {
      if (negligible(A[r][col])) continue;
      const double mag = std::abs(ScalarTraits<T>::to_double(A[r][col]));
      if (mag > best_mag) best = r, best_mag = mag;
    }
    if (best == m) continue;
    std::swap(A[row], A[best]);
    std::swap(b[row], b[best]);
    for (size_t r = 0; r < m; ++r) {
      if (r == row || is_zero(A[r][col])) continue;
      const T f = A[r][col] / A[row][col];
      for (size_t c = col; c < n; ++c) A[r][c] = A[r][c] - f * A[row][c];
      b[r] = b[r] - f * b[row];
    }
    pivot_col.push_back(col);
    ++row;
  }
  out.rank = static_cast<int>(row);
  for (size_t r = row; r < m; ++r)
    if (!negligible(b[r])) out.consistent = false;
  if (out.consistent && row == n) {
    out.x.assign(n, from_int<T>(0));
    for (size_t r = 0; r < row; ++r) out.x[pivot_col[r]] = b[r] / A[r][pivot_col[r]];
  }
  return out;
}

}  // namespace linkproof
