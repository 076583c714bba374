// The routes to omega-dot_{n-1,n} in floating-point and exact arithmetic, timed on the same
// random polygons:
//   BM_Eq22Double           the paper's formula (22) on the generic construction (Q_j, P'_j,
//                           beta_j per four-bar j: construct_four_bar_steps), in plain double:
//                           the graphic method's cost;
//   BM_Eq22ClosedFormsDouble  (22) with i, lambda from the closed forms: the formula alone;
//   BM_ClosedFormMotion<T>  the ground truth by the closed forms of conventions §A2;
//   BM_TapeMotion<T>        the ground truth by the compiled symbolic tape (route d).
// Counter per_side = time / (n-3 inputs), in seconds (the table prints 21.3n for 21.3 ns).
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_cases.h"
#include "geometry/closed_forms.h"
#include "geometry/construction.h"
#include "symbolic/ground_truth.h"

namespace linkproof::bench {
namespace {

/// S = sum_{j != l} a_j a_l over ordered pairs (conventions §A3), in O(n).
template <class T>
struct PairSum {
  T sum{}, squares{};
  void add(const T& a) {
    sum += a;
    squares += a * a;
  }
  T value() const { return sum * sum - squares; }
};

/// Eq. (22): sum_j (lambda_j w_j^2 + i_{n-1,j} wd_j) - cot phi S1 - rho S2, with lambda_j and
/// the ratios taken from the graphic construction of each four-bar j (construct_four_bar_steps,
/// as the construction route runs it), cot phi and rho = |r_{n-2}|^2/D from the signed angle.
template <class T>
T eq22_by_construction(const Polygon<T>& p, const InputRates<T>& in) {
  const int n = p.n();
  const Vec2<T> a = p.side(n - 2), b = p.side(n - 1);
  const T D = cross(a, b);
  if (linkproof::is_zero(D)) throw dead_centre_error();
  FourBarFrame<T> frame = make_four_bar_frame(p);
  T first{};
  PairSum<T> s1, s2;
  for (int j = 1; j <= n - 3; ++j) {
    FourBarSteps<T> c = construct_four_bar_steps(frame, p.joint(j), p.side(j));
    if (!c.coefficients_defined) throw_first_undefined_coefficient(p, j);
    const T& w = in.omega[static_cast<size_t>(j - 1)];
    const T& wd = in.omega_dot[static_cast<size_t>(j - 1)];
    first += c.lambda * w * w + c.i_out * wd;
    s1.add(c.i_out * w);
    s2.add(c.i_cpl * w);
  }
  return first - dot(a, b) / D * s1.value() - norm2(a) / D * s2.value();
}

/// Eq. (22) with every coefficient from the closed forms (no construction).
template <class T>
T eq22_by_closed_forms(const Polygon<T>& p, const InputRates<T>& in) {
  const ClosedForms<T> cf = compute_closed_forms(p);
  T first{};
  PairSum<T> s1, s2;
  for (size_t j = 0; j < cf.i_out.size(); ++j) {
    const T& w = in.omega[j];
    first += cf.lambda[j] * w * w + cf.i_out[j] * in.omega_dot[j];
    s1.add(cf.i_out[j] * w);
    s2.add(cf.i_cpl[j] * w);
  }
  return first - cf.cot_phi * s1.value() - cf.rho * s2.value();
}

template <class T>
struct Case {
  Polygon<T> polygon;
  InputRates<T> rates;
};

/// The random cases in type T; the label names their families. Cases on which the construction
/// is undefined (a pole at infinity: measure zero, but possible with small rationals) are left
/// out, since (22) by construction cannot be evaluated there.
template <class T>
std::vector<Case<T>> converted_cases(benchmark::State& state, int n) {
  const std::vector<RandomPolygonCase>& drawn = make_cases(n, 16);
  state.SetLabel(families(drawn));
  std::vector<Case<T>> out;
  for (const RandomPolygonCase& c : drawn) {
    try {
      (void)eq22_by_construction(c.polygon, c.rates);
    } catch (const UndefinedQuantity&) {
      continue;
    }
    out.push_back({c.polygon.template convert<T>(), c.rates.template convert<T>()});
  }
  return out;
}

/// Before timing a formula, prove on the first case, exactly, that the timed code computes
/// omega-dot_{n-1,n}: a fast wrong formula is not a result.
template <class F>
bool formula_is_exact(int n, F formula) {
  const RandomPolygonCase& c = make_cases(n, 1).front();
  const PolygonMotion<Rational> truth = compute_closed_form_motion(c.polygon, c.rates);
  return formula(c.polygon, c.rates) == truth.omega_dot[static_cast<size_t>(n - 2)];
}

void set_per_side(benchmark::State& state, int n) {
  state.counters["per_side"] =
      benchmark::Counter(n - 3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Eq22Double(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  if (!formula_is_exact(n, [](const auto& p, const auto& r) { return eq22_by_construction(p, r); })) {
    state.SkipWithError("eq. (22) by construction differs from the exact truth");
    return;
  }
  const auto cases = converted_cases<double>(state, n);
  size_t k = 0;
  for (auto _ : state) {
    const Case<double>& c = cases[k++ % cases.size()];
    benchmark::DoNotOptimize(eq22_by_construction(c.polygon, c.rates));
  }
  set_per_side(state, n);
}

void BM_Eq22ClosedFormsDouble(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  if (!formula_is_exact(n, [](const auto& p, const auto& r) { return eq22_by_closed_forms(p, r); })) {
    state.SkipWithError("eq. (22) by closed forms differs from the exact truth");
    return;
  }
  const auto cases = converted_cases<double>(state, n);
  size_t k = 0;
  for (auto _ : state) {
    const Case<double>& c = cases[k++ % cases.size()];
    benchmark::DoNotOptimize(eq22_by_closed_forms(c.polygon, c.rates));
  }
  set_per_side(state, n);
}

template <class T>
void BM_ClosedFormMotion(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto cases = converted_cases<T>(state, n);
  size_t k = 0;
  for (auto _ : state) {
    const Case<T>& c = cases[k++ % cases.size()];
    PolygonMotion<T> m = compute_closed_form_motion(c.polygon, c.rates);
    benchmark::DoNotOptimize(m);
  }
  set_per_side(state, n);
}

template <class T>
void BM_TapeMotion(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto cases = converted_cases<T>(state, n);
  GroundTruthEngine engine;
  engine.derivation(n);
  size_t k = 0;
  for (auto _ : state) {
    const Case<T>& c = cases[k++ % cases.size()];
    PolygonMotion<T> m = engine.motion(c.polygon, c.rates);
    benchmark::DoNotOptimize(m);
  }
  set_per_side(state, n);
}

using TrackedDouble = Tracked<double>;
using TrackedLongDouble = Tracked<long double>;

BENCHMARK(BM_Eq22Double)->Arg(5)->Arg(12)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Eq22ClosedFormsDouble)->Arg(5)->Arg(12)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_ClosedFormMotion, double)->Arg(5)->Arg(12)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_ClosedFormMotion, TrackedDouble)->Arg(5)->Arg(12)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_ClosedFormMotion, long double)->Arg(5)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_ClosedFormMotion, TrackedLongDouble)->Arg(5)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_ClosedFormMotion, Rational)->Arg(5)->Arg(12)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_TapeMotion, double)->Arg(5)->Arg(12)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_TapeMotion, TrackedDouble)->Arg(5)->Arg(12)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_TapeMotion, Rational)->Arg(5)->Arg(12)->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace linkproof::bench
