#include "core/inline_rational.h"

#include <cln/integer.h>

// CLN's constructor of the ratio a/b from coprime a and b > 0, without the gcd its quotient
// operator computes to reduce (declared in CLN's internal rational/cl_RA.h, exported by
// libcln). The parts passed here come reduced by InlineRational's own gcd; a CLN quotient of
// two 2-word integers would compute their gcd again in CLN's bignum gcd (17 % of an exact
// n = 1000 check, perf). InlineRationalOps.* compares every value made here with CLN's own.
namespace cln {
const cl_RA I_I_to_RA(const cl_I& a, const cl_I& b);
}  // namespace cln

namespace linkproof {

namespace {

// True if x is in the word range [-(2^63 - 1), 2^63 - 1] (the ends symmetric: a negation of a
// word stays a word).
bool fits_word(const cln::cl_I& x) {
  return cln::integer_length(x) <= 63 && x != cln::cl_I(static_cast<long>(INT64_MIN));
}

cln::cl_I from_int128(Int128 x) {
  const UInt128 u = x < 0 ? -static_cast<UInt128>(x) : static_cast<UInt128>(x);
  const auto high = static_cast<unsigned long long>(u >> 64), low = static_cast<unsigned long long>(u);
  cln::cl_I v = high == 0 ? cln::cl_I(low) : cln::ash(cln::cl_I(high), 64) + cln::cl_I(low);
  return x < 0 ? -v : v;
}

}  // namespace

InlineRational InlineRational::big_from_reduced(Int128 n, Int128 d) {
  InlineRational r;
  r.num_ = 0;
  r.den_ = 0;
  r.big_ = cln::I_I_to_RA(from_int128(n), from_int128(d));
  return r;
}

Rational InlineRational::word_rational() const {
  if (den_ == 1) return cln::cl_I(static_cast<long>(num_));
  // Reduced by the word gcd, then made from the coprime parts: CLN's quotient would reduce it
  // again in its bignum gcd (12 % of an exact pentagon check, which reads every comparison's
  // values, perf).
  const std::uint64_t magnitude = num_ < 0 ? 0 - static_cast<std::uint64_t>(num_) : static_cast<std::uint64_t>(num_);
  const auto g = static_cast<std::int64_t>(word_gcd(magnitude, static_cast<std::uint64_t>(den_)));
  return cln::I_I_to_RA(cln::cl_I(static_cast<long>(num_ / g)), cln::cl_I(static_cast<long>(den_ / g)));
}

void InlineRational::assign(const Rational& q) {
  const cln::cl_I n = cln::numerator(q), d = cln::denominator(q);
  if (fits_word(n) && fits_word(d)) {
    num_ = cln::cl_I_to_Q(n);
    den_ = cln::cl_I_to_Q(d);
    big_ = 0;
  } else {
    num_ = 0;
    den_ = 0;
    big_ = q;
  }
}

}  // namespace linkproof
