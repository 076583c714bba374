// Choosing claims of a claim file and checking the proof options: shared by `prove` and
// `report` on a claim file.
#include <fmt/format.h>

#include "command.h"
#include "linkproof/core/error.h"
#include "proof/prove.h"

namespace linkproof::cli {

std::vector<const DataClaim*> choose_claims(const ClaimFile& file, const std::vector<std::string>& ids) {
  std::vector<const DataClaim*> chosen;
  for (const auto& id : ids) {
    const DataClaim* found = nullptr;
    for (const auto& c : file.claims)
      if (!found && (c.info.id == id || c.info.id.ends_with("." + id))) found = &c;
    if (!found) throw InputError("<command line>", "--claim", "no claim '" + id + "' in " + file.source);
    chosen.push_back(found);
  }
  if (chosen.empty())
    for (const auto& c : file.claims) chosen.push_back(&c);
  return chosen;
}

void check_prove_limits(const std::optional<int>& n, double ladder_seconds) {
  if (n && (*n < 4 || *n > kMaxClaimSides))
    throw InputError("<command line>", "--n", "must be between 4 and " + std::to_string(kMaxClaimSides));
  if (n && *n > kMaxPerNProofSides)
    throw InputError("<command line>", "--n",
                     "a proof at one n is limited to n <= " + std::to_string(kMaxPerNProofSides) +
                         ": its cost grows about as n^3 (eq. 22: about 20 s at n = 20, hours at n = 200); the proof "
                         "for every n (without --n) covers n = " + std::to_string(*n) + " (docs/limits.md)");
  // Written so that NaN fails too (every comparison with NaN is false: `nan` passed the range
  // check and the ladder ran until the run's budget).
  if (!(ladder_seconds >= 0 && ladder_seconds <= kMaxClaimLadderSeconds))
    throw InputError("<command line>", "--ladder-seconds",
                     fmt::format("must be between 0 and {}", kMaxClaimLadderSeconds));
}

void set_ladder(ProveOptions& o, const std::optional<double>& ladder_seconds, bool range_asked) {
  o.ladder_seconds = ladder_seconds.value_or(o.ladder_seconds);
  o.recheck_proved = ladder_seconds.has_value() || range_asked;
}

}  // namespace linkproof::cli
