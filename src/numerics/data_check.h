// `linkproof check-data`: recorded motion (io/motion_data.h) against the exact truth at the
// recorded positions.
//
// Per sample:
//   truth      the linkage of the scene with this sample's joint positions (a link is the rigid
//              body through its joints) and input rates, solved exactly (rigid-body vector route);
//   user       each recorded omega.<L> / alpha.<L> (a link's rates) and v.<J> / a.<J> (the sliding
//              rates of a prismatic joint J that is not an input): difference = user - exact,
//              decided exactly (the difference is a rational, the tolerance a finite double read
//              exactly), with the outcome
//                inconclusive  the tolerance is not finite (NaN or infinite: nothing decided);
//                differs       |user - exact| > tolerance;
//                inconclusive  otherwise, when the tolerance is not smaller than
//                              |exact| (within the data's precision the truth may have either
//                              sign or be 0: no recorded value can be told apart from it);
//                agrees        otherwise (|user - exact| <= tolerance < |exact|, or the
//                              tolerance is 0 and user = exact);
//   tolerance  derived from the data's digits, per value:
//                radius of the same solve in Tracked<double> with every position and input rate
//                given its digits' uncertainty (io/motion_data.h) as a starting radius: a
//                rigorous bound on how far the truth moves within the data's precision, plus all
//                rounding of a double computation of it (core/tracked.h)
//              + the uncertainty of the user's value's own digits (rounded up);
//   closure    the positions must be the scene's mechanism moved rigidly, decided exactly:
//              for each pair of joints of one link (revolute joints, and a slider's point on the
//              slider) | |J_a J_b| - reference | <= sqrt 2 (u_a + u_b) for the sample's and the
//              scene's coordinates (u: their uncertainties), the reference from the scene's joint
//              positions; for each triple of joints of one link the orientation (sign of the
//              cross product) must not be reversed beyond the uncertainty of both triangles (a
//              mirror image keeps every distance, but no rigid motion makes it); and a slider's
//              point must stay on its (fixed) guide line. A sample beyond it is "inconsistent":
//              its positions do not close the loops of the scene's mechanism.
//              The scene's coordinates are exact (integers, fractions, decimals), except that a
//              decimal value with 16 or more significant digits is taken as a printed binary64
//              and uncertain by one ulp at the scene's scale (scene_coordinate_uncertainty in
//              io/motion_data.h).
// A sample with no recorded value to compare is "nothing compared"; a file in which no value at
// all was compared is not a pass (exit 1).
// Prismatic pairs must have the ground as guide (the axis is read from the scene).
#pragma once

#include <string>
#include <vector>

#include "io/motion_data.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// What a recorded value is: a link's omega or alpha, or a prismatic joint's sliding rates.
enum class RecordedQuantity { Omega, Alpha, SlideVelocity, SlideAcceleration };
/// Outcome of one recorded value against the exact truth (see above).
enum class RateOutcome { Agrees, Differs, Inconclusive };
/// Verdict of one sample: every value agrees, one differs, none differs but one is inconclusive,
/// no value was recorded, or the sample could not be solved.
enum class SampleVerdict { Agrees, Differs, Inconclusive, NothingCompared, Unsolvable };

struct RecordedRateCheck {
  std::string name;         ///< the link (omega, alpha) or the prismatic joint (v, a)
  RecordedQuantity quantity = RecordedQuantity::Alpha;
  Rational exact;
  std::string user_text;    ///< as recorded
  double difference = 0;    ///< user - exact, rounded to double (may be infinite: display only)
  double tolerance = 0;
  RateOutcome outcome = RateOutcome::Inconclusive;
  bool agrees() const { return outcome == RateOutcome::Agrees; }
  bool is_slide() const {
    return quantity == RecordedQuantity::SlideVelocity || quantity == RecordedQuantity::SlideAcceleration;
  }
};

/// The outcome of |user - exact| against `tolerance` (the rule above), decided exactly.
RateOutcome compare_recorded(const Rational& user, const Rational& exact, double tolerance);

struct SampleCheck {
  int line = 0;
  std::string label, t, input_angle;
  /// Exact omega and alpha of every link at the recorded positions (scene link order).
  std::vector<Rational> omega, alpha;
  std::vector<RecordedRateCheck> checks;
  double closure_residual = 0, closure_tolerance = 0;
  std::string closure_worst;  ///< e.g. "|BC| of link BCD", "P off its guide", "orientation of B, C, D ..."
  bool consistent = true;
  std::string error;  ///< the sample could not be solved (locked, ...): no verdicts
  SampleVerdict verdict() const;
  bool agrees() const { return verdict() == SampleVerdict::Agrees; }
};

struct DataCheck {
  std::string scene, data;
  std::vector<std::string> link_names;
  std::vector<SampleCheck> samples;
  /// Samples by verdict, and inconsistent samples (any verdict).
  int agreeing = 0, differing = 0, inconclusive = 0, nothing_compared = 0, inconsistent = 0, unsolvable = 0;
  int compared = 0;  ///< recorded values compared in the whole file
};

DataCheck check_motion_data(const MechanismScene& scene, const MotionData& data);

}  // namespace linkproof
