// MpFloat<Digits>: a CLN long float (cln::cl_F) at a fixed precision of at least `Digits`
// decimal digits, as a scalar type for the generic evaluation code (core/scalar.h).
//
// Why a compile-time precision: CLN combines two floats of different precisions by dropping to
// the lower one (see STYLE.md, "GiNaC / CLN traps"), so a run-time precision stored per number
// would silently degrade a whole computation if one constant were made at the wrong precision.
// With the precision in the type, every MpFloat<D> is created by cl_float(x, float_format(D))
// and every operation keeps that format, so mixing is a compile error.
//
// Precision: float_format(D) gives a long float with a mantissa of a whole number of machine
// words, at least D decimal digits: D = 30, 50, 100, 1000 give p = 128, 192, 384, 3392 bits
// (precision_bits()). Each operation is correctly rounded to p bits (CLN long-float +, -, *, /
// round to nearest), so the unit roundoff is u = 2^-p (unit_roundoff()).
//
// Conversion from an exact rational rounds once, at the target precision (cl_float(q, format));
// never through double. There is no NaN or infinity: a division by an exact zero throws
// cln's division_by_0_exception; generic code tests is_zero before dividing, as it must for
// exact rationals anyway. The ladder instantiates D = 30, 50, 100, 1000 (numerics/ladder.h).
//
// Tracked<MpFloat<D>> (TrackedTraits below) gives MpFloat a running error bound, so claims can
// be judged in it (--arith mp30 ... mp1000). Its radius is a WideBound (core/wide_bound.h):
// p-bit precision is wasted on a radius, but it needs the wide exponent range.
// Underflow: CLN has no denormals; by default (cln::cl_inhibit_floating_point_underflow ==
// false, which neither linkproof nor GiNaC changes) a result below the least long float throws
// floating_point_underflow_exception instead of being flushed to 0. So every operation that
// returns is correctly rounded with relative error <= u = 2^-p and needs no absolute term; the
// exception (like overflow's) reaches the claim runner, which makes the verdict
// `inconclusive`. Should someone inhibit the exception, CLN flushes to 0 and the underflow
// term becomes least_positive_float, as denorm_min is for IEEE. (Long floats have a 64-bit
// exponent: 2^-(2^63) is far beyond anything a scene can produce.)
#pragma once

#include <cln/float.h>
#include <cln/real.h>
#include <cln/rational.h>
#include <cln/float_io.h>

#include <string>
#include <string_view>

#include "core/scalar.h"
#include "linkproof/core/wide_bound.h"

namespace linkproof {

template <int Digits>
class MpFloat {
  static_assert(Digits >= 20, "below 20 digits use double or long double");

 public:
  /// The CLN float format of this precision (made once).
  static cln::float_format_t format() {
    static const cln::float_format_t f = cln::float_format(static_cast<unsigned int>(Digits));
    return f;
  }
  /// Mantissa bits p of the format (a multiple of the machine word size).
  static int precision_bits() {
    static const int p = static_cast<int>(cln::float_digits(cln::cl_float(1, format())));
    return p;
  }

  MpFloat() : x_(cln::cl_float(0, format())) {}
  /// An integer, exact (|k| < 2^p).
  explicit MpFloat(int k) : x_(cln::cl_float(k, format())) {}
  /// Rounds the exact rational q to p bits.
  explicit MpFloat(const Rational& q) : x_(cln::cl_float(q, format())) {}
  /// Adopts a float; it is converted to this format if it has another one.
  explicit MpFloat(const cln::cl_F& x) : x_(cln::cl_float(x, format())) {}

  const cln::cl_F& value() const { return x_; }

  friend MpFloat operator+(const MpFloat& a, const MpFloat& b) { return raw(a.x_ + b.x_); }
  friend MpFloat operator-(const MpFloat& a, const MpFloat& b) { return raw(a.x_ - b.x_); }
  friend MpFloat operator*(const MpFloat& a, const MpFloat& b) { return raw(a.x_ * b.x_); }
  friend MpFloat operator/(const MpFloat& a, const MpFloat& b) { return raw(a.x_ / b.x_); }
  friend MpFloat operator-(const MpFloat& a) { return raw(-a.x_); }
  MpFloat& operator+=(const MpFloat& b) { return *this = *this + b; }
  MpFloat& operator-=(const MpFloat& b) { return *this = *this - b; }
  MpFloat& operator*=(const MpFloat& b) { return *this = *this * b; }
  MpFloat& operator/=(const MpFloat& b) { return *this = *this / b; }

 private:
  struct Raw {};
  MpFloat(Raw, cln::cl_F x) : x_(std::move(x)) {}
  /// Results of operations on two numbers of this format are already in it.
  static MpFloat raw(cln::cl_F x) { return MpFloat(Raw{}, std::move(x)); }
  cln::cl_F x_;
};

/// Decimal text of a CLN float with CLN's exponent marker replaced by 'e' ("3.25e-7").
std::string format_cln_float(const cln::cl_F& x);

template <int Digits>
struct ScalarTraits<MpFloat<Digits>> {
  static constexpr bool is_exact = false;
  static constexpr bool has_error_bound = false;
  static constexpr std::string_view name = Digits == 30    ? "mp30"
                                           : Digits == 50  ? "mp50"
                                           : Digits == 100 ? "mp100"
                                           : Digits == 1000 ? "mp1000"
                                                            : "mp";
  static MpFloat<Digits> from_rational(const Rational& q) { return MpFloat<Digits>(q); }
  static bool is_zero(const MpFloat<Digits>& x) { return cln::zerop(x.value()); }
  static MpFloat<Digits> abs(const MpFloat<Digits>& x) { return MpFloat<Digits>(cln::abs(x.value())); }
  static bool less(const MpFloat<Digits>& a, const MpFloat<Digits>& b) { return a.value() < b.value(); }
  /// Nearest double; 0 below double's range (CLN's exponent range is far wider).
  static double to_double(const MpFloat<Digits>& x) { return cln::double_approx(x.value()); }
  static std::string to_string(const MpFloat<Digits>& x) { return format_cln_float(x.value()); }
  /// The exact rational value of the float (every binary float is a dyadic rational).
  static Rational to_rational(const MpFloat<Digits>& x) { return cln::rational(x.value()); }
};

/// What Tracked needs of MpFloat<D> (core/tracked.h): radius in WideBound, rounded upward.
template <int Digits>
struct TrackedTraits<MpFloat<Digits>> {
  using F = MpFloat<Digits>;
  using Radius = WideBound;
  static constexpr bool has_infinity = false;
  static int precision_bits() { return F::precision_bits(); }
  /// u = 2^-p exactly.
  static WideBound unit_roundoff() {
    static const WideBound u = WideBound::power_of_two(-precision_bits());
    return u;
  }
  static F abs(const F& v) { return F(cln::abs(v.value())); }
  static WideBound magnitude(const F& v) { return WideBound::from_float_up(v.value()); }
  static WideBound underflow_term() {
    if (!cln::cl_inhibit_floating_point_underflow) return WideBound();  // CLN throws instead
    static const WideBound least = WideBound::from_float_up(cln::least_positive_float(F::format()));
    return least;
  }
  /// WideBound rounds every operation upward.
  static WideBound add_up(const WideBound& a, const WideBound& b) { return a + b; }
  static WideBound mul_up(const WideBound& a, const WideBound& b) { return a * b; }
  static WideBound div_up(const WideBound& a, const WideBound& b) { return a / b; }
  /// CLN rounds each operation correctly (to nearest): |x - v| <= u |v| for v = RN(x), plus
  /// the underflow term (0 while CLN throws on underflow).
  static WideBound rounding_error(const F& v) { return unit_roundoff() * magnitude(v) + underflow_term(); }
  /// CLN has no gradual underflow: a sum that rounds to 0 is not known to be exact.
  static WideBound sum_rounding_error(const F& v) { return rounding_error(v); }
  static bool is_zero(const F& v) { return cln::zerop(v.value()); }
  /// magnitude(v) is >= |v| (1 + 2^-54) (from_float_up: a 53-bit mantissa moved one ulp up),
  /// and |x| <= |v| (1 + u) with u <= 2^-128: no extra step is needed.
  static WideBound quotient_magnitude(const F& v) { return magnitude(v); }
  /// A lower bound on |v| - e. Usually e <= |v|/1024, and L (1 - 2^-9) rounded up is below
  /// |v| - e for L <= |v| (WideBound's rounding adds < 2^-52 relative): no CLN operation.
  /// Otherwise |v| - e in F (e is exact in F, so one correctly rounded subtraction, relative
  /// error <= 2^-p), rounded down to a WideBound (>= 2^-54 relative below).
  static WideBound margin(const F& v, const WideBound& e) {
    if (e.is_infinite()) return WideBound();
    const WideBound low = WideBound::from_float_down(v.value());
    static const WideBound k1024(1024.0), shrink(1.0 - 1.0 / 512);
    if (e * k1024 <= low) return low * shrink;
    const cln::cl_F d = cln::abs(v.value()) - e.to_float(F::format());
    if (!cln::plusp(d)) return WideBound();
    return WideBound::from_float_down(d);
  }
  static bool is_positive(const WideBound& r) { return !r.is_zero(); }
  static WideBound unbounded() { return WideBound::infinity(); }
  static bool is_unbounded(const WideBound& r) { return r.is_infinite(); }
  static WideBound radius_up(const Rational& q) { return WideBound::from_rational_up(q); }
};

}  // namespace linkproof
