#include "proof/topology_sweep.h"

namespace linkproof {

TopologySweepCase run_topology_sweep_case(const TopologyConfigurations& configurations, long index) {
  const size_t claims = configurations.claims().size();
  TopologySweepCase c;
  c.index = index;
  std::vector<SampleResult> notes(claims);  // not kept: finish_topology_sweep judges the first cases again
  std::vector<double> seconds(claims, 0.0);
  auto verdicts = configurations.judge(static_cast<int>(index), std::vector<bool>(claims, false), notes, seconds);
  if (!verdicts) {
    c.singular = true;
    return c;
  }
  c.verdicts = std::move(*verdicts);
  for (const Verdict v : c.verdicts)
    if (v == Verdict::Fails) {
      c.degenerate = !configurations.is_replayable(static_cast<int>(index));
      break;
    }
  return c;
}

TopologySweepTally::TopologySweepTally(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                       const TopologySampling& options) {
  report_.run.topology = scene.name;
  report_.run.options = options;
  for (const MechanismDataClaim& c : claims) {
    SampleResult r;
    r.info = c.info;
    report_.run.claims.push_back(std::move(r));
  }
  report_.claims.resize(claims.size());
}

void TopologySweepTally::add(const TopologySweepCase& c) {
  TopologySampleRun& run = report_.run;
  LINKPROOF_ASSERT(c.index > last_index_, "topology sweep cases folded out of order");
  last_index_ = c.index;
  LINKPROOF_ASSERT(c.singular || c.verdicts.size() == run.claims.size(), "a topology sweep case without every verdict");
  ++run.generated;
  if (c.singular) {
    ++run.singular;
    return;
  }
  ++run.solved;
  bool unexpected = false;
  for (size_t k = 0; k < run.claims.size(); ++k) {
    SampleResult& r = run.claims[k];
    TopologySweepClaim& x = report_.claims[k];
    switch (c.verdicts[k]) {
      case Verdict::Holds: ++r.compared; break;
      case Verdict::Undefined:
        ++r.undefined;
        if (!x.first_undefined_case) x.first_undefined_case = c.index;
        break;
      case Verdict::Inconclusive:
        ++r.inconclusive;
        if (!x.first_inconclusive_case) x.first_inconclusive_case = c.index;
        break;
      default:
        if (c.degenerate) {  // no replayable counterexample: skipped, as check-claim does
          ++run.degenerate;
          break;
        }
        ++x.fails;
        if (!x.first_failing_case) x.first_failing_case = c.index;
        unexpected = unexpected || r.info.expected != Expectation::Fails;
        break;
    }
  }
  unexpected_ += unexpected;
}

TopologySweepReport finish_topology_sweep(const TopologyConfigurations& configurations, const TopologySweepTally& tally) {
  TopologySweepReport report = tally.counts();
  const size_t claims = report.run.claims.size();
  std::vector<double> seconds(claims, 0.0);
  for (size_t k = 0; k < claims; ++k) {
    SampleResult& r = report.run.claims[k];
    const TopologySweepClaim& x = report.claims[k];
    r.verdict = topology_verdict(r, x.fails > 0);
    if (x.first_failing_case) r.counterexample = configurations.shrink(k, static_cast<int>(*x.first_failing_case));
    // The first undefined quantity and undecided comparison: the claim alone judged again on its
    // first such case, so that they do not depend on which process judged it.
    std::vector<bool> skip(claims, true);
    skip[k] = false;
    std::vector<SampleResult> notes(claims);
    for (const auto& first : {x.first_undefined_case, x.first_inconclusive_case})
      if (first) configurations.judge(static_cast<int>(*first), skip, notes, seconds);
    r.undefined_quantity = notes[k].undefined_quantity;
    r.undefined_reason = notes[k].undefined_reason;
    r.first_inconclusive = notes[k].first_inconclusive;
  }
  return report;
}

}  // namespace linkproof
