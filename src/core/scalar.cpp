#include "core/scalar.h"

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

/// An integer of at most 53 bits: exact in double and long double, so its rounding is
/// cln::double_approx itself. The fast path of from_int<T> and of integer coordinates, which
/// every floating solve converts many times (the general path below compares neighbours exactly).
bool is_small_integer(const Rational& q) {
  return cln::denominator(q) == 1 && cln::integer_length(cln::numerator(q)) <= 53;
}

/// p/q with |p|, q < 2^53 (both exact in double): IEEE division of exact operands is correctly
/// rounded to nearest, ties to even, and the quotient (>= 2^-53) is never subnormal.
bool is_small_fraction(const Rational& q) {
  return cln::integer_length(cln::numerator(q)) <= 53 && cln::integer_length(cln::denominator(q)) <= 53;
}

}  // namespace

bool as_small_fraction(const Rational& q, double& p, double& d) {
  if (!is_small_fraction(q)) return false;
  p = static_cast<double>(cln::cl_I_to_long(cln::numerator(q)));
  d = static_cast<double>(cln::cl_I_to_long(cln::denominator(q)));
  return true;
}

/// Correctly rounded (to nearest, ties to even): cln::double_approx is only an approximation,
/// so its neighbours are compared exactly.
template <>
double round_rational<double>(const Rational& q) {
  if (is_small_integer(q)) return cln::double_approx(q);
  if (is_small_fraction(q)) return cln::double_approx(cln::numerator(q)) / cln::double_approx(cln::denominator(q));
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

namespace {

/// 2^k as an exact rational.
Rational power_of_two(long k) {
  return k >= 0 ? Rational(cln::ash(cln::cl_I(1), k)) : Rational(1) / cln::ash(cln::cl_I(1), -k);
}

/// q correctly rounded to F (to nearest, ties to even) over F's whole range, subnormals and
/// overflow included, by integer arithmetic only: |q| in [2^(e-1), 2^e) has the quantum
/// (spacing of F there) 2^(max(e, min_exponent) - p), and the rounded value is the nearest
/// integer multiple of it.
template <class F>
F round_by_integers(const Rational& q) {
  using L = std::numeric_limits<F>;
  if (cln::zerop(q)) return F(0);
  const Rational a = cln::abs(q);
  // a lies in [2^(e-1), 2^(e+1)) for e = length(numerator) - length(denominator).
  long e = static_cast<long>(cln::integer_length(cln::numerator(a))) -
           static_cast<long>(cln::integer_length(cln::denominator(a)));
  if (a >= power_of_two(e)) ++e;
  long quantum = std::max<long>(e, L::min_exponent) - L::digits;
  cln::cl_I m = cln::round1(a / power_of_two(quantum));  // ties to even; m <= 2^p
  if (m == cln::ash(cln::cl_I(1), L::digits)) {             // rounded up to the next binade
    m = cln::ash(cln::cl_I(1), L::digits - 1);
    ++quantum;
  }
  if (quantum + L::digits > L::max_exponent) return cln::minusp(q) ? -L::infinity() : L::infinity();
  // m < 2^p <= 2^64: two 32-bit halves, each exact in F, and m 2^quantum is representable.
  const F high = static_cast<F>(cln::cl_I_to_ulong(cln::ash(m, -32)));
  const F low = static_cast<F>(cln::cl_I_to_ulong(cln::logand(m, cln::cl_I(0xffffffffL))));
  const F r = std::ldexp(high * F(4294967296.0) + low, static_cast<int>(quantum));
  return cln::minusp(q) ? -r : r;
}

}  // namespace

/// Correctly rounded over long double's whole range (2^-16445 .. 2^16384): CLN has no long
/// double conversion, and going through double would flush everything outside double's range.
template <>
long double round_rational<long double>(const Rational& q) {
  if (is_small_integer(q)) return static_cast<long double>(cln::double_approx(q));
  return round_by_integers<long double>(q);
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
  // An integer below 2^62 converts exactly through long long (the fast path of integer values).
  if (std::abs(x) < F(4611686018427387904.0) && x == std::trunc(x))
    return cln::cl_I(static_cast<long long>(x));
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

// For consumers of the public vec2.h / polygon.h, which see only the declaration of from_rational.
template double from_rational<double>(const Rational&);
template long double from_rational<long double>(const Rational&);
template Rational from_rational<Rational>(const Rational&);

}  // namespace linkproof
