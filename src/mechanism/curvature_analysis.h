// The second-order work a mechanism scene asks for (scene keys `curvature` and `joint_joining`;
// docs/curvature.md): every pole, the requested path curvature centres with their inflection
// circles, Bobillier's construction, the joint-joining reductions, and the claims that check them.
//
//   MechanismScene s = load_mechanism_scene("verify/scenes/mechanisms/dijksman1984_eightbar.yaml");
//   CurvatureCheck r = check_curvature(s, {});
//
// Exact throughout (CLN rationals). Points at infinity and undefined centres are values
// (PlanePoint) naming the quantity and the reason; a claim that needs one is `undefined`.
//
// Claims (ids; expected verdict):
//   curvature.joint_poles                      holds  P_ij of the two links of every revolute joint is the joint
//   curvature.aronhold_kennedy                 holds  P_ij, P_jk, P_ik collinear, every triple
//   curvature.bar_far_joint_is_centre          holds  every bar: the far joint is the curvature centre of the
//                                                     near joint in the motion of the two links it connects
//   curvature.euler_savary.bar_lines           holds  Euler-Savary with S_a, S_b the two joints of every bar
//   curvature.euler_savary.rays                holds  Euler-Savary on rays from the pole in fixed directions,
//                                                     S_b the analytic centre (also: S_b lies on the ray)
//   curvature.bobillier                        holds  steps (a)-(e) give the analytic centre of each request
//   curvature.bobillier.mirrored_step_c        fails  erratum reading of step (c) (docs/conventions.md §D)
//   joint_joining.first_order.velocities_preserved        holds
//   joint_joining.first_order.accelerations_preserved     fails (first order keeps velocities only)
//   joint_joining.second_order.velocities_preserved       holds
//   joint_joining.second_order.accelerations_preserved    holds
//   joint_joining.second_order.relocation_is_centre       holds  F' by (1') equals the centre of I
//   joint_joining.second_order.any_near_point             holds  another point K of the bar line as
//                                                                 near joint preserves accelerations
// Reductions apply in the order listed, each on the linkage left by the previous one; each step is
// compared with the linkage before it on every link except its two bars.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mechanism/bobillier.h"
#include "mechanism/curvature.h"
#include "mechanism/joint_joining.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {

struct PoleEntry {
  int i = 0, k = 0;
  PlanePoint<Rational> pole;
};

struct CentreEntry {
  CurvatureRequest request;
  RelativePointMotion<Rational> motion;
  PlanePoint<Rational> centre;
  InflectionCircle<Rational> circle;
  /// Bobillier's construction from two (point, centre) pairs of the same relative motion, and
  /// where the pairs came from (bars joining the two links, or analytic centres of two joints).
  std::optional<BobillierConstruction<Rational>> bobillier, bobillier_mirrored;
  std::string bobillier_pairs;
};

struct ReductionEntry {
  JointJoiningRequest request;
  Linkage linkage_before;  ///< the linkage the step was applied to
  JointJoiningStep step;
  /// Before and after the step (exact, rigid-body route); `after` is empty if problem is set.
  MechanismSolution<Rational> before, after;
  bool solved = false;
  std::string problem;
  bool velocities_preserved = false, accelerations_preserved = false;
};

struct CurvatureAnalysis {
  std::vector<PoleEntry> poles;  ///< every pair i < k in link order
  std::vector<CentreEntry> centres;
  std::vector<ReductionEntry> reductions;
  /// The pole of (i, k) (either order; a pole is symmetric).
  const PlanePoint<Rational>& pole(int i, int k) const;
};

CurvatureAnalysis analyse_curvature(const MechanismScene& scene, const MechanismSolution<Rational>& truth);

/// The claims listed above, on a finished analysis.
std::vector<MechanismClaim> curvature_claims(std::shared_ptr<const CurvatureAnalysis> analysis);

struct CurvatureCheck {
  std::string scene;
  std::vector<std::string> link_names;
  std::shared_ptr<const CurvatureAnalysis> analysis;
  std::vector<ClaimOutcome> claims;
  std::vector<std::string> not_applicable;
};

/// Solves the scene exactly, analyses it and runs the claims plus those of `catalogues`.
/// Throws InputError for a scene that cannot be solved.
CurvatureCheck check_curvature(const MechanismScene& scene, const std::vector<MechanismCatalogue>& catalogues);

/// The squared distance as an exact radius text: "p/q" when it is a rational square, else
/// "sqrt(p/q)".
std::string exact_radius_text(const Rational& squared);

}  // namespace linkproof
