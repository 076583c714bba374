// A dense matrix stored row after row in one block, read as a sequence of rows: A.size() rows,
// A[r] a span of A.cols() entries, A[r][c] an entry, push_back(row) a new last row.
//
// Why not a vector of row vectors: a mechanism's velocity system is a few rows of a few
// entries, solved once per sampled configuration, and one allocation per row (and per copy of
// it) was a fifth of a sampled configuration in double (issue 26's profile). One block costs one.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <span>
#include <vector>

#include "linkproof/core/error.h"

namespace linkproof {

template <class T>
class DenseMatrix {
 public:
  DenseMatrix() = default;
  /// rows x cols entries, each `fill`.
  DenseMatrix(size_t rows, size_t cols, const T& fill) : rows_(rows), cols_(cols), entries_(rows * cols, fill) {}
  /// Written row by row: {{a, b}, {c, d}}; every row has as many entries as the first.
  DenseMatrix(std::initializer_list<std::initializer_list<T>> rows) {
    for (const auto& row : rows) push_back(std::span<const T>(row.begin(), row.size()));
  }

  /// The number of rows.
  size_t size() const { return rows_; }
  bool empty() const { return rows_ == 0; }
  /// The number of columns (0 before the first row of a matrix built row by row, unless made
  /// by with_columns).
  size_t cols() const { return cols_; }

  std::span<T> operator[](size_t r) { return {entries_.data() + r * cols_, cols_}; }
  std::span<const T> operator[](size_t r) const { return {entries_.data() + r * cols_, cols_}; }

  /// The rows in order (range-for over a matrix reads it row by row).
  template <class Matrix>
  class RowIterator {
   public:
    RowIterator(Matrix* m, size_t r) : m_(m), r_(r) {}
    auto operator*() const { return (*m_)[r_]; }
    RowIterator& operator++() { return ++r_, *this; }
    bool operator==(const RowIterator& o) const { return r_ == o.r_; }

   private:
    Matrix* m_;
    size_t r_;
  };
  RowIterator<DenseMatrix> begin() { return {this, 0}; }
  RowIterator<DenseMatrix> end() { return {this, rows_}; }
  RowIterator<const DenseMatrix> begin() const { return {this, 0}; }
  RowIterator<const DenseMatrix> end() const { return {this, rows_}; }

  void reserve(size_t rows) { entries_.reserve(rows * std::max<size_t>(cols_, 1)); }

  /// Appends a row; the first row fixes the number of columns, every later one must match it.
  void push_back(std::span<const T> row) {
    if (rows_ == 0 && cols_ == 0) cols_ = row.size();
    LINKPROOF_ASSERT(row.size() == cols_, "DenseMatrix: a row of the wrong length");
    entries_.insert(entries_.end(), row.begin(), row.end());
    ++rows_;
  }
  void push_back(const std::vector<T>& row) { push_back(std::span<const T>(row)); }
  /// Appends a row of `cols()` entries, each `fill`, and returns it to be written.
  std::span<T> add_row(const T& fill) {
    entries_.resize(entries_.size() + cols_, fill);
    return (*this)[rows_++];
  }
  /// Makes an empty matrix of `cols` columns, to be filled with add_row.
  static DenseMatrix with_columns(size_t cols) {
    DenseMatrix m;
    m.cols_ = cols;
    return m;
  }

  bool operator==(const DenseMatrix&) const = default;

  void swap_rows(size_t a, size_t b) {
    if (a != b) std::swap_ranges(entries_.begin() + static_cast<std::ptrdiff_t>(a * cols_),
                                 entries_.begin() + static_cast<std::ptrdiff_t>((a + 1) * cols_),
                                 entries_.begin() + static_cast<std::ptrdiff_t>(b * cols_));
  }

 private:
  size_t rows_ = 0, cols_ = 0;
  std::vector<T> entries_;
};

}  // namespace linkproof
