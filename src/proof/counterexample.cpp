#include "proof/counterexample.h"

#include <chrono>

#include <cln/integer.h>

#include "check/random_polygon.h"
#include "core/time_budget.h"
#include "linkproof/io/scene.h"
#include "check/arithmetic_types.h"
#include "check/check_polygon.h"

namespace linkproof {

namespace {

/// The size a shrink step must decrease: sum of |numerator| + denominator - 1 over every number.
double magnitude(const Polygon<Rational>& p, const InputRates<Rational>& r) {
  double m = 0;
  const auto add = [&m](const Rational& q) {
    m += cln::double_approx(cln::abs(cln::numerator(q))) + cln::double_approx(cln::denominator(q)) - 1;
  };
  for (int k = 1; k <= p.n(); ++k) {
    add(p.joint(k).x);
    add(p.joint(k).y);
  }
  for (const auto& w : r.omega) add(w);
  for (const auto& w : r.omega_dot) add(w);
  return m;
}

/// Candidates one step smaller than (p, r): a side fewer, or one number moved towards 0.
std::vector<std::pair<Polygon<Rational>, InputRates<Rational>>> smaller(const Polygon<Rational>& p,
                                                                        const InputRates<Rational>& r, int n_min) {
  std::vector<std::pair<Polygon<Rational>, InputRates<Rational>>> out;
  const int n = p.n();
  if (n - 1 >= n_min)
    for (int k = 1; k <= n - 3; ++k) {  // drop input joint K_k: the polygon keeps its last three sides
      std::vector<Vec2<Rational>> joints;
      for (int i = 1; i <= n; ++i)
        if (i != k) joints.push_back(p.joint(i));
      InputRates<Rational> rr = r;
      rr.omega.erase(rr.omega.begin() + (k - 1));
      rr.omega_dot.erase(rr.omega_dot.begin() + (k - 1));
      out.emplace_back(Polygon<Rational>(joints), rr);
    }
  const auto towards_zero = [](const Rational& v) {
    std::vector<Rational> c;
    if (!cln::zerop(v)) c.push_back(0);
    const cln::cl_I t = cln::truncate1(v);
    if (t != v) c.push_back(t);
    else if (!cln::zerop(v)) c.push_back(v - cln::signum(v));
    return c;
  };
  for (int k = 1; k <= n; ++k)
    for (int axis = 0; axis < 2; ++axis) {
      const Rational v = axis == 0 ? p.joint(k).x : p.joint(k).y;
      for (const Rational& c : towards_zero(v)) {
        std::vector<Vec2<Rational>> joints;
        for (int i = 1; i <= n; ++i) joints.push_back(p.joint(i));
        (axis == 0 ? joints[static_cast<size_t>(k - 1)].x : joints[static_cast<size_t>(k - 1)].y) = c;
        out.emplace_back(Polygon<Rational>(joints), r);
      }
    }
  for (size_t k = 0; k < r.omega.size(); ++k)
    for (int which = 0; which < 2; ++which) {
      const Rational v = which == 0 ? r.omega[k] : r.omega_dot[k];
      for (const Rational& c : towards_zero(v)) {
        InputRates<Rational> rr = r;
        (which == 0 ? rr.omega[k] : rr.omega_dot[k]) = c;
        out.emplace_back(p, rr);
      }
    }
  return out;
}

}  // namespace

ClaimOutcome check_data_claim(GroundTruthEngine& engine, const DataClaim& claim, const Polygon<Rational>& polygon,
                              const InputRates<Rational>& rates) {
  using Exact = ScalarTypeOf<Arithmetic::Exact>;
  const PolygonContext<Exact> ctx = build_polygon_context<Exact>(engine, polygon, rates);
  return run_claim(to_claim(claim), ctx);
}

std::optional<Counterexample> find_counterexample(GroundTruthEngine& engine, const DataClaim& claim,
                                                  const CounterexampleSearch& o) {
  const auto start = std::chrono::steady_clock::now();
  Counterexample cx;
  const auto fails = [&](const Polygon<Rational>& p, const InputRates<Rational>& r, ClaimOutcome* keep) {
    if (!claim.info.applies_to(p.n()) || !polygon_input_problem(p).empty()) return false;
    if (cln::zerop(p.dead_centre_determinant())) return false;  // the truth does not exist there
    ++cx.candidates_tried;
    ClaimOutcome out = check_data_claim(engine, claim, p, r);
    // The statement itself must fail at these rates, not only a coefficient.
    bool total_fails = false;
    for (const auto& i : out.instances) total_fails = total_fails || i.verdict == Verdict::Fails;
    if (out.verdict != Verdict::Fails || !total_fails) return false;
    if (keep) *keep = std::move(out);
    return true;
  };
  bool found = false;
  const int lo = std::max(o.n_min, claim.info.min_n);
  const int hi = claim.info.max_n ? std::min(o.n_max, claim.info.max_n) : o.n_max;
  for (int n = lo; n <= hi && !found; ++n) {
    SplitMix64 rng(o.seed * 1000003u + static_cast<std::uint64_t>(n));
    for (int a = 0; a < o.attempts_per_n + o.rational_attempts_per_n && !found; ++a) {
      TimeBudget::check("the counterexample search of " + claim.info.id + " at n = " + std::to_string(n));
      const bool integer = a < o.attempts_per_n;
      const long range = integer ? 2 + a / 10 : 4;  // small integers first
      const auto coordinate = [&]() -> Rational {
        if (integer) return Rational(rng.uniform(-range, range));
        const long q = rng.uniform(2, 12);
        return Rational(rng.uniform(-range * q, range * q)) / Rational(q);
      };
      std::vector<Vec2<Rational>> joints;
      for (int k = 0; k < n; ++k) {
        Rational x = coordinate();
        joints.push_back({std::move(x), coordinate()});
      }
      InputRates<Rational> r;
      for (int k = 0; k < n - 3; ++k) {
        r.omega.push_back(rng.uniform(-3, 3));
        r.omega_dot.push_back(rng.uniform(-3, 3));
      }
      Polygon<Rational> p(joints);
      if (fails(p, r, &cx.outcome)) {
        cx.polygon = p;
        cx.rates = r;
        found = true;
      }
    }
  }
  if (!found) return std::nullopt;
  // Also try the random exact polygons of the sweep (non-integer, varied shapes) if needed: the
  // integer search above finds generic failures quickly; a claim failing only on special
  // configurations is reported as not disproved rather than searched for forever.
  if (o.shrink) {
    bool progress = true;
    while (progress) {
      progress = false;
      const double size = magnitude(cx.polygon, cx.rates);
      for (auto& [p, r] : smaller(cx.polygon, cx.rates, lo)) {
        if (p.n() == cx.polygon.n() && magnitude(p, r) >= size) continue;
        ClaimOutcome out;
        if (fails(p, r, &out)) {
          cx.polygon = std::move(p);
          cx.rates = std::move(r);
          cx.outcome = std::move(out);
          ++cx.shrink_steps;
          progress = true;
          break;
        }
      }
    }
  }
  PolygonScene scene{"counterexample-" + claim.info.id, "", cx.polygon, cx.rates};
  cx.scene_yaml = polygon_scene_to_yaml(scene);
  cx.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return cx;
}

}  // namespace linkproof
