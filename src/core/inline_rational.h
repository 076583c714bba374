// The exact arithmetic's scalar: a rational number held in two machine words while it fits, and
// as a CLN rational (cl_RA) only when it does not.
//
// Why: a CLN rational that is not an integer is a heap object, and every CLN operation
// normalises its result by a gcd. An exact pentagon check spent a third of its time in cln::gcd
// and a sixth in malloc and free (perf, 2026-11-28), on numbers that almost all fit in 64 bits.
// Here the word path is inline and needs no gcd while its results fit: a sum or product forms
// numerator and denominator exactly in 128 bits (each part of an operand is below 2^63) and
// keeps them as they are when both fit in words. Only a result that does not fit is reduced
// (one gcd of the 128-bit parts, core/word_gcd.h), and only one whose reduced form still does not fit
// goes to CLN. A value is reduced for good when it is read as a cl_RA (printing, evidence).
//
// Invariant: a value is in the word form exactly when its reduced form fits (|numerator| and
// denominator <= 2^63 - 1), not necessarily reduced, with a positive denominator; 0 is 0/1.
// So a word and a CLN value are never equal, two words compare by cross-multiplication in 128
// bits, and zero is a zero numerator. Every value, its text and every verdict are those of cl_RA
// (InlineRationalOps.* compares them operation by operation on random operands of every size,
// ExactRoutes.* every claim on random polygons). Division by zero throws what cl_RA throws.
#pragma once

#include <cln/rational.h>

#include <compare>
#include <cstdint>
#include <utility>
#include <string>

#include "linkproof/core/exact.h"
#include "core/scalar.h"
#include "core/word_gcd.h"
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

  /// The value as a CLN rational (reduced, as cl_RA keeps every value).
  Rational to_rational() const { return is_word() ? word_rational() : big_; }
  bool is_zero() const { return is_word() && num_ == 0; }
  bool is_one() const { return is_word() && num_ == den_; }
  /// True while numerator and denominator are held in words (for tests and benchmarks).
  bool is_word() const { return den_ != 0; }
  int sign() const { return is_word() ? (num_ > 0) - (num_ < 0) : cln::minusp(big_) ? -1 : cln::zerop(big_) ? 0 : 1; }

  friend InlineRational operator+(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() && b.is_word()) return word_sum(a, b, false);
    if (a.is_zero()) return b;
    if (b.is_zero()) return a;
    return InlineRational(a.to_rational() + b.to_rational());
  }
  friend InlineRational operator-(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() && b.is_word()) return word_sum(a, b, true);
    if (b.is_zero()) return a;
    return InlineRational(a.to_rational() - b.to_rational());
  }
  friend InlineRational operator*(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() && b.is_word()) return word_product(a.num_, a.den_, b.num_, b.den_);
    // A CLN value times 1 (rate polynomials multiply every coefficient by its rates' 1s): itself.
    if (a.is_one()) return b;
    if (b.is_one()) return a;
    return InlineRational(a.to_rational() * b.to_rational());
  }
  /// a / b; b = 0 throws what cl_RA's division throws.
  friend InlineRational operator/(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() && b.is_word() && b.num_ != 0) {
      // a / b = a * (1 / b), the reciprocal's sign moved to its numerator.
      const std::int64_t rn = b.num_ > 0 ? b.den_ : -b.den_;
      const std::int64_t rd = b.num_ > 0 ? b.num_ : -b.num_;
      return word_product(a.num_, a.den_, rn, rd);
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

  /// A value is in words exactly when its reduced form fits, so a word and a CLN value differ.
  friend bool operator==(const InlineRational& a, const InlineRational& b) {
    if (a.is_word() != b.is_word()) return false;
    if (!a.is_word()) return a.big_ == b.big_;
    return static_cast<Int128>(a.num_) * b.den_ == static_cast<Int128>(b.num_) * a.den_;
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
  /// n/d for coprime n and d > 0 that do not both fit in words: the CLN value, built from the
  /// reduced parts (the operands need not be read as cl_RA, nor the operation redone in CLN).
  static InlineRational big_from_reduced(Int128 n, Int128 d);

  /// Stores n/d (d > 0; 0 as 0/1) if both parts fit in words; false leaves *this unspecified.
  bool store(Int128 n, Int128 d) {
    if (n == 0) d = 1;
    if (n < -static_cast<Int128>(kMax) || n > kMax || d > kMax) return false;
    num_ = static_cast<std::int64_t>(n);
    den_ = static_cast<std::int64_t>(d);
    return true;
  }
  /// n/d (d > 0): in words if its reduced form fits (as it is when it fits, else reduced),
  /// else the CLN value of the reduced form.
  static InlineRational reduced(Int128 n, Int128 d) {
    InlineRational r;
    if (r.store(n, d)) return r;
    const Int128 g = static_cast<Int128>(wide_gcd(n < 0 ? -static_cast<UInt128>(n) : static_cast<UInt128>(n), static_cast<UInt128>(d)));
    if (r.store(n / g, d / g)) return r;
    return big_from_reduced(n / g, d / g);
  }

  /// a +- b of two word values.
  static InlineRational word_sum(const InlineRational& a, const InlineRational& b, bool subtract) {
    const Int128 bn = subtract ? -static_cast<Int128>(b.num_) : static_cast<Int128>(b.num_);
    if (a.den_ == b.den_) return reduced(a.num_ + bn, a.den_);
    // |an bd +- bn ad| < 2^127 and ad bd < 2^126: exact in 128 bits.
    return reduced(static_cast<Int128>(a.num_) * b.den_ + bn * a.den_, static_cast<Int128>(a.den_) * b.den_);
  }

  /// (an/ad)(bn/bd) with ad, bd > 0: |an bn| < 2^126, exact in 128 bits.
  static InlineRational word_product(std::int64_t an, std::int64_t ad, std::int64_t bn, std::int64_t bd) {
    return reduced(static_cast<Int128>(an) * bn, static_cast<Int128>(ad) * bd);
  }

  // Word form when den_ > 0 (num_ / den_, not necessarily reduced, |num_| <= 2^63 - 1); else
  // big_ holds the value, whose reduced form then does not fit in words.
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
