// What a claim is, apart from how it is evaluated: its id, source, statement, expected verdict
// and the polygon sizes it applies to.
#pragma once

#include <string>

#include "linkproof/core/verdict.h"

namespace linkproof {

struct ClaimInfo {
  std::string id;         ///< e.g. "dijksman1966.eq22", "dijksman1966.eq4.printed"
  std::string source;     ///< paper, section, equation
  std::string statement;  ///< the statement, in words and symbols
  Expectation expected = Expectation::Holds;
  std::string note;       ///< for erratum readings: what is misread and why it fails
  int min_n = 4;          ///< the claim applies for min_n <= n <= max_n (0: no upper bound)
  int max_n = 0;
  /// The user's claim file it was read from (load_claim_file); empty in linkproof's own
  /// catalogue. A user's claim that is not well formed is bad input (exit 2, naming this file and
  /// the claim); in the catalogue it is a bug (the verdict error, exit 3).
  std::string file{};  // {}: the catalogue's aggregate initialisations may leave it out
  bool applies_to(int n) const { return n >= min_n && (max_n == 0 || n <= max_n); }
};

}  // namespace linkproof
