// Sweeps: every claim of a catalogue on many random exact polygons, tallied per claim.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "check/check_polygon.h"
#include "check/random_polygon.h"

namespace linkproof {

struct SweepOptions {
  int n_min = 4, n_max = 12;
  int count = 100;                  ///< cases per n
  std::uint64_t seed = 1;
  Arithmetic arithmetic = Arithmetic::Exact;
  std::optional<int> only_index;    ///< replay just this case index (for every n in range)
  int max_examples_per_claim = 3;   ///< unexpected failures kept per claim, as exact scenes
};

struct ClaimTally {
  std::string id;
  Expectation expected = Expectation::Holds;
  long holds = 0, fails = 0, undefined = 0, inconclusive = 0, error = 0, not_applicable = 0;
  long total() const { return holds + fails + undefined + inconclusive + error; }
};

struct SweepExample {
  std::string claim_id;
  Verdict verdict;
  RandomPolygonCase polygon;
  ComparisonOutcome headline;
  std::string error;
  /// For an example read back from a result file: its evidence as the file recorded it (a
  /// JSON object's text, checked when read); `headline` is then empty.
  std::string recorded_evidence = {};
};

struct SweepReport {
  SweepOptions options;
  long cases = 0;
  double seconds = 0;
  std::vector<ClaimTally> tallies;
  /// Cases where a claim expected to hold failed or errored (the ones that matter).
  std::vector<SweepExample> unexpected;
  /// For each erratum reading, one case where it fails (its disproof), if any was seen.
  std::vector<SweepExample> erratum_counterexamples;

  /// Evaluations that errored, over every claim and polygon.
  long errors() const;
  /// Polygons on which a claim expected to hold failed, over every such claim.
  long unexpected_failures() const;
};

SweepReport run_sweep(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const SweepOptions& options);

}  // namespace linkproof
