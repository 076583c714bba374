#include "linkproof/count/counting.h"

#include <algorithm>
#include <chrono>

#include "linkproof/geometry/closed_forms.h"

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
/// body k's rates are appended; triangle_basis() renumbers them as RelativeRates(m) does. The
/// relations are those of triangle_relations(), grouped by their largest body; the rank of a
/// system does not depend on the order of its rows or columns.
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

/// The reduced triangle relations of m bodies in RelativeRates(m)'s columns.
RowEchelon<Rational> triangle_basis(const RelativeRates& rates) {
  const int m = rates.bodies();
  const RowEchelon<Rational>& grown = grown_triangle_basis(m);
  std::vector<int> to(static_cast<size_t>(rates.columns()));
  for (int k = 1; k < m; ++k)
    for (int i = 0; i < k; ++i) to[static_cast<size_t>(appended_column(i, k))] = rates.column(i, k);
  return grown.renumbered(to);
}

}  // namespace

RankResult add_and_rank(RowEchelon<Rational>& echelon, const std::vector<RateRelation>& relations) {
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& r : relations) echelon.add(r.row, r.rhs);
  return state_of(echelon, seconds_since(t0));
}

RankResult count_triangle_relations(int n) {
  const auto t0 = std::chrono::steady_clock::now();
  const RowEchelon<Rational> e = triangle_basis(RelativeRates(n));
  return state_of(e, seconds_since(t0));
}

std::vector<Rational> side_velocities(const Polygon<Rational>& p, const InputRates<Rational>& in) {
  return compute_closed_form_motion(p, in).omega;
}

std::vector<FixedSideFamily> count_fixed_side_relations(const Polygon<Rational>& p,
                                                         const std::vector<Rational>& omega) {
  const int n = p.n();
  LINKPROOF_ASSERT(n >= 3 && static_cast<int>(omega.size()) == n, "count_fixed_side_relations: bad input");
  BodyPolygon bp;
  bp.polygon = p;
  for (int b = 0; b < n; ++b) bp.bodies.push_back(b);
  const RelativeRates rates(n);

  // Build the three families first (this throws at a dead centre before anything is ranked).
  std::vector<RateRelation> velocity, eq22, companion;
  for (int f = 1; f <= n; ++f) {
    const BodyPolygon q = with_fixed_side(bp, f);
    for (auto& r : velocity_relations(rates, q)) velocity.push_back(std::move(r));
    auto acc = acceleration_relations(rates, q, omega);
    eq22.push_back(std::move(acc[0]));
    companion.push_back(std::move(acc[1]));
  }

  const auto t0 = std::chrono::steady_clock::now();
  const RowEchelon<Rational> tri = triangle_basis(rates);
  const RankResult tri_state = state_of(tri, seconds_since(t0));

  std::vector<FixedSideFamily> out;
  // `start` (a reduced basis holding the triangles, and earlier relations `earlier` long) plus
  // `family`: the (22)+companion family continues from the (22) one (the rank of a set of
  // relations does not depend on their order), so the (22) rows are reduced once.
  const auto rank_family = [&](std::string name, const RowEchelon<Rational>& start, double earlier_seconds,
                               const std::vector<RateRelation>& family, long size) {
    const auto t1 = std::chrono::steady_clock::now();
    RowEchelon<Rational> e = start;
    add_and_rank(e, family);
    FixedSideFamily fam;
    fam.name = std::move(name);
    fam.relations = size;
    fam.triangles = tri_state;
    fam.combined = state_of(e, earlier_seconds + seconds_since(t1));
    out.push_back(std::move(fam));
    return e;
  };
  rank_family("velocity (5),(6)", tri, tri_state.seconds, velocity, static_cast<long>(velocity.size()));
  const RowEchelon<Rational> with_eq22 =
      rank_family("acceleration (22)", tri, tri_state.seconds, eq22, static_cast<long>(eq22.size()));
  rank_family("acceleration (22)+companion", with_eq22, out.back().combined.seconds, companion,
              static_cast<long>(eq22.size() + companion.size()));
  return out;
}

}  // namespace linkproof
