#include "core/inline_rational.h"

#include <cln/integer.h>

namespace linkproof {

namespace {

// True if x is in the word range [-(2^63 - 1), 2^63 - 1] (the ends symmetric: a negation of a
// word stays a word).
bool fits_word(const cln::cl_I& x) {
  return cln::integer_length(x) <= 63 && x != cln::cl_I(static_cast<long>(INT64_MIN));
}

}  // namespace

Rational InlineRational::word_rational() const {
  const cln::cl_I n(static_cast<long>(num_));
  if (den_ == 1) return n;
  // CLN's quotient reduces it.
  return n / cln::cl_I(static_cast<long>(den_));
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
