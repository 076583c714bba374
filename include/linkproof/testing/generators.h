// RapidCheck generators of exact polygons and mechanisms (families: testing/cases.h), for
// property tests in other projects:
//
//   RC_GTEST_PROP(MyKinematics, AlphaIsRight, ()) {
//     const auto c = *linkproof::testing::gen_mechanism();
//     linkproof::testing::rc_assert_alpha_matches(c, my_alpha);   // testing/oracle.h
//   }
//
// Every case assembles exactly: joints have rational coordinates (small integers over a common
// denominator), rates are small fractions, and a case is generated only if it is well posed
// (testing/cases.h is_well_posed: it solves exactly with its inputs; polygons: no dead centre).
//
// Shrinking works in mechanism space: every case is built from non-negative integer parameters
// whose shrink target is the simplest mechanism, so RapidCheck reports the smallest failure:
//   fewer links     gen_mechanism's family index shrinks toward the four-bar; polygons' n
//                   toward n_min;
//   smaller coords  each coordinate shrinks toward 0 through 1, -1, 2, -2, ... and the common
//                   denominator toward 1;
//   simpler rates   omega and omega-dot shrink toward 0, then small integers, then halves;
//   milder bias     the bias exponent k (epsilon = 10^-k, ratio 10^k) shrinks toward 2.
//
// Bias toward the hard places (docs/conventions.md §A6; Bias::None draws ordinary cases). A mechanism's
// loop is read as Dijksman's polygon K_1..K_n (docs/conventions.md §A1: side n fixed, sides 1..n-3 known, the
// unknowns r_{n-2}, r_{n-1}); the bias moves K_{n-1} ~10^-k off a line through K_{n-2}. The loops:
//   four-bar        O2, A, B, O4        (crank, coupler, rocker, ground; j = 1)
//   Watt I          C, D, E, F          (BCD, DE, EF, CFG fixed: the dyad DE-EF driven by BCD; j = 1)
//   Stephenson III  A, B, E, F, G       (AB, BCE, EF, FG, ground; j = 1 or 2)
//   Fig. 5          J01, J12, J23, J34, J40   (pentagon 1-2-3-4-0; j = 1 or 2)
//   NearDeadCentre  polygons: K_{n-1} at distance ~10^-k from the line K_{n-2} K_n (D ~ 0);
//                   four-bars: B ~10^-k off the line A O4 (coupler and rocker nearly aligned: the
//                   toggle where the crank cannot drive); six-bars: the same on their loop (Watt:
//                   E off line D F; Stephenson: F off line E G), the mechanism's dead point since
//                   that loop is a dyad; Fig. 5: its loops are coupled, so no loop's D is the dead
//                   point: one joint J moves along a small integer direction u to ~10^-k (in t
//                   of J + t u) past a root of the velocity determinant (compute_velocity_
//                   determinant, quadratic in t); slider-crank: the rod nearly perpendicular to
//                   the guide; inverted slider-crank: the block A ~10^-k from the slot's pivot O4
//                   (the rocker's omega ~ 1/|A O4|: its only dead point, crank driving).
//                   Labels ".../near-toggle-1e-7" (four-bar, sliders), ".../near-toggle-loop-C.D.E.F-1e-7",
//                   "eightbar/fig5/near-toggle-J57-1e-7".
//   QFar            polygons: r_{n-2} x (r_1 + r_{n-1}) ~ 10^-k (Q_1 far away); mechanisms: the
//                   same with j on their loop ("/q-far-j2-loop-A.B.E.F.G-1e-6"); a four-bar's Q_1
//                   (crank-rocker pole) is far when the coupler is nearly parallel to the ground.
//   BetaSmall       polygons: r_1 nearly parallel to r_{n-2} (beta_1 ~ 10^-k); mechanisms: r_j
//                   nearly parallel to r_{n-2} on their loop ("/beta-small-j1-loop-C.D.E.F-1e-3");
//                   a four-bar's beta_1 is small when crank and coupler are nearly aligned.
//   ExtremeRatio    one link 10^k times shorter or longer than the rest, k up to 8
//   Any             one of the above, or none
// Biases that cannot apply give an ordinary case labelled "/<bias>-does-not-apply":
//   QFar, BetaSmall on sliders: a loop with a prismatic pair is not one of Dijksman's polygons
//   (revolute joints K_j, docs/conventions.md §A1; mechanism/dijksman_compound.h refuses it), so it has no Q_j,
//   P'_j or beta_j (the slider-crank's output never turns: i_{n-1,1} = 0);
//   any bias on gen_fourbar(GrashofClass::ChangePoint): s + l = p + q is an equality that
//   moving a joint by 10^-k breaks, so the class could not be kept.
// gen_fig5_eightbar(NearDeadCentre) redraws a case whose six (joint, direction) tries found no
// root within |t| <= 8, so it always gives a near-toggle case.
//
// Coverage: classify_case(c) calls RC_CLASSIFY with the case's family label (testing/cases.h)
// without the bias exponent.
#pragma once

#include <rapidcheck.h>

#include <optional>

#include "linkproof/testing/cases.h"

namespace linkproof::testing {

enum class PolygonShape { Convex, Star, Scattered, Any };
enum class Bias { None, NearDeadCentre, QFar, BetaSmall, ExtremeRatio, Any };

struct PolygonOptions {
  int n_min = 4, n_max = 8;  ///< 4 <= n_min <= n_max
  PolygonShape shape = PolygonShape::Any;
  Bias bias = Bias::None;
  int coordinate_bound = 12;  ///< integer numerators in [-bound, bound]
};

enum class Family { FourBar, SliderCrank, InvertedSliderCrank, WattSixBar, StephensonSixBar, Fig5EightBar, Polygon };

struct MechanismOptions {
  /// The families to draw from, in the order of shrinking (the first is the simplest); empty:
  /// all of them in the order of the enum (four-bar first, polygons last).
  std::vector<Family> families;
  Bias bias = Bias::None;
  /// Four-bars only: the Grashof class (nullopt: any).
  std::optional<GrashofClass> grashof;
  int coordinate_bound = 12;
  PolygonOptions polygon;  ///< for Family::Polygon
};

/// A rate: 0, a small integer or a small fraction p/q (q <= 4), shrinking toward 0.
rc::Gen<Rational> gen_rate();
/// A coordinate numerator in [-bound, bound], shrinking toward 0 (|value| first).
rc::Gen<int> gen_coordinate(int bound);

rc::Gen<PolygonCase> gen_polygon(PolygonOptions options = {});
rc::Gen<MechanismCase> gen_fourbar(std::optional<GrashofClass> grashof = std::nullopt, Bias bias = Bias::None,
                                   int coordinate_bound = 12);
rc::Gen<MechanismCase> gen_watt_sixbar(Bias bias = Bias::None, int coordinate_bound = 12);
rc::Gen<MechanismCase> gen_stephenson_sixbar(Bias bias = Bias::None, int coordinate_bound = 12);
rc::Gen<MechanismCase> gen_fig5_eightbar(Bias bias = Bias::None, int coordinate_bound = 12);
/// Slider-crank and inverted slider-crank (the latter has the Coriolis term).
rc::Gen<MechanismCase> gen_slider_mechanism(Bias bias = Bias::None, int coordinate_bound = 12);
/// Any of the families of `options`, shrinking toward the first.
rc::Gen<MechanismCase> gen_mechanism(MechanismOptions options = {});

/// The RC_CLASSIFY label of a family: without the bias exponent ("fourbar/crank-rocker/near-toggle").
std::string coverage_label(std::string family);
/// RC_CLASSIFY by family and bias (call inside a property).
void classify_case(const MechanismCase& c);
void classify_case(const PolygonCase& c);

}  // namespace linkproof::testing
