#include "check/check_polygon.h"

#include <cln/float.h>

#include <algorithm>
#include <new>
#include <optional>

#include "check/inconclusive_cause.h"
#include "check/arithmetic_types.h"

namespace linkproof {

bool ClaimOutcome::is_as_expected() const {
  if (verdict == Verdict::Error) return false;
  return info.expected != Expectation::Holds || verdict != Verdict::Fails;
}

namespace {
/// Adds the quantity that made each undecided floating-point comparison inconclusive, among
/// what the claim read (`reads`).
template <class T>
void name_inconclusive_cause(const PolygonContext<T>& context, const typename PolygonContext<T>::Reads& reads,
                             ClaimOutcome& out) {
  std::optional<InconclusiveCause> cause;
  for (auto* group : {&out.instances, &out.terms})
    for (ComparisonOutcome& c : *group) {
      if (c.verdict != Verdict::Inconclusive || !c.floating || c.floating->undecided == Undecided::None) continue;
      if (!cause) cause = find_inconclusive_cause(context, reads);
      c.cause = cause;
    }
}
}  // namespace

bool is_unexpected(Expectation expected, Verdict v) {
  return v == Verdict::Error || (expected == Expectation::Holds && v == Verdict::Fails);
}

bool is_disproof(Expectation expected, Verdict v) { return expected == Expectation::Fails && v == Verdict::Fails; }

template <class T>
ClaimOutcome run_claim(const Claim& claim, const PolygonContext<T>& context, Evidence evidence) {
  ClaimOutcome out;
  out.info = claim.info;
  try {
    context.clear_reads();
    const ClaimSides<T> sides = claim.function<T>()(context);
    const typename PolygonContext<T>::Reads reads = context.reads();
    if (sides.instances.empty()) {
      out.verdict = Verdict::Error;
      out.error = "the claim produced no comparison";
      return out;
    }
    if (evidence != Evidence::All) {
      // Verdicts only; the text of one comparison, the headline (the first whose verdict is
      // the claim's), is made at the end: the evidence of the others is never printed.
      std::vector<Verdict> verdicts;
      verdicts.reserve(sides.instances.size() + sides.terms.size());
      Verdict v = Verdict::Holds;
      for (const auto* group : {&sides.instances, &sides.terms})
        for (const auto& c : *group) v = combine(v, verdicts.emplace_back(judge_verdict(c)));
      out.verdict = v;
      // A sweep keeps a headline only as an example (sweep_case.cpp).
      const Expectation expected = claim.info.expected;
      if (evidence == Evidence::Examples && !is_unexpected(expected, v) && !is_disproof(expected, v)) return out;
      const auto first = std::find(verdicts.begin(), verdicts.end(), v) - verdicts.begin();
      const size_t k = first == static_cast<std::ptrdiff_t>(verdicts.size()) ? 0 : static_cast<size_t>(first);
      const Comparison<T>* headline =
          k < sides.instances.size() ? &sides.instances[k] : &sides.terms[k - sides.instances.size()];
      out.headline = judge(*headline);
      if constexpr (!ScalarTraits<T>::is_exact) {
        out.instances.push_back(out.headline);
        name_inconclusive_cause(context, reads, out);
        out.headline = std::move(out.instances.front());
        out.instances.clear();
      }
      return out;
    }
    // Reserved: a ComparisonOutcome's move may throw (its CLN values are copied), so a vector
    // that grew would copy every outcome made so far.
    out.instances.reserve(sides.instances.size());
    out.terms.reserve(sides.terms.size());
    Verdict v = Verdict::Holds;
    for (const auto& c : sides.instances) {
      out.instances.push_back(judge(c));
      v = combine(v, out.instances.back().verdict);
    }
    for (const auto& c : sides.terms) {
      out.terms.push_back(judge(c));
      v = combine(v, out.terms.back().verdict);
    }
    out.verdict = v;
    if constexpr (!ScalarTraits<T>::is_exact) name_inconclusive_cause(context, reads, out);
    const ComparisonOutcome* headline = &out.instances.front();
    for (const auto* group : {&out.instances, &out.terms}) {
      const auto it = std::find_if(group->begin(), group->end(), [v](const ComparisonOutcome& c) { return c.verdict == v; });
      if (it == group->end()) continue;
      headline = &*it;
      break;
    }
    out.headline = *headline;
  } catch (const UndefinedQuantity& u) {
    out.mark_undefined(u.quantity(), u.reason());
  } catch (const cln::floating_point_exception& e) {
    // CLN long floats (mp arithmetics) have no denormals or infinity: underflow and overflow
    // throw (core/multiprecision.h). The precision says nothing here, so neither may the verdict.
    out.verdict = Verdict::Inconclusive;
    out.headline.verdict = Verdict::Inconclusive;
    out.headline.reason = std::string("CLN ") + e.what() + " (exponent range exceeded in this precision)";
  } catch (const std::bad_alloc&) {
    throw;  // out of memory (--max-memory-mb) ends the run: not an evaluation's error
  } catch (const std::exception& e) {
    refuse_if_ill_formed_user_claim(claim.info, e);  // a vector as a number, division by rates: exit 2
    out.verdict = Verdict::Error;
    out.error = e.what();
    out.headline.verdict = Verdict::Error;
    out.headline.reason = e.what();
  }
  return out;
}

#define LINKPROOF_INSTANTIATE_RUN_CLAIM(enumerator, name, T) \
  template ClaimOutcome run_claim<T>(const Claim&, const PolygonContext<T>&, Evidence);
LINKPROOF_FOR_EACH_ARITHMETIC(LINKPROOF_INSTANTIATE_RUN_CLAIM)
#undef LINKPROOF_INSTANTIATE_RUN_CLAIM

namespace {

// Every applicable claim inconclusive with `reason`; the rates stay unknown.
void mark_out_of_range(PolygonCheck& r, const std::vector<Claim>& catalogue, const std::string& reason) {
  r.omega.assign(static_cast<std::size_t>(r.n), std::nullopt);
  r.omega_dot.assign(static_cast<std::size_t>(r.n), std::nullopt);
  for (const Claim& claim : catalogue) {
    if (!claim.info.applies_to(r.n)) {
      r.not_applicable.push_back(claim.info.id);
      continue;
    }
    ClaimOutcome out;
    out.info = claim.info;
    out.verdict = Verdict::Inconclusive;
    out.headline.verdict = Verdict::Inconclusive;
    out.headline.reason = reason;
    r.claims.push_back(std::move(out));
  }
}

// Only the rates `r.ask` names: an input's is given, the fixed side's is 0, and only sides
// n-2 and n-1 need the engine's motion (undefined at the dead centre).
template <class T>
void fill_asked_rates(PolygonCheck& r, const PolygonContext<T>& ctx) {
  r.omega.assign(static_cast<std::size_t>(r.n), std::nullopt);
  r.omega_dot.assign(static_cast<std::size_t>(r.n), std::nullopt);
  for (const AskedRate& asked : r.ask->rates) {
    const int j = std::stoi(asked.subject.name);  // validated 1..n by the scene reader
    auto& slot = (asked.dot ? r.omega_dot : r.omega)[static_cast<std::size_t>(j - 1)];
    if (j <= ctx.inputs())
      slot = result_number(asked.dot ? ctx.omega_dot_in(j) : ctx.omega_in(j));
    else if (j == r.n)
      slot = ResultNumber(Rational(0));
    else if (ctx.truth().has_value())
      slot = result_number((asked.dot ? ctx.truth().get().omega_dot : ctx.truth().get().omega)[static_cast<std::size_t>(j - 1)]);
  }
}

}  // namespace

PolygonCheck check_polygon(GroundTruthEngine& engine, const std::vector<Claim>& catalogue, const std::string& scene,
                           const Polygon<Rational>& polygon, const InputRates<Rational>& rates, Arithmetic a,
                           Evidence evidence, const std::optional<SceneAsk>& ask) {
  PolygonCheck r;
  if (ask && ask->restricts()) r.ask = ask;
  r.scene = scene;
  r.arithmetic = a;
  r.n = polygon.n();
  r.determinant = polygon.dead_centre_determinant();
  r.dead_centre = cln::zerop(polygon.dead_centre_determinant());
  if (r.dead_centre) r.dead_centre_reason = dead_centre_error().reason();

  with_scalar_type(a, [&]<class T>() {
    std::optional<PolygonContext<T>> built;
    try {
      built.emplace(build_polygon_context<T>(engine, polygon, rates));
      built->values_on_demand = evidence == Evidence::Examples;
    } catch (const cln::floating_point_exception& e) {
      // The exact input does not fit this arithmetic's exponent range (e.g. 1e400 in double):
      // no claim can be judged in it, which is inconclusive, not an internal error.
      mark_out_of_range(r, catalogue, std::string("the input is outside the exponent range of this arithmetic (CLN ") +
                                          e.what() + "); exact arithmetic or a multiprecision one decides");
      return 0;
    }
    const PolygonContext<T>& ctx = *built;
    if (a != Arithmetic::Exact)
      r.determinant = result_number(r.dead_centre ? from_int<T>(0) : cross(ctx.r(r.n - 2), ctx.r(r.n - 1)));
    if (r.ask) {
      fill_asked_rates(r, ctx);
    } else {
      for (int j = 0; j < r.n; ++j) {
        r.omega.push_back(ctx.truth().has_value() ? std::optional(result_number(ctx.truth().get().omega[j])) : std::nullopt);
        r.omega_dot.push_back(ctx.truth().has_value() ? std::optional(result_number(ctx.truth().get().omega_dot[j])) : std::nullopt);
      }
    }
    r.claims.reserve(catalogue.size());  // a ClaimOutcome's move may throw: growing would copy
    for (const Claim& claim : catalogue) {
      if (!claim.info.applies_to(r.n)) {
        r.not_applicable.push_back(claim.info.id);
        continue;
      }
      r.claims.push_back(run_claim(claim, ctx, evidence));
    }
    r.computed = {ctx.has_truth(), ctx.has_closed_forms(), !ctx.computed_constructions().empty(),
                  ctx.has_four_bar_truth()};
    return 0;
  });
  // At the dead centre the inputs are still known; only sides n-2 and n-1 are undefined.
  if (r.dead_centre && !r.ask) {
    for (int j = 0; j < r.n - 3; ++j) {
      r.omega[j] = rates.omega[j];
      r.omega_dot[j] = rates.omega_dot[j];
    }
    r.omega[r.n - 1] = r.omega_dot[r.n - 1] = Rational(0);
  }
  return r;
}

}  // namespace linkproof
