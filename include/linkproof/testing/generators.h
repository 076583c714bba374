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
// Bias toward the hard places (SPEC.md A6; Bias::None draws ordinary cases):
//   NearDeadCentre  polygons: K_{n-1} at distance ~10^-k from the line K_{n-2} K_n (D ~ 0);
//                   four-bars: B ~10^-k off the line A O4 (coupler and rocker nearly aligned:
//                   the toggle where the crank cannot drive)
//   QFar            polygons: r_{n-2} x (r_1 + r_{n-1}) ~ 10^-k (Q_1 far away)
//   BetaSmall       polygons: r_1 nearly parallel to r_{n-2} (beta_1 ~ 10^-k)
//   ExtremeRatio    one link 10^k times shorter or longer than the rest, k up to 8
//   Any             one of the above, or none
// Biases that do not apply to a family (QFar, BetaSmall on mechanisms) give ordinary cases.
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
