#include "check/sweep_tally.h"

#include "check/check_polygon.h"

namespace linkproof {

SweepTally::SweepTally(const std::vector<Claim>& catalogue, const SweepOptions& options) {
  report_.options = options;
  for (const Claim& c : catalogue) {
    slot_[c.info.id] = claims_.size();
    claims_.push_back(c.info);
    report_.tallies.push_back(ClaimTally{c.info.id, c.info.expected});
  }
}

bool SweepTally::has_unexpected(const SweepCase& c) const {
  for (const auto& info : claims_) {
    const auto v = c.verdicts.find(info.id);
    if (v != c.verdicts.end() && is_unexpected(info.expected, v->second)) return true;
  }
  return false;
}

std::optional<std::string> SweepTally::add(SweepCase& c) {
  LINKPROOF_ASSERT(c.k > last_k_, "sweep cases must be added in increasing case order");
  // First pass: which examples does the report keep? (Nothing changes until all are present.)
  std::vector<SweepExample> kept;
  std::vector<bool> unexpected_slots, disproof_slots;
  for (const auto& info : claims_) {
    const auto v = c.verdicts.find(info.id);
    if (v == c.verdicts.end()) continue;
    const bool keep_unexpected =
        is_unexpected(info.expected, v->second) && unexpected_kept_[info.id] < report_.options.max_examples_per_claim;
    const bool keep_disproof = is_disproof(info.expected, v->second) && !disproof_kept_[info.id];
    if (!keep_unexpected && !keep_disproof) continue;
    const SweepExample* e = c.example_for(info.id);
    if (e == nullptr) return info.id;
    kept.push_back(*e);
  }
  // Second pass: count.
  last_k_ = c.k;
  ++report_.cases;
  if (has_unexpected(c)) ++unexpected_cases_;
  for (const auto& id : c.not_applicable) {
    const auto s = slot_.find(id);
    if (s != slot_.end()) ++report_.tallies[s->second].not_applicable;
  }
  for (const auto& [id, verdict] : c.verdicts) {
    const auto s = slot_.find(id);
    if (s == slot_.end()) continue;
    ClaimTally& t = report_.tallies[s->second];
    switch (verdict) {
      case Verdict::Holds: ++t.holds; break;
      case Verdict::Fails: ++t.fails; break;
      case Verdict::Undefined: ++t.undefined; break;
      case Verdict::Inconclusive: ++t.inconclusive; break;
      case Verdict::Error: ++t.error; break;
    }
  }
  for (const auto& e : kept) {
    const Expectation expected = claims_[slot_.at(e.claim_id)].expected;
    if (is_unexpected(expected, e.verdict)) {
      ++unexpected_kept_[e.claim_id];
      report_.unexpected.push_back(e);
    } else {
      disproof_kept_[e.claim_id] = true;
      report_.erratum_counterexamples.push_back(e);
    }
  }
  c.examples = std::move(kept);
  return std::nullopt;
}

}  // namespace linkproof
