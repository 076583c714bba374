// Counting and solving the rate relations of a compound mechanism built of polygons
// (Dijksman 1966, sec. 3 and Fig. 5; docs/conventions.md §A7, §A8).
//
// A mechanism here is a set of links 0..m-1 joined by turning pairs at known positions, one
// fixed link and one input link with given omega and omega-dot relative to the fixed link. The
// analyst names loops of links ("1-2-3-4-0"): polygon sides are the links in that order, the
// joint between consecutive links of the loop is a vertex, and the **last** link of the loop is
// side n, the one the formulas take as fixed (docs/conventions.md §A1). Side j runs from the joint with the
// previous link to the joint with the next one.
//
// count_compound ranks, over the m(m-1)/2 relative rates:
//   velocities:    triangle relations + input + (5), (6) of every polygon  -> solved exactly;
//   accelerations: triangle relations (rank T), + input (T + 1), + (22) and the companion of
//                  every polygon, their constants from the exact velocities (rank, consistency)
//                  -> solved exactly when the rank reaches m(m-1)/2.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "count/counting.h"

namespace linkproof {

struct CompoundMechanism {
  std::string name;
  int links = 0;                                      ///< links 0..links-1
  int fixed_link = 0;
  int input_link = 1;
  Rational input_omega = 0;                           ///< omega_{input,fixed}
  Rational input_omega_dot = 0;                       ///< omega-dot_{input,fixed}
  std::map<std::pair<int, int>, Vec2<Rational>> joints;  ///< key (a, b), a < b: the joint of links a, b
};

/// "1-2-3-4-0,1-5-7-4-0" -> {{1,2,3,4,0},{1,5,7,4,0}}. Throws InputError(source, field, ...)
/// on anything else (empty loops, non-numbers, fewer than 3 links, a repeated link).
std::vector<std::vector<int>> parse_polygon_list(const std::string& text, const std::string& source,
                                                 const std::string& field);

/// The polygon of a loop of links (see above). Throws InputError if a link is out of range or
/// two consecutive links share no joint.
BodyPolygon construct_loop_polygon(const CompoundMechanism& m, const std::vector<int>& loop);

struct CompoundCount {
  int unknowns = 0;
  RankResult velocity;              ///< triangles + input + (5),(6) of every polygon
  RankResult triangles;             ///< accelerations: triangle relations alone
  RankResult with_input;            ///< + the input omega-dot
  std::optional<RankResult> with_polygons;  ///< + (22), companion; absent if the velocities are not determined
  /// omega of every link relative to the fixed link (absent where not determined).
  std::vector<std::optional<Rational>> omega;
  /// omega-dot of every link relative to the fixed link (absent where not determined).
  std::vector<std::optional<Rational>> omega_dot;
  /// omega-dot_{a,b} if determined.
  std::optional<Rational> relative_omega_dot(int a, int b) const;
};

/// Throws InputError for bad loops, UndefinedQuantity if a loop is at a dead centre.
CompoundCount count_compound(const CompoundMechanism& m, const std::vector<std::vector<int>>& loops);

}  // namespace linkproof
