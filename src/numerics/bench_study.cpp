#include "numerics/bench_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "linkproof/core/error.h"
#include "numerics/adaptive.h"
#include "check/random_polygon.h"

namespace linkproof {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<ParetoEntry> aggregate(const std::vector<CaseStudy>& studies) {
  std::vector<ParetoEntry> out;
  std::map<std::pair<int, std::string>, size_t> index;
  std::map<size_t, std::vector<double>> errors, bits, seconds;
  for (const CaseStudy& s : studies) {
    for (const RouteMeasurement& m : s.measurements) {
      auto key = std::make_pair(static_cast<int>(m.route), m.arithmetic);
      auto [it, fresh] = index.emplace(key, out.size());
      if (fresh) {
        ParetoEntry e;
        e.route = m.route;
        e.arithmetic = m.arithmetic;
        e.precision_bits = m.precision_bits;
        e.max_log2_error = -kInf;
        out.push_back(e);
      }
      ParetoEntry& e = out[it->second];
      ++e.cases;
      if (!m.defined) continue;
      ++e.defined;
      errors[it->second].push_back(m.n1.log2_relative_error);
      bits[it->second].push_back(std::max(m.n1.error_bits, m.n2.error_bits));
      seconds[it->second].push_back(m.seconds_per_eval);
      e.max_log2_error = std::max({e.max_log2_error, m.n1.log2_relative_error, m.n2.log2_relative_error});
    }
  }
  for (size_t k = 0; k < out.size(); ++k) {
    out[k].median_log2_error = median(errors[k]);
    out[k].median_error_bits = median(bits[k]);
    out[k].median_seconds = median(seconds[k]);
  }
  // The front: entries no other entry beats in both time and (worst) error.
  for (ParetoEntry& e : out) {
    if (e.defined == 0) continue;
    e.on_front = std::none_of(out.begin(), out.end(), [&](const ParetoEntry& o) {
      if (&o == &e || o.defined == 0) return false;
      const bool no_worse = o.median_seconds <= e.median_seconds && o.max_log2_error <= e.max_log2_error;
      const bool better = o.median_seconds < e.median_seconds || o.max_log2_error < e.max_log2_error;
      return no_worse && better;
    });
  }
  return out;
}

/// Where each route fails in double on the family, and which route to trust there.
void describe_family(FamilyCurve& curve) {
  // Half the digits of double: beyond this a double figure is not worth reporting.
  constexpr double kHalfDigits = -26;
  // Score: (points where the route is undefined, worst error where defined), lexicographic, so
  // that on a family where every route breaks in double (the dead centre) the best still shows.
  std::pair<int, double> best_score{1 << 30, kInf};
  for (Route r : kAllRoutes) {
    double worst = -kInf, worst_defined = -kInf;
    int undefined_points = 0;
    std::string first_loss, first_undefined;
    bool seen = false;
    for (const FamilyPoint& p : curve.points) {
      if (!p.study.exact_n1) continue;  // the truth does not exist (exact dead centre)
      for (const RouteMeasurement& m : p.study.measurements) {
        if (m.route != r || m.arithmetic != "double") continue;
        seen = true;
        if (!m.defined) {
          worst = kInf;
          ++undefined_points;
          if (first_undefined.empty())
            first_undefined = fmt::format("undefined at {} = {} ({}: {})", curve.family->parameter,
                                          format_parameter(p.parameter), m.undefined_quantity, m.reason);
          continue;
        }
        const double err = std::max(m.n1.log2_relative_error, m.n2.log2_relative_error);
        worst = std::max(worst, err);
        worst_defined = std::max(worst_defined, err);
        if (err > kHalfDigits && first_loss.empty())
          first_loss = fmt::format("{:.0f} of 53 bits lost at {} = {}", std::min(53.0, 53 + err),
                                   curve.family->parameter, format_parameter(p.parameter));
      }
    }
    if (!seen) continue;
    std::string finding = std::string(to_string(r)) + " in double: ";
    if (first_loss.empty() && first_undefined.empty())
      finding += fmt::format("accurate throughout (worst relative error 2^{:.0f})", worst);
    else
      finding += first_loss + (first_loss.empty() || first_undefined.empty() ? "" : "; ") + first_undefined;
    curve.findings.push_back(std::move(finding));
    const std::pair<int, double> score{undefined_points, worst_defined};
    if (score < best_score) {
      best_score = score;
      curve.trust_route = std::string(to_string(r));
    }
  }
  if (curve.family->singular)
    curve.findings.push_back(
        "the mechanism is singular at the limit (dead centre): omega-dot ~ 1/D^3, every route's condition grows "
        "like 1/eps^3 and at D = 0 no value exists; only the exact arithmetic decides D = 0");
}

/// "2^-26 relative" for a power of two, "correctly rounded" for 0.
std::string request_text(const AdaptiveOptions& o) {
  if (o.relative_tolerance == 0) return "correctly rounded";
  return fmt::format("2^{} relative", std::ilogb(o.relative_tolerance));
}

AdaptiveSummary adaptive_summary(std::string corpus, const std::vector<ExtremeCase>& cases, const AdaptiveOptions& request,
                                 double budget) {
  AdaptiveSummary s;
  s.corpus = std::move(corpus);
  s.request = request_text(request);
  int within = 0;
  for (const ExtremeCase& c : cases) {
    const Polygon<double> p = c.polygon.convert<double>();
    const InputRates<double> in = c.rates.convert<double>();
    const AdaptiveResult r = compute_omega_dot_adaptive(p, in, request);
    ++s.cases;
    if (!r.defined) {
      ++s.undefined;
      continue;
    }
    ++s.by_level[static_cast<size_t>(r.level)];
    ++s.by_stage[static_cast<size_t>(r.stage)];
    double t_double = 0;
    try {
      t_double = seconds_per_call([&] { return compute_by_direct_solve(p, in); }, budget);
    } catch (const UndefinedQuantity&) {
      t_double = kInf;  // plain double cannot even produce a number
    }
    const double t_adaptive = seconds_per_call([&] { return compute_omega_dot_adaptive(p, in, request); }, budget);
    s.mean_double_seconds += std::isfinite(t_double) ? t_double : 0;
    s.mean_adaptive_seconds += t_adaptive;
    if (t_adaptive <= 2 * t_double) ++within;
  }
  const int timed = s.cases - s.undefined;
  if (timed > 0) {
    s.mean_double_seconds /= timed;
    s.mean_adaptive_seconds /= timed;
    s.fraction_within_2x = static_cast<double>(within) / timed;
  }
  return s;
}

}  // namespace

std::string format_parameter(const Rational& x) {
  if (cln::zerop(x)) return "0";
  if (cln::denominator(x) == 1 && cln::abs(x) < 100000) return format_rational(x);
  const double l = std::round(log2_abs(x) * std::log10(2.0));
  // An exact power of ten prints as 1e<k>.
  Rational p = 1;
  for (int i = 0; i < std::abs(static_cast<int>(l)); ++i) p = p * 10;
  if (l < 0) p = 1 / p;
  if (p == x) return fmt::format("1e{}", static_cast<int>(l));
  return fmt::format("{:.3g}", cln::double_approx(x));
}

double parameter_log10(const Rational& x) {
  if (cln::zerop(x)) return -kInf;
  return log2_abs(x) * std::log10(2.0);
}

BenchResult run_bench(const BenchOptions& o) {
  BenchResult result;
  result.options = o;
  for (const std::string& name : o.families)
    if (!find_extreme_family(name)) {
      std::string known;
      for (const ExtremeFamily& f : extreme_families()) known += (known.empty() ? "" : ", ") + f.name;
      throw InputError("<api>", "families", "unknown family '" + name + "' (known: " + known + ")");
    }
  std::vector<const ExtremeFamily*> families;
  for (const ExtremeFamily& f : extreme_families())
    if (o.families.empty() || o.families.count(f.name)) families.push_back(&f);

  // The random cases, the families' points, and the four adaptive summaries of step 3.
  int total = o.random_cases + 4, done = 0;
  for (const ExtremeFamily* f : families) total += static_cast<int>((o.full ? f->full_values : f->quick_values).size());
  const auto tick = [&] {
    ++done;
    if (o.progress) o.progress(done, total);
  };

  GroundTruthEngine engine;
  // 1. Error against time on random polygons.
  std::vector<CaseStudy> studies;
  StudyOptions timed;
  timed.time_budget_seconds = o.time_budget_seconds;
  for (int i = 0; i < o.random_cases; ++i) {
    const RandomPolygonCase c = generate_random_polygon(o.seed, o.n, i);
    studies.push_back(study_case(engine, c.polygon, c.rates, timed));
    tick();
  }
  result.pareto = aggregate(studies);

  // 2. Error against the parameter of each extreme family (one evaluation per point).
  std::vector<ExtremeCase> extreme_corpus;
  for (const ExtremeFamily* f : families) {
    FamilyCurve curve;
    curve.family = f;
    for (const Rational& x : o.full ? f->full_values : f->quick_values) {
      const ExtremeCase c = f->make(x);
      curve.points.push_back({x, study_case(engine, c.polygon, c.rates, {})});
      extreme_corpus.push_back(c);
      tick();
    }
    describe_family(curve);
    result.families.push_back(std::move(curve));
  }

  // 3. Adaptive mode: cost and escalations.
  std::vector<ExtremeCase> random_pentagons;
  for (int i = 0; i < o.adaptive_cases; ++i) {
    const RandomPolygonCase c = generate_random_polygon(o.seed + 1, 5, i);
    random_pentagons.push_back({c.polygon, c.rates});
  }
  const double budget = o.full ? 2e-4 : 2e-5;
  for (const AdaptiveOptions& request : {AdaptiveOptions{}, AdaptiveOptions{0x1p-40}, AdaptiveOptions{0}}) {
    result.adaptive.push_back(adaptive_summary("random pentagons", random_pentagons, request, budget));
    tick();
  }
  result.adaptive.push_back(adaptive_summary("extreme families", extreme_corpus, AdaptiveOptions{}, budget));
  tick();
  return result;
}

}  // namespace linkproof
