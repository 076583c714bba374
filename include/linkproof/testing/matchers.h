// GoogleTest matchers over linkproof's truth (needs <gmock/gmock.h>; link linkproof::testing).
//
//   const MechanismTruth truth = compute_truth(c.scene);
//   EXPECT_THAT(my_alphas, AngularAccelerationsMatch(truth, Tolerance::double_bound(4)));
//   EXPECT_THAT(polygon_case, ClaimHolds("dijksman1966.eq22"));
//
// AngularAccelerationsMatch(expected, tolerance) matches a std::vector<double> of angular
// accelerations, one per link in the scene's link order (the ground included, 0), by the rule of
// testing/compare.h; the failure message is the per-link table: the user's value, the exact value
// (25 digits), the difference, the tolerance and linkproof's own double bound.
// ClaimHolds(id) matches a PolygonCase or MechanismCase on which the claim `id` holds exactly
// (testing/claim_result.h); otherwise it explains the verdict and the residual, or lists the
// claim ids that apply when `id` is unknown.
#pragma once

#include <gmock/gmock.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/testing/claim_result.h"
#include "linkproof/testing/compare.h"

namespace linkproof::testing {

class AngularAccelerationsMatcher {
 public:
  using is_gtest_matcher = void;
  AngularAccelerationsMatcher(MechanismTruth expected, Tolerance tolerance)
      : expected_(std::move(expected)), tolerance_(tolerance) {}
  bool MatchAndExplain(const std::vector<double>& alphas, std::ostream* listener) const {
    const AlphaComparison c = compare_alphas(expected_, alphas, tolerance_);
    if (listener) *listener << "\n" << c.report();
    return c.ok;
  }
  void DescribeTo(std::ostream* os) const {
    *os << "are the angular accelerations of `" << expected_.scene << "` within " << tolerance_.describe();
  }
  void DescribeNegationTo(std::ostream* os) const {
    *os << "are not the angular accelerations of `" << expected_.scene << "` within " << tolerance_.describe();
  }

 private:
  MechanismTruth expected_;
  Tolerance tolerance_;
};

inline AngularAccelerationsMatcher AngularAccelerationsMatch(MechanismTruth expected, Tolerance tolerance) {
  return {std::move(expected), tolerance};
}

class ClaimHoldsMatcher {
 public:
  using is_gtest_matcher = void;
  explicit ClaimHoldsMatcher(std::string id) : id_(std::move(id)) {}
  template <class Case>
  bool MatchAndExplain(const Case& c, std::ostream* listener) const {
    const ClaimResult r = check_claim(id_, c);
    if (listener) *listener << "claim " << id_ << " on " << c.family << ": " << r.verdict << " (" << r.detail << ")";
    return r.holds;
  }
  void DescribeTo(std::ostream* os) const { *os << "is a case on which claim " << id_ << " holds exactly"; }
  void DescribeNegationTo(std::ostream* os) const { *os << "is a case on which claim " << id_ << " does not hold"; }

 private:
  std::string id_;
};

inline ClaimHoldsMatcher ClaimHolds(std::string id) { return ClaimHoldsMatcher(std::move(id)); }

}  // namespace linkproof::testing
