#include "exit_status.h"

#include <algorithm>

#include "cli.h"

namespace linkproof::cli {

bool is_as_expected(const ClaimOutcome& outcome, bool strict) {
  if (!outcome.is_as_expected()) return false;
  if (!strict || outcome.info.expected != Expectation::Holds) return true;
  return outcome.verdict == Verdict::Holds;
}

ClaimsStatus claims_status(const std::vector<ClaimOutcome>& outcomes, bool strict) {
  ClaimsStatus s;
  s.strict = strict;
  bool error = false;
  for (const ClaimOutcome& c : outcomes) {
    s.as_expected.push_back(is_as_expected(c, strict));
    error = error || c.verdict == Verdict::Error;
    if (!s.as_expected.back()) s.exit_status = kClaimFailed;
  }
  if (error) s.exit_status = kInternalError;
  return s;
}

int exit_status(const std::vector<ClaimOutcome>& outcomes, bool strict) {
  return claims_status(outcomes, strict).exit_status;
}

int exit_status(const SweepReport& sweep) {
  if (sweep.errors() > 0) return kInternalError;
  return sweep.unexpected_failures() > 0 ? kClaimFailed : kAsExpected;
}

int exit_status(const BatchRun& run, int complete) {
  switch (run.status) {
    case BatchRun::Status::Complete: return complete;
    case BatchRun::Status::Interrupted: return 128 + run.signal;
    case BatchRun::Status::OutOfTime: return kBadInput;
    case BatchRun::Status::WorkerFailed: return kInternalError;
  }
  return kInternalError;
}

int exit_status(const BatchSweepResult& r) { return exit_status(r, exit_status(r.report)); }

ClaimsStatus topology_sweep_status(const TopologySweepReport& report) { return sampling_status(report.run, false); }

int exit_status(const TopologyBatchResult& r) {
  return exit_status(r, topology_sweep_status(r.report).exit_status);
}

int exit_status(const DataCheck& check) {
  // A run that compared nothing, or could not decide a value, is not a pass.
  const bool pass = check.compared > 0 && check.differing + check.inconclusive + check.inconsistent + check.unsolvable == 0;
  return pass ? kAsExpected : kClaimFailed;
}

bool is_as_expected(const CountClaim& claim, bool strict) {
  return strict ? claim.verdict == claim.expected : claim.as_expected();
}

ClaimsStatus count_status(const CountReport& report, bool strict) {
  ClaimsStatus s;
  s.strict = strict;
  for (const CountClaim& c : report.claims) s.as_expected.push_back(is_as_expected(c, strict));
  const bool all = std::all_of(s.as_expected.begin(), s.as_expected.end(), [](bool b) { return b; });
  s.exit_status = all ? kAsExpected : kClaimFailed;
  return s;
}

bool is_as_expected(const ProofResult& result, bool strict) {
  if (!result.is_as_expected()) return false;
  if (!strict || result.expected != Expectation::Holds) return true;
  return result.verdict == ProofVerdict::Proved || result.verdict == ProofVerdict::ProvedGenerically;
}

ClaimsStatus proofs_status(const std::vector<ProofResult>& results, bool strict) {
  ClaimsStatus s;
  s.strict = strict;
  bool error = false;
  for (const ProofResult& r : results) {
    s.as_expected.push_back(is_as_expected(r, strict));
    error = error || r.verdict == ProofVerdict::Error;
    if (!s.as_expected.back()) s.exit_status = kClaimFailed;
  }
  if (error) s.exit_status = kInternalError;
  return s;
}

int exit_status(const std::vector<ProofResult>& results, bool strict) { return proofs_status(results, strict).exit_status; }

ClaimsStatus sampling_status(const TopologySampleRun& run, bool strict) {
  ClaimsStatus s;
  s.strict = strict;
  for (const SampleResult& r : run.claims) {
    const bool holds_only_on_samples = r.info.expected == Expectation::Holds;
    s.as_expected.push_back(r.is_as_expected() && !(strict && holds_only_on_samples));
    if (!s.as_expected.back()) s.exit_status = kClaimFailed;
  }
  return s;
}

ClaimsStatus topology_proof_status(const TopologyProofRun& run, bool strict) {
  ClaimsStatus s;
  s.strict = strict;
  bool error = false;
  for (const TopologyProof& p : run.claims) {
    const bool sampled_only = p.info.expected == Expectation::Holds && (p.verdict == ProofVerdict::HoldsOnSamples ||
                                                                        p.verdict == ProofVerdict::HoldsWithProbability);
    s.as_expected.push_back(p.is_as_expected() && !(strict && sampled_only));
    error = error || p.verdict == ProofVerdict::Error;
    if (!s.as_expected.back()) s.exit_status = kClaimFailed;
  }
  if (error) s.exit_status = kInternalError;
  return s;
}

}  // namespace linkproof::cli
