// Placing the joints of a mechanism scene from dimensions (io/mechanism_scene.h: `polar`, `dyad`,
// `slide`, `at: J`), and writing angles and rates that hold pi as rationals with a stated bound.
// Private to src/io.
//
// Every position is computed as a certified enclosure (enclosure.h) in the order the references
// allow; exact data stay exact (a rational cos/sin, a discriminant that is the square of a
// rational). A position that is not exact is then replaced by the rational nearest its
// enclosure's midpoint on a decimal grid kRationalisedDigits below the scene's scale, and the
// distance to the dimensioned position is bounded by the rounding plus the enclosure's radius.
// Later joints are placed from the enclosures of earlier ones, not from their rationals, so the
// bounds do not accumulate along a chain of placements.
//
// Constructions (J, J1, J2 placed; L, L1, L2 > 0; e = (cos A, sin A); J x = (-x_y, x_x)):
//   polar  P = J + L e
//   dyad   D = J2 - J1, d2 = |D|^2, k = d2 + L1^2 - L2^2, Delta = 4 d2 L1^2 - k^2
//          P = J1 + (k / (2 d2)) D +- (sqrt(Delta) / (2 d2)) J D      (+: left of J1 -> J2)
//          Delta < 0: the circles do not meet (|J1 J2| > L1 + L2, or < |L1 - L2|).
//   slide  W = J - J2, b = W.e, Disc = b^2 - (|W|^2 - L^2) = L^2 - h^2 (h: distance of J2 from
//          the line), t = -b +- sqrt(Disc) (+: ahead, farther along e), P = J + t e.
// Delta or Disc whose sign the enclosure cannot decide is computed again at twice the working
// precision, up to kMaxWorkingBits; an undecidable sign at the last precision (a dyad tangent to
// within 10^-1500) is refused rather than guessed.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "linkproof/geometry/vec2.h"
#include "quantity_text.h"

namespace linkproof::placement {

/// Decimal digits below the scene's scale (its largest given coordinate or length) to which an
/// irrational position is rationalised; rates and directions: below their own magnitude.
inline constexpr int kRationalisedDigits = 60;
/// The first working precision (about 96 decimal digits) and the last one tried.
inline constexpr int kFirstWorkingBits = 320;
inline constexpr int kMaxWorkingBits = 5120;
/// Largest |angle| accepted, in radians (docs/limits.md): 10^6 rad, about 160,000 turns.
inline constexpr long kMaxAngleRadians = 1000000;

/// How the scene places one joint.
struct JointSpec {
  enum class Kind { Point, AtJoint, Polar, Dyad, Slide };
  Kind kind = Kind::Point;
  std::string name;   ///< the joint's name
  std::string field;  ///< the placement's field, e.g. "mechanism.joints[3].dyad"
  Vec2<Rational> point;  ///< Point: the given position
  /// The joints it is placed from, with the field naming each: AtJoint {J}, Polar {from},
  /// Dyad {J1, J2}, Slide {the line's joint, the circle's centre}.
  std::vector<std::pair<std::string, std::string>> from;
  Rational length, length2;  ///< Polar: L; Dyad: L1, L2; Slide: L
  PiMultiple angle;          ///< Polar, Slide (radians)
  std::string angle_text;    ///< as written, for messages
  int side = 1;              ///< Dyad: +1 left, -1 right; Slide: +1 ahead, -1 behind
};

/// A placed joint: the rational position used, and how far it may be from the dimensioned one.
struct PlacedJoint {
  Vec2<Rational> at;
  bool exact = true;
  Rational bound = 0;  ///< |x - x*|, |y - y*| <= bound (0 when exact)
};

struct Placement {
  std::vector<PlacedJoint> joints;  ///< in the order of the specs
  int working_bits = 0;             ///< the precision that decided every sign and met the grid
};

/// Places every joint. `scale` > 0 is the scene's size (its largest given coordinate or
/// length). InputError(source, field, problem) naming the joint for a reference to an unknown
/// joint, a joint that cannot be placed from placed ones (a cycle), concentric circles, and a
/// dyad or slide that does not assemble (with the distance by which it misses).
Placement place_joints(const std::vector<JointSpec>& specs, const Rational& scale, const std::string& source);

/// A value c pi^k written as a rational: exact when it is one, else the rational nearest the
/// value kRationalisedDigits below its magnitude, with |value - true| <= bound.
struct RationalisedNumber {
  Rational value;
  bool exact = true;
  Rational bound = 0;
};
RationalisedNumber rationalise_number(const PiMultiple& x);

/// The direction (cos A, sin A) as an exactly unit rational vector ((1 - t^2, 2t) / (1 + t^2)
/// with a rational t near tan(A/2)): exact at multiples of 90 degrees, else each coordinate
/// within `bound` of the true direction.
struct RationalisedDirection {
  Vec2<Rational> unit;
  bool exact = true;
  Rational bound = 0;
};
RationalisedDirection rationalise_direction(const PiMultiple& angle);

/// True when |angle| <= kMaxAngleRadians.
bool is_angle_within_limit(const PiMultiple& angle);

}  // namespace linkproof::placement
