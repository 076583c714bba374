// Checking one named claim of linkproof's catalogue on a generated case, exactly: the core of the
// GTest matcher ClaimHolds (testing/matchers.h). No GTest or RapidCheck needed here.
//
//   polygon cases    the claims of Dijksman (1966), ids "dijksman1966.eq22", "dijksman1966.eq9a",
//                    ... (docs/claims.md), erratum readings "dijksman1966.eq4.printed", ...
//   mechanism cases  "mechanism.routes_agree", "mechanism.driver_inversion", and the claims of
//                    the catalogues a scene names (docs/mechanisms.md)
// The claim is evaluated in exact arithmetic (residual exactly 0 or not).
#pragma once

#include <optional>
#include <string>

#include "linkproof/core/exact.h"
#include "linkproof/core/verdict.h"
#include "linkproof/testing/cases.h"

namespace linkproof::testing {

struct ClaimResult {
  bool found = false;  ///< the id names a claim that applies to this case
  bool holds = false;  ///< verdict == Verdict::Holds
  /// The verdict (Verdict::Error also when `found` is false: no such claim here).
  Verdict verdict = Verdict::Error;
  /// The headline comparison's residual lhs - rhs, exactly and as the nearest double; empty when
  /// the claim is undefined, errored or was not found.
  std::optional<Rational> residual_exact;
  std::optional<double> residual;
  std::string detail;  ///< the residual, the undefined quantity, or the known ids, in words
};

ClaimResult check_claim(const std::string& id, const PolygonCase& c);
ClaimResult check_claim(const std::string& id, const MechanismCase& c);

}  // namespace linkproof::testing
