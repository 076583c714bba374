// GoogleTest matchers over linkproof's truth (needs <gmock/gmock.h>; link linkproof::testing).
//
//   const MechanismTruth truth = compute_truth(c.scene);
//   EXPECT_THAT(my_alphas, AngularAccelerationsMatch(truth, Tolerance::double_bound(4)));
//   EXPECT_THAT(polygon_case, ClaimHolds("dijksman1966.eq22"));
//
// AngularAccelerationsMatch(expected, tolerance) (AngularVelocitiesMatch: the same for omega)
// matches a std::vector<double> of angular accelerations, one per link in the scene's link order (the ground included, 0), by the rule of
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

class AngularRatesMatcher {
 public:
  using is_gtest_matcher = void;
  AngularRatesMatcher(MechanismTruth expected, Rate rate, Tolerance tolerance)
      : expected_(std::move(expected)), rate_(rate), tolerance_(tolerance) {}
  bool MatchAndExplain(const std::vector<double>& values, std::ostream* listener) const {
    const RateComparison c = compare_rates(expected_, rate_, values, tolerance_);
    if (listener) *listener << "\n" << c.report();
    return c.ok;
  }
  void DescribeTo(std::ostream* os) const {
    *os << "are the angular " << what() << " of `" << expected_.scene << "` within " << tolerance_.describe();
  }
  void DescribeNegationTo(std::ostream* os) const {
    *os << "are not the angular " << what() << " of `" << expected_.scene << "` within " << tolerance_.describe();
  }

 private:
  const char* what() const { return rate_ == Rate::Omega ? "velocities" : "accelerations"; }
  MechanismTruth expected_;
  Rate rate_;
  Tolerance tolerance_;
};

inline AngularRatesMatcher AngularAccelerationsMatch(MechanismTruth expected, Tolerance tolerance) {
  return {std::move(expected), Rate::Alpha, tolerance};
}
inline AngularRatesMatcher AngularVelocitiesMatch(MechanismTruth expected, Tolerance tolerance) {
  return {std::move(expected), Rate::Omega, tolerance};
}

class ClaimHoldsMatcher {
 public:
  using is_gtest_matcher = void;
  explicit ClaimHoldsMatcher(std::string id) : id_(std::move(id)) {}
  template <class Case>
  bool MatchAndExplain(const Case& c, std::ostream* listener) const {
    const ClaimResult r = check_claim(id_, c);
    if (listener) *listener << "claim " << id_ << " on " << c.family << ": " << to_string(r.verdict) << " (" << r.detail << ")";
    return r.holds;
  }
  void DescribeTo(std::ostream* os) const { *os << "is a case on which claim " << id_ << " holds exactly"; }
  void DescribeNegationTo(std::ostream* os) const { *os << "is a case on which claim " << id_ << " does not hold"; }

 private:
  std::string id_;
};

inline ClaimHoldsMatcher ClaimHolds(std::string id) { return ClaimHoldsMatcher(std::move(id)); }

}  // namespace linkproof::testing
