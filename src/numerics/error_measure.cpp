#include "numerics/error_measure.h"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

#include <algorithm>

namespace linkproof {

double log2_abs(const Rational& q) {
  if (cln::zerop(q)) return -std::numeric_limits<double>::infinity();
  const Rational a = cln::abs(q);
  const cln::cl_I num = cln::numerator(a), den = cln::denominator(a);
  // a = 2^k m with m in [1/2, 2): the double approximation of m is accurate.
  const long k = static_cast<long>(cln::integer_length(num)) - static_cast<long>(cln::integer_length(den));
  // (cln::expt_pos needs a positive exponent: it does not return for 0.)
  const Rational m = k >= 0 ? a / cln::ash(cln::cl_I(1), k) : a * cln::ash(cln::cl_I(1), -k);
  return static_cast<double>(k) + std::log2(cln::double_approx(m));
}

ErrorMeasure measure_error(const Rational& computed, const Rational& exact, int precision_bits) {
  ErrorMeasure m;
  const Rational err = computed - exact;
  const double p = precision_bits;
  if (cln::zerop(err)) {
    m.correct_bits = precision_bits > 0 ? p : std::numeric_limits<double>::infinity();
    return m;
  }
  const double log2_err = log2_abs(err);
  if (cln::zerop(exact)) {
    m.log2_relative_error = log2_err;  // absolute error: there is no relative one
    m.correct_bits = 0;
    m.error_bits = p;
    return m;
  }
  const double log2_exact = log2_abs(exact);
  m.log2_relative_error = log2_err - log2_exact;
  m.correct_bits = std::clamp(-m.log2_relative_error, 0.0, p);
  if (precision_bits > 0) {
    // ulp_p(x) = 2^(floor(log2 |x|) - p + 1)
    const double log2_ulps = log2_err - (std::floor(log2_exact) - p + 1);
    m.error_bits = std::min(p, log2_ulps > 60 ? log2_ulps : std::log2(1 + std::exp2(log2_ulps)));
  }
  return m;
}

std::string format_log2_as_decimal(double log2_value) {
  if (std::isinf(log2_value) && log2_value < 0) return "0";
  if (!std::isfinite(log2_value)) return "inf";
  const double l10 = log2_value * std::log10(2.0);
  double e = std::floor(l10);
  double mant = std::pow(10.0, l10 - e);
  if (mant >= 9.95) {
    mant /= 10;
    e += 1;
  }
  return fmt::format("{:.1f}e{}", mant, static_cast<long>(e));
}

}  // namespace linkproof
