// solve_linear_system: the exact (sparse) route gives the rank, consistency and solution of a
// dense reference elimination, on square, rectangular and rank-deficient systems; the floating
// route, one elimination replayed on several right-hand sides (LinearSystem), gives the same
// bits as eliminating each [A | b] on its own.
#include "mechanism/linear_system.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>

#include "core/tracked.h"

namespace linkproof {
namespace {

/// Reference: dense Gauss-Jordan on [A | b] over the rationals, written out here.
LinearSolution<Rational> dense_reference(DenseMatrix<Rational> A, std::vector<Rational> b) {
  const size_t m = A.size(), n = m ? A[0].size() : 0;
  LinearSolution<Rational> out;
  std::vector<size_t> pivots;
  size_t row = 0;
  for (size_t col = 0; col < n && row < m; ++col) {
    size_t p = row;
    while (p < m && cln::zerop(A[p][col])) ++p;
    if (p == m) continue;
    std::swap(A[p], A[row]);
    std::swap(b[p], b[row]);
    for (size_t r = 0; r < m; ++r) {
      if (r == row || cln::zerop(A[r][col])) continue;
      const Rational f = A[r][col] / A[row][col];
      for (size_t c = 0; c < n; ++c) A[r][c] = A[r][c] - f * A[row][c];
      b[r] = b[r] - f * b[row];
    }
    pivots.push_back(col);
    ++row;
  }
  out.rank = static_cast<int>(row);
  for (size_t r = row; r < m; ++r) out.consistent = out.consistent && cln::zerop(b[r]);
  if (out.consistent && row == n) {
    out.x.assign(n, 0);
    for (size_t r = 0; r < row; ++r) out.x[pivots[r]] = b[r] / A[r][pivots[r]];
  }
  return out;
}

TEST(LinearSystem, ExactSparseRouteAgreesWithDenseEliminationOnRandomSystems) {
  const unsigned seed = 13;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coeff(-3, 3), size(1, 7), zero(0, 2);
  for (int trial = 0; trial < 300; ++trial) {
    const size_t m = static_cast<size_t>(size(rng)), n = static_cast<size_t>(size(rng));
    DenseMatrix<Rational> A(m, std::vector<Rational>(n, 0));
    std::vector<Rational> b(m, 0);
    for (size_t r = 0; r < m; ++r) {
      for (size_t c = 0; c < n; ++c)
        if (zero(rng) == 0) A[r][c] = Rational(coeff(rng)) / (1 + zero(rng));
      b[r] = coeff(rng);
    }
    if (m > 1 && trial % 3 == 0) {  // a dependent row, consistent or not
      for (size_t c = 0; c < n; ++c) A[m - 1][c] = A[0][c] * 2 - (m > 2 ? A[1][c] : Rational(0));
      b[m - 1] = b[0] * 2 - (m > 2 ? b[1] : Rational(0)) + (trial % 2);
    }
    const auto ref = dense_reference(A, b);
    const auto got = solve_linear_system<Rational>(A, b);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
    EXPECT_EQ(got.rank, ref.rank);
    EXPECT_EQ(got.consistent, ref.consistent);
    ASSERT_EQ(got.x.size(), ref.x.size());
    for (size_t c = 0; c < ref.x.size(); ++c) EXPECT_EQ(got.x[c], ref.x[c]) << "x[" << c << "]";
  }
}


/// Reference for the floating route: partial pivoting on [A | b] (the pivot with the largest
/// midpoint among those above max(m, n) u max|A_ij|), written out here.
LinearSolution<Tracked<double>> augmented_reference(DenseMatrix<Tracked<double>> A, std::vector<Tracked<double>> b) {
  using T = Tracked<double>;
  const size_t m = A.size(), n = m ? A[0].size() : 0;
  double amax = 0;
  for (const auto& row : A)
    for (const T& v : row) amax = std::max(amax, std::abs(v.v));
  const double threshold = static_cast<double>(std::max(m, n)) * std::numeric_limits<double>::epsilon() / 2 * amax;
  LinearSolution<T> out;
  std::vector<size_t> pivots;
  size_t row = 0;
  for (size_t col = 0; col < n && row < m; ++col) {
    size_t best = m;
    double best_mag = -1;
    for (size_t r = row; r < m; ++r)
      if (std::abs(A[r][col].v) > threshold && std::abs(A[r][col].v) > best_mag) best = r, best_mag = std::abs(A[r][col].v);
    if (best == m) continue;
    std::swap(A[row], A[best]);
    std::swap(b[row], b[best]);
    for (size_t r = 0; r < m; ++r) {
      if (r == row || (A[r][col].v == 0 && A[r][col].e == 0)) continue;
      const T f = A[r][col] / A[row][col];
      for (size_t c = col; c < n; ++c) A[r][c] = A[r][c] - f * A[row][c];
      b[r] = b[r] - f * b[row];
    }
    pivots.push_back(col);
    ++row;
  }
  out.rank = static_cast<int>(row);
  for (size_t r = row; r < m; ++r) out.consistent = out.consistent && std::abs(b[r].v) <= threshold;
  if (out.consistent && row == n) {
    out.x.assign(n, T(0));
    for (size_t r = 0; r < row; ++r) out.x[pivots[r]] = b[r] / A[r][pivots[r]];
  }
  return out;
}

bool same_bits(const Tracked<double>& a, const Tracked<double>& b) {
  return std::bit_cast<std::uint64_t>(a.v) == std::bit_cast<std::uint64_t>(b.v) &&
         std::bit_cast<std::uint64_t>(a.e) == std::bit_cast<std::uint64_t>(b.e);
}

TEST(LinearSystem, OneFloatingEliminationReplayedOnTwoRightHandSidesIsBitForBitEliminatingEachAugmentedMatrix) {
  const unsigned seed = 29;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-4, 4), radius(0, 1e-12);
  std::uniform_int_distribution<int> size(1, 7), zero(0, 3);
  using T = Tracked<double>;
  int solved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Square systems mostly (solved ones), also one row more or fewer (inconsistent, underdetermined).
    const size_t n = static_cast<size_t>(size(rng)), m = trial % 4 == 1 ? n + 1 : trial % 4 == 2 && n > 1 ? n - 1 : n;
    DenseMatrix<T> A(m, std::vector<T>(n, T(0)));
    for (auto& row : A)
      for (T& v : row)
        if (zero(rng) != 0) v = T(value(rng), zero(rng) == 0 ? 0.0 : radius(rng));
    if (m > 1 && trial % 3 == 0)  // a dependent row: the rank and the consistency test matter
      for (size_t c = 0; c < n; ++c) A[m - 1][c] = A[0][c] * T(2);
    std::vector<std::vector<T>> rhs(2, std::vector<T>(m, T(0)));
    for (auto& b : rhs)
      for (T& v : b) v = T(value(rng), radius(rng));
    const LinearSystem<T> system(A);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
    for (const auto& b : rhs) {
      const auto ref = augmented_reference(A, b);
      const auto got = system.solve(b);
      EXPECT_EQ(system.rank(), ref.rank);
      EXPECT_EQ(got.rank, ref.rank);
      EXPECT_EQ(got.consistent, ref.consistent);
      ASSERT_EQ(got.x.size(), ref.x.size());
      for (size_t c = 0; c < ref.x.size(); ++c) EXPECT_TRUE(same_bits(got.x[c], ref.x[c])) << "x[" << c << "]";
      solved += !ref.x.empty();
    }
  }
  EXPECT_GT(solved, 100);  // the trials exercise solutions, not only rank-deficient systems
}

}  // namespace
}  // namespace linkproof
