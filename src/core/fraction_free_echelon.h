// Exact rank of a system of affine relations with integer coefficients, without fractions.
//
// FractionFreeEchelon is RowEchelon<Rational> (core/row_echelon.h) for dense integer rows of a
// system whose rank stays small: no rational is formed and no gcd is taken, which is what an
// exact rank over the rationals costs when its entries carry large denominators (`count`'s
// acceleration relations: sums of n terms whose denominators differ).
//
// Bareiss' fraction-free elimination (Bareiss 1968), one row at a time. The pivot rows E_1..E_r
// are kept as elimination left them; a new row x is reduced by each in turn,
//     x <- (E_k[c_k] x - x[c_k] E_k) / E_{k-1}[c_{k-1}]      (E_0[c_0] = 1),
// where c_k is E_k's pivot column. After step k every entry x[j] is the determinant of the
// original rows of E_1..E_k and x restricted to the columns c_1..c_k, j (Sylvester's identity),
// so the division is exact and the entries grow like k x k minors, not like 2^k. That holds
// only if every step is applied, also when x[c_k] is already 0: no step is skipped.
// The right-hand side is one more column that is never a pivot; a row whose coefficients reduce
// to 0 with a nonzero right-hand side makes the system inconsistent, as in RowEchelon.
// The rank over the integers' fraction field is the rank over the rationals: the result is the
// same rank RowEchelon<Rational> computes (tests/core/fraction_free_echelon_test.cpp compares).
#pragma once

#include <cln/integer.h>

#include <utility>
#include <vector>

#include "linkproof/core/error.h"
#include "core/row_echelon.h"

namespace linkproof {

class FractionFreeEchelon {
 public:
  /// A system in `columns` unknowns.
  explicit FractionFreeEchelon(int columns) : columns_(columns) {}

  int columns() const { return columns_; }
  long relations() const { return relations_; }
  int rank() const { return static_cast<int>(pivots_.size()); }
  int augmented_rank() const { return rank() + (inconsistent_ ? 1 : 0); }
  bool is_consistent() const { return !inconsistent_; }

  /// Adds the relation sum_c row[c] x_c = rhs (`row` dense, columns() entries).
  RowOutcome add(std::vector<cln::cl_I> row, cln::cl_I rhs) {
    LINKPROOF_ASSERT(static_cast<int>(row.size()) == columns_, "FractionFreeEchelon: row length");
    ++relations_;
    cln::cl_I previous = 1;
    for (const Pivot& e : pivots_) {
      const cln::cl_I& p = e.row[static_cast<size_t>(e.column)];
      const cln::cl_I f = row[static_cast<size_t>(e.column)];
      const bool divide = previous != 1;
      for (size_t c = 0; c < row.size(); ++c) {
        cln::cl_I v = p * row[c] - f * e.row[c];
        row[c] = divide ? cln::exquo(v, previous) : std::move(v);
      }
      cln::cl_I v = p * rhs - f * e.rhs;
      rhs = divide ? cln::exquo(v, previous) : std::move(v);
      previous = p;
    }
    // The new pivot: the last column left (any nonzero column would do).
    int column = -1;
    for (int c = columns_ - 1; c >= 0; --c)
      if (!cln::zerop(row[static_cast<size_t>(c)])) {
        column = c;
        break;
      }
    if (column < 0) {
      if (cln::zerop(rhs)) return RowOutcome::Dependent;
      inconsistent_ = true;
      return RowOutcome::Inconsistent;
    }
    pivots_.push_back({column, std::move(row), std::move(rhs)});
    return RowOutcome::Independent;
  }

 private:
  struct Pivot {
    int column;
    std::vector<cln::cl_I> row;
    cln::cl_I rhs;
  };
  int columns_;
  long relations_ = 0;
  bool inconsistent_ = false;
  std::vector<Pivot> pivots_;
};

}  // namespace linkproof
