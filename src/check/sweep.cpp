#include "linkproof/check/sweep.h"

#include <chrono>
#include <map>

#include <fmt/format.h>

namespace linkproof {

int SweepReport::exit_status() const {
  int status = 0;
  for (const auto& t : tallies) {
    if (t.error > 0) return 3;
    if (t.expected == Expectation::Holds && t.fails > 0) status = 1;
  }
  return status;
}

SweepReport run_sweep(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const SweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  SweepReport r;
  r.options = o;
  std::map<std::string, size_t> slot;
  for (const Claim& c : catalogue) {
    slot[c.info.id] = r.tallies.size();
    r.tallies.push_back(ClaimTally{c.info.id, c.info.expected});
  }
  std::map<std::string, int> examples;
  for (int n = o.n_min; n <= o.n_max; ++n) {
    const int first = o.only_index ? *o.only_index : 0;
    const int last = o.only_index ? *o.only_index + 1 : o.count;
    for (int index = first; index < last; ++index) {
      const RandomPolygonCase rc = generate_random_polygon(o.seed, n, index);
      const PolygonCheck check = check_polygon(engine, catalogue, fmt::format("random-n{}-i{}", n, index),
                                               rc.polygon, rc.rates, o.arithmetic);
      if (r.tolerance_rule.empty()) r.tolerance_rule = check.tolerance_rule;
      ++r.cases;
      for (const auto& id : check.not_applicable) ++r.tallies[slot[id]].not_applicable;
      for (const ClaimOutcome& c : check.claims) {
        ClaimTally& t = r.tallies[slot[c.info.id]];
        switch (c.verdict) {
          case Verdict::Holds: ++t.holds; break;
          case Verdict::Fails: ++t.fails; break;
          case Verdict::Undefined: ++t.undefined; break;
          case Verdict::Inconclusive: ++t.inconclusive; break;
          case Verdict::Error: ++t.error; break;
        }
        const bool unexpected = c.is_unexpected_failure() || c.verdict == Verdict::Error;
        if (unexpected && examples[c.info.id]++ < o.max_examples_per_claim)
          r.unexpected.push_back({c.info.id, c.verdict, rc, c.headline, c.error});
        if (c.info.expected == Expectation::Fails && c.verdict == Verdict::Fails &&
            examples[c.info.id + "#disproof"]++ == 0)
          r.erratum_counterexamples.push_back({c.info.id, c.verdict, rc, c.headline, ""});
      }
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace linkproof
