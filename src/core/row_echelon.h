// Exact rank of a system of linear (or affine) relations, built one relation at a time.
//
// RowEchelon<T> keeps a sparse *reduced* row-echelon basis of the relations added so far, over
// an exact field T (Rational; any T with +, -, *, / and ScalarTraits<T>::is_zero works). Every
// relation is  sum_c a_c x_c = b  over the unknowns x_0 .. x_{m-1}. Adding one:
//   1. it is reduced by the basis: every basis row has pivot coefficient 1 and no entry in any
//      other pivot column, so one subtraction per pivot column present in the new row clears
//      them all (the subtractions bring in non-pivot columns only);
//   2. if unknowns remain, the largest remaining column becomes a new pivot, the row is scaled
//      to pivot 1 and the new pivot column is eliminated from the earlier basis rows that
//      contain it (found through a column -> rows index), so the basis stays reduced;
//   3. if no unknown remains but b != 0, the relation contradicts the earlier ones: the system
//      is inconsistent (the augmented matrix [A | b] has one more rank than A).
// The rank of A is the number of pivots; the augmented rank adds 1 when a contradiction was
// seen. Nothing is approximated: the result is the rank over the rationals.
//
// Cost: reduction is proportional to the fill of the rows involved, not to the matrix size, so
// sparse systems whose basis stays sparse are cheap. The triangle relations of n bodies
// (counting.h) added in lexicographic order of the triples (0,j,k) first are the extreme case:
// each of the first T rows brings its own pivot x_jk and the other C(n,3) - T rows reduce to 0
// after three subtractions, so n = 60 (34220 relations in 1770 unknowns) takes milliseconds.
// The order affects the speed only, never the rank.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "linkproof/core/error.h"
#include "core/scalar.h"

namespace linkproof {

/// A sparse row: (column, coefficient) pairs, columns strictly increasing, no zero coefficient.
template <class T>
using SparseRow = std::vector<std::pair<int, T>>;

/// Builds a SparseRow from unsorted (column, coefficient) pairs: sorts, sums repeated columns,
/// drops zeros.
template <class T>
SparseRow<T> make_sparse_row(std::vector<std::pair<int, T>> entries) {
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  SparseRow<T> out;
  for (auto& e : entries) {
    if (!out.empty() && out.back().first == e.first)
      out.back().second = out.back().second + e.second;
    else
      out.push_back(std::move(e));
    if (is_zero(out.back().second)) out.pop_back();
  }
  return out;
}

/// What adding one relation did to the system.
enum class RowOutcome {
  Independent,  ///< raised the rank of A by one
  Dependent,    ///< a combination of the earlier relations (A and [A | b] keep their rank)
  Inconsistent  ///< A's part is a combination of the earlier rows but b is not: no solution
};

template <class T>
class RowEchelon {
 public:
  /// A system in `columns` unknowns.
  explicit RowEchelon(int columns) : columns_(columns), pivot_row_(static_cast<size_t>(columns), -1),
                                     rows_with_column_(static_cast<size_t>(columns)) {}

  int columns() const { return columns_; }
  /// Number of relations added so far.
  long relations() const { return relations_; }
  /// Rank of the coefficient matrix A.
  int rank() const { return static_cast<int>(basis_.size()); }
  /// Rank of the augmented matrix [A | b].
  int augmented_rank() const { return rank() + (inconsistent_ ? 1 : 0); }
  bool is_consistent() const { return !inconsistent_; }

  /// Adds the relation sum_c row_c x_c = rhs. `row` must be a valid SparseRow with columns in
  /// [0, columns()).
  RowOutcome add(const SparseRow<T>& row, const T& rhs) {
    ++relations_;
    T b = rhs;
    // 1. Reduce by the basis (one subtraction per pivot column of the original row), in a dense
    //    scratch row: each subtraction touches only the basis row's entries (no row copies).
    if (static_cast<int>(scratch_.size()) < columns_) {
      scratch_.resize(static_cast<size_t>(columns_), from_int<T>(0));
      touched_mark_.resize(static_cast<size_t>(columns_), 0);
    }
    const auto touch = [this](int col) {
      if (!touched_mark_[static_cast<size_t>(col)]) {
        touched_mark_[static_cast<size_t>(col)] = 1;
        touched_.push_back(col);
      }
    };
    for (const auto& [col, coeff] : row) {
      LINKPROOF_ASSERT(col >= 0 && col < columns_, "RowEchelon: column out of range");
      scratch_[static_cast<size_t>(col)] = coeff;
      touch(col);
    }
    for (const auto& [col, coeff] : row) {
      const int p = pivot_row_[static_cast<size_t>(col)];
      if (p < 0) continue;
      const T f = scratch_[static_cast<size_t>(col)];
      if (is_zero(f)) continue;
      for (const auto& [c, v] : basis_[static_cast<size_t>(p)].row) {
        touch(c);
        scratch_[static_cast<size_t>(c)] = scratch_[static_cast<size_t>(c)] - f * v;
      }
      b = b - f * basis_[static_cast<size_t>(p)].rhs;
    }
    std::sort(touched_.begin(), touched_.end());
    SparseRow<T> r;
    r.reserve(touched_.size());
    for (int c : touched_) {
      T& v = scratch_[static_cast<size_t>(c)];
      if (!is_zero(v)) r.emplace_back(c, std::move(v));
      v = from_int<T>(0);
      touched_mark_[static_cast<size_t>(c)] = 0;
    }
    touched_.clear();
    if (r.empty()) {
      if (is_zero(b)) return RowOutcome::Dependent;
      inconsistent_ = true;
      return RowOutcome::Inconsistent;
    }
    // 2. New pivot: the largest remaining column; scale to 1.
    const int pc = r.back().first;
    const T inv = from_int<T>(1) / r.back().second;
    for (auto& e : r) e.second = e.second * inv;
    b = b * inv;
    // Eliminate pc from the earlier rows that contain it.
    for (int q : rows_with_column_[static_cast<size_t>(pc)]) {
      Basis& other = basis_[static_cast<size_t>(q)];
      const T f = coefficient(other.row, pc);
      if (is_zero(f)) continue;  // stale index entry
      other.row = axpy(other.row, f, r);
      other.rhs = other.rhs - f * b;
      index_row(q);
    }
    rows_with_column_[static_cast<size_t>(pc)].clear();
    const int id = rank();
    pivot_row_[static_cast<size_t>(pc)] = id;
    basis_.push_back({pc, std::move(r), b});
    index_row(id);
    return RowOutcome::Independent;
  }

  /// Appends `more` unknowns (columns columns() .. columns() + more - 1) that no relation so far
  /// contains: the rank is unchanged, later relations may use them.
  void add_columns(int more) {
    columns_ += more;
    pivot_row_.resize(static_cast<size_t>(columns_), -1);
    rows_with_column_.resize(static_cast<size_t>(columns_));
  }

  /// The value of unknown `col` if the relations fix it (its pivot row has no free column),
  /// otherwise nullopt. Meaningful only while the system is consistent.
  std::optional<T> determined_value(int col) const {
    const int p = pivot_row_[static_cast<size_t>(col)];
    if (p < 0) return std::nullopt;
    const Basis& bs = basis_[static_cast<size_t>(p)];
    if (bs.row.size() != 1) return std::nullopt;
    return bs.rhs;
  }

 private:
  struct Basis {
    int pivot;
    SparseRow<T> row;
    T rhs;
  };

  static T coefficient(const SparseRow<T>& r, int col) {
    auto it = std::lower_bound(r.begin(), r.end(), col, [](const auto& e, int c) { return e.first < c; });
    return (it != r.end() && it->first == col) ? it->second : from_int<T>(0);
  }

  /// r - f * s (sparse merge).
  static SparseRow<T> axpy(const SparseRow<T>& r, const T& f, const SparseRow<T>& s) {
    SparseRow<T> out;
    out.reserve(r.size() + s.size());
    size_t i = 0, k = 0;
    while (i < r.size() || k < s.size()) {
      if (k == s.size() || (i < r.size() && r[i].first < s[k].first)) {
        out.push_back(r[i++]);
      } else if (i == r.size() || s[k].first < r[i].first) {
        out.emplace_back(s[k].first, -(f * s[k].second));
        ++k;
      } else {
        T v = r[i].second - f * s[k].second;
        if (!is_zero(v)) out.emplace_back(r[i].first, std::move(v));
        ++i;
        ++k;
      }
    }
    return out;
  }

  /// Records the non-pivot columns of basis row q in the column index (duplicates and stale
  /// entries are harmless: users re-read the coefficient).
  void index_row(int q) {
    const Basis& bs = basis_[static_cast<size_t>(q)];
    for (const auto& e : bs.row)
      if (e.first != bs.pivot) {
        auto& list = rows_with_column_[static_cast<size_t>(e.first)];
        if (list.empty() || list.back() != q) list.push_back(q);
      }
  }

  int columns_;
  long relations_ = 0;
  bool inconsistent_ = false;
  std::vector<Basis> basis_;
  std::vector<int> pivot_row_;                   // column -> basis row, -1 if not a pivot
  std::vector<std::vector<int>> rows_with_column_;  // non-pivot column -> rows that may hold it
  std::vector<T> scratch_;                       // dense row of add(), all zero between calls
  std::vector<char> touched_mark_;               // columns of scratch_ in use
  std::vector<int> touched_;
};

}  // namespace linkproof
