// The streaming result file of a sweep (`sweep --out FILE`): JSON Lines, one case per line in
// case order, then one summary line. Field names are a contract (docs/sweeps.md):
//
//   {"arithmetic":"exact","case":17,"digest":"6c1f0e2a9b3d4c57","examples":[...],"family":"star",
//    "index":3,"n":5,"not_applicable":["dijksman1966.sec3"],"seed":7,
//    "verdicts":{"dijksman1966.eq22":"holds",...}}
//   {"summary":{ ...the `sweep --json` object without "seconds"..., "shard":"2/4" (sharded only)}}
//
// `examples` holds the evidence of the outcomes the report keeps from this case (SweepTally):
// {"claim", "verdict", "evidence" (as a comparison in `check --json`), "error" (if any)}.
// Keys are sorted and numbers printed by nlohmann::json, so equal results give equal bytes.
// `digest` is the line's content hash (sweep_line_digest): FNV-1a, 64 bits, of the line without
// its `digest` member, 16 lowercase hex digits. A line read back must carry it, match it, and be
// in the canonical form (the bytes the writer gives for what it holds): an edited, damaged or
// hand-written line is refused. A content hash detects edits, truncation and lines from another
// writer; it is not a signature (anyone can recompute it), so it does not stop a forgery.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "check/sweep_case.h"

namespace linkproof {

/// Shard K of N (1 <= K <= N): the cases k with k mod N = K - 1. {1, 1} is the whole sweep.
struct Shard {
  int k = 1, n = 1;
  bool whole() const { return n == 1; }
};

/// One case as a result-file line (no trailing newline).
std::string sweep_case_line(const SweepCase& c, Arithmetic arithmetic);
/// The summary line (no trailing newline): the report as `sweep --json` prints it, without
/// the run time, plus "shard" when the sweep is sharded. `exit_status` is the program's decision
/// on the report (cli/exit_status.h), recorded as given.
std::string sweep_summary_line(const SweepReport& report, const Shard& shard, int exit_status);
/// How the writers of result files (batch/batch_sweep.h, batch/merge.h) learn the exit status a
/// summary line records: the program's function of the report, handed to them.
using SweepExitStatus = std::function<int(const SweepReport&)>;

/// What one line of a result file holds.
struct SweepLine {
  std::optional<SweepCase> sweep_case;  ///< a case line
  std::optional<nlohmann::json> summary;  ///< the summary line's object
  Arithmetic arithmetic = Arithmetic::Exact;  ///< of a case line
};

/// Parses one line; an InputError names `file`, "line L" and the problem. A case line must carry
/// its digest, match it and be in canonical form (see above); field types and verdict words are
/// checked, and the family against the polygon regenerated from (seed, n, index). What a line
/// must hold for a given catalogue is check_case_claims (check/sweep_case.h).
SweepLine parse_sweep_line(const std::string& line, const std::string& file, long line_number);

/// The digest of a case line: FNV-1a (64 bits) of `canonical_line` (the JSON text of the line
/// without its "digest" member), as 16 lowercase hex digits.
std::string sweep_line_digest(const std::string& canonical_line);

/// Checks that `j` has the form of to_json(const ComparisonOutcome&) (report/json_report.h): the
/// evidence of an example read back is kept as recorded; throws InputError naming the field.
void check_evidence_json(const nlohmann::json& j, const std::string& file, const std::string& field);

}  // namespace linkproof
