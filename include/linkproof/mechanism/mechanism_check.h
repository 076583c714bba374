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
// `catalogue` field). Claims are evaluated in exact arithmetic; --arith double solves the
// rigid-body route in IEEE double and reports the values with the system's condition number.
#pragma once

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
  /// Per link (relative to the ground), per joint, per tracer point: exact, or the values of
  /// the floating-point route in its own type.
  std::vector<ResultNumber> omega, omega_dot;
  struct PointMotion {
    std::string name;
    ResultNumber v[2], a[2];
    std::optional<ResultNumber> slide, slide_dot;  ///< prismatic joints only
  };
  std::vector<PointMotion> joints, points;
  /// Every pair of links i < k (in link order): omega_ik = omega_i - omega_k, and omega-dot_ik.
  struct Relative {
    std::string i, k;
    ResultNumber omega, omega_dot;
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
  /// --strict: undefined or inconclusive on a true claim is not as expected (exit 1).
  bool strict = false;
};

/// Solves the scene and runs the built-in claims (in arithmetic `a`, as MechanismCheck describes).
/// The paper catalogues of `linkproof check` are the program's, not the library's. Throws
/// InputError for a scene that cannot be solved (locked, wrong number of inputs, ...).
MechanismCheck check_mechanism(const MechanismScene& scene, Arithmetic a);

/// 0 every claim as expected; 1 a claim not as expected (is_as_expected(check.strict)); 3 a
/// claim errored.
int exit_status(const MechanismCheck& check);

}  // namespace linkproof
