// Counting relations between relative angular rates (Dijksman 1966, sec. 3; docs/conventions.md §A7).
//
// Every count here is a computed exact rank (core/row_echelon.h over CLN rationals), never a
// formula: the formulas of the paper are what the ranks are judged against (count_claim.h).
//  * count_triangle_relations(n): the C(n,3) relations rate_ij + rate_jk = rate_ik of n bodies
//    in the n(n-1)/2 relative rates; the paper's T.
//  * count_fixed_side_relations(p, omega): for an n-side polygon, the relations of every
//    choice of the fixed side f = 1..n (2n velocity relations (5)/(6), n relations (22), 2n
//    acceleration relations (22) + companion), each family ranked *modulo the triangle
//    relations of the n sides*: rank[triangles; family] - rank[triangles]. That is the number
//    of independent constraints the family puts on the n - 1 independent rates of the polygon.
//    Computed as the rank of the family restricted to the n - 1 rates the triangles leave free
//    (x_ik = y_k - y_i), which equals that difference once rank[triangles] is (n-1)(n-2)/2
//    (counting.cpp says why); tests compare it with ranking [triangles; family] directly.
//    The acceleration families are affine (their constants depend on the velocities): the
//    linear part and the augmented matrix are ranked; equal ranks mean the family is consistent.
#pragma once

#include <string>
#include <vector>

#include "mechanism/relative_rates.h"

namespace linkproof {

/// The rank of one system of relations, with its size and the time it took.
struct RankResult {
  long relations = 0;      ///< rows added
  int unknowns = 0;        ///< columns
  int rank = 0;            ///< rank of the coefficient matrix A
  int augmented_rank = 0;  ///< rank of [A | b]; equals `rank` iff the system is consistent
  double seconds = 0;
  bool consistent() const { return rank == augmented_rank; }
};

/// Adds `relations` to `echelon` and returns its state afterwards (relations counts all rows
/// ever added, seconds only this call).
RankResult add_and_rank(RowEchelon<Rational>& echelon, const std::vector<RateRelation>& relations);

/// Rank of the triangle relations of n >= 2 bodies (expected: T = (n-1)(n-2)/2).
RankResult count_triangle_relations(int n);

/// One family of polygon relations over all n choices of the fixed side.
struct FixedSideFamily {
  std::string name;        ///< "velocity (5),(6)", "acceleration (22)", "acceleration (22)+companion"
  long relations = 0;      ///< 2n, n or 2n
  RankResult triangles;    ///< the triangle relations of the n sides alone
  RankResult combined;     ///< triangles followed by the family
  /// rank[triangles; family] - rank[triangles], and the same for the augmented matrices.
  int rank_over_triangles() const { return combined.rank - triangles.rank; }
  int augmented_rank_over_triangles() const { return combined.augmented_rank - triangles.augmented_rank; }
};

/// The angular velocity of every side of `p` relative to side n (0-based; entry n-1 is 0), by
/// the closed forms of docs/conventions.md §A2 from the inputs. Throws UndefinedQuantity at the dead centre.
std::vector<Rational> side_velocities(const Polygon<Rational>& p, const InputRates<Rational>& in);

/// The three families of docs/conventions.md §A7 for polygon `p` (n >= 3; side j is body j-1) with side
/// velocities `omega` (one per side, any common reference). Throws UndefinedQuantity if some
/// choice of fixed side is a dead centre.
std::vector<FixedSideFamily> count_fixed_side_relations(const Polygon<Rational>& p,
                                                         const std::vector<Rational>& omega);

}  // namespace linkproof
