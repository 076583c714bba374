// The report of proofs (`linkproof report CLAIMS.yaml`): for each claim of a claim file, the
// verdict and what it rests on (a symbolic proof for every n, per-n proofs, exact samples, or
// a counterexample), the argument step by step, the exceptional set with the meaning of each
// factor, and for a disproved claim the counterexample polygon drawn with its construction.
//
// ProofResult is read through its JSON form (report/prove_report.h), so that verdicts and
// fields added to the prover appear without a change here: a verdict is shown as its string.
#pragma once

#include <vector>

#include "io/claim_file.h"
#include "proof/prove.h"
#include "report/document.h"

namespace linkproof::report {

Document build_proof_document(const ClaimFile& file, const std::vector<ProofResult>& results);

}  // namespace linkproof::report
