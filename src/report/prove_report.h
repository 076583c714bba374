// Reports of `linkproof prove` and `linkproof check-claim`: JSON (the contract in
// docs/claims.md) and readable text. Per claim: id, verdict (proved, proved_generically with
// `except`, proved_for with `proved_n`, disproved with `counterexample`, holds_on_samples with
// the samples counted, error), scope, the proof's steps, per-n proofs with times and expression
// sizes, timings. Whether a claim is as expected, and the exit status, are the program's
// decisions (report/claims_status.h; with --strict only proved/proved_generically count for a
// true claim, docs/verdicts.md): the JSON and the text print them as given.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <vector>

#include "proof/prove.h"
#include "report/claims_status.h"

namespace linkproof {

nlohmann::json to_json(const Counterexample& c);
/// One claim; `as_expected` as decided (ProofResult::is_as_expected() outside a command).
nlohmann::json to_json(const ProofResult& r, bool as_expected);
/// {"claims": [...], "summary": {...}, "coordinates": "...", "exit_status": ...}
nlohmann::json to_json(const std::vector<ProofResult>& results, const ClaimsStatus& status);

void write_text(std::ostream& out, const std::vector<ProofResult>& results, const ClaimsStatus& status);

/// Prints the results as JSON or text: the one ending of `prove` and `check-claim`.
void report_proofs(std::ostream& out, const std::vector<ProofResult>& results, bool as_json, const ClaimsStatus& status);

/// What the symbols of proofs mean.
inline constexpr const char* kProofCoordinates =
    "x_k, y_k: components of side r_k = K_{k+1} - K_k (k = 1..n-1); (px, py): joint K_n; in a proof for every n "
    "x_j, x_l, x_{n-2}, x_{n-1} name the sides of two inputs j, l and the last two sides";

}  // namespace linkproof
