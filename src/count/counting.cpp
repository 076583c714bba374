#include "count/counting.h"

#include <algorithm>
#include <chrono>

#include "core/fraction_free_echelon.h"
#include "count/integer_families.h"
#include "geometry/closed_forms.h"

namespace linkproof {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

RankResult state_of(const RowEchelon<Rational>& e, double seconds) {
  return {e.relations(), e.columns(), e.rank(), e.augmented_rank(), seconds};
}

/// The triangle relations of m bodies, reduced, grown one body at a time and kept between calls
/// (`count --n 3..200` ranks every m in turn: C(200,3) rows in all instead of the sum of C(m,3)).
/// Its columns are numbered by body added: rate (i, k), i < k, is column k(k-1)/2 + i, so that
/// body k's rates are appended. The relations are those of triangle_relations(), grouped by their
/// largest body; the rank of a system does not depend on the order of its rows or columns.
struct TriangleBasis {
  int bodies = 0;
  RowEchelon<Rational> echelon{0};
};

int appended_column(int i, int k) { return k * (k - 1) / 2 + i; }

const RowEchelon<Rational>& grown_triangle_basis(int m) {
  thread_local TriangleBasis cache;
  if (cache.bodies > m) cache = TriangleBasis{};
  for (int k = cache.bodies; k < m; ++k) {  // add body k: the triples (i, j, k), i < j < k
    cache.echelon.add_columns(k);
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j)
        cache.echelon.add(make_sparse_row<Rational>({{appended_column(i, j), 1}, {appended_column(j, k), 1},
                                                     {appended_column(i, k), -1}}),
                          0);
  }
  cache.bodies = std::max(cache.bodies, m);
  return cache.echelon;
}

// Why ranking a family restricted to the free rates ranks it modulo the triangle relations of m
// bodies, when those are known to leave exactly the rates of W = {x_ik = y_k - y_i : y_0 = 0}
// free (rank[triangles] = m(m-1)/2 - (m-1)). Every rate of W satisfies the triangle relations,
// so their span lies in the annihilator of W, and with that rank it *is* the annihilator. The
// rows of [triangles; family] modulo that span are then the rows of the family restricted to W
// (the quotient of the dual by the annihilator of W is the dual of W): rank[triangles; family] -
// rank[triangles] is the rank of the restricted family, an (m-1)-column system, and the same for
// the augmented matrices (W x R, with the constant kept). This replaces reducing the family
// against a copy of the C(m,3)-row triangle basis (most of `count` at large n) by O(entries)
// work per relation. The restricted rows are made integer (count/integer_families.h) and ranked
// without fractions (core/fraction_free_echelon.h).
void add_relations(FractionFreeEchelon& e, const std::vector<IntegerRelation>& family) {
  for (const IntegerRelation& r : family) e.add(r.row, r.rhs);
}

}  // namespace

RankResult add_and_rank(RowEchelon<Rational>& echelon, const std::vector<RateRelation>& relations) {
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& r : relations) echelon.add(r.row, r.rhs);
  return state_of(echelon, seconds_since(t0));
}

RankResult count_triangle_relations(int n) {
  const auto t0 = std::chrono::steady_clock::now();
  // The rank does not depend on the numbering of the columns: the grown basis is ranked as it is.
  const RowEchelon<Rational>& e = grown_triangle_basis(n);
  return state_of(e, seconds_since(t0));
}

std::vector<Rational> side_velocities(const Polygon<Rational>& p, const InputRates<Rational>& in) {
  return compute_closed_form_motion(p, in).omega;
}

std::vector<FixedSideFamily> count_fixed_side_relations(const Polygon<Rational>& p,
                                                         const std::vector<Rational>& omega) {
  const int n = p.n();
  LINKPROOF_ASSERT(n >= 3 && static_cast<int>(omega.size()) == n, "count_fixed_side_relations: bad input");
  // Build the three families first (this throws at a dead centre before anything is ranked).
  const IntegerFamilies families = integer_fixed_side_families(p, omega);

  const RankResult tri_state = count_triangle_relations(n);
  // The restriction to W rests on the triangles leaving exactly n - 1 rates free.
  const int rate_columns = RelativeRates(n).columns();
  LINKPROOF_ASSERT(tri_state.rank == rate_columns - (n - 1) && tri_state.consistent(),
                   "count_fixed_side_relations: the triangle relations do not have rank (n-1)(n-2)/2");

  std::vector<FixedSideFamily> out;
  // `restricted` holds the family rows restricted to W (earlier relations `earlier` long, taking
  // `earlier_seconds`): the (22)+companion family continues from the (22) one (the rank of a set
  // of relations does not depend on their order), so the (22) rows are reduced once.
  const auto rank_family = [&](std::string name, FractionFreeEchelon restricted, long earlier, double earlier_seconds,
                               const std::vector<IntegerRelation>& family) {
    const auto t1 = std::chrono::steady_clock::now();
    FractionFreeEchelon e = std::move(restricted);
    add_relations(e, family);
    FixedSideFamily fam;
    fam.name = std::move(name);
    fam.relations = earlier + static_cast<long>(family.size());
    fam.triangles = tri_state;
    fam.combined = {tri_state.relations + fam.relations, rate_columns, tri_state.rank + e.rank(),
                    tri_state.augmented_rank + e.augmented_rank(),
                    tri_state.seconds + earlier_seconds + seconds_since(t1)};
    out.push_back(std::move(fam));
    return e;
  };
  const FractionFreeEchelon none(n - 1);
  rank_family("velocity (5),(6)", none, 0, 0, families.velocity);
  const FractionFreeEchelon with_eq22 = rank_family("acceleration (22)", none, 0, 0, families.eq22);
  const long eq22_rows = out.back().relations;
  const double eq22_seconds = out.back().combined.seconds - tri_state.seconds;
  rank_family("acceleration (22)+companion", with_eq22, eq22_rows, eq22_seconds, families.companion);
  return out;
}

}  // namespace linkproof
