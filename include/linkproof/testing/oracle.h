// The one-line oracle for RapidCheck properties: checks a user's angular accelerations on a
// generated case against linkproof's exact truth, and on failure reports the case as a scene
// file that `linkproof check` reads (RapidCheck then shrinks it to the smallest failing one).
//
//   std::vector<double> my_alpha(const linkproof::Linkage& m,
//                                const std::vector<linkproof::MechanismInput>& inputs);
//
//   RC_GTEST_PROP(MyLib, FourBarAlphaIsExact, ()) {
//     linkproof::testing::rc_assert_alpha_matches(*linkproof::testing::gen_fourbar(), my_alpha);
//   }
//
// `alpha(mechanism, inputs)` returns one angular acceleration per link, in the linkage's link
// order (Linkage::link_names(), the ground included: 0), relative to the ground, ccw positive.
// The comparison and the tolerance are those of testing/compare.h (default: 4 times linkproof's
// own rigorous double bound plus half an ulp, per link). The case's family is classified
// (RC_CLASSIFY). On failure the message holds the per-link table and the scene YAML, between the
// lines "--- scene ---" and "--- end scene ---".
#pragma once

#include <rapidcheck.h>

#include <string>
#include <utility>
#include <vector>

#include "linkproof/io/mechanism_scene.h"
#include "linkproof/testing/compare.h"
#include "linkproof/testing/generators.h"

namespace linkproof::testing {

/// The failure text: the table and the scene YAML (see above).
std::string failure_report(const MechanismCase& c, const RateComparison& comparison);

/// Checks `rate_fn(linkage, inputs)` (one value of `rate` per link) against the exact truth.
template <class RateFn>
void rc_assert_rates_match(const MechanismCase& c, Rate rate, RateFn&& rate_fn, const Tolerance& tolerance) {
  classify_case(c);
  const MechanismTruth truth = compute_truth(c.scene);
  const std::vector<double> got = rate_fn(c.scene.linkage, c.scene.inputs);
  const RateComparison comparison = compare_rates(truth, rate, got, tolerance);
  if (!comparison.ok) RC_FAIL(failure_report(c, comparison));
}

template <class AlphaFn>
void rc_assert_alpha_matches(const MechanismCase& c, AlphaFn&& alpha,
                             const Tolerance& tolerance = Tolerance::double_bound(4)) {
  rc_assert_rates_match(c, Rate::Alpha, std::forward<AlphaFn>(alpha), tolerance);
}

/// The same for angular velocities: `omega(linkage, inputs)`, one per link.
template <class OmegaFn>
void rc_assert_omega_matches(const MechanismCase& c, OmegaFn&& omega,
                             const Tolerance& tolerance = Tolerance::double_bound(4)) {
  rc_assert_rates_match(c, Rate::Omega, std::forward<OmegaFn>(omega), tolerance);
}

}  // namespace linkproof::testing
