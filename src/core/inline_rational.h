// The exact arithmetic's scalar: a rational number held in two machine words while it fits, and
// as a CLN rational (cl_RA) only when it does not.
//
// Why: a CLN rational that is not an integer is a heap object, and every operation on it
// normalises by a gcd through CLN's generic dispatch. An exact pentagon check spent a third of
// its time in cln::gcd and a sixth in malloc and free (perf, 2026-11-28), on numbers that almost
// all fit in 64 bits. Here the word path is inline: sums and products form their numerator and
// denominator in 128 bits (Knuth's reduced sum and cross-cancelled product, TAOCP 4.5.1, so the
// gcds are of the small operands), and only a result that does not fit in 64 bits goes to CLN.
//
// Every value is kept reduced with a positive denominator, and in the word form exactly when
// it fits (|numerator| <= 2^63 - 1, denominator <= 2^63 - 1): the representation is canonical,
// so equality compares words, and every value, its text and every verdict are those of cl_RA
// (InlineRationalOps.* compares them operation by operation on random operands of every size,
// ExactRoutes.* whole checks). Division by zero throws what cl_RA throws.
#pragma once

#include <cln/rational.h>

#include <compare>
#include <cstdint>
#include <numeric>
#include <string>

#include "linkproof/core/exact.h"
#include "core/scalar.h"
#include "linkproof/core/result_number.h"

namespace linkproof {

// GCC's 128-bit integers (__extension__: -Wpedantic knows they are not ISO C++).
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

class InlineRational {
 public:
  InlineRational() = default;
  /// The integer k (k != INT64_MIN takes the word form).
  explicit InlineRational(std::int64_t k) {
    if (k != kMin) {
      num_ = k;
    } else {
      den_ = 0;
      big_ = Rational(k);
    }
  }
  /// q, in the word form when it fits.
  explicit InlineRational(const Rational& q) { assign(q); }

  /// The value as a CLN rational (its numerator and denominator reduced, as cl_RA keeps them).
  Rational to_rational() const { return is_word() ? word_rational() : big_; }
  bool is_zero() const { return is_word() && num_ == 0; }
  /// True while numerator and denominator are held in words (for tests and benchmarks).
  bool is_word() const { return den_ != 0; }
  int sign() const { return is_word() ? (num_ > 0) - (num_ < 0) : cln::minusp(big_) ? -1 : cln::zerop(big_) ? 0 : 1; }

  friend InlineRational operator+(const InlineRational& a, const InlineRational& b) {
    InlineRational r;
    if (a.is_word() && b.is_word() && r.word_sum(a, b, false)) return r;
    return InlineRational(a.to_rational() + b.to_rational());
  }
  friend InlineRational operator-(const InlineRational& a, const InlineRational& b) {
    InlineRational r;
    if (a.is_word() && b.is_word() && r.word_sum(a, b, true)) return r;
    return InlineRational(a.to_rational() - b.to_rational());
  }
  friend InlineRational operator*(const InlineRational& a, const InlineRational& b) {
    InlineRational r;
    if (a.is_word() && b.is_word() && r.word_product(a.num_, a.den_, b.num_, b.den_)) return r;
    return InlineRational(a.to_rational() * b.to_rational());
  }
  /// a / b; b = 0 throws what cl_RA's division throws.
  friend InlineRational operator/(const InlineRational& a, const InlineRational& b) {
    InlineRational r;
    if (a.is_word() && b.is_word() && b.num_ != 0) {
      // a / b = a * (1 / b): the reciprocal of a reduced word fraction is one, sign moved up.
      const std::int64_t rn = b.num_ > 0 ? b.den_ : -b.den_;
      const std::int64_t rd = b.num_ > 0 ? b.num_ : -b.num_;
      if (r.word_product(a.num_, a.den_, rn, rd)) return r;
    }
    return InlineRational(a.to_rational() / b.to_rational());
  }
  friend InlineRational operator-(const InlineRational& a) {
    if (a.is_word()) {
      InlineRational r;
      r.num_ = -a.num_;  // |num| <= 2^63 - 1: negation stays in range
      r.den_ = a.den_;
      return r;
    }
    return InlineRational(-a.big_);
  }
  InlineRational& operator+=(const InlineRational& b) { return *this = *this + b; }
  InlineRational& operator-=(const InlineRational& b) { return *this = *this - b; }
  InlineRational& operator*=(const InlineRational& b) { return *this = *this * b; }
  InlineRational& operator/=(const InlineRational& b) { return *this = *this / b; }

  /// Canonical form: equal values have equal representations.
  friend bool operator==(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() != b.is_word()) return false;
    return a.is_word() ? a.num_ == b.num_ && a.den_ == b.den_ : a.big_ == b.big_;
  }
  friend std::strong_ordering operator<=>(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() && b.is_word()) {
      // a/b <=> c/d with positive denominators: a d <=> c b, exact in 128 bits.
      const Int128 l = static_cast<Int128>(a.num_) * b.den_;
      const Int128 r = static_cast<Int128>(b.num_) * a.den_;
      return l <=> r;
    }
    const int c = cln::compare(a.to_rational(), b.to_rational());
    return c < 0 ? std::strong_ordering::less : c > 0 ? std::strong_ordering::greater : std::strong_ordering::equal;
  }

 private:
  static constexpr std::int64_t kMin = INT64_MIN;
  static constexpr std::int64_t kMax = INT64_MAX;

  Rational word_rational() const;
  void assign(const Rational& q);

  /// Stores the reduced n/d (d > 0; 0 as 0/1) if both fit in words; false leaves *this
  /// unspecified.
  bool store(Int128 n, Int128 d) {
    if (n == 0) d = 1;
    if (n < -static_cast<Int128>(kMax) || n > kMax || d > kMax) return false;
    num_ = static_cast<std::int64_t>(n);
    den_ = static_cast<std::int64_t>(d);
    return true;
  }
  static std::uint64_t magnitude(std::int64_t x) { return x < 0 ? -static_cast<std::uint64_t>(x) : static_cast<std::uint64_t>(x); }

  /// a +- b of two word values (Knuth's reduced sum). False when the result needs more than words.
  bool word_sum(const InlineRational& a, const InlineRational& b, bool subtract) {
    const Int128 bn = subtract ? -static_cast<Int128>(b.num_) : static_cast<Int128>(b.num_);
    if (a.den_ == b.den_) {
      // Common denominator d: (an +- bn) / d, reduced by gcd(sum, d) (1 when d = 1).
      const Int128 s = a.num_ + bn;
      if (a.den_ == 1) return store(s, 1);
      const std::uint64_t g = gcd_128_64(s, static_cast<std::uint64_t>(a.den_));
      return store(s / static_cast<Int128>(g), a.den_ / static_cast<std::int64_t>(g));
    }
    const std::uint64_t g = std::gcd(static_cast<std::uint64_t>(a.den_), static_cast<std::uint64_t>(b.den_));
    if (g == 1) {
      // Coprime denominators: an d + bn b over b d is already reduced; its parts fit in 128 bits.
      const Int128 n = static_cast<Int128>(a.num_) * b.den_ + bn * a.den_;
      const Int128 d = static_cast<Int128>(a.den_) * b.den_;
      return store(n, d);
    }
    const std::int64_t ad = a.den_ / static_cast<std::int64_t>(g), bd = b.den_ / static_cast<std::int64_t>(g);
    const Int128 t = static_cast<Int128>(a.num_) * bd + bn * ad;  // |t| < 2^127
    const std::uint64_t g2 = gcd_128_64(t, g);
    const Int128 d = static_cast<Int128>(ad) * (b.den_ / static_cast<std::int64_t>(g2));
    return store(t / static_cast<Int128>(g2), d);
  }

  /// (an/ad)(bn/bd) of reduced fractions with positive denominators: cross-cancelled first, so
  /// the product is reduced. False when it needs more than words.
  bool word_product(std::int64_t an, std::int64_t ad, std::int64_t bn, std::int64_t bd) {
    if (an == 0 || bn == 0) {
      num_ = 0;
      den_ = 1;
      return true;
    }
    const std::int64_t g1 = static_cast<std::int64_t>(std::gcd(magnitude(an), static_cast<std::uint64_t>(bd)));
    const std::int64_t g2 = static_cast<std::int64_t>(std::gcd(magnitude(bn), static_cast<std::uint64_t>(ad)));
    return store(static_cast<Int128>(an / g1) * (bn / g2), static_cast<Int128>(ad / g2) * (bd / g1));
  }

  /// gcd(|t|, g) for g >= 1: one 128-bit remainder brings t below g, then word gcds.
  static std::uint64_t gcd_128_64(Int128 t, std::uint64_t g) {
    const UInt128 m = t < 0 ? -static_cast<UInt128>(t) : static_cast<UInt128>(t);
    const std::uint64_t r = m >> 64 == 0 ? static_cast<std::uint64_t>(m) % g : static_cast<std::uint64_t>(m % g);
    return std::gcd(r, g);
  }

  // Word form when den_ > 0 (num_ / den_ reduced, num_ != INT64_MIN); else big_ holds the value,
  // which then does not fit in words.
  std::int64_t num_ = 0;
  std::int64_t den_ = 1;
  Rational big_;
};

template <>
struct ScalarTraits<InlineRational> {
  static constexpr bool is_exact = true;
  static constexpr bool has_error_bound = false;
  static constexpr std::string_view name = "exact";
  static InlineRational from_rational(const Rational& q) { return InlineRational(q); }
  static InlineRational from_int64(std::int64_t k) { return InlineRational(k); }
  static InlineRational from_fraction(std::int64_t p, std::int64_t d) { return InlineRational(p) / InlineRational(d); }
  static bool is_zero(const InlineRational& x) { return x.is_zero(); }
  static InlineRational abs(const InlineRational& x) { return x.sign() < 0 ? -x : x; }
  static bool less(const InlineRational& a, const InlineRational& b) { return a < b; }
  static Rational to_rational(const InlineRational& x) { return x.to_rational(); }
  static double to_double(const InlineRational& x) { return cln::double_approx(x.to_rational()); }
  static std::string to_string(const InlineRational& x) { return format_rational(x.to_rational()); }
};

/// The value of an exact result (core/result_number.h).
inline ResultNumber result_number(const InlineRational& x) { return x.to_rational(); }

}  // namespace linkproof
