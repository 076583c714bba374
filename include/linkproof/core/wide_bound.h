// WideBound: a non-negative upper bound with a double mantissa and a 64-bit exponent, every
// operation rounded upward. The radius type of Tracked<MpFloat<D>> (core/multiprecision.h).
//
// Why not a CLN float for the radius: a radius needs a few correct bits, not p of them, but it
// needs the exponent range of the midpoint (an mp1000 radius is ~1e-1000 relative, far below
// double's 1e-308), and it must never be rounded down. CLN rounds to nearest only, and its
// long floats cost 0.1-10 us an operation (a 3392-bit product ~7 us), so a radius kept in the
// midpoint's own format would make every Tracked operation ~6 times the cost of the plain one.
// WideBound keeps the value m 2^k with m a double in [1/2, 1) (or 0, or +infinity) and k a
// 64-bit integer: + * / are one double operation each, rounded to nearest by the hardware
// (default rounding mode, SSE2) and then moved one ulp up (the next double, by its bit
// pattern), so the result is always >= the exact result of the same operation on the exact
// operands (upward rounding without changing the FPU mode). Nothing underflows: the exponent is clamped to
// [-2^61, 2^61], a value below the range becomes 2^-2^61 (still an upper bound), one above it
// becomes +infinity.
//
// +infinity is the "unbounded" radius (CLN floats have no infinity): any operation with an
// infinite operand is infinite (0 * inf too: conservative), and x / 0 is infinite.
// Conversions from CLN floats and rationals round upward (from_*_up) or downward
// (from_float_down, for a divisor's margin); conversions to CLN floats and rationals are exact.
#pragma once

#include <cln/float.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <string>

#include "linkproof/core/exact.h"

namespace linkproof {

class WideBound {
 public:
  /// Exponent range [kMinExponent, kMaxExponent] of normalized values (well inside CLN's).
  static constexpr std::int64_t kMaxExponent = std::int64_t{1} << 61;  // sums of two stay in int64
  static constexpr std::int64_t kMinExponent = -kMaxExponent;

  WideBound() = default;  ///< 0
  /// The exact value x >= 0 (a double: exact); a negative x is a bug.
  explicit WideBound(double x);

  static WideBound infinity();
  /// 2^k exactly.
  static WideBound power_of_two(std::int64_t k);
  /// The least representable bound >= |q| (a few ulps above, never below).
  static WideBound from_rational_up(const Rational& q);
  /// A bound >= |x| for a CLN float x of any format.
  static WideBound from_float_up(const cln::cl_F& x);
  /// A value <= |x| (never above; 0 for x = 0).
  static WideBound from_float_down(const cln::cl_F& x);

  bool is_zero() const { return m_ == 0; }
  bool is_infinite() const { return m_ == std::numeric_limits<double>::infinity(); }
  /// m in [1/2, 1) (0 for zero, +inf for infinity) and k with value m 2^k.
  double mantissa() const { return m_; }
  std::int64_t exponent() const { return k_; }

  /// Exact value; precondition: finite.
  Rational to_rational() const;
  /// Exact value as a CLN float of format f (f has at least 53 bits); precondition: finite.
  cln::cl_F to_float(cln::float_format_t f) const;
  /// The least double >= the value: +inf above double's range, the least positive double for a
  /// positive value below it (so a bound printed as a double is still a bound).
  double to_double_up() const;
  /// Decimal text that reads back, at 64 bits, to the exact value ("2.5e-40"); "inf".
  std::string to_string() const;
  /// About 3 significant digits, for prose ("1.23e-1000"); not exact.
  std::string to_short_string() const;

  /// a + b, a * b, a / b rounded up (inline: they are most of the cost of a Tracked operation).
  friend WideBound operator+(const WideBound& a, const WideBound& b);
  friend WideBound operator*(const WideBound& a, const WideBound& b);
  /// Infinite if b = 0 or either operand is infinite.
  friend WideBound operator/(const WideBound& a, const WideBound& b);
  WideBound& operator+=(const WideBound& b) { return *this = *this + b; }

  /// Exact comparison.
  friend int compare(const WideBound& a, const WideBound& b);
  friend bool operator==(const WideBound& a, const WideBound& b) { return compare(a, b) == 0; }
  friend bool operator<(const WideBound& a, const WideBound& b) { return compare(a, b) < 0; }
  friend bool operator>(const WideBound& a, const WideBound& b) { return compare(a, b) > 0; }
  friend bool operator<=(const WideBound& a, const WideBound& b) { return compare(a, b) <= 0; }

 private:
  WideBound(double m, std::int64_t k) : m_(m), k_(k) {}
  /// m 2^k for a finite m >= 0 that is exact: normalized, exponent clamped upward.
  static WideBound normalized(double m, std::int64_t k);
  /// The same for m in (0, 4), the result of an operation on two mantissas (no frexp).
  static WideBound normalized_near_one(double m, std::int64_t k) {
    while (m >= 1) m *= 0.5, ++k;  // exact: scaling a normal double by 2
    while (m < 0.5) m *= 2, --k;
    return clamped(m, k);
  }
  static WideBound clamped(double m, std::int64_t k) {
    if (k > kMaxExponent) return infinity();
    if (k < kMinExponent) return WideBound(0.5, kMinExponent);  // rounded up to the least value
    return WideBound(m, k);
  }
  /// The next double above x >= 0 (finite): one more in the bit pattern (0 -> least subnormal).
  static double up(double x) { return std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) + 1); }
  /// 2^-d exactly, 0 <= d <= 1000.
  static double two_to_minus(std::int64_t d) {
    return std::bit_cast<double>(static_cast<std::uint64_t>(1023 - d) << 52);
  }
  double m_ = 0;
  std::int64_t k_ = 0;
};

inline WideBound operator+(const WideBound& a, const WideBound& b) {
  if (a.is_infinite() || b.is_infinite()) return WideBound::infinity();
  if (a.is_zero()) return b;
  if (b.is_zero()) return a;
  const WideBound& hi = a.k_ >= b.k_ ? a : b;
  const WideBound& lo = a.k_ >= b.k_ ? b : a;
  const std::int64_t d = hi.k_ - lo.k_;
  // lo < 2^-d in units of 2^hi.k; past d = 60 that is below one ulp (2^-53) of hi.m: one step up.
  if (d > 60) return WideBound::normalized_near_one(WideBound::up(hi.m_), hi.k_);
  // lo.m 2^-d is exact (lo.m >= 1/2, d <= 60); the sum is rounded to nearest, then moved up.
  return WideBound::normalized_near_one(WideBound::up(hi.m_ + lo.m_ * WideBound::two_to_minus(d)), hi.k_);
}

inline WideBound operator*(const WideBound& a, const WideBound& b) {
  if (a.is_infinite() || b.is_infinite()) return WideBound::infinity();
  if (a.is_zero() || b.is_zero()) return WideBound();
  return WideBound::normalized_near_one(WideBound::up(a.m_ * b.m_), a.k_ + b.k_);  // in [1/4, 1)
}

inline WideBound operator/(const WideBound& a, const WideBound& b) {
  if (a.is_infinite() || b.is_infinite() || b.is_zero()) return WideBound::infinity();
  if (a.is_zero()) return WideBound();
  return WideBound::normalized_near_one(WideBound::up(a.m_ / b.m_), a.k_ - b.k_);  // in (1/2, 2)
}

}  // namespace linkproof
