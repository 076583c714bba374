// Mechanism engine timings (issue 4): the Fig. 5 eight-bar solved exactly by the symbolic loop
// closure (goal < 5 ms for all 28 relative omega-dot), by the rigid-body route, and by Dijksman's
// multi-polygon method; a random 30-link chain of RRR dyads (exact and double).
#include <benchmark/benchmark.h>

#include <random>

#include "linkproof/io/mechanism_scene.h"
#include "linkproof/mechanism/dijksman_compound.h"
#include "linkproof/mechanism/mechanism_check.h"
#include "linkproof/mechanism/mechanism_vector_route.h"
#include "linkproof/mechanism/mechanism_closure.h"

namespace linkproof {
namespace {

MechanismScene eightbar() {
  return load_mechanism_scene(std::string(LINKPROOF_BENCH_SOURCE_DIR) + "/verify/scenes/mechanisms/fig5_eightbar.yaml");
}

// A four-bar, then dyads (two new links, three joints) each pinned to two random earlier links:
// mobility stays 1. Coordinates are random rationals (fixed seed), so the chain is generic.
MechanismScene random_chain(int links, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(-50, 50);
  const auto point = [&] { return Vec2<Rational>{Rational(c(rng)) / 7, Rational(c(rng)) / 7}; };
  std::vector<std::string> names;
  for (int l = 0; l < links; ++l) names.push_back(std::to_string(l));
  std::vector<LinkageJoint> joints;
  const auto add = [&](int a, int b) {
    joints.push_back({"J" + std::to_string(joints.size()), JointType::Revolute, {a, b}, point(), {}});
  };
  add(0, 1), add(1, 2), add(2, 3), add(3, 0);
  for (int p = 4; p + 1 < links; p += 2) {
    std::uniform_int_distribution<int> earlier(0, p - 1);
    const int e1 = earlier(rng);
    int e2 = earlier(rng);
    while (e2 == e1) e2 = earlier(rng);
    add(e1, p), add(p, p + 1), add(p + 1, e2);
  }
  MechanismScene s;
  s.name = "chain";
  s.source = "chain";
  s.linkage = Linkage(names, 0, joints);
  s.inputs = {MechanismInput{MechanismInput::Kind::Link, 1, Rational(1), Rational(1) / 2}};
  return s;
}

void BM_EightBarExactSymbolic(benchmark::State& st) {
  const MechanismScene s = eightbar();
  for (auto _ : st) benchmark::DoNotOptimize(solve_mechanism_exact(s));
}
BENCHMARK(BM_EightBarExactSymbolic)->Unit(benchmark::kMillisecond);

template <class T>
MechanismSolution<T> vector_solve(const MechanismScene& s) {
  return solve_mechanism<T>(
      s.linkage, s.inputs, rigid_body_constraint_matrix<T>(s.linkage),
      [&](const std::vector<T>& qd) { return rigid_body_acceleration_rhs<T>(s.linkage, qd); }, s.source);
}

void BM_EightBarExactVectorRoute(benchmark::State& st) {
  const MechanismScene s = eightbar();
  for (auto _ : st) benchmark::DoNotOptimize(vector_solve<Rational>(s));
}
BENCHMARK(BM_EightBarExactVectorRoute)->Unit(benchmark::kMillisecond);

void BM_EightBarExactDijksmanPolygons(benchmark::State& st) {
  const MechanismScene s = eightbar();
  for (auto _ : st) benchmark::DoNotOptimize(solve_dijksman_compound<Rational>(s.linkage, s.inputs[0]));
}
BENCHMARK(BM_EightBarExactDijksmanPolygons)->Unit(benchmark::kMillisecond);

void BM_ChainExactSymbolic(benchmark::State& st) {
  const MechanismScene s = random_chain(static_cast<int>(st.range(0)), 7);
  for (auto _ : st) benchmark::DoNotOptimize(solve_mechanism_exact(s));
}
BENCHMARK(BM_ChainExactSymbolic)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_ChainExactVectorRoute(benchmark::State& st) {
  const MechanismScene s = random_chain(static_cast<int>(st.range(0)), 7);
  for (auto _ : st) benchmark::DoNotOptimize(vector_solve<Rational>(s));
}
BENCHMARK(BM_ChainExactVectorRoute)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_ChainDouble(benchmark::State& st) {
  const MechanismScene s = random_chain(static_cast<int>(st.range(0)), 7);
  for (auto _ : st) benchmark::DoNotOptimize(vector_solve<double>(s));
}
BENCHMARK(BM_ChainDouble)->Arg(30)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace linkproof
