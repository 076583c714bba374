#include "proof/lift.h"

#include <chrono>
#include <set>

#include "core/symbolic_scalar.h"
#include "rational_normal.h"
#include "symbolic_polygon.h"

namespace linkproof {

using GiNaC::ex;
using proof_detail::make_symbolic_polygon;

LiftCheck check_lift_lemma(GroundTruthEngine& engine, const DataClaim& claim, int n) {
  const auto start = std::chrono::steady_clock::now();
  LiftCheck r;
  r.n = n;
  const proof_detail::SymbolicPolygon sp = make_symbolic_polygon(n);
  const InputRates<ex> zero_rates{std::vector<ex>(static_cast<size_t>(n - 3), ex(0)),
                                  std::vector<ex>(static_cast<size_t>(n - 3), ex(0))};
  ZeroTestLog log;  // the zero tests made here are not part of any proof
  const PolygonContext<ex> ctx = build_polygon_context_from<ex>(engine, sp.polygon, zero_rates, false);
  proof_detail::RationalNormalizer normalizer;
  const auto note = [&r](const std::string& v) {
    for (const auto& x : r.violations)
      if (x == v) return;
    r.violations.push_back(v);
  };
  const auto check_at = [&](int j) {
    IndexBindings b;
    b.j = j;
    for (const ClaimExpression* side : {&claim.lhs, &claim.rhs}) {
      ClaimEvaluator<ex> eval(ctx, claim.reading);
      const RatePoly<ex> p = eval.scalar(*side, b);
      for (const auto& v : eval.locality_violations()) note(v);
      if (p.degree() > 2) note("degree > 2 in the rates");
      for (const auto& [monomial, coefficient] : p.terms()) {
        ++r.coefficients;
        std::set<int> allowed{n - 2, n - 1};
        for (int i : monomial_indices(monomial)) allowed.insert(i);
        if (j) allowed.insert(j);
        for (int k = 1; k <= n - 1; ++k) {
          if (allowed.count(k)) continue;
          for (const ex& s : sp.side_symbols(k)) {
            if (normalizer.is_constant_in(coefficient, GiNaC::ex_to<GiNaC::symbol>(s)))
              continue;
            note("the coefficient of " + monomial_label(monomial) + (j ? " (j = " + std::to_string(j) + ")" : "") +
                 " in the " + (side == &claim.lhs ? "lhs" : "rhs") + " depends on r_" + std::to_string(k) +
                 " at n = " + std::to_string(n) + ", a side it does not name (the claim's reading reads it)");
            break;
          }
        }
      }
    }
  };
  if (claim.for_each_j)
    for (int j = 1; j <= n - 3; ++j) check_at(j);
  else
    check_at(0);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace linkproof
