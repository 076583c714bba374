// The program's exit codes, decided from the typed results (STYLE.md: exit codes and the
// --strict policy live in cli/ alone; the library and report/ keep the facts: verdicts, counts,
// how a run ended). The codes (cli.h, ExitCode; docs/check.md, "Exit status"):
//   0  every claim as expected
//   1  a claim not as expected: a true claim fails (with --strict also: a true claim is
//      undefined or inconclusive; prove: proved only for some n or on samples; count: holds
//      only on samples), an erratum reading that is not disproved (prove), a data check that
//      found a difference or compared nothing
//   2  bad input (the error reports, cli/error_report.h), or a sweep stopped by --max-seconds
//   3  an evaluation error or an internal error (a worker of a sweep failed)
//   128 + signal: a sweep interrupted by that signal
#pragma once

#include <vector>

#include "batch/batch_sweep.h"
#include "batch/topology_sweep_job.h"
#include "check/sweep.h"
#include "count/count_claim.h"
#include "linkproof/check/check.h"
#include "numerics/data_check.h"
#include "proof/mechanism_proof.h"
#include "proof/mechanism_sampling.h"
#include "proof/prove.h"
#include "report/claims_status.h"

namespace linkproof::cli {

/// The --strict policy on one claim's outcome. Without `strict`: nothing against the claim's
/// expectation (ClaimOutcome::is_as_expected(): a true claim does not fail, no error). With
/// `strict` a true claim must also be decided: undefined or inconclusive is not as expected.
bool is_as_expected(const ClaimOutcome& outcome, bool strict);

/// The decisions on a check's claims (polygon, mechanism, curvature): each claim's mark under
/// the policy and the exit status, 3 if a verdict is Error, else 1 if a claim is not as
/// expected, else 0.
ClaimsStatus claims_status(const std::vector<ClaimOutcome>& outcomes, bool strict = false);
int exit_status(const std::vector<ClaimOutcome>& outcomes, bool strict = false);

/// A sweep: 3 if an evaluation errored on some polygon, else 1 if a true claim failed on one,
/// else 0.
int exit_status(const SweepReport& sweep);
/// A batch sweep: the report's status when complete; 128 + signal when interrupted; 2 when
/// stopped by the time budget (--max-seconds); 3 when a worker failed.
int exit_status(const BatchSweepResult& result);
/// A batch run that ended as `run` says: `complete` when it completed, else as above.
int exit_status(const BatchRun& run, int complete);

/// A sweep of a topology (sweep --topology): as check-claim --topology --count (sampling_status,
/// without --strict): a true claim holding on the samples and a claim expected to fail disproved
/// are as expected; exit 1 if a claim is not.
ClaimsStatus topology_sweep_status(const TopologySweepReport& report);
/// ... run as a batch job: its status when complete, else as a polygon sweep's batch run.
int exit_status(const TopologyBatchResult& result);

/// check-data: 0 when every sample is consistent, at least one value was compared and every
/// compared value agrees (a sample with nothing recorded does not count against it); 1
/// otherwise (a value differs or is inconclusive, a sample is inconsistent or unsolvable, or
/// nothing was compared: a run that decided nothing is not a pass).
int exit_status(const DataCheck& check);

/// The --strict policy on a counting claim: without `strict`, CountClaim::as_expected() (a
/// stated "proved" is also met by holds_on_samples); with `strict` only the stated verdict.
bool is_as_expected(const CountClaim& claim, bool strict);
/// count: each claim's mark under the policy; exit 0 when every claim is as expected, else 1.
ClaimsStatus count_status(const CountReport& report, bool strict = false);

/// The --strict policy on a proof: without `strict`, ProofResult::is_as_expected() (a true claim
/// proved, or proved for some n, or holding on samples); with `strict` a true claim must be
/// proved for its whole range (proved or proved_generically).
bool is_as_expected(const ProofResult& result, bool strict);
/// prove and check-claim: each claim's mark under the policy; exit 3 if a claim errored, else 1
/// if one is not as expected, else 0.
ClaimsStatus proofs_status(const std::vector<ProofResult>& results, bool strict = false);
int exit_status(const std::vector<ProofResult>& results, bool strict = false);

/// Claims on random configurations of a topology: a true claim holding on the samples is as
/// expected, except with `strict` (samples are no proof); a claim expected to fail must be
/// disproved. Exit 1 if one is not as expected.
ClaimsStatus sampling_status(const TopologySampleRun& run, bool strict = false);

/// Mechanism claims over a topology: as for proofs (a true claim proved, proved_generically or,
/// not strict, holding on samples; an erratum disproved); 3 if a verdict is Error.
ClaimsStatus topology_proof_status(const TopologyProofRun& run, bool strict);

}  // namespace linkproof::cli
