// The truth of one mechanism at one instant, for property tests in other projects: every link's
// angular velocity omega and angular acceleration alpha (= omega-dot), relative to the ground,
//   exact    CLN rationals, from the rigid-body vector route (mechanism/mechanism_vector_route.h)
//            solved exactly; the same numbers `linkproof check` prints for the scene;
//   double   the same solve in Tracked<double> (core/tracked.h) from every joint position and
//            rate rounded to double (as a double library receives them): a double midpoint and a
//            radius that bounds its distance from the exact value rigorously (running error
//            analysis of every rounding, the rounding of the inputs included).
// The double pair is what a double-precision library can be expected to reach: a user's value
// within `bound` of `value` is as good as double arithmetic on this route gets.
//
//   MechanismTruth t = compute_truth(scene);          // scene: io/mechanism_scene.h
//   t.links[2].alpha            exact rational
//   t.links[2].alpha_double     {value, bound}
//
// Errors: InputError for a scene that cannot be solved (locked, wrong number of inputs),
// exactly as `linkproof check` reports it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "linkproof/core/exact.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof::testing {

/// A double and a rigorous bound on its distance from the exact value: |exact - value| <= bound.
/// bound is +inf when the double computation lost every digit (a pivot indistinguishable from 0).
struct BoundedDouble {
  double value = 0;
  double bound = 0;
};

struct LinkTruth {
  std::string link;  ///< the link's name in the scene
  bool ground = false;
  Rational omega, alpha;  ///< exact (the ground: 0, 0)
  BoundedDouble omega_double, alpha_double;
};

struct MechanismTruth {
  std::string scene;              ///< the scene's name
  std::vector<LinkTruth> links;   ///< in the scene's link order (Linkage::link_names())
  /// The exact alphas in link order, as doubles rounded to nearest (what a perfect double
  /// implementation would return): a convenience for comparisons.
  std::vector<double> alpha_doubles() const;
  /// The same for the exact omegas.
  std::vector<double> omega_doubles() const;
  /// The index of the link named `name` in `links`; throws std::out_of_range naming it if there
  /// is none.
  size_t link_index(std::string_view name) const;
};

/// Solves the scene exactly and in Tracked<double> (see above).
MechanismTruth compute_truth(const MechanismScene& scene);

}  // namespace linkproof::testing
