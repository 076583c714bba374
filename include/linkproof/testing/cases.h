// Generated test cases for other projects' property tests (linkproof/testing.h): exact polygons
// and mechanisms of named families, built from a few exact parameters so that every case
// assembles exactly (rational joints; a link is the rigid body through its joints,
// mechanism/linkage.h) and prints as a scene `linkproof check` reads.
//
// Families (MechanismCase::family, the label RC_CLASSIFY reports):
//   polygon/<shape>/n=<n>       Dijksman's n-side polygon (docs/conventions.md §A1) as an n-link closed chain:
//                               links s1..sn (side j = K_j -> K_{j+1}), ground sn, joints K1..Kn
//                               (K_j joins sides j-1 and j), inputs s1..s_{n-3}
//   fourbar/<grashof class>     ground, crank, coupler, rocker; joints O2, A, B, O4; input crank
//   sixbar/watt-i               PMKS Watt I (docs/conventions.md §E): AB, BCD, DE, EF, CFG; ground joints A, G
//   sixbar/stephenson-iii       PMKS Stephenson III: AB, BCE, CD, EF, FG; ground joints A, D, G
//   eightbar/fig5               Dijksman Fig. 5 (docs/conventions.md §A7): links 0..7, joints 12 23 34 40 01 15 57
//                               74 56 63; link 0 fixed, input link 1
//   slider/crank                slider-crank: ground, crank, rod, slider; joint P prismatic
//                               (guide: ground) at B
//   slider/inverted             inverted slider-crank: ground, crank, block, rocker; the block
//                               slides in a slot of the rocker along O4 -> A (Coriolis, docs/conventions.md §C)
// A suffix "/near-toggle...", "/near-dead-centre...", "/q-far...", "/beta-small..." or "/ratio-1e<k>"
// marks a biased case, "/<bias>-does-not-apply" a case drawn under a bias that the family cannot
// have (testing/generators.h says which and why).
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "linkproof/geometry/polygon.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof::testing {

using Point = Vec2<Rational>;

struct PolygonCase {
  std::string family;
  Polygon<Rational> polygon;     ///< K_1..K_n
  InputRates<Rational> rates;    ///< omega_{j,n}, omega-dot_{j,n}, j = 1..n-3
};

struct MechanismCase {
  std::string family;
  MechanismScene scene;
};

/// The polygon as a closed chain (see the family table above); the truth of this mechanism is
/// the polygon's ground truth (docs/conventions.md §A2): link s_j turns with omega_{j,n}.
MechanismCase polygon_mechanism(const PolygonCase& p);

/// Grashof's classes of a four-bar with lengths s <= p <= q <= l (shortest, two middle, longest):
///   s + l < p + q: CrankRocker (shortest is the crank), DoubleCrank (shortest is the ground,
///   "drag link"), DoubleRocker (shortest is the coupler); s + l = p + q: ChangePoint;
///   s + l > p + q: TripleRocker (non-Grashof). Decided exactly from the squared lengths.
enum class GrashofClass { CrankRocker, DoubleCrank, DoubleRocker, ChangePoint, TripleRocker };
std::string_view to_string(GrashofClass c);
GrashofClass classify_grashof(const Point& o2, const Point& a, const Point& b, const Point& o4);

/// sign(sqrt(a) + sqrt(b) - sqrt(c) - sqrt(d)) for rationals a, b, c, d >= 0, exactly.
int sign_of_root_sum_difference(const Rational& a, const Rational& b, const Rational& c, const Rational& d);

/// Builders. `omega`, `omega_dot` drive the input link (slider families: the crank).
MechanismCase make_fourbar(const Point& o2, const Point& a, const Point& b, const Point& o4, const Rational& omega,
                           const Rational& omega_dot);
/// Joints A..G in this order.
MechanismCase make_watt_sixbar(const std::array<Point, 7>& abcdefg, const Rational& omega, const Rational& omega_dot);
MechanismCase make_stephenson_sixbar(const std::array<Point, 7>& abcdefg, const Rational& omega,
                                     const Rational& omega_dot);
/// Joints in the order 12, 23, 34, 40, 01, 15, 57, 74, 56, 63.
MechanismCase make_fig5_eightbar(const std::array<Point, 10>& joints, const Rational& omega, const Rational& omega_dot);
MechanismCase make_slider_crank(const Point& o, const Point& a, const Point& b, const Point& axis, const Rational& omega,
                                const Rational& omega_dot);
MechanismCase make_inverted_slider_crank(const Point& o2, const Point& a, const Point& o4, const Rational& omega,
                                         const Rational& omega_dot);

/// True if the scene solves exactly (valid linkage, mobility = number of inputs, inputs fix the
/// motion) and no two joints of one link coincide.
bool is_well_posed(const MechanismScene& scene);

/// The determinant of the square velocity system of a scene, exactly: the rigid-body constraint
/// rows A q-dot = 0 (mechanism/mechanism_solve.h) and one unit row per input. It is 0 exactly
/// where the inputs cannot drive the mechanism (a toggle, the dead centre D = 0 of a loop,
/// docs/conventions.md §A6), and changes sign across such a configuration, so a sign change of it between two nearby
/// configurations proves a singular one between them. Its scale depends on the coordinates and
/// the sign on the numbering: only its zeros and sign changes mean something.
/// InputError if the system is not square (rows != unknowns) or the scene has no linkage.
Rational compute_velocity_determinant(const MechanismScene& scene);

/// For RapidCheck's counterexamples and messages: the family and the scene YAML; the polygon's
/// joints and rates as exact fractions; the class name.
std::ostream& operator<<(std::ostream& os, const MechanismCase& c);
std::ostream& operator<<(std::ostream& os, const PolygonCase& c);
std::ostream& operator<<(std::ostream& os, GrashofClass c);

/// Convenience for a user's alpha function: a joint's position in double (nearest), by name
/// (InputError if there is none).
std::array<double, 2> joint_xy(const Linkage& g, const std::string& joint);

}  // namespace linkproof::testing
