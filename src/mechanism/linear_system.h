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

#include "core/dense_matrix.h"
#include "core/row_echelon.h"
#include "core/scalar.h"

namespace linkproof {

template <class T>
struct LinearSolution {
  int rank = 0;
  bool consistent = true;
  std::vector<T> x;
};

/// The exact route: sparse reduced row echelon form (rank, consistency, the unique solution).
template <class T>
LinearSolution<T> solve_linear_system_sparse(const DenseMatrix<T>& A, const std::vector<T>& b) {
  const size_t m = A.size(), n = A.cols();
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

/// A x = b for one matrix A and any number of right-hand sides b: the velocity and acceleration
/// systems of a mechanism share their matrix, so it is eliminated once.
///   exact (Rational, GiNaC):  A is kept and each solve runs the sparse route (its cost is in
///                             the rationals, not in repeating the elimination);
///   floating point:           A is eliminated at construction (Gauss-Jordan elimination with
///                             partial pivoting), recording each row exchange and each
///                             multiplier; a solve replays them on b. The pivots depend on A
///                             alone, so a replayed b is the same bits as eliminating [A | b].
///                             A row operation skips the columns where the pivot row is an
///                             exact 0 (a - f 0 = a: a mechanism's rows are mostly zeros) and
///                             writes the exact 0 it makes in the pivot's column.
template <class T>
class LinearSystem {
 public:
  explicit LinearSystem(DenseMatrix<T> A) : a_(std::move(A)) {
    if constexpr (!ScalarTraits<T>::is_exact) eliminate(true);
  }

  /// The rank of A, when nothing will be solved with it: in floating point, the same pivots
  /// with the rows below each pivot alone eliminated and nothing recorded.
  static int rank_of(DenseMatrix<T> A) {
    LinearSystem s(std::move(A), RankOnly{});
    return s.rank();
  }

  /// The rank of A.
  int rank() const {
    if constexpr (ScalarTraits<T>::is_exact)
      return solve_linear_system_sparse(a_, std::vector<T>(a_.size(), from_int<T>(0))).rank;
    else
      return static_cast<int>(pivot_col_.size());
  }

  LinearSolution<T> solve(std::vector<T> b) const {
    if constexpr (ScalarTraits<T>::is_exact) {
      return solve_linear_system_sparse(a_, b);
    } else {
      for (const Step& st : steps_) {
        if (st.exchange) std::swap(b[st.row], b[st.other]);
        else b[st.other] = b[st.other] - st.factor * b[st.row];
      }
      LinearSolution<T> out;
      const size_t rank = pivot_col_.size(), n = columns();
      out.rank = static_cast<int>(rank);
      for (size_t r = rank; r < a_.size(); ++r)
        if (!negligible(b[r])) out.consistent = false;
      if (out.consistent && rank == n) {
        out.x.assign(n, from_int<T>(0));
        for (size_t r = 0; r < rank; ++r) out.x[pivot_col_[r]] = b[r] / a_[r][pivot_col_[r]];
      }
      return out;
    }
  }

 private:
  // One operation on the right-hand side: exchange rows `row` and `other`, or
  // b[other] -= factor * b[row].
  struct Step {
    bool exchange = false;
    size_t row = 0, other = 0;
    T factor{};
  };

  size_t columns() const { return a_.cols(); }

  // A pivot counts as zero when |p| <= max(m, n) * u * max|A_ij| (see the file comment).
  bool negligible(const T& v) const { return std::abs(ScalarTraits<T>::to_double(v)) <= threshold_; }

  struct RankOnly {};
  LinearSystem(DenseMatrix<T> A, RankOnly) : a_(std::move(A)) {
    if constexpr (!ScalarTraits<T>::is_exact) eliminate(false);
  }

  // Gauss-Jordan with each operation recorded (`solvable`), or, for the rank alone, the rows
  // below each pivot eliminated (the pivots depend on those rows alone, so the rank is the same).
  void eliminate(bool solvable) {
    const size_t m = a_.size(), n = columns();
    double amax = 0;
    for (size_t r = 0; r < m; ++r)
      for (const T& v : a_[r]) amax = std::max(amax, std::abs(ScalarTraits<T>::to_double(v)));
    threshold_ = static_cast<double>(std::max(m, n)) * std::numeric_limits<double>::epsilon() / 2 * amax;
    if (solvable) steps_.reserve(m * std::min(m, n));
    pivot_col_.reserve(std::min(m, n));
    std::vector<size_t> nonzero;  // the columns right of the pivot where its row is not an exact 0
    nonzero.reserve(n);
    size_t row = 0;
    for (size_t col = 0; col < n && row < m; ++col) {
      size_t best = m;
      double best_mag = -1;
      for (size_t r = row; r < m; ++r) {
        if (negligible(a_[r][col])) continue;
        const double mag = std::abs(ScalarTraits<T>::to_double(a_[r][col]));
        if (mag > best_mag) best = r, best_mag = mag;
      }
      if (best == m) continue;
      if (best != row) {
        a_.swap_rows(row, best);
        if (solvable) steps_.push_back({true, row, best, T{}});
      }
      nonzero.clear();
      for (size_t c = col + 1; c < n; ++c)
        if (!is_zero(a_[row][c])) nonzero.push_back(c);
      for (size_t r = solvable ? 0 : row + 1; r < m; ++r) {
        if (r == row || is_zero(a_[r][col])) continue;
        const T f = a_[r][col] / a_[row][col];
        // a - (a / p) p is exactly 0 for the exact operands: an exact 0 encloses it.
        a_[r][col] = from_int<T>(0);
        for (const size_t c : nonzero) a_[r][c] = a_[r][c] - f * a_[row][c];
        if (solvable) steps_.push_back({false, row, r, f});
      }
      pivot_col_.push_back(col);
      ++row;
    }
  }

  DenseMatrix<T> a_;
  double threshold_ = 0;
  std::vector<Step> steps_;
  std::vector<size_t> pivot_col_;
};

template <class T>
LinearSolution<T> solve_linear_system(DenseMatrix<T> A, std::vector<T> b) {
  return LinearSystem<T>(std::move(A)).solve(std::move(b));
}

}  // namespace linkproof
