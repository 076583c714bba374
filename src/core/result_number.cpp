#include "linkproof/core/result_number.h"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <cmath>
#include <limits>

#include "core/directed_rounding.h"

namespace linkproof {

namespace {

// CLN's double_approx signals an error outside double's exponent range: decide the range first
// from the operands' bit lengths (2^(a-b-1) < |p/q| < 2^(a-b+1) for a, b the lengths of p, q).
double rational_to_double(const Rational& q) {
  if (cln::zerop(q)) return 0.0;
  const long a = static_cast<long>(cln::integer_length(cln::abs(cln::numerator(q))));
  const long b = static_cast<long>(cln::integer_length(cln::denominator(q)));
  if (a - b > 1026) return cln::minusp(q) ? -HUGE_VAL : HUGE_VAL;
  if (a - b < -1080) return cln::minusp(q) ? -0.0 : 0.0;
  return cln::double_approx(q);
}

double float_to_double(const cln::cl_F& x) {
  if (cln::zerop(x)) return 0.0;
  const long e = cln::float_exponent(x);
  if (e > 1025) return cln::minusp(x) ? -HUGE_VAL : HUGE_VAL;
  if (e < -1080) return cln::minusp(x) ? -0.0 : 0.0;
  return cln::double_approx(x);
}

}  // namespace

double to_double(const ResultNumber& x) {
  return std::visit(
      [](const auto& v) -> double {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, Rational>) {
          return rational_to_double(v);
        } else if constexpr (std::is_same_v<V, cln::cl_F>) {
          return float_to_double(v);
        } else {
          return static_cast<double>(v);
        }
      },
      x);
}

double to_double_up(const ResultRadius& r) {
  return std::visit(
      [](const auto& v) -> double {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, WideBound>) {
          return v.to_double_up();
        } else {
          return std::isnan(v) ? HUGE_VAL : round_up_to_double(v);
        }
      },
      r);
}

}  // namespace linkproof
