// Counterexamples: exact configurations on which a claim fails, searched in mechanism space
// (small integer joint coordinates and rates, not raw doubles) and shrunk to the smallest one
// that still fails: fewer sides, then smaller |coordinates| and |rates|, one step at a time
// (the shrinking of property-based testing, on the linkage itself).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "claims/data_claim.h"
#include "check/check_polygon.h"

namespace linkproof {

struct Counterexample {
  Polygon<Rational> polygon;
  InputRates<Rational> rates;
  ClaimOutcome outcome;           ///< the failing check (exact), with the differing terms
  int candidates_tried = 0;       ///< configurations evaluated by search and shrinking
  int shrink_steps = 0;           ///< accepted shrinking steps
  double seconds = 0;
  std::string scene_yaml;         ///< the configuration as a scene file `linkproof check` reads
};

struct CounterexampleSearch {
  int n_min = 4, n_max = 8;       ///< sides to search (clipped to the claim's range)
  int attempts_per_n = 60;        ///< random integer configurations per n before giving up on n
  /// Then random rational ones (coordinates p/q, 2 <= q <= 12): a wrong term whose coefficient
  /// vanishes at every small integer point (a factor x (x - 1) ... of a coordinate) is nonzero at
  /// almost every rational one.
  int rational_attempts_per_n = 0;
  std::uint64_t seed = 1;
  bool shrink = true;
};

/// Searches for an exact configuration on which `claim` fails; nullopt if none was found.
std::optional<Counterexample> find_counterexample(GroundTruthEngine& engine, const DataClaim& claim,
                                                  const CounterexampleSearch& options);

/// The claim checked exactly on one configuration.
ClaimOutcome check_data_claim(GroundTruthEngine& engine, const DataClaim& claim, const Polygon<Rational>& polygon,
                              const InputRates<Rational>& rates);

}  // namespace linkproof
