// solve_linear_system: the exact (sparse) route gives the rank, consistency and solution of a
// dense reference elimination, on square, rectangular and rank-deficient systems.
#include "mechanism/linear_system.h"

#include <gtest/gtest.h>

#include <random>

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

}  // namespace
}  // namespace linkproof
