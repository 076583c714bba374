#include "linkproof/core/wide_bound.h"

#include <cln/dfloat.h>
#include <cln/float_io.h>
#include <cln/integer.h>
#include <cln/lfloat.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "linkproof/core/error.h"
#include "core/multiprecision.h"
#include "core/scalar.h"

namespace linkproof {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
double down(double x) { return std::nextafter(x, 0.0); }
// Exponents of CLN floats this close to double's limits are handled by scaling first.
constexpr std::int64_t kDoubleSafeExponent = 1000;
}  // namespace

WideBound::WideBound(double x) {
  LINKPROOF_ASSERT(x >= 0 && !std::isnan(x), "WideBound of a negative number");
  *this = std::isinf(x) ? infinity() : normalized(x, 0);
}

WideBound WideBound::infinity() { return WideBound(kInf, 0); }

WideBound WideBound::power_of_two(std::int64_t k) { return normalized(0.5, k + 1); }

WideBound WideBound::normalized(double m, std::int64_t k) {
  if (m == 0) return WideBound();
  int e = 0;
  const double f = std::frexp(m, &e);  // exact: m = f 2^e, f in [1/2, 1)
  // k + e cannot overflow: |k| <= 2^62 + a few thousand for every caller.
  return clamped(f, k + e);
}

int compare(const WideBound& a, const WideBound& b) {
  if (a.is_infinite() || b.is_infinite()) return a.is_infinite() == b.is_infinite() ? 0 : a.is_infinite() ? 1 : -1;
  if (a.is_zero() || b.is_zero()) return a.is_zero() == b.is_zero() ? 0 : a.is_zero() ? -1 : 1;
  if (a.k_ != b.k_) return a.k_ < b.k_ ? -1 : 1;
  return a.m_ < b.m_ ? -1 : a.m_ > b.m_ ? 1 : 0;
}

namespace {
/// |x| = f 2^e with f in [1/2, 1] the nearest double to the mantissa of x (relative error of
/// f at most 2^-54: CLN's double_approx rounds to nearest); f = 0 for x = 0.
std::pair<double, std::int64_t> nearest_mantissa(const cln::cl_F& x) {
  if (cln::zerop(x)) return {0.0, 0};
  const std::int64_t e = cln::float_exponent(x);  // |x| in [2^(e-1), 2^e)
  if (e > -kDoubleSafeExponent && e < kDoubleSafeExponent) return {std::abs(cln::double_approx(x)), 0};
  return {std::abs(cln::double_approx(cln::scale_float(x, cln::cl_I(static_cast<long long>(-e))))), e};
}
}  // namespace

WideBound WideBound::from_float_up(const cln::cl_F& x) {
  const auto [f, e] = nearest_mantissa(x);
  if (f == 0) return WideBound();
  // Rounding to nearest lost at most half an ulp: one ulp up is >= |x|.
  return normalized(up(f), e);
}

WideBound WideBound::from_float_down(const cln::cl_F& x) {
  const auto [f, e] = nearest_mantissa(x);
  if (f == 0) return WideBound();
  // Two ulps down: below |x| even when f was rounded up to a power of two (where the ulp below
  // is half the ulp above).
  return normalized(down(down(f)), e);
}

WideBound WideBound::from_rational_up(const Rational& q) {
  if (cln::zerop(q)) return WideBound();
  // Rounded to nearest at 64 bits (relative error <= 2^-64), then a bound at least 2^-54
  // relative above that float: >= |q|.
  return from_float_up(cln::cl_float(cln::abs(q), cln::float_format_t(64)));
}

Rational WideBound::to_rational() const {
  LINKPROOF_ASSERT(!is_infinite(), "WideBound::to_rational of infinity");
  if (is_zero()) return 0;
  const Rational m = exact_value_of(m_);
  if (k_ >= 0) return m * cln::ash(cln::cl_I(1), cln::cl_I(static_cast<long long>(k_)));
  return m / cln::ash(cln::cl_I(1), cln::cl_I(static_cast<long long>(-k_)));
}

cln::cl_F WideBound::to_float(cln::float_format_t f) const {
  LINKPROOF_ASSERT(!is_infinite(), "WideBound::to_float of infinity");
  if (is_zero()) return cln::cl_float(0, f);
  // A double is exact in any format of >= 53 bits; scaling by a power of two is exact.
  return cln::scale_float(cln::cl_float(cln::cl_DF(m_), f), cln::cl_I(static_cast<long long>(k_)));
}

double WideBound::to_double_up() const {
  if (is_infinite()) return kInf;
  if (is_zero()) return 0;
  if (k_ > std::numeric_limits<double>::max_exponent) return kInf;
  if (k_ < std::numeric_limits<double>::min_exponent - std::numeric_limits<double>::digits)
    return std::numeric_limits<double>::denorm_min();
  const double r = std::ldexp(m_, static_cast<int>(k_));  // exact unless subnormal
  return r < std::numeric_limits<double>::min() ? up(r) : r;
}

std::string WideBound::to_string() const {
  if (is_infinite()) return "inf";
  return format_cln_float(to_float(cln::float_format_t(64)));
}

std::string WideBound::to_short_string() const {
  if (is_infinite()) return "inf";
  if (k_ > -kDoubleSafeExponent && k_ < kDoubleSafeExponent) return fmt::format("{:.3g}", std::ldexp(m_, static_cast<int>(k_)));
  // log10(m 2^k) split into a decimal exponent and a mantissa in [1, 10).
  const double l = std::log10(m_) + static_cast<double>(k_) * std::log10(2.0);
  double exponent = std::floor(l);
  double mantissa = std::pow(10.0, l - exponent);
  if (mantissa >= 9.995) mantissa /= 10, exponent += 1;  // would print as 10.0
  return fmt::format("{:.3g}e{:+.0f}", mantissa, exponent);
}

}  // namespace linkproof
