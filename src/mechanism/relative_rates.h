// Relations between the relative angular rates of bodies (docs/conventions.md §A7), as exact sparse rows.
//
// The unknowns are the relative rates x_{ik} = rate_{i,k} (angular velocity or acceleration of
// body i relative to body k) for 0 <= i < k < m; rate_{k,i} = -x_{ik} is not a separate
// unknown (Dijksman sec. 3). Columns are numbered in lexicographic order of (i, k).
// Three kinds of relations are built here:
//  * the triangle relations rate_{i,j} + rate_{j,k} = rate_{i,k}, one per triple i < j < k;
//  * the velocity relations (5), (6) of an n-side polygon whose sides are bodies, side n fixed;
//  * the acceleration relations (22) and its companion (docs/conventions.md §A4) of such a polygon: affine,
//    their constant terms depend on the angular velocities (given as exact numbers).
// The coefficients are the closed forms of geometry/closed_forms.h (i_{n-1,j}, i_{n-2,j},
// lambda_j, mu_j, cot phi, r_{n-2}/(r_{n-1} sin phi), |r_{n-1}|^2/D), exact.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/row_echelon.h"
#include "linkproof/geometry/polygon.h"

namespace linkproof {

/// Column numbering of the relative rates of m bodies.
class RelativeRates {
 public:
  /// m >= 2 bodies, numbered 0..m-1.
  explicit RelativeRates(int bodies);
  int bodies() const { return m_; }
  /// m(m-1)/2 unknowns.
  int columns() const { return m_ * (m_ - 1) / 2; }
  /// Column of x_{ik}, i < k.
  int column(int i, int k) const;
  /// The pair (i, k), i < k, of a column.
  std::pair<int, int> bodies_of(int column) const;
  /// The term c * rate_{a,b} as a (column, coefficient) entry: +c at x_{ab} if a < b, -c at
  /// x_{ba} otherwise. a != b.
  std::pair<int, Rational> term(int a, int b, const Rational& c) const;

 private:
  int m_;
};

/// One relation sum_c row_c x_c = rhs, with a label saying where it comes from.
struct RateRelation {
  std::string label;
  SparseRow<Rational> row;
  Rational rhs;
};

/// rate_{i,j} + rate_{j,k} - rate_{i,k} = 0 for every triple i < j < k, in lexicographic order
/// (C(m,3) relations; the order makes RowEchelon fast, see row_echelon.h).
std::vector<RateRelation> triangle_relations(const RelativeRates& rates);

/// A polygon of a mechanism: side j of `polygon` (from K_j to K_{j+1}) is body `bodies[j-1]`;
/// side n, the last, is the one taken as fixed by the formulas.
struct BodyPolygon {
  std::vector<int> bodies;
  Polygon<Rational> polygon;
};

/// The same polygon with side f (1..n) moved to the end, so that side f is the fixed one:
/// sides f+1, ..., n, 1, ..., f (the joints rotate with them; each side keeps its vector).
BodyPolygon with_fixed_side(const BodyPolygon& p, int f);

/// Eq. (5) rate_{n-1,n} - sum_j i_{n-1,j} rate_{j,n} = 0 and eq. (6)
/// rate_{n-2,n} - sum_j i_{n-2,j} rate_{j,n} = 0 for side n of `p` fixed (j = 1..n-3).
/// Throws UndefinedQuantity at the dead centre r_{n-2} x r_{n-1} = 0.
std::vector<RateRelation> velocity_relations(const RelativeRates& rates, const BodyPolygon& p);

/// Eq. (22) omega-dot_{n-1,n} - sum_j i_{n-1,j} omega-dot_{j,n} = c_22 and the companion
/// omega-dot_{n-2,n} - sum_j i_{n-2,j} omega-dot_{j,n} = c_comp, side n of `p` fixed, with
///   c_22   = sum_j lambda_j w_j^2 - cot phi S1 - (r_{n-2}/(r_{n-1} sin phi)) S2,
///   c_comp = sum_j mu_j w_j^2 + cot phi S2 + (|r_{n-1}|^2 / D) S1,
/// w_j = omega_{j,n} = omega[bodies_j] - omega[bodies_n], S1, S2 the ordered-pair sums of docs/conventions.md §A3.
/// `omega` holds one angular velocity per body, relative to any common reference.
/// Throws UndefinedQuantity at the dead centre.
std::vector<RateRelation> acceleration_relations(const RelativeRates& rates, const BodyPolygon& p,
                                                 const std::vector<Rational>& omega);

}  // namespace linkproof
