// `linkproof check-data`: recorded motion (io/motion_data.h) against the exact truth at the
// recorded positions.
//
// Per sample:
//   truth      the linkage of the scene with this sample's joint positions (a link is the rigid
//              body through its joints) and input rates, solved exactly (rigid-body vector route);
//   user       each recorded omega.<L> / alpha.<L>: difference = user - exact, and the verdict
//              agrees  |user - exact| <= tolerance
//              differs otherwise;
//   tolerance  derived from the data's digits, per value:
//                radius of the same solve in Tracked<double> with every position and input rate
//                given its digits' uncertainty (io/motion_data.h) as a starting radius: a
//                rigorous bound on how far the truth moves within the data's precision, plus all
//                rounding of a double computation of it (core/tracked.h)
//              + the uncertainty of the user's value's own digits;
//   closure    the positions must keep every link rigid: for each pair of joints of one link
//              (revolute joints, and a slider's point on the slider), | |J_a J_b| - reference | with
//              the reference from the scene's joint positions; and a slider's point must stay on
//              its (fixed) guide line. Tolerance: sqrt 2 (u_a + u_b) for the sample's and for the
//              scene's coordinates (u: their digits' uncertainties). A sample beyond it is
//              "inconsistent": its positions do not close the loops of the scene's mechanism.
// Prismatic pairs must have the ground as guide (the axis is read from the scene).
#pragma once

#include <string>
#include <vector>

#include "linkproof/io/motion_data.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

struct RecordedRateCheck {
  std::string link;
  std::string quantity;     ///< "omega" or "alpha"
  Rational exact;
  std::string user_text;    ///< as recorded
  double difference = 0;    ///< user - exact, rounded to double
  double tolerance = 0;
  bool agrees = false;
};

struct SampleCheck {
  int line = 0;
  std::string label, t, input_angle;
  /// Exact omega and alpha of every link at the recorded positions (scene link order).
  std::vector<Rational> omega, alpha;
  std::vector<RecordedRateCheck> checks;
  double closure_residual = 0, closure_tolerance = 0;
  std::string closure_worst;  ///< e.g. "|BC| of link BCD" or "P off its guide"
  bool consistent = true;
  std::string error;  ///< the sample could not be solved (locked, ...): no verdicts
  bool agrees() const;
};

struct DataCheck {
  std::string scene, data;
  std::vector<std::string> link_names;
  std::vector<SampleCheck> samples;
  int agreeing = 0, differing = 0, inconsistent = 0, unsolvable = 0;
  std::string tolerance_rule;
};

DataCheck check_motion_data(const MechanismScene& scene, const MotionData& data);

/// 0 every sample consistent and every recorded value agrees; 1 otherwise.
int exit_status(const DataCheck& check);

}  // namespace linkproof
