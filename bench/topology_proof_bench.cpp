// Mechanism claims over a topology (issue 26): every claim of a bundled claim file proved for
// every configuration of its scene's topology (prove --file CLAIMS --topology SCENE), and exact
// random configurations of a four-bar checked per second (check-claim --topology --count K).
#include <benchmark/benchmark.h>

#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"
#include "proof/mechanism_proof.h"
#include "proof/mechanism_sampling.h"

namespace linkproof {
namespace {

std::string source(const std::string& rel) { return std::string(LINKPROOF_BENCH_SOURCE_DIR) + "/" + rel; }

struct ClaimSet {
  const char* claims;
  const char* scene;
};

// The Arg of BM_TopologyProofEveryClaim.
const ClaimSet kSets[] = {
    {"verify/claims/mechanisms/fourbar.yaml", "verify/scenes/mechanisms/seed001_fourbar.yaml"},
    {"verify/claims/mechanisms/fourbar_acceleration_polygon.yaml", "verify/scenes/mechanisms/seed001_fourbar.yaml"},
    {"verify/claims/mechanisms/slider_crank.yaml", "verify/scenes/mechanisms/dimensions_slider_crank.yaml"},
    {"verify/claims/mechanisms/inverted_slider_crank.yaml", "verify/scenes/mechanisms/inverted_slider_crank.yaml"},
    {"verify/claims/mechanisms/sixbar_watt.yaml", "verify/scenes/mechanisms/pmks_watt_i_0.yaml"},
    {"verify/claims/mechanisms/sixbar_stephenson.yaml", "verify/scenes/mechanisms/pmks_stephenson_iii_example_2_0.yaml"}};

std::vector<MechanismDataClaim> bound_claims(const ClaimSet& set, const MechanismScene& scene) {
  MechanismClaimFile f = load_mechanism_claim_file(source(set.claims));
  for (MechanismDataClaim& c : f.claims) bind_mechanism_claim(c, scene);
  return f.claims;
}

// Every claim of one file, true ones proved and wrong ones disproved; the counter is the
// slowest claim's time.
void BM_TopologyProofEveryClaim(benchmark::State& st) {
  const ClaimSet& set = kSets[st.range(0)];
  const MechanismScene scene = load_mechanism_scene(source(set.scene));
  const std::vector<MechanismDataClaim> claims = bound_claims(set, scene);
  double slowest = 0;
  for (auto _ : st) {
    const TopologyProofRun run = prove_topology(scene, claims, {});
    for (const TopologyProof& p : run.claims) slowest = std::max(slowest, p.seconds);
    benchmark::DoNotOptimize(run);
  }
  st.counters["slowest_claim_s"] = slowest;
  st.counters["claims"] = static_cast<double>(claims.size());
}
BENCHMARK(BM_TopologyProofEveryClaim)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

// Random configurations of the four-bar, one claim with a point acceleration (the coupler
// point's), solved and judged in arithmetic `a`: configurations per second. The exact and the
// double rows are read together (the issue asks double >= 10x exact).
void sample_fourbar(benchmark::State& st, Arithmetic a) {
  const ClaimSet& set = kSets[0];
  const MechanismScene scene = load_mechanism_scene(source(set.scene));
  std::vector<MechanismDataClaim> claims = bound_claims(set, scene);
  std::erase_if(claims, [](const MechanismDataClaim& c) { return c.info.id != "fourbar.coupler_point_acceleration"; });
  TopologySampling o;
  o.count = 1000;
  o.arithmetic = a;
  long solved = 0;
  for (auto _ : st) {
    const TopologySampleRun run = sample_topology(scene, claims, o);
    solved += run.solved;
    benchmark::DoNotOptimize(run);
  }
  st.SetItemsProcessed(solved);
}
void BM_TopologySamplesExact(benchmark::State& st) { sample_fourbar(st, Arithmetic::Exact); }
BENCHMARK(BM_TopologySamplesExact)->Unit(benchmark::kMillisecond);
void BM_TopologySamplesDouble(benchmark::State& st) { sample_fourbar(st, Arithmetic::Double); }
BENCHMARK(BM_TopologySamplesDouble)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkproof
