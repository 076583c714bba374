// RowEchelon: exact rank, consistency and solution, against a dense reference elimination.
#include "core/row_echelon.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "check/random_polygon.h"

namespace linkproof {
namespace {

using Row = SparseRow<Rational>;

/// Independent reference: dense Gauss-Jordan over the rationals on [A | b]; returns
/// (rank A, rank [A | b]).
std::pair<int, int> dense_ranks(std::vector<std::vector<Rational>> m, int columns) {
  const auto rank_of = [](std::vector<std::vector<Rational>> a, int cols) {
    int r = 0;
    for (int c = 0; c < cols && r < static_cast<int>(a.size()); ++c) {
      int p = r;
      while (p < static_cast<int>(a.size()) && cln::zerop(a[static_cast<size_t>(p)][static_cast<size_t>(c)])) ++p;
      if (p == static_cast<int>(a.size())) continue;
      std::swap(a[static_cast<size_t>(p)], a[static_cast<size_t>(r)]);
      for (size_t i = 0; i < a.size(); ++i) {
        if (static_cast<int>(i) == r) continue;
        const Rational f = a[i][static_cast<size_t>(c)] / a[static_cast<size_t>(r)][static_cast<size_t>(c)];
        for (int k = 0; k < cols; ++k)
          a[i][static_cast<size_t>(k)] = a[i][static_cast<size_t>(k)] - f * a[static_cast<size_t>(r)][static_cast<size_t>(k)];
      }
      ++r;
    }
    return r;
  };
  return {rank_of(m, columns), rank_of(m, columns + 1)};
}

TEST(RowEchelon, IndependentDependentAndInconsistentRowsAreTold) {
  RowEchelon<Rational> e(3);
  EXPECT_EQ(e.add(make_sparse_row<Rational>({{0, 1}, {1, 1}}), 2), RowOutcome::Independent);
  EXPECT_EQ(e.add(make_sparse_row<Rational>({{1, 1}, {2, -1}}), 0), RowOutcome::Independent);
  // (x0 + x1) - (x1 - x2) = x0 + x2 = 2: dependent and consistent.
  EXPECT_EQ(e.add(make_sparse_row<Rational>({{0, 1}, {2, 1}}), 2), RowOutcome::Dependent);
  EXPECT_EQ(e.rank(), 2);
  EXPECT_TRUE(e.is_consistent());
  // The same left side with another right side contradicts them.
  EXPECT_EQ(e.add(make_sparse_row<Rational>({{0, 2}, {2, 2}}), 5), RowOutcome::Inconsistent);
  EXPECT_EQ(e.rank(), 2);
  EXPECT_EQ(e.augmented_rank(), 3);
  EXPECT_FALSE(e.is_consistent());
  EXPECT_EQ(e.relations(), 4);
}

TEST(RowEchelon, DeterminesTheSolutionOfANonSingularSystem) {
  // 2x + y = 1, x - 3z = 2, y + z = 1/2: the determined values must satisfy all three.
  RowEchelon<Rational> e(3);
  e.add(make_sparse_row<Rational>({{0, 2}, {1, 1}}), 1);
  EXPECT_FALSE(e.determined_value(0).has_value());
  e.add(make_sparse_row<Rational>({{0, 1}, {2, -3}}), 2);
  e.add(make_sparse_row<Rational>({{1, 1}, {2, 1}}), Rational(1) / 2);
  ASSERT_EQ(e.rank(), 3);
  const Rational x = *e.determined_value(0), y = *e.determined_value(1), z = *e.determined_value(2);
  EXPECT_EQ(2 * x + y, 1);
  EXPECT_EQ(x - 3 * z, 2);
  EXPECT_EQ(y + z, Rational(1) / 2);
}

TEST(RowEchelon, MakeSparseRowSortsMergesAndDropsZeros) {
  const Row r = make_sparse_row<Rational>({{3, 1}, {1, 2}, {3, -1}, {0, 0}, {1, 1}});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].first, 1);
  EXPECT_EQ(r[0].second, 3);
}

TEST(RowEchelon, MatchesDenseReferenceOnRandomLowRankSystems) {
  // Rows are random combinations of a few random base rows (so ranks are deficient), with
  // right-hand sides either consistent or perturbed. Seed printed by the failure message.
  const std::uint64_t seed = 20261121;
  SplitMix64 rng(seed);
  for (int trial = 0; trial < 200; ++trial) {
    const int cols = static_cast<int>(rng.uniform(1, 9));
    const int base = static_cast<int>(rng.uniform(1, cols + 1));
    const int rows = static_cast<int>(rng.uniform(1, 14));
    std::vector<std::vector<Rational>> basis(static_cast<size_t>(base), std::vector<Rational>(static_cast<size_t>(cols + 1)));
    for (auto& b : basis)
      for (auto& v : b) v = rng.uniform(0, 2) == 0 ? Rational(0) : Rational(rng.uniform(-4, 4)) / Rational(rng.uniform(1, 3));
    std::vector<std::vector<Rational>> dense;
    RowEchelon<Rational> e(cols);
    for (int r = 0; r < rows; ++r) {
      std::vector<Rational> row(static_cast<size_t>(cols + 1), Rational(0));
      for (const auto& b : basis) {
        const Rational f = rng.uniform(-2, 2);
        for (size_t k = 0; k < row.size(); ++k) row[k] = row[k] + f * b[k];
      }
      if (rng.uniform(0, 9) == 0) row.back() = row.back() + 1;  // occasionally inconsistent
      dense.push_back(row);
      std::vector<std::pair<int, Rational>> entries;
      for (int k = 0; k < cols; ++k) entries.emplace_back(k, row[static_cast<size_t>(k)]);
      e.add(make_sparse_row(std::move(entries)), row.back());
    }
    const auto [rank, aug] = dense_ranks(dense, cols);
    ASSERT_EQ(e.rank(), rank) << "seed " << seed << " trial " << trial;
    ASSERT_EQ(e.augmented_rank(), aug) << "seed " << seed << " trial " << trial;
  }
}

}  // namespace
}  // namespace linkproof
