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
//   v.<J>, a.<J>      for a slider input on prismatic joint J (required): sigma-dot, sigma-ddot;
//                     for another prismatic joint: the user's sigma-dot / sigma-ddot
// A column is read by matching its whole name against the names the scene allows (a joint named
// `a`, `v`, `omega` or `alpha` has columns `a.x`, `a.y`, ...); a name that would mean two
// different columns in this scene (joint `v`'s x and the sliding velocity of a joint `x`) is
// refused, naming both meanings.
// At least one user column (omega.<L> or alpha.<L> of a non-input, non-ground link, or v.<J> /
// a.<J> of a prismatic joint that is not an input) is required.
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
// Labels (`sample`, `t`, `input_angle`) are kept with control characters and invalid UTF-8
// escaped (yaml_io::clean_text), so a label cannot forge report lines.
//
// Limits (docs/limits.md): the file 2 MiB (kMaxInputBytes), a cell kMaxCsvCellBytes bytes, a
// header kMaxCsvColumns columns, a number's decimal exponent |e| <= 4000 (parse_rational) and its
// magnitude at most the largest binary64 (kMaxRecordedMagnitude: tolerances are computed in
// double; 2e309 is refused, not read as infinity). Quoted input in messages is cut to 60
// characters with the total length.
//
// Errors: InputError(file, "line L, column C (`name`)", problem) naming the CSV row (1-based
// line in the file) and column; unknown, duplicate or missing columns name the header column.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// A cell longer than this is refused (a number needs far fewer; a label is free text).
inline constexpr std::size_t kMaxCsvCellBytes = 4096;
/// A header with more columns than this is refused (2 per joint plus 2 per link for the largest
/// mechanism scene fits comfortably).
inline constexpr std::size_t kMaxCsvColumns = 20000;

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
  std::vector<std::optional<RecordedNumber>> user_slide, user_slide_dot;  ///< per joint (prismatic, not an input)
};

struct MotionData {
  std::string source;
  std::vector<std::string> columns;
  std::vector<MotionSample> samples;
};

/// The uncertainty implied by a number's text (see above); `value` is its exact value, `scale`
/// the magnitude whose ulp bounds a printed double's error (default: |value| itself).
double decimal_uncertainty(std::string_view text, const Rational& value, double scale = 0);
/// The uncertainty of a scene's coordinate `value` for check-data's closure: a scene's numbers
/// are exact (integers, fractions, decimals: "1/2" and "0.5" are both exactly one half), except
/// that a value whose decimal expansion terminates with 16 or more significant digits is taken as
/// a printed binary64 (scenes generated from double data) and uncertain by one ulp of
/// max(|value|, scale). (The scene keeps exact values, not their text: a fraction with such an
/// expansion, 1/2^60 say, gets the same ulp.)
double scene_coordinate_uncertainty(const Rational& value, double scale = 0);

MotionData parse_motion_data(const std::string& csv_text, const std::string& source, const MechanismScene& scene);
MotionData load_motion_data(const std::string& path, const MechanismScene& scene);

}  // namespace linkproof
