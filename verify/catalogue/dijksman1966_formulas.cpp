// Eq. (22), sec. 3 and the companion formula: the acceleration formulas, total and term by term.
#include "dijksman1966.h"
#include "dijksman1966_parts.h"

namespace linkproof::dijksman1966 {

using namespace parts;

template <class T>
ClaimSides<T> eq22_sides(const PolygonContext<T>& c, const FormulaReading& rd) {
  const auto cons = constructions(c, rd.construction);
  const auto at = [&cons](int j) -> const FourBarConstruction<T>& { return cons[static_cast<size_t>(j - 1)]; };
  const auto i_out = [&](int j) { return at(j).i_out.get(); };
  const auto i_cpl = [&](int j) { return at(j).i_cpl.get(); };
  const T sign = from_int<T>(rd.mixed_term_sign);
  QuadraticFormula<T> f{
      i_out,
      [&](int j) { return at(j).lambda.get(); },
      rd.swap_mixed_ratios ? std::function<T(int)>(i_cpl) : std::function<T(int)>(i_out),
      rd.swap_mixed_ratios ? std::function<T(int)>(i_out) : std::function<T(int)>(i_cpl),
      [&] { return -sign * phi_terms(c, rd.signed_phi).cot_phi; },
      [&] { return -sign * phi_terms(c, rd.signed_phi).rho; },
      from_int<T>(rd.ordered_pairs ? 2 : 1)};
  const int n = c.n;
  return quadratic_sides<T>(c, f, [&] { return c.truth.get().omega_dot[static_cast<size_t>(n - 2)]; },
                            [&]() -> const TermCoefficients<T>& { return c.coefficients.get().first; });
}

template <class T>
ClaimSides<T> companion_sides(const PolygonContext<T>& c, const FormulaReading& rd) {
  const auto cons = constructions(c, rd.construction);
  const auto at = [&cons](int j) -> const FourBarConstruction<T>& { return cons[static_cast<size_t>(j - 1)]; };
  const auto i_out = [&](int j) { return at(j).i_out.get(); };
  const auto i_cpl = [&](int j) { return at(j).i_cpl.get(); };
  const T sign = from_int<T>(rd.mixed_term_sign);
  QuadraticFormula<T> f{
      i_cpl,
      [&](int j) { return at(j).mu.get(); },
      rd.swap_mixed_ratios ? std::function<T(int)>(i_out) : std::function<T(int)>(i_cpl),
      rd.swap_mixed_ratios ? std::function<T(int)>(i_cpl) : std::function<T(int)>(i_out),
      [&] { return sign * phi_terms(c, rd.signed_phi).cot_phi; },
      [&] { return sign * phi_terms(c, rd.signed_phi).rho_companion; },
      from_int<T>(rd.ordered_pairs ? 2 : 1)};
  const int n = c.n;
  return quadratic_sides<T>(c, f, [&] { return c.truth.get().omega_dot[static_cast<size_t>(n - 3)]; },
                            [&]() -> const TermCoefficients<T>& { return c.coefficients.get().second; });
}

#define LINKPROOF_INSTANTIATE(T)                                                     \
  template ClaimSides<T> eq22_sides<T>(const PolygonContext<T>&, const FormulaReading&); \
  template ClaimSides<T> companion_sides<T>(const PolygonContext<T>&, const FormulaReading&);
LINKPROOF_INSTANTIATE(Rational)
LINKPROOF_INSTANTIATE(Tracked<double>)
LINKPROOF_INSTANTIATE(Tracked<long double>)
#undef LINKPROOF_INSTANTIATE

}  // namespace linkproof::dijksman1966
