#include "check/inconclusive_cause.h"
#include "check/arithmetic_types.h"

#include <cln/float.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <type_traits>

namespace linkproof {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Has the bound reached the magnitude (no positive margin |v| - e)?
template <class F>
bool reached(const Tracked<F>& x) {
  using TT = TrackedTraits<F>;
  return TT::is_unbounded(x.e) || !TT::is_positive(TT::margin(x.v, x.e));
}

/// Is the bound wider than sqrt(u) |value|, the judge's limit (check/judge.h)? Decided exactly.
template <class F>
bool too_wide(const Tracked<F>& x) {
  using TT = TrackedTraits<F>;
  if constexpr (std::is_floating_point_v<F>) {
    return x.e > std::sqrt(TT::unit_roundoff()) * std::abs(x.v);  // sqrt(u) rounded: a policy, not a bound
  } else {
    // u = 2^-p with p even: sqrt(u) |v| = |v| 2^-(p/2) exactly.
    const cln::cl_F limit = cln::scale_float(cln::abs(x.v.value()), -static_cast<long>(F::precision_bits() / 2));
    return x.e.to_float(F::format()) > limit;
  }
}

/// bound / |value| as a double, for display only.
template <class F>
double relative_bound(const Tracked<F>& x) {
  using TT = TrackedTraits<F>;
  if (TT::is_unbounded(x.e)) return kInf;
  if constexpr (std::is_floating_point_v<F>) {
    if (x.e == 0) return 0;
    return std::isfinite(x.v) && x.v != 0 ? static_cast<double>(x.e / std::abs(x.v)) : kInf;
  } else {
    if (x.e.is_zero()) return 0;
    const WideBound m = WideBound::from_float_down(x.v.value());
    return m.is_zero() ? kInf : (x.e / m).to_double_up();
  }
}

/// The search of the file comment: the first quantity that reached its magnitude, else the
/// widest one.
template <class F>
struct Search {
  InconclusiveCause cause;
  bool found = false;
  void visit(const Tracked<F>& x, const std::string& name, InconclusiveCause::Kind kind) {
    if (found) return;
    const double rel = relative_bound(x);
    if (reached(x) || too_wide(x)) {
      cause = {kind, name, rel};
      found = true;
    } else if (rel > cause.relative_bound) {
      cause = {InconclusiveCause::Kind::OwnArithmetic, name, rel};
    }
  }
  void visit(const Defined<Tracked<F>>& x, const std::string& name, InconclusiveCause::Kind kind) {
    if (x.has_value()) visit(x.get(), name, kind);
  }
  void visit(const Defined<Vec2<Tracked<F>>>& p, const std::string& name, InconclusiveCause::Kind kind) {
    if (!p.has_value()) return;
    visit(p.get().x, name + ".x", kind);
    visit(p.get().y, name + ".y", kind);
  }
};

}  // namespace

template <class T>
InconclusiveCause find_inconclusive_cause(const PolygonContext<T>& context, const typename PolygonContext<T>::Reads& reads) {
  using F = decltype(T::v);
  using Kind = InconclusiveCause::Kind;
  Search<F> s;
  const int n = context.n;
  if (reads.truth || reads.closed_forms || reads.four_bar_truth || reads.readings != 0)
    s.visit(cross(context.polygon.side(n - 2), context.polygon.side(n - 1)), "D = r_{n-2} x r_{n-1}", Kind::DeadCentre);
  for (const auto& [reading, four_bars] : context.computed_constructions()) {
    if ((reads.readings >> reading & 1u) == 0) continue;  // computed for another claim
    const std::string tag = reading == 0 ? "" : fmt::format(" under reading {}", reading);
    for (size_t k = 0; k < four_bars.size(); ++k) {
      const auto& c = four_bars[k];
      const int j = static_cast<int>(k) + 1;
      const auto name = [&](const char* q) { return fmt::format("{}_{} of four-bar {} (construction{})", q, j, j, tag); };
      s.visit(c.q, name("Q"), Kind::Construction);
      s.visit(c.p_prime, name("P'"), Kind::Construction);
      s.visit(c.i_out, name("i_{n-1}"), Kind::Construction);
      s.visit(c.i_cpl, name("i_{n-2}"), Kind::Construction);
      s.visit(c.cot_beta, name("cot beta"), Kind::Construction);
      s.visit(c.cot_gamma, name("cot gamma"), Kind::Construction);
      s.visit(c.lambda, name("lambda"), Kind::Construction);
      s.visit(c.mu, name("mu"), Kind::Construction);
    }
  }
  return s.cause;
}

// Every floating-point arithmetic (exact comparisons are never inconclusive).
#define LINKPROOF_INSTANTIATE_CAUSE(enumerator, name, T) \
  template InconclusiveCause find_inconclusive_cause<T>(const PolygonContext<T>&, const PolygonContext<T>::Reads&);
LINKPROOF_FOR_EACH_FLOATING_ARITHMETIC(LINKPROOF_INSTANTIATE_CAUSE)
#undef LINKPROOF_INSTANTIATE_CAUSE

}  // namespace linkproof
