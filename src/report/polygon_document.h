// The derivation report of one polygon scene (Dijksman 1966, docs/conventions.md part A): built from the check's
// verdicts, the engine's symbolic derivation and the paper's construction, in this order:
//   summary       each claim, its verdict and what the verdict rests on (exact residual, or a
//                 floating-point residual against its derived bound);
//   derivation    the loop closure, its first and second time derivatives and the solved
//                 omega, omega-dot of sides n-2, n-1 as GiNaC prints them in LaTeX, and the
//                 coefficients of omega-dot_j, omega_j^2, omega_j omega_l of omega-dot_{n-1,n}
//                 (symbolic for n <= kSymbolicReportMaxN, their values always);
//   construction  K'_j, Q_j, P'_j, i_{n-1,j}, i_{n-2,j}, cot beta_j, lambda_j, phi, exact with
//                 their decimals (the drawing is the summary's);
//   terms         the term-by-term tables of the claims that have them ((22) among them);
//   errata        each erratum reading beside its corrected form, with this scene as the
//                 counterexample where the reading fails here;
//   numerics      (when asked) the claims in every floating-point arithmetic: largest derived
//                 relative error bound against run time;
//   reproduce     the command, seed, version and commit.
#pragma once

#include <string>
#include <vector>

#include "check/check_polygon.h"
#include "linkproof/io/scene.h"
#include "report/document.h"

namespace linkproof::report {

/// Above this n the symbolic expressions are summarised rather than printed (they grow as n).
inline constexpr int kSymbolicReportMaxN = 6;

struct PolygonReportOptions {
  bool numerics = false;     ///< add the numerics section (re-checks in every floating-point arithmetic)
  std::string scene_text;    ///< the scene file's text, shown as the counterexample of failing errata
};

/// Builds the report; `check` is check_polygon's result on `scene` with `catalogue`.
Document build_polygon_document(GroundTruthEngine& engine, const std::vector<Claim>& catalogue,
                                const PolygonScene& scene, const PolygonCheck& check,
                                const PolygonReportOptions& options);

/// The polygon to scale with the construction of every four-bar j (K'_j, Q_j, P'_j, beta_j and
/// the lines that meet in Q_j and P'_j); points that do not exist are left out. Without
/// `with_construction`, the polygon alone.
Drawing polygon_construction_drawing(const Polygon<Rational>& polygon, bool with_construction = true);

/// "what the verdict rests on" for one claim outcome, in words (shared by the mechanism report).
std::string verdict_basis(const ClaimOutcome& c, Arithmetic a);

/// The claims at a glance, for the headline of a report: "17 of 17 true claims hold", "12 of 13
/// erratum readings fail, as expected (1 coincides with the truth on this scene)", and either
/// "every claim as expected" or "N NOT as expected: ids".
std::vector<Rich> claims_at_a_glance(const std::vector<ClaimOutcome>& claims);

/// The summary table of claim outcomes (claim, statement, expected, verdict, rests on).
Table claim_summary_table(const std::vector<ClaimOutcome>& claims, Arithmetic a);

/// The errata section: each claim expected to fail beside its corrected form (the claim whose id
/// is the erratum's id without its last ".reading", else the first claim expected to hold under
/// that prefix), with `scene_text` as the counterexample
/// where the erratum fails on this scene. Empty section (no blocks) when there is no erratum.
Section errata_section(const std::vector<ClaimOutcome>& claims, const std::string& scene_text);

/// The term-by-term tables of the claims that have terms.
Section terms_section(const std::vector<ClaimOutcome>& claims);

}  // namespace linkproof::report
