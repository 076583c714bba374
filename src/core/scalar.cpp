#include "linkproof/core/scalar.h"

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/lfloat.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace linkproof {

namespace {

/// Below 2^-1022 doubles are evenly spaced by 2^-1074 (the subnormals, which cln::double_approx
/// flushes to zero): there the nearest double is the step count rounded to nearest even.
bool below_normal_range(const Rational& q) { return cln::abs(q) < Rational(1) / cln::ash(cln::cl_I(1), 1022); }
double nearest_subnormal(const Rational& q) {
  const cln::cl_I k = cln::round1(q * cln::ash(cln::cl_I(1), 1074));  // |k| <= 2^52: exact in double
  return std::ldexp(static_cast<double>(cln::cl_I_to_long(k)), -1074);
}

}  // namespace

/// Correctly rounded (to nearest, ties to even): cln::double_approx is only an approximation,
/// so its neighbours are compared exactly.
template <>
double round_rational<double>(const Rational& q) {
  if (below_normal_range(q)) return nearest_subnormal(q);
  double best = cln::double_approx(q);
  if (!std::isfinite(best)) return best;
  Rational best_err = cln::abs(q - exact_value_of(best));
  for (double c : {std::nextafter(best, -HUGE_VAL), std::nextafter(best, HUGE_VAL)}) {
    if (!std::isfinite(c)) continue;
    const Rational err = cln::abs(q - exact_value_of(c));
    int exponent = 0;
    const bool even = std::fmod(std::ldexp(std::frexp(c, &exponent), 53), 2.0) == 0;
    if (err < best_err || (err == best_err && even)) {
      best = c;
      best_err = err;
    }
  }
  return best;
}

template <>
long double round_rational<long double>(const Rational& q) {
  // No long double conversion in CLN: go through a 64-bit-mantissa long float, whose digits
  // are exact in long double, then round once more (at most one extra half-ulp of long double).
  // The value is first scaled by 2^-e into [1/2, 2], so that doubles can carry it whatever its
  // size (1e400 overflows double but not long double), and scaled back at the end.
  if (cln::zerop(q)) return 0.0L;
  const cln::cl_I num = cln::numerator(q), den = cln::denominator(q);
  const long e = static_cast<long>(cln::integer_length(num)) - static_cast<long>(cln::integer_length(den));
  const Rational scaled = e >= 0 ? Rational(num) / Rational(cln::ash(den, e)) : Rational(cln::ash(num, -e)) / Rational(den);
  const cln::cl_F f = cln::cl_float(scaled, cln::float_format(std::numeric_limits<long double>::digits10 + 4));
  const double hi = cln::double_approx(f);
  const double lo = cln::double_approx(f - cln::cl_float(hi, f));
  const long clamped = std::clamp(e, -100000L, 100000L);  // beyond +-16445 the result is inf or 0 anyway
  return std::ldexp(static_cast<long double>(hi) + static_cast<long double>(lo), static_cast<int>(clamped));
}

template <class F>
std::string format_float(F x) {
  char buf[64];
  if constexpr (sizeof(F) == sizeof(double)) {
    std::snprintf(buf, sizeof buf, "%.17g", static_cast<double>(x));
  } else {
    std::snprintf(buf, sizeof buf, "%.21Lg", static_cast<long double>(x));
  }
  return buf;
}
template std::string format_float<double>(double);
template std::string format_float<long double>(long double);

template <class F>
Rational exact_value_of(F x) {
  int exponent = 0;
  const F mantissa = std::frexp(x, &exponent);  // x = mantissa * 2^exponent, |mantissa| in [0.5,1)
  constexpr int digits = std::numeric_limits<F>::digits;
  const F scaled = std::ldexp(mantissa, digits);  // an integer with `digits` bits
  // Split into two 32-bit halves to build the integer exactly.
  const F high = std::floor(scaled / F(4294967296.0));
  const F low = scaled - high * F(4294967296.0);
  cln::cl_I m = cln::cl_I(static_cast<long long>(high)) * cln::cl_I(4294967296LL) +
                cln::cl_I(static_cast<long long>(low));
  const int shift = exponent - digits;
  // cln::ash, not expt_pos: expt_pos(2, 0) does not return (it needs a positive exponent),
  // and every double in [2^52, 2^53) has shift 0.
  if (shift >= 0) return cln::ash(m, shift);
  return Rational(m) / cln::ash(cln::cl_I(1), -shift);
}
template Rational exact_value_of<double>(double);
template Rational exact_value_of<long double>(long double);

template struct ScalarTraits<Tracked<double>>;
template struct ScalarTraits<Tracked<long double>>;

}  // namespace linkproof
