// A claim given as data (a claim file, io/claim_file.h): its ClaimInfo, how it reads the paper,
// and its two sides as expressions. Evaluated by ClaimEvaluator in any arithmetic; as a Claim it
// runs through the same checker and comparator as every other claim.
//
// Comparisons made (claim.h): the statement as a whole at the given rates ("total", or "j=1",
// "j=2", ... with for_each: j), and, when the sides contain rates, the coefficient of every
// monomial in the rates ("omega_dot[1]", "omega[1]*omega[2]", ...) on both sides.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <vector>
#include <string>

#include "claims/claim.h"
#include "claims/claim_evaluator.h"
#include "claims/claim_expression.h"
#include "core/exact_sum.h"

namespace linkproof {

struct DataClaim {
  ClaimInfo info;
  ClaimReading reading;
  ClaimExpression lhs, rhs;
  bool for_each_j = false;  ///< one statement per input j (j free in both sides)
};

/// One side as a rate polynomial, with the inputs whose terms had to be left out (partial
/// evaluation, claim_evaluator.h): those monomials and the total are undefined.
template <class T>
struct SideValue {
  Defined<RatePoly<T>> poly = Defined<RatePoly<T>>::undefined("", "");
  std::map<std::vector<int>, typename ClaimEvaluator<T>::Undefined> undefined_inputs;

  /// The coefficient of m; throws UndefinedQuantity if m involves an undefined input.
  /// Monomials are read in ascending order: the search starts at `from` (where the previous one
  /// ended), so reading every monomial is one pass over the terms.
  T coefficient(const Monomial& m, size_t& from) const {
    if (!undefined_inputs.empty()) {
      const std::vector<int> idx = monomial_indices(m);
      for (const auto& [inputs, u] : undefined_inputs)
        if (std::includes(idx.begin(), idx.end(), inputs.begin(), inputs.end()))
          throw UndefinedQuantity(u.quantity, u.reason);
    }
    const auto& t = poly.get().terms();
    while (from < t.size() && t[from].first < m) ++from;
    return from < t.size() && t[from].first == m ? t[from].second : from_int<T>(0);
  }
  /// The value at the given rates; throws UndefinedQuantity if any term was left out.
  T total(const std::vector<T>& w, const std::vector<T>& wd) const {
    if (!undefined_inputs.empty())
      throw UndefinedQuantity(undefined_inputs.begin()->second.quantity, undefined_inputs.begin()->second.reason);
    return poly.get().evaluate(w, wd);
  }
};

template <class T>
SideValue<T> evaluate_side(const DataClaim& claim, const ClaimExpression& side, const PolygonContext<T>& c, int j) {
  IndexBindings b;
  b.j = j;
  ClaimEvaluator<T> eval(c, claim.reading);
  eval.set_partial(true);
  SideValue<T> v;
  v.poly = Defined<RatePoly<T>>::attempt([&] { return eval.scalar(side, b); });
  v.undefined_inputs = eval.undefined_inputs();
  // Leaving terms out is exact only for a local expression; otherwise the side is undefined.
  if (!v.undefined_inputs.empty() && !eval.locality_violations().empty()) {
    const auto& u = v.undefined_inputs.begin()->second;
    v.poly = Defined<RatePoly<T>>::undefined(u.quantity, u.reason);
  }
  return v;
}

template <class T>
ClaimSides<T> evaluate_data_claim(const DataClaim& claim, const PolygonContext<T>& c) {
  ClaimSides<T> s;
  const std::vector<T>& w = c.rates.omega;
  const std::vector<T>& wd = c.rates.omega_dot;
  const auto add = [&](const std::string& prefix, SideValue<T> lhs_side, SideValue<T> rhs_side) {
    // Shared: a total made on demand reads a side after this returns.
    const auto shared_lhs = std::make_shared<const SideValue<T>>(std::move(lhs_side));
    const auto shared_rhs = std::make_shared<const SideValue<T>>(std::move(rhs_side));
    const SideValue<T>& l = *shared_lhs;
    const SideValue<T>& r = *shared_rhs;
    const std::string label = prefix.empty() ? "total" : prefix;
    // Exact: the sides' values at the rates differ only by their differing terms, lhs - rhs =
    // l' - r' (differing_terms). Where there are none, the sides are one polynomial and have one
    // value, made once from the side with fewer terms (a side may keep the terms that
    // cancelled), and on demand only where no verdict reads it; elsewhere the rhs is lhs - l' + r'
    // where those are fewer terms than the rhs has (a side's value at n = 1000 is a sum of
    // 500,000 products of growing rationals). The term-by-term comparisons below still compare
    // every coefficient.
    std::optional<std::pair<RatePoly<T>, RatePoly<T>>> differing;  // set where it is the cheaper route
    bool same = false;
    if constexpr (GrowingExactNumber<T>)
      if (l.undefined_inputs.empty() && r.undefined_inputs.empty() && l.poly.has_value() && r.poly.has_value()) {
        auto d = differing_terms(l.poly.get(), r.poly.get());
        const size_t count = d.first.terms().size() + d.second.terms().size();
        same = count == 0;
        if (count < r.poly.get().terms().size()) differing = std::move(d);
      }
    if (same) {
      const auto fewer = r.poly.get().terms().size() < l.poly.get().terms().size() ? shared_rhs : shared_lhs;
      Comparison<T> total{label, Defined<T>::pending(), Defined<T>::pending()};
      if (c.values_on_demand) {
        total.same_value = [fewer, w, wd] { return fewer->total(w, wd); };
      } else {  // made now, as make_same_value() makes it (no copy of the rates to keep)
        total.set_same_value(Defined<T>::attempt([&] { return fewer->total(w, wd); }));
      }
      s.instances.push_back(std::move(total));
    } else {
      std::optional<T> lhs_total;
      s.instances.push_back(compare<T>(label, [&] { return *(lhs_total = l.total(w, wd)); }, [&] {
        if (!differing || !lhs_total) return r.total(w, wd);
        return *lhs_total - differing->first.evaluate(w, wd) + differing->second.evaluate(w, wd);
      }));
    }
    // Term by term, if either side is a polynomial of positive degree in the rates.
    if (!l.poly.has_value() || !r.poly.has_value() || (l.poly.get().is_constant() && r.poly.get().is_constant()))
      return;
    // Every monomial of either side, in order, once (both term lists are sorted: merged).
    std::vector<Monomial> monomials;
    const auto &lt = l.poly.get().terms(), &rt = r.poly.get().terms();
    monomials.reserve(lt.size() + rt.size());
    for (size_t a = 0, b = 0; a < lt.size() || b < rt.size();) {
      if (b == rt.size() || (a < lt.size() && lt[a].first < rt[b].first)) monomials.push_back(lt[a++].first);
      else if (a == lt.size() || rt[b].first < lt[a].first) monomials.push_back(rt[b++].first);
      else monomials.push_back((++b, lt[a++].first));
    }
    bool left_out = false;
    for (const auto* side : {&l, &r})
      for (const auto& u : side->undefined_inputs)  // the left-out terms: at least their own monomials
        if (u.first.size() == 1)
          for (auto kind : {RateVariable::Omega, RateVariable::OmegaDot}) {
            monomials.push_back(Monomial{RateVariable{u.first[0], kind}.id()});
            left_out = true;
          }
    if (left_out) {
      std::sort(monomials.begin(), monomials.end());
      monomials.erase(std::unique(monomials.begin(), monomials.end()), monomials.end());
    }
    s.terms.reserve(s.terms.size() + monomials.size());
    double scale = 0;
    if constexpr (!ScalarTraits<T>::is_exact)
      for (const auto* p : {&l.poly.get(), &r.poly.get()})
        for (const auto& t : p->terms()) scale = std::max(scale, std::abs(ScalarTraits<T>::to_double(t.second)));
    size_t at_l = 0, at_r = 0;
    for (const Monomial& m : monomials) {
      s.terms.push_back(compare<T>(prefix.empty() ? "" : prefix + ": ", [&] { return l.coefficient(m, at_l); },
                                   [&] { return r.coefficient(m, at_r); }));
      s.terms.back().scale = scale;
      s.terms.back().monomial = m;  // labelled when judged with its text
    }
  };
  if (claim.for_each_j) {
    for (int j = 1; j <= c.inputs(); ++j)
      add("j=" + std::to_string(j), evaluate_side(claim, claim.lhs, c, j), evaluate_side(claim, claim.rhs, c, j));
  } else {
    add("", evaluate_side(claim, claim.lhs, c, 0), evaluate_side(claim, claim.rhs, c, 0));
  }
  return s;
}

/// The data claim as a Claim for check_polygon and run_sweep: evaluate_data_claim instantiated
/// for every arithmetic of ClaimScalarTypes, once, in src/claims/data_claim.cpp (seven
/// instantiations of the evaluator are the heaviest template code of the library).
Claim to_claim(const DataClaim& claim);

}  // namespace linkproof
