// What asking for less saves (issue 15, scenes with `ask`, check/ask.h). Pairs timed in one run,
// on the same data; read the ratios:
//   BM_AskPolygon/<what>/n     one random polygon (bench_cases.h), exact, as `check` does it:
//                              everything / one solved rate omega-dot_{n-1,n} / one claim (eq22)
//                              / one input's rate (no engine at all)
//   BM_AskMechanism/<what>     a bundled mechanism, exact, as `check` does it: everything /
//                              the link asked (the sub-mechanism that reaches it) / with one claim
// The engine's derivation is made before timing (a once-per-process cost, BM_SymbolicDerivation).
#include <benchmark/benchmark.h>

#include "bench_cases.h"
#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof::bench {
namespace {

enum class PolygonAsk { Everything, OneSolvedRate, OneClaim, OneInputRate };

SceneAsk polygon_ask(PolygonAsk what, int n) {
  SceneAsk ask;
  if (what == PolygonAsk::OneSolvedRate) ask.rates = {AskedRate{true, {std::to_string(n - 1), "ask[0]"}}};
  if (what == PolygonAsk::OneInputRate) ask.rates = {AskedRate{true, {"1", "ask[0]"}}};
  if (what == PolygonAsk::OneClaim) ask.claims = std::vector<AskedName>{{"eq22", "ask[0].claims[0]"}};
  return ask;
}

void BM_AskPolygon(benchmark::State& state, PolygonAsk what) {
  const int n = static_cast<int>(state.range(0));
  const RandomPolygonCase& c = make_cases(n, 1).front();
  const std::optional<SceneAsk> ask =
      what == PolygonAsk::Everything ? std::nullopt : std::optional<SceneAsk>(polygon_ask(what, n));
  const std::vector<Claim> claims = asked_claims(dijksman1966::catalogue(), ask, "bench");
  GroundTruthEngine engine;
  engine.derivation(n);
  engine.derivation(4);
  for (auto _ : state) {
    PolygonCheck r = check_polygon(engine, claims, "bench", c.polygon, c.rates, Arithmetic::Exact, Evidence::All, ask);
    benchmark::DoNotOptimize(r);
  }
  state.counters["claims"] = benchmark::Counter(static_cast<double>(claims.size()));
}
BENCHMARK_CAPTURE(BM_AskPolygon, everything, PolygonAsk::Everything)->Arg(5)->Arg(12)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AskPolygon, one_claim_eq22, PolygonAsk::OneClaim)->Arg(5)->Arg(12)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AskPolygon, one_solved_rate, PolygonAsk::OneSolvedRate)->Arg(5)->Arg(12)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_AskPolygon, one_input_rate, PolygonAsk::OneInputRate)->Arg(5)->Arg(12)->Arg(40)->Unit(benchmark::kMicrosecond);

enum class MechanismAsk { Everything, OneLink, OneLinkOneClaim };

void BM_AskMechanism(benchmark::State& state, const char* scene, const char* link, MechanismAsk what) {
  MechanismScene s = load_mechanism_scene(std::string(LINKPROOF_BENCH_SOURCE_DIR) + "/verify/scenes/mechanisms/" + scene);
  if (what != MechanismAsk::Everything) {
    s.ask = SceneAsk{};
    s.ask->links = {AskedName{link, "ask[0].links[0]"}};
    if (what == MechanismAsk::OneLinkOneClaim) s.ask->claims = std::vector<AskedName>{{"routes_agree", "ask[1]"}};
  }
  size_t links = 0;
  for (auto _ : state) {
    MechanismCheck r = check_mechanism(s, {}, Arithmetic::Exact);
    links = r.ask ? r.computed_links.size() : r.link_names.size();
    benchmark::DoNotOptimize(r);
  }
  state.counters["links_solved"] = benchmark::Counter(static_cast<double>(links));
}
BENCHMARK_CAPTURE(BM_AskMechanism, stephenson_everything, "pmks_stephenson_iii_example_2_1.yaml", "CD",
                  MechanismAsk::Everything)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AskMechanism, stephenson_link_CD, "pmks_stephenson_iii_example_2_1.yaml", "CD",
                  MechanismAsk::OneLink)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AskMechanism, stephenson_link_CD_routes_agree, "pmks_stephenson_iii_example_2_1.yaml", "CD",
                  MechanismAsk::OneLinkOneClaim)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AskMechanism, watt_everything, "pmks_watt_i_0.yaml", "BCD", MechanismAsk::Everything)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AskMechanism, watt_link_BCD, "pmks_watt_i_0.yaml", "BCD", MechanismAsk::OneLink)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AskMechanism, eightbar_everything, "dijksman1984_eightbar.yaml", "3", MechanismAsk::Everything)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AskMechanism, eightbar_link_3, "dijksman1984_eightbar.yaml", "3", MechanismAsk::OneLink)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linkproof::bench
