// Reports of `linkproof prove` and `linkproof check-claim`: JSON (the contract in README.md)
// and readable text. Per claim: id, verdict (proved, proved_generically with `except`,
// disproved with `counterexample`, holds_on_samples, error), scope, the proof's steps, per-n
// proofs with times and expression sizes, timings.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <vector>

#include "linkproof/proof/prove.h"

namespace linkproof {

nlohmann::json to_json(const Counterexample& c);
nlohmann::json to_json(const ProofResult& r);
/// {"claims": [...], "summary": {...}, "coordinates": "..."}
nlohmann::json to_json(const std::vector<ProofResult>& results);

void write_text(std::ostream& out, const std::vector<ProofResult>& results);

/// 0 every claim as expected (true ones proved or holding, errata disproved); 1 otherwise;
/// 3 if any claim errored.
int exit_status(const std::vector<ProofResult>& results);

/// Prints the results as JSON or text and returns exit_status(results): the one ending of
/// `prove` and `check-claim`.
int report_proofs(std::ostream& out, const std::vector<ProofResult>& results, bool json);

/// What the symbols of proofs mean.
inline constexpr const char* kProofCoordinates =
    "x_k, y_k: components of side r_k = K_{k+1} - K_k (k = 1..n-1); (px, py): joint K_n";

}  // namespace linkproof
