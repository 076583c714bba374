// DenseMatrix: one block of entries read as rows (core/dense_matrix.h).
#include "core/dense_matrix.h"

#include <gtest/gtest.h>

#include <vector>

namespace linkproof {
namespace {

std::vector<std::vector<int>> rows_of(const DenseMatrix<int>& m) {
  std::vector<std::vector<int>> out;
  for (const auto row : m) out.emplace_back(row.begin(), row.end());
  return out;
}

TEST(DenseMatrix, ReadsAsTheRowsItWasWrittenWith) {
  const DenseMatrix<int> m{{1, 2, 3}, {4, 5, 6}};
  EXPECT_EQ(m.size(), 2u);
  EXPECT_EQ(m.cols(), 3u);
  EXPECT_EQ(m[1][0], 4);
  EXPECT_EQ(m[0].size(), 3u);
  EXPECT_EQ(rows_of(m), (std::vector<std::vector<int>>{{1, 2, 3}, {4, 5, 6}}));
}

TEST(DenseMatrix, SwappingRowsExchangesWholeRowsAndNothingElse) {
  DenseMatrix<int> m{{1, 2}, {3, 4}, {5, 6}};
  m.swap_rows(0, 2);
  m.swap_rows(1, 1);
  EXPECT_EQ(rows_of(m), (std::vector<std::vector<int>>{{5, 6}, {3, 4}, {1, 2}}));
}

TEST(DenseMatrix, RowsAddedToAMatrixOfKnownWidthAreFilledAndWritable) {
  DenseMatrix<int> m = DenseMatrix<int>::with_columns(3);
  EXPECT_TRUE(m.empty());
  m.add_row(0)[1] = 7;
  m.add_row(2);
  m.push_back(std::vector<int>{8, 9, 10});
  EXPECT_EQ(rows_of(m), (std::vector<std::vector<int>>{{0, 7, 0}, {2, 2, 2}, {8, 9, 10}}));
  EXPECT_EQ(m, (DenseMatrix<int>{{0, 7, 0}, {2, 2, 2}, {8, 9, 10}}));
  EXPECT_NE(m, (DenseMatrix<int>{{0, 7, 0}, {2, 2, 2}, {8, 9, 11}}));
}

TEST(DenseMatrix, ARowOfAnotherLengthIsAnInternalError) {
#ifdef LINKPROOF_NO_ASSERTS
  GTEST_SKIP() << "built without LINKPROOF_ASSERT checks (LINKPROOF_ASSERTS=OFF)";
#endif
  DenseMatrix<int> m{{1, 2}};
  EXPECT_THROW(m.push_back(std::vector<int>{1, 2, 3}), InternalError);
  DenseMatrix<int> n = DenseMatrix<int>::with_columns(2);
  EXPECT_THROW(n.push_back(std::vector<int>{1}), InternalError);
}

TEST(DenseMatrix, AFilledMatrixHasEveryEntryTheFill) {
  const DenseMatrix<int> m(2, 3, 5);
  EXPECT_EQ(rows_of(m), (std::vector<std::vector<int>>{{5, 5, 5}, {5, 5, 5}}));
}

}  // namespace
}  // namespace linkproof
