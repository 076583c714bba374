// The block triangular form of a square sparse pattern (core/block_triangular.h).
#include "core/block_triangular.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>
#include <vector>

namespace linkproof {
namespace {

using Pattern = std::vector<std::vector<bool>>;

Pattern pattern(const std::vector<std::string>& rows) {
  Pattern p;
  for (const std::string& r : rows) {
    p.emplace_back();
    for (char ch : r) p.back().push_back(ch == 'x');
  }
  return p;
}

// Every block is square, the blocks partition rows and columns, and each row's entries outside
// its block lie in columns of blocks solved before it: the solve order is valid.
void expect_valid_order(const Pattern& p, const std::vector<MatrixBlock>& blocks) {
  const size_t n = p.size();
  std::vector<int> block_of_col(n, -1);
  std::set<int> rows_seen;
  for (size_t b = 0; b < blocks.size(); ++b) {
    ASSERT_EQ(blocks[b].rows.size(), blocks[b].cols.size());
    for (int c : blocks[b].cols) {
      ASSERT_EQ(block_of_col[static_cast<size_t>(c)], -1) << "column " << c << " in two blocks";
      block_of_col[static_cast<size_t>(c)] = static_cast<int>(b);
    }
    for (int r : blocks[b].rows) ASSERT_TRUE(rows_seen.insert(r).second) << "row " << r << " in two blocks";
  }
  ASSERT_EQ(rows_seen.size(), n);
  for (size_t b = 0; b < blocks.size(); ++b)
    for (int r : blocks[b].rows)
      for (size_t c = 0; c < n; ++c)
        if (p[static_cast<size_t>(r)][c]) {
          EXPECT_LE(block_of_col[c], static_cast<int>(b)) << "row " << r << ", column " << c;
        }
}

TEST(BlockTriangularForm, ALowerTriangularPatternIsOneBlockPerUnknownInOrder) {
  const Pattern p = pattern({"x..", "xx.", ".xx"});
  const auto blocks = block_triangular_form(p);
  ASSERT_TRUE(blocks);
  ASSERT_EQ(blocks->size(), 3u);
  EXPECT_EQ((*blocks)[0].cols, std::vector<int>{0});
  EXPECT_EQ((*blocks)[1].cols, std::vector<int>{1});
  EXPECT_EQ((*blocks)[2].cols, std::vector<int>{2});
}

TEST(BlockTriangularForm, ADyadAfterItsDriverIsOneBlockOfTwoSolvedSecond) {
  // Unknowns: the driver's rate (column 0), then two rates coupled by two loop equations.
  const Pattern p = pattern({".xx", "x..", "xxx"});
  const auto blocks = block_triangular_form(p);
  ASSERT_TRUE(blocks);
  ASSERT_EQ(blocks->size(), 2u);
  EXPECT_EQ((*blocks)[0].cols, std::vector<int>{0});
  EXPECT_EQ((*blocks)[0].rows, std::vector<int>{1});
  EXPECT_EQ((*blocks)[1].cols, (std::vector<int>{1, 2}));
  EXPECT_EQ((*blocks)[1].rows, (std::vector<int>{0, 2}));
  expect_valid_order(p, *blocks);
}

TEST(BlockTriangularForm, AFullPatternIsASingleBlock) {
  const auto blocks = block_triangular_form(pattern({"xxx", "xxx", "xxx"}));
  ASSERT_TRUE(blocks);
  ASSERT_EQ(blocks->size(), 1u);
  EXPECT_EQ((*blocks)[0].cols, (std::vector<int>{0, 1, 2}));
}

TEST(BlockTriangularForm, AStructurallySingularPatternHasNoForm) {
  EXPECT_FALSE(block_triangular_form(pattern({"xx.", "xx.", "xx."})));  // column 2 is empty
  EXPECT_FALSE(block_triangular_form(pattern({"x..", "...", "..x"})));  // row 1 is empty
  EXPECT_FALSE(block_triangular_form(pattern({"x..", "x..", "xxx"})));  // rows 0, 1 share one column
}

TEST(BlockTriangularForm, NeedsAnAugmentingPathToMatchEveryRow) {
  // Matching row 0 to column 0 first forces row 1 to take it back through a path.
  const Pattern p = pattern({"xx.", "x..", ".xx"});
  const auto blocks = block_triangular_form(p);
  ASSERT_TRUE(blocks);
  expect_valid_order(p, *blocks);
  EXPECT_EQ(blocks->size(), 3u);
}

TEST(BlockTriangularForm, RandomPermutedBlockPatternsGiveValidOrdersAndTheirBlocks) {
  const unsigned seed = 20261128;
  std::mt19937 rng(seed);
  SCOPED_TRACE("seed " + std::to_string(seed));
  for (int trial = 0; trial < 200; ++trial) {
    // Blocks of sizes 1..4 on the diagonal, full inside, random entries below, then rows and
    // columns permuted at random: the form must find blocks of those sizes again.
    std::vector<int> sizes;
    int n = 0;
    while (n < 10) sizes.push_back(1 + static_cast<int>(rng() % 4)), n += sizes.back();
    Pattern p(static_cast<size_t>(n), std::vector<bool>(static_cast<size_t>(n), false));
    int start = 0;
    for (int s : sizes) {
      for (int r = start; r < start + s; ++r) {
        for (int c = start; c < start + s; ++c) p[static_cast<size_t>(r)][static_cast<size_t>(c)] = true;
        for (int c = 0; c < start; ++c) p[static_cast<size_t>(r)][static_cast<size_t>(c)] = rng() % 3 == 0;
      }
      start += s;
    }
    std::vector<int> pr(static_cast<size_t>(n)), pc(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) pr[static_cast<size_t>(i)] = pc[static_cast<size_t>(i)] = i;
    std::shuffle(pr.begin(), pr.end(), rng);
    std::shuffle(pc.begin(), pc.end(), rng);
    Pattern q(static_cast<size_t>(n), std::vector<bool>(static_cast<size_t>(n)));
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        q[static_cast<size_t>(pr[static_cast<size_t>(r)])][static_cast<size_t>(pc[static_cast<size_t>(c)])] =
            p[static_cast<size_t>(r)][static_cast<size_t>(c)];
    const auto blocks = block_triangular_form(q);
    ASSERT_TRUE(blocks) << "trial " << trial;
    expect_valid_order(q, *blocks);
    std::multiset<size_t> found, made;
    for (const MatrixBlock& b : *blocks) found.insert(b.cols.size());
    for (int s : sizes) made.insert(static_cast<size_t>(s));
    EXPECT_EQ(found, made) << "trial " << trial;
  }
}

}  // namespace
}  // namespace linkproof
