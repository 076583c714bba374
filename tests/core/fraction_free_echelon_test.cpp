// FractionFreeEchelon: the same outcome of every added row, rank and consistency as
// RowEchelon<Rational> on random integer systems of every rank (fixed, printed seeds).
#include "core/fraction_free_echelon.h"

#include <gtest/gtest.h>

#include <random>

namespace linkproof {
namespace {

using cln::cl_I;

/// rows x columns integer system of rank <= `rank` (a product of random factors), right-hand
/// sides consistent with it unless `consistent` is false; some entries are 0 (sparse factors),
/// so pivot columns with a zero entry in the incoming row occur.
struct System {
  std::vector<std::vector<cl_I>> rows;
  std::vector<cl_I> rhs;
};

System random_system(std::mt19937_64& gen, int rows, int columns, int rank, bool consistent) {
  std::uniform_int_distribution<int> small(-9, 9), coin(0, 3);
  const auto entry = [&] { return coin(gen) == 0 ? 0 : small(gen); };
  std::vector<std::vector<long>> left(static_cast<size_t>(rows), std::vector<long>(static_cast<size_t>(rank)));
  std::vector<std::vector<long>> right(static_cast<size_t>(rank), std::vector<long>(static_cast<size_t>(columns)));
  for (auto& r : left)
    for (auto& v : r) v = entry();
  for (auto& r : right)
    for (auto& v : r) v = entry();
  std::vector<long> solution(static_cast<size_t>(columns));
  for (auto& v : solution) v = small(gen);
  System s;
  for (int i = 0; i < rows; ++i) {
    std::vector<cl_I> row(static_cast<size_t>(columns), 0);
    for (int c = 0; c < columns; ++c)
      for (int k = 0; k < rank; ++k)
        row[static_cast<size_t>(c)] = row[static_cast<size_t>(c)] + cl_I(left[static_cast<size_t>(i)][static_cast<size_t>(k)] *
                                                                          right[static_cast<size_t>(k)][static_cast<size_t>(c)]);
    cl_I b = 0;
    for (int c = 0; c < columns; ++c) b = b + row[static_cast<size_t>(c)] * solution[static_cast<size_t>(c)];
    if (!consistent && i == rows / 2) b = b + 1;
    s.rows.push_back(std::move(row));
    s.rhs.push_back(b);
  }
  return s;
}

TEST(FractionFreeEchelon, EveryRowHasTheOutcomeRowEchelonOverTheRationalsGives) {
  const std::uint64_t seed = 20261127;
  std::mt19937_64 gen(seed);
  std::uniform_int_distribution<int> size(1, 14);
  int checked = 0, rank_deficient = 0, inconsistent = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int rows = size(gen), columns = size(gen);
    const int rank = std::uniform_int_distribution<int>(0, std::min(rows, columns))(gen);
    const bool consistent = trial % 3 != 0;
    const System s = random_system(gen, rows, columns, rank, consistent);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
    FractionFreeEchelon ff(columns);
    RowEchelon<Rational> reference(columns);
    for (int i = 0; i < rows; ++i) {
      std::vector<std::pair<int, Rational>> sparse;
      for (int c = 0; c < columns; ++c) sparse.emplace_back(c, s.rows[static_cast<size_t>(i)][static_cast<size_t>(c)]);
      const RowOutcome want = reference.add(make_sparse_row(std::move(sparse)), s.rhs[static_cast<size_t>(i)]);
      EXPECT_EQ(ff.add(s.rows[static_cast<size_t>(i)], s.rhs[static_cast<size_t>(i)]), want) << "row " << i;
    }
    EXPECT_EQ(ff.rank(), reference.rank());
    EXPECT_EQ(ff.augmented_rank(), reference.augmented_rank());
    EXPECT_EQ(ff.relations(), rows);
    ++checked;
    rank_deficient += reference.rank() < std::min(rows, columns);
    inconsistent += !reference.is_consistent();
  }
  // The corpus reaches every case it is meant to.
  EXPECT_EQ(checked, 400);
  EXPECT_GT(rank_deficient, 100);
  EXPECT_GT(inconsistent, 50);
}

TEST(FractionFreeEchelon, EntriesStayMinorsOnAFullRankSystem) {
  // A 40 x 40 system with entries in [-9, 9]: a division that was not exact would throw in
  // cln::exquo, and entries growing like 2^k (no division) would exceed the Hadamard bound
  // (40 * 9^2)^(40/2) < 2^240 by far; both are ruled out by finishing with full rank.
  std::mt19937_64 gen(7);
  const System s = random_system(gen, 40, 40, 40, true);
  FractionFreeEchelon ff(40);
  for (size_t i = 0; i < s.rows.size(); ++i) ff.add(s.rows[i], s.rhs[i]);
  EXPECT_EQ(ff.rank(), 40);
  EXPECT_TRUE(ff.is_consistent());
}

}  // namespace
}  // namespace linkproof
