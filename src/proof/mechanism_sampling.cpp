#include "proof/mechanism_sampling.h"

#include <fmt/format.h>

#include <chrono>
#include <map>

#include "proof/topology_configurations.h"

namespace linkproof {

std::string to_string(TopologyVerdict v) {
  switch (v) {
    case TopologyVerdict::HoldsOnSamples: return "holds_on_samples";
    case TopologyVerdict::Disproved: return "disproved";
    case TopologyVerdict::Undefined: return "undefined";
    case TopologyVerdict::Inconclusive: return "inconclusive";
  }
  return "?";
}

bool SampleResult::is_as_expected() const {
  if (info.expected == Expectation::Fails) return verdict == TopologyVerdict::Disproved;
  return verdict == TopologyVerdict::HoldsOnSamples;
}

MechanismScene random_topology_configuration(const MechanismScene& scene, std::uint64_t seed, int index,
                                             int coordinate_range) {
  const TopologyLayout layout = topology_layout(scene);
  TopologySampling o;
  o.seed = seed;
  o.coordinate_range = coordinate_range;
  const std::vector<MechanismDataClaim> no_claims;
  const TopologyConfigurations configurations(scene, no_claims, o);
  return topology_configuration(scene, layout, configurations.values(index), configurations.name(index));
}

TopologyVerdict topology_verdict(const SampleResult& r, bool failed) {
  if (failed) return TopologyVerdict::Disproved;
  return r.compared > 0                          ? TopologyVerdict::HoldsOnSamples
         : r.undefined == 0 && r.inconclusive > 0 ? TopologyVerdict::Inconclusive
                                                  : TopologyVerdict::Undefined;
}

TopologySampleRun sample_topology(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                  const TopologySampling& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  TopologySampleRun run;
  run.topology = scene.name;
  run.options = o;
  const TopologyConfigurations configurations(scene, claims, o);
  for (const MechanismDataClaim& c : claims) {
    SampleResult r;
    r.info = c.info;
    run.claims.push_back(std::move(r));
  }
  std::vector<double> claim_seconds(claims.size(), 0.0);
  const int attempts = 20 * o.count + 100;
  std::vector<bool> done(claims.size(), false);
  std::map<size_t, int> failures;  // claim -> the configuration it first failed on
  for (int i = 0; i < attempts; ++i) {
    bool any_open = false;
    for (size_t k = 0; k < claims.size(); ++k) any_open = any_open || !done[k];
    if (!any_open) break;
    ++run.generated;
    const std::optional<std::vector<Verdict>> verdicts = configurations.judge(i, done, run.claims, claim_seconds);
    if (!verdicts) {
      ++run.singular;
      continue;
    }
    ++run.solved;
    for (size_t k = 0; k < claims.size(); ++k) {
      if (done[k]) continue;
      SampleResult& r = run.claims[k];
      switch ((*verdicts)[k]) {
        case Verdict::Holds: done[k] = ++r.compared >= o.count; break;
        case Verdict::Undefined: ++r.undefined; break;
        case Verdict::Inconclusive: ++r.inconclusive; break;
        default:
          if (!configurations.is_replayable(i)) {  // degenerate: no replayable counterexample
            ++run.degenerate;
            break;
          }
          done[k] = true;
          failures[k] = i;
          break;
      }
    }
  }
  for (size_t k = 0; k < claims.size(); ++k) {
    SampleResult& r = run.claims[k];
    const auto t0 = Clock::now();
    const auto f = failures.find(k);
    r.verdict = topology_verdict(r, f != failures.end());
    if (f != failures.end()) r.counterexample = configurations.shrink(k, f->second);
    r.seconds = claim_seconds[k] + std::chrono::duration<double>(Clock::now() - t0).count();
  }
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return run;
}

}  // namespace linkproof
