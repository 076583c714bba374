// Recorded motion data (CSV) for `linkproof check-data SCENE DATA.csv`: per sample the joint
// positions, the input rates and the user's angular velocities / accelerations, every number
// read exactly from its text, with the uncertainty its digits imply.
//
// Format: comma-separated; lines starting with '#' and blank lines are skipped; the first other
// line is the header. Columns (any order; names are the scene's joint and link names):
//   sample            optional: a label per row (free text without commas)
//   t, input_angle    optional: carried into the report, not used
//   <J>.x, <J>.y      required for every joint J of the scene: its position in this sample
//   omega.<L>         for an input link L (required): omega; for another link: the user's omega
//   alpha.<L>         for an input link L (required): omega-dot; for another link: the user's alpha
//   v.<J>, a.<J>      for a slider input on prismatic joint J (required): sigma-dot, sigma-ddot
// At least one user column (omega.<L> or alpha.<L> of a non-input, non-ground link) is required.
// An empty cell in a user column means "not recorded" for that sample.
//
// Numbers: integers, decimals ("-2.7200000000000002", "1.5e-3") and fractions ("7/3"), exact.
// Uncertainty from the digits (decimal_uncertainty): an integer or a fraction is exact; a
// decimal whose last digit is at 10^m is uncertain by 10^m / 2; a decimal with 16 or more
// significant digits is a printed binary64 (round-trip form) computed at the scale of the
// mechanism, uncertain by one ulp of that scale (the largest |coordinate| of the row) if that is
// larger: positions computed in double as sums of vectors of that size carry errors of that
// order, whatever the size of the coordinate itself.
//
// Errors: InputError(file, "line L, column C (`name`)", problem) naming the CSV row (1-based
// line in the file) and column; unknown, duplicate or missing columns name the header column.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// A number read from data: its exact value and the uncertainty of its digits (see above).
struct RecordedNumber {
  Rational value;
  double uncertainty = 0;
  std::string text;
};

struct MotionSample {
  int line = 0;            ///< 1-based line in the file
  std::string label;       ///< column `sample`, or "line L"
  std::string t, input_angle;  ///< as written (may be empty)
  std::vector<RecordedNumber> x, y;            ///< per joint (scene order)
  std::vector<RecordedNumber> rate, rate_dot;  ///< per scene input
  std::vector<std::optional<RecordedNumber>> user_omega, user_alpha;  ///< per link (nullopt: not recorded)
};

struct MotionData {
  std::string source;
  std::vector<std::string> columns;
  std::vector<MotionSample> samples;
};

/// The uncertainty implied by a number's text (see above); `value` is its exact value, `scale`
/// the magnitude whose ulp bounds a printed double's error (default: |value| itself).
double decimal_uncertainty(std::string_view text, const Rational& value, double scale = 0);
/// The same rule for an exact rational from a scene file (its shortest decimal form): integers
/// and non-terminating fractions are exact; a terminating decimal with k decimals is uncertain by
/// 10^-k / 2, or one ulp of max(|value|, scale) when it has 16 or more significant digits.
double rational_uncertainty(const Rational& value, double scale = 0);

MotionData parse_motion_data(const std::string& csv_text, const std::string& source, const MechanismScene& scene);
MotionData load_motion_data(const std::string& path, const MechanismScene& scene);

}  // namespace linkproof
