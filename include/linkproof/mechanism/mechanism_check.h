// Checking claims on a mechanism scene: the exact truth of every link and joint, and a verdict
// per claim. The mechanism counterpart of check/check.h (polygons).
//
//   MechanismScene s = load_mechanism_scene("verify/scenes/mechanisms/fig5_eightbar.yaml");
//   MechanismCheck r = check_mechanism(s, Arithmetic::Exact);
//   r.omega[k], r.omega_dot[k], r.joints[j].v[0], r.claims[c].verdict, ...
//
// Truth: the symbolic loop closure (mechanism/mechanism_closure.h) solved exactly. Built-in
// claims, run on every scene:
//   mechanism.routes_agree     the GiNaC closure and the rigid-body vector formulas give the
//                              same q-dot and q-ddot (two independent derivations);
//   mechanism.driver_inversion (mobility 1) taking any other moving link as the driver, with its
//                              rates from the solution, gives the same motion (docs/conventions.md §C: the
//                              results do not depend on which link drives).
// Paper-specific claims come from catalogues (the program's own, selected by the scene's
// `catalogue` field). Claims are evaluated in exact arithmetic. In a floating arithmetic (double,
// long double, mp30, ...) the rigid-body route is solved again in that arithmetic with running
// error bounds (Tracked<F>, core/tracked.h: midpoint-radius arithmetic): every value is reported
// as its midpoint with a rigorous bound on its distance to the exact value, derived from the
// rounding of the scene's rationals and of every operation (never measured against the exact
// solve), beside the system's condition number.
#pragma once

#include <cln/integer.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/check/arithmetic.h"
#include "linkproof/check/check.h"
#include "linkproof/core/result_number.h"
#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

/// A table of named quantities for reports (e.g. the vectors of an acceleration polygon).
struct ReportTable {
  std::string title;
  std::vector<std::pair<std::string, std::string>> rows;
};

/// For a scene run on rationalised positions, axes or rates (MechanismScene::placement): how far
/// each exact result for the rationals may be from the same result at the dimensioned values
/// (docs/mechanisms.md, "Rationalised, and said so"; mechanism/dimensioned_bound.h derives it).
/// Every bound b is |result for the rationals - result at the dimensioned values| <= b, per
/// coordinate for a vector, rounded up to a double; +inf where nothing is bounded.
struct DimensionedBound {
  bool bounded = false;  ///< every bound below is finite
  std::string reason;    ///< when not bounded: the first quantity without a bound, and why
  int digits = 0;        ///< decimal digits of the bounding solve
  struct Link {
    std::string name;
    double omega = 0, omega_dot = 0;
  };
  struct Point {
    std::string name;
    double v = 0, a = 0;
    /// Prismatic joints: sigma-dot, sigma-ddot (per unit of the axis as written), the rates along
    /// the unit axis and the Coriolis term.
    std::optional<double> slide, slide_dot, v_unit, a_unit, coriolis;
  };
  std::vector<Link> links;           ///< every link but the ground, in link order
  std::vector<Point> joints, points;
  /// The largest bound of each kind (the summary): omega, omega-dot, point velocity and
  /// acceleration, sliding velocity and acceleration (along the unit axis; 0 without sliders).
  double omega = 0, omega_dot = 0, v = 0, a = 0, sliding_v = 0, sliding_a = 0;
};

struct MechanismCheck {
  std::string scene;
  Arithmetic arithmetic = Arithmetic::Exact;
  /// Mobility and rank are decided exactly whatever `arithmetic` says.
  int mobility = 0, grubler = 0, rank = 0, loops = 0, unknowns = 0;
  /// Set when the floating-point route could not solve the configuration (its rank decision
  /// disagreed with the exact one, or its exponent range was exceeded, e.g. coordinates near
  /// 1e200 in double): the reason; the motion shown is then the exact one.
  std::string arithmetic_note;
  std::vector<std::string> link_names;
  /// Per link (relative to the ground), per joint, per tracer point: exact, or the midpoints of
  /// the floating-point route in its own type.
  std::vector<ResultNumber> omega, omega_dot;
  /// Beside every value, its bound (the `_bound` members, same index): nullopt for an exact
  /// value; for a midpoint of the floating route a rigorous bound, |exact - midpoint| <= bound
  /// (core/tracked.h; unbounded, i.e. infinite, when the solve divided by a pivot whose bound
  /// reaches zero).
  std::vector<std::optional<ResultRadius>> omega_bound, omega_dot_bound;
  /// A prismatic pair as textbooks state it (docs/mechanisms.md, "Sliders"). Sign convention:
  /// the motion of the SLIDER relative to the GUIDE, positive when the slider moves along +u
  /// (u the axis as written, fixed in the guide); swapping the pair's [guide, slider] order
  /// flips the sign, as it flips which body moves relative to which.
  struct Sliding {
    std::string guide, slider;  ///< link names
    Vec2<Rational> axis;        ///< u as written in the scene (any non-zero length)
    /// |u| = axis_length * sqrt(axis_radicand), exactly; axis_radicand is 1 when |u| is
    /// rational (e.g. [3/5, 4/5], [3, 4]), > 1 otherwise ([1, 1]: 1 * sqrt(2)).
    Rational axis_length;
    cln::cl_I axis_radicand = 1;
    /// The sliding velocity and acceleration along the unit axis u/|u| (length/time,
    /// length/time^2): sigma-dot |u|, sigma-ddot |u|. Their values are v_unit * sqrt(rate_radicand)
    /// and a_unit * sqrt(rate_radicand). Exact arithmetic: rate_radicand = axis_radicand, so an
    /// irrational |u| is never rounded (v_unit is then the exact coefficient of the root).
    /// Floating arithmetic: rate_radicand = 1 and the values carry bounds that cover both the
    /// solve and the enclosure of |u|.
    ResultNumber v_unit, a_unit;
    cln::cl_I rate_radicand = 1;
    std::optional<ResultRadius> v_unit_bound, a_unit_bound;
    /// The Coriolis acceleration 2 omega_guide x v_rel = 2 omega_guide J v_rel (v_rel = sigma-dot u,
    /// the slider's velocity relative to the guide): the part of the slider point's acceleration
    /// that is neither the guide point's nor the sliding acceleration (docs/conventions.md §C).
    ResultNumber coriolis[2];
    std::optional<ResultRadius> coriolis_bound[2];
  };
  struct PointMotion {
    std::string name;
    ResultNumber v[2], a[2];
    /// Prismatic joints only: sigma-dot, sigma-ddot, the rates per unit of the axis AS WRITTEN
    /// (the slider's velocity relative to the guide is sigma-dot u); `sliding` restates them
    /// along the unit axis with the Coriolis term.
    std::optional<ResultNumber> slide, slide_dot;
    std::optional<ResultRadius> v_bound[2], a_bound[2], slide_bound, slide_dot_bound;
    std::optional<Sliding> sliding;  ///< prismatic joints only
  };
  std::vector<PointMotion> joints, points;
  /// Every pair of links i < k (in link order): omega_ik = omega_i - omega_k, and omega-dot_ik.
  struct Relative {
    std::string i, k;
    ResultNumber omega, omega_dot;
    std::optional<ResultRadius> omega_bound, omega_dot_bound;
  };
  std::vector<Relative> relative;
  std::vector<ReportTable> tables;
  /// 2-norm condition number of the velocity system (constraints + input rows), in double.
  double condition = 0;
  /// The position closure residual (max |row| at the given joints; 0 when exact).
  Rational closure_residual;
  double dimension_residual = 0;
  std::vector<ClaimOutcome> claims;
  std::vector<std::string> not_applicable;
  /// The scene's `ask` when it restricts (check/ask.h): only the asked links, joints and points
  /// are listed (no relative rates) and only the asked claims run. Asked claims are evaluated on
  /// the whole mechanism (a claim may speak of any link, loop or rank); without them everything
  /// is computed on the smallest determined sub-mechanism found that contains the asked links
  /// (mechanism/sub_mechanism.h). Either way the links solved are `computed_links`, of
  /// `all_links` links and `all_loops` loops in the whole (mobility, loops, rank, condition are
  /// those of what was solved).
  std::optional<SceneAsk> ask;
  std::vector<std::string> computed_links;
  int all_links = 0, all_loops = 0;
  /// Set for a scene whose positions, axes or rates are rationalised (nullopt for an exact scene).
  std::optional<DimensionedBound> dimensioned;
  /// A pin in a straight slot (`type: slot`, docs/mechanisms.md "Slots"), which the reader writes
  /// as the prismatic pair `joint` [slotted, block] and the revolute pair `pin` [block, pin_link]
  /// at one point: reports show it as one joint and no row for the block link (JSON keeps both).
  struct Slot {
    std::string joint, block, pin;  ///< P, P.block, P.pin
    std::string slotted, pin_link;  ///< the link with the slot, the link with the pin
  };
  std::vector<Slot> slots;
};

/// Solves the scene and runs the built-in claims (in arithmetic `a`, as MechanismCheck describes).
/// The paper catalogues of `linkproof check` are the program's, not the library's. Throws
/// InputError for a scene that cannot be solved (locked, wrong number of inputs, ...).
MechanismCheck check_mechanism(const MechanismScene& scene, Arithmetic a);

}  // namespace linkproof
