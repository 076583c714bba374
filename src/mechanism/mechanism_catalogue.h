// Mechanism claims and catalogues, and the check that runs them (private: claims are evaluated
// on the library's exact solution type).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "check/judge.h"
#include "linkproof/mechanism/mechanism_check.h"
#include "mechanism/mechanism_solve.h"

namespace linkproof {

/// What a mechanism claim may use: the scene and its exact solution.
struct MechanismContext {
  const MechanismScene& scene;
  const MechanismSolution<Rational>& truth;
};

struct MechanismClaim {
  ClaimInfo info;
  std::function<ClaimSides<Rational>(const MechanismContext&)> evaluate;
  /// Optional: false if the claim does not apply to this mechanism (listed as not applicable).
  std::function<bool(const MechanismContext&)> applies;
};

/// A named set of claims (one paper's), selectable by a scene's `catalogue` field, with the
/// tables it adds to the report (may be empty).
struct MechanismCatalogue {
  std::string name;
  std::vector<MechanismClaim> claims;
  std::function<std::vector<ReportTable>(const MechanismContext&)> tables;
};

/// The exact solution by the symbolic route (throws InputError for bad mobility/inputs).
MechanismSolution<Rational> solve_mechanism_exact(const MechanismScene& scene);

/// Solves and runs the built-in claims plus those of `catalogues` (the scene's); with a
/// restricting `ask`, only what it asks (see MechanismCheck::ask). Throws InputError for a scene
/// that cannot be solved (locked, wrong number of inputs, ...) or an ask naming an unknown claim.
MechanismCheck check_mechanism(const MechanismScene& scene, const std::vector<MechanismCatalogue>& catalogues,
                               Arithmetic a);

/// Solves the scene exactly and runs `claims` only (not the built-in ones, nor the scene's
/// catalogues or ask): `linkproof check-claim CLAIMS --scene MECHANISM_SCENE`.
MechanismCheck check_mechanism_claims(const MechanismScene& scene, const std::vector<MechanismClaim>& claims);

/// Runs one claim: its comparisons judged exactly; an UndefinedQuantity thrown by the claim
/// gives `undefined`, any other exception `error`.
ClaimOutcome run_mechanism_claim(const MechanismClaim& claim, const MechanismContext& ctx);
/// Runs every claim that applies (appended to `outcomes`); the ids of the others are appended to
/// `not_applicable`.
void run_mechanism_claims(const std::vector<MechanismClaim>& claims, const MechanismContext& ctx,
                          std::vector<ClaimOutcome>& outcomes, std::vector<std::string>& not_applicable);

/// The built-in claims (routes_agree, driver_inversion).
std::vector<MechanismClaim> builtin_mechanism_claims();

}  // namespace linkproof
