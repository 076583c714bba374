// solve_linear_system: the exact (sparse) route gives the rank, consistency and solution of a
// dense reference elimination, on square, rectangular and rank-deficient systems; the floating
// route, one elimination replayed on several right-hand sides (LinearSystem), gives the same
// bits as eliminating each [A | b] on its own, and every solution encloses the exact one.
#include "mechanism/linear_system.h"

#include <cln/rational.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "core/tracked.h"

namespace linkproof {
namespace {

/// Reference: dense Gauss-Jordan on [A | b] over the rationals, written out here.
LinearSolution<Rational> dense_reference(DenseMatrix<Rational> A, std::vector<Rational> b) {
  const size_t m = A.size(), n = A.cols();
  LinearSolution<Rational> out;
  std::vector<size_t> pivots;
  size_t row = 0;
  for (size_t col = 0; col < n && row < m; ++col) {
    size_t p = row;
    while (p < m && cln::zerop(A[p][col])) ++p;
    if (p == m) continue;
    A.swap_rows(p, row);
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
    DenseMatrix<Rational> A(m, n, Rational(0));
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
/// midpoint among those above max(m, n) u max|A_ij|), written out here; a row operation writes
/// the exact 0 it makes in the pivot's column and leaves the entries where the pivot row is an
/// exact 0.
LinearSolution<Tracked<double>> augmented_reference(DenseMatrix<Tracked<double>> A, std::vector<Tracked<double>> b) {
  using T = Tracked<double>;
  const size_t m = A.size(), n = A.cols();
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
    A.swap_rows(row, best);
    std::swap(b[row], b[best]);
    const auto exact_zero = [](const T& v) { return v.v == 0 && v.e == 0; };
    for (size_t r = 0; r < m; ++r) {
      if (r == row || exact_zero(A[r][col])) continue;
      const T f = A[r][col] / A[row][col];
      A[r][col] = T(0);  // exactly 0 for the exact operands
      for (size_t c = col + 1; c < n; ++c)
        if (!exact_zero(A[row][c])) A[r][c] = A[r][c] - f * A[row][c];  // a - f 0 = a
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

// A double's exact value (subnormals too: CLN's double floats have none).
Rational exact_of(double v) {
  if (v == 0) return 0;
  int e = 0;
  const double m = std::frexp(v, &e);  // v = m 2^e, 1/2 <= |m| < 1
  return Rational(static_cast<long long>(std::ldexp(m, 53))) * cln::expt(Rational(2), e - 53);
}

DenseMatrix<Rational> exact_rows(const DenseMatrix<Tracked<double>>& A) {
  DenseMatrix<Rational> out;
  for (size_t i = 0; i < A.size(); ++i) {
    std::vector<Rational> r;
    for (const auto& v : A[i]) r.push_back(exact_of(v.v));
    out.push_back(r);
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
    DenseMatrix<T> A(m, n, T(0));
    for (size_t r = 0; r < A.size(); ++r)
      for (T& v : A[r])
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
      EXPECT_EQ(LinearSystem<T>::rank_of(A), ref.rank);
      EXPECT_EQ(got.rank, ref.rank);
      EXPECT_EQ(got.consistent, ref.consistent);
      ASSERT_EQ(got.x.size(), ref.x.size());
      for (size_t c = 0; c < ref.x.size(); ++c) EXPECT_TRUE(same_bits(got.x[c], ref.x[c])) << "x[" << c << "]";
      solved += !ref.x.empty();
    }
  }
  EXPECT_GT(solved, 100);  // the trials exercise solutions, not only rank-deficient systems
}


// The exact solution of a system whose entries are the midpoints (radius 0): every floating
// solution must enclose it, x.v - x.e <= x <= x.v + x.e (core/tracked.h), whatever the pivots.
std::vector<Rational> exact_solution_of_midpoints(const DenseMatrix<Tracked<double>>& A, const std::vector<Tracked<double>>& b) {
  const DenseMatrix<Rational> Aq = exact_rows(A);
  std::vector<Rational> bq;
  for (const auto& v : b) bq.push_back(exact_of(v.v));
  return solve_linear_system<Rational>(Aq, bq).x;
}

bool encloses(const Tracked<double>& x, const Rational& exact) {
  return std::isfinite(x.e) && cln::abs(exact - exact_of(x.v)) <= exact_of(x.e);
}

TEST(LinearSystem, EveryFloatingSolutionEnclosesTheExactSolutionOfItsMidpoints) {
  const unsigned seed = 31;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> small(-9, 9), size(1, 6), zero(0, 2);
  using T = Tracked<double>;
  int enclosed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // A mechanism's shape: constraint rows (mostly zeros, sometimes a dependent one), then unit
    // input rows; radius 0, so the exact solution of the midpoints is the one to enclose.
    const size_t n = static_cast<size_t>(size(rng));
    const size_t inputs = static_cast<size_t>(std::uniform_int_distribution<int>(0, 2)(rng));
    const size_t constraints = n > inputs ? n - inputs + (trial % 5 == 0 ? 1 : 0) : 1;
    DenseMatrix<T> A(constraints, n, T(0));
    for (size_t r = 0; r < A.size(); ++r)
      for (T& v : A[r])
        if (zero(rng) != 0) v = T(std::ldexp(small(rng), std::uniform_int_distribution<int>(-8, 8)(rng)), 0.0);
    if (constraints > 1 && trial % 3 == 0)
      for (size_t c = 0; c < n; ++c) A[constraints - 1][c] = A[0][c] * T(3);
    for (size_t k = 0; k < inputs; ++k) {
      std::vector<T> row(n, T(0));
      row[static_cast<size_t>(std::uniform_int_distribution<int>(0, static_cast<int>(n) - 1)(rng))] = T(1);
      A.push_back(row);
    }
    std::vector<T> b(A.size(), T(0));
    for (T& v : b) v = T(small(rng));
    SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
    const LinearSystem<T> system(A);
    EXPECT_EQ(system.rank(), LinearSystem<Rational>(exact_rows(A)).rank());
    EXPECT_EQ(LinearSystem<T>::rank_of(A), system.rank());
    const LinearSolution<T> got = system.solve(b);
    const std::vector<Rational> exact = exact_solution_of_midpoints(A, b);
    if (got.x.empty() || exact.empty()) continue;
    for (size_t c = 0; c < n; ++c) EXPECT_TRUE(encloses(got.x[c], exact[c])) << "x[" << c << "]";
    ++enclosed;
  }
  EXPECT_GT(enclosed, 50);  // the trials exercise solutions, not only singular systems
}

TEST(LinearSystem, AnInputRowIsThePivotWhereTheConstraintsLeaveOnlyARoundingResidue) {
  // A four-bar with a crank 100 times shorter than its other links, its joints rounded to double
  // (O2 = (2, 0), A = (2.01, 0.01), B = (3, 1), O4 = (0, 0)): eliminating the loop's two rows
  // first leaves 2e-14 +- 2.2e-14 in the coupler's column, which is no pivot; the crank's unit
  // input row is. Every rate is then bounded and encloses the exact one.
  using T = Tracked<double>;
  const T O2x = from_rational<T>(2), Ax = from_rational<T>(Rational(201) / 100), Ay = from_rational<T>(Rational(1) / 100);
  const T Bx = from_rational<T>(3), By = from_rational<T>(1), z = from_int<T>(0);
  const T crank_x = Ax - O2x, crank_y = Ay - z, coupler_x = Bx - Ax, coupler_y = By - Ay;
  const DenseMatrix<T> A{{-crank_y, -coupler_y, By}, {crank_x, coupler_x, z - Bx}, {T(1), T(0), T(0)}};
  const LinearSolution<T> got = LinearSystem<T>(A).solve({z, z, T(1)});
  ASSERT_EQ(got.x.size(), 3u);
  // The exact rates of the exact four-bar (omega_crank = 1): omega_coupler = -1/99, omega_rocker = 0.
  const std::vector<Rational> exact{1, Rational(-1) / 99, 0};
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_LT(got.x[c].e, 1e-12) << "x[" << c << "]";
    EXPECT_TRUE(encloses(got.x[c], exact[c])) << "x[" << c << "]";  // the joints' rounding is in the radii
  }
}

}  // namespace
}  // namespace linkproof
