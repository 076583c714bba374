// A claim: a statement from a paper, its source, what it is expected to do, and how to
// evaluate its two sides on a polygon in any supported arithmetic.
//
// A claim's evaluation returns comparisons (lhs = rhs), never a verdict: the verdict is drawn by
// the comparator (check/judge.h), the same for every claim, so that a deliberately wrong formula
// fed through it is rejected exactly like an erratum. A comparison is one of
//   instances  the statement itself, once per index j where it is indexed (eq. 4: every j);
//   terms      the coefficient of one monomial (omega-dot_j, omega_j^2, omega_j omega_l) of an
//              identity that is a polynomial in the input rates: a wrong term is named.
#pragma once

#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "claims/polygon_context.h"
#include "claims/rate_poly.h"
#include "check/arithmetic_types.h"
#include "core/multiprecision.h"
#include "linkproof/claims/claim_info.h"
#include "linkproof/core/verdict.h"

namespace linkproof {

/// Called where an evaluation of a claim threw `e`. For a user's claim (info.file set) an
/// InputError means the claim is not well formed: bad input, rethrown naming the file and the
/// claim (exit 2). Otherwise it returns and the caller records the verdict error (in the
/// catalogue an ill-formed claim is a bug: exit 3).
void refuse_if_ill_formed_user_claim(const ClaimInfo& info, const std::exception& e);

template <class T>
struct Comparison {
  /// The label ("j=1", "total", ...) or, for a term's comparison, its head ("" or "j=1: "),
  /// the monomial's label following it: read full_label().
  std::string label_head;
  Defined<T> lhs, rhs;
  /// Floating point: the magnitude the error bound is judged against, if larger than
  /// max(|lhs|, |rhs|). For one coefficient of a polynomial it is the polynomial's largest
  /// coefficient: a coefficient that is exactly 0 is then confirmed to the polynomial's accuracy.
  double scale = 0;
  /// A term's comparison: its monomial. Its label is written only when the comparison is judged
  /// with its text: a sweep judges the verdicts of all m^2 terms and writes the text of one.
  std::optional<Monomial> monomial{};  // {}: a comparison of a statement is {label, lhs, rhs}
  /// Exact, on demand (PolygonContext::values_on_demand): both sides are one polynomial in the
  /// rates, term by term, so they are equal at any rates. lhs and rhs are then left pending and
  /// this makes their common value, when the comparison is judged with its text; its verdict
  /// alone (judge_verdict) needs no value. Empty otherwise.
  std::function<T()> same_value{};
  /// Makes lhs and rhs from same_value (if set), as an eager comparison would have them.
  void make_same_value() {
    if (!same_value) return;
    set_same_value(Defined<T>::attempt(same_value));
    same_value = nullptr;
  }
  /// Both sides the common value v (defined or not).
  void set_same_value(Defined<T> v) {
    lhs = std::move(v);
    rhs = lhs;
  }
  /// "total", "j=1", "omega_dot[1]", "j=2: omega[1]*omega[2]", ...
  std::string full_label() const { return monomial ? label_head + monomial_label(*monomial) : label_head; }
};

template <class T>
struct ClaimSides {
  std::vector<Comparison<T>> instances;
  std::vector<Comparison<T>> terms;
};

/// lhs and rhs evaluated separately: an undefined quantity on one side is reported as such.
template <class T, class L, class R>
Comparison<T> compare(std::string label, L&& lhs, R&& rhs) {
  return {std::move(label), Defined<T>::attempt(std::forward<L>(lhs)), Defined<T>::attempt(std::forward<R>(rhs))};
}

/// The arithmetics a claim can be evaluated in: exact rationals, and IEEE double, long double
/// and CLN long floats at 128, 192, 384 and 3392 bits (mp30 ... mp1000), each with running
/// error bounds (core/tracked.h). The list is check/arithmetic_types.h's: a new arithmetic there is
/// one more instantiation of every claim.
using ClaimScalarTypes = ArithmeticScalarTypes;  // every arithmetic (check/arithmetic_types.h)

template <class T>
using ClaimFunction = std::function<ClaimSides<T>(const PolygonContext<T>&)>;

namespace claim_detail {
template <class Tuple>
struct FunctionsOf;
template <class... T>
struct FunctionsOf<std::tuple<T...>> {
  using type = std::tuple<ClaimFunction<T>...>;
  template <class G>
  static type make(const G& generic) {
    return type{ClaimFunction<T>(generic)...};
  }
};
}  // namespace claim_detail

struct Claim {
  using Functions = claim_detail::FunctionsOf<ClaimScalarTypes>;
  ClaimInfo info;
  Functions::type functions;

  template <class T>
  const ClaimFunction<T>& function() const { return std::get<ClaimFunction<T>>(functions); }

  /// `generic` is a generic callable: [](const auto& context) { ... return ClaimSides<T>; }.
  template <class F>
  static Claim make(ClaimInfo info, F generic) {
    return Claim{std::move(info), Functions::make(generic)};
  }
};

}  // namespace linkproof
