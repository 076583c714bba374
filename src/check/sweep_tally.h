// The fold of a sweep: cases in k order in, a SweepReport out.
//
// The report keeps, per claim, the first `max_examples_per_claim` unexpected outcomes and, per
// erratum reading, the first case that disproves it ("first" in k order). add() applies that
// rule and trims the case's examples to those kept, so a case written after add() carries only
// the evidence the report uses. The rule is monotone: the examples kept from all cases are
// among those kept from any subset containing them, so shards that each trim by the same rule
// still hold every example the whole sweep keeps (the merge re-applies it).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "check/sweep_case.h"

namespace linkproof {

class SweepTally {
 public:
  SweepTally(const std::vector<Claim>& catalogue, const SweepOptions& options);

  /// Counts case c (cases must come in increasing k) and trims c.examples to the ones the report
  /// keeps. Returns the id of a claim whose example the report needs but c does not carry (a
  /// result file trimmed by a different rule); nullopt when all is well. Nothing is counted then.
  std::optional<std::string> add(SweepCase& c);

  /// Number of cases counted so far.
  long cases() const { return report_.cases; }
  /// Cases counted so far with at least one unexpected outcome.
  long unexpected_cases() const { return unexpected_cases_; }
  /// True if case c (already added) has an unexpected outcome.
  bool has_unexpected(const SweepCase& c) const;

  /// The report of every case added so far (seconds left 0: the caller times the run).
  const SweepReport& report() const { return report_; }

 private:
  std::vector<ClaimInfo> claims_;  // catalogue order
  std::map<std::string, size_t> slot_;
  std::map<std::string, int> unexpected_kept_;
  std::map<std::string, bool> disproof_kept_;
  long unexpected_cases_ = 0;
  long last_k_ = -1;
  SweepReport report_;
};

}  // namespace linkproof
