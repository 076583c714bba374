// Eq. (22), sec. 3 and the companion formula: the acceleration formulas, total and term by term.
#include "dijksman1966.h"
#include "dijksman1966_parts.h"

namespace linkproof::dijksman1966 {

using namespace parts;

namespace {

/// (22) is the formula for side n-1, the companion the one for side n-2: the same shape,
///   sum_j (square_j omega_j^2 + ratio_j omega-dot_j) + mixed term,
/// with the roles of i_{n-1,j} and i_{n-2,j} exchanged, lambda_j -> mu_j, the mixed term's
/// sign reversed and |r_{n-2}|^2/D -> |r_{n-1}|^2/D (SPEC A4).
enum class Side { NMinus1, NMinus2 };

template <class T>
ClaimSides<T> acceleration_formula_sides(const PolygonContext<T>& c, const FormulaReading& rd, Side side) {
  const bool out = side == Side::NMinus1;
  const auto cons = constructions(c, rd.construction);
  const auto at = [&cons](int j) -> const FourBarConstruction<T>& { return cons[static_cast<size_t>(j - 1)]; };
  const std::function<T(int)> own = [&](int j) { return (out ? at(j).i_out : at(j).i_cpl).get(); };
  const std::function<T(int)> other = [&](int j) { return (out ? at(j).i_cpl : at(j).i_out).get(); };
  // As printed, (22) subtracts its mixed term and the companion adds its own.
  const T sign = from_int<T>(out ? -rd.mixed_term_sign : rd.mixed_term_sign);
  QuadraticFormula<T> f{own,
                        [&](int j) { return (out ? at(j).lambda : at(j).mu).get(); },
                        rd.swap_mixed_ratios ? other : own,
                        rd.swap_mixed_ratios ? own : other,
                        [&] { return sign * phi_terms(c, rd.signed_phi).cot_phi; },
                        [&] {
                          const PhiTerms<T> phi = phi_terms(c, rd.signed_phi);
                          return sign * (out ? phi.rho : phi.rho_companion);
                        },
                        from_int<T>(rd.ordered_pairs ? 2 : 1)};
  const auto index = static_cast<size_t>(out ? c.n - 2 : c.n - 3);
  return quadratic_sides<T>(c, f, [&] { return c.truth.get().omega_dot[index]; },
                            [&]() -> const TermCoefficients<T>& {
                              return out ? c.coefficients.get().first : c.coefficients.get().second;
                            });
}

}  // namespace

template <class T>
ClaimSides<T> eq22_sides(const PolygonContext<T>& c, const FormulaReading& reading) {
  return acceleration_formula_sides(c, reading, Side::NMinus1);
}

template <class T>
ClaimSides<T> companion_sides(const PolygonContext<T>& c, const FormulaReading& reading) {
  return acceleration_formula_sides(c, reading, Side::NMinus2);
}

#define LINKPROOF_INSTANTIATE(T)                                                     \
  template ClaimSides<T> eq22_sides<T>(const PolygonContext<T>&, const FormulaReading&); \
  template ClaimSides<T> companion_sides<T>(const PolygonContext<T>&, const FormulaReading&);
LINKPROOF_INSTANTIATE(Rational)
LINKPROOF_INSTANTIATE(Tracked<double>)
LINKPROOF_INSTANTIATE(Tracked<long double>)
#undef LINKPROOF_INSTANTIATE

}  // namespace linkproof::dijksman1966
