// The counting claims of Dijksman (1966), sec. 3 and the end of sec. 2.1 (conventions §A7, §A5.5), and
// the eight-bar of Fig. 5 (conventions §A8). Every rank is computed exactly (count/counting.h,
// count/compound_count.h); the paper's numbers are only what it is judged against.
//
// Claim ids (N the number of bodies / sides):
//   dijksman1966.A7.triangle_rank[n=N]       rank of rate_ij + rate_jk = rate_ik is (N-1)(N-2)/2
//   dijksman1966.A7.balance[n=N]             N(N-1)/2 - (N-3) = 2 + T, T the computed rank
//   dijksman1966.A7.velocity_rank2[n=N]      the 2N relations (5),(6) over all fixed sides: rank 2
//   dijksman1966.A7.eq22_rank2[n=N]          the N relations (22): rank 2, consistent
//   dijksman1966.A7.acceleration_rank2[n=N]  the 2N relations (22) + companion: rank 2, consistent
//   dijksman1966.fig5.*                      the eight-bar: unknowns, ranks 21 -> 22 -> 28, values
//   dijksman1966.sec3.count                  §A5.5: 6 relations remain once the input is given
//   dijksman1966.sec3.count.printed          the printed "28 - 21 = 7 ... bound to be found"
//                                            read as remaining after the input: expected disproved
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "count/compound_count.h"
#include "count/count_claim.h"

namespace linkproof::dijksman1966 {

/// The polygon on which the fixed-side claims for n sides are evaluated: for n >= 4 the first
/// random exact polygon of generate_random_polygon(seed, n, index = 0, 3, 6, ...) that is not at a
/// dead centre for any choice of fixed side; for n = 3 a fixed non-degenerate triangle.
/// Returns the polygon and its side velocities (relative to side n).
struct CountingPolygon {
  Polygon<Rational> polygon;
  std::vector<Rational> omega;
  std::string origin;  ///< how to reproduce it ("random polygon seed 1, n 7, index 0")
};
CountingPolygon counting_polygon(int n, std::uint64_t seed);

/// The five claims for n bodies / an n-side polygon (3 <= n).
std::vector<CountClaim> count_claims_for_n(int n, std::uint64_t seed);

/// The eight-bar of Fig. 5 with the geometry and input of conventions §A8.
CompoundMechanism fig5_eightbar();

/// The paper's choice of loops: "1-2-3-4-0,1-5-7-4-0,1-5-6-3-2".
inline constexpr const char* kFig5Polygons = "1-2-3-4-0,1-5-7-4-0,1-5-6-3-2";

/// Claims for the eight-bar and the §A5.5 erratum, for the given loops (the paper's by default).
/// The ranks are judged for any mechanism; the value claims (fig5.omega, fig5.omega_dot_4_0,
/// fig5.omega_dot_1_2) are the conventions §A8 known answers and so presuppose `m` = fig5_eightbar()
/// (any loops). `notes` receives the erratum statement. Throws InputError for bad loops.
std::vector<CountClaim> eightbar_claims(const CompoundMechanism& m, const std::vector<std::vector<int>>& loops,
                                        std::vector<std::string>& notes);

}  // namespace linkproof::dijksman1966
