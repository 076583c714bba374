#include "mechanism/axis_length.h"

#include <cln/integer.h>
#include <cln/rational.h>

#include "linkproof/core/error.h"

namespace linkproof {

namespace {
// Square factors d^2 with d up to this bound are taken out of the radicand by trial division.
constexpr long kSquareFactorTrials = 1000;
}  // namespace

SquareRootForm construct_square_root(const Rational& q) {
  LINKPROOF_ASSERT(cln::plusp(q), "the square root of a non-positive number");
  const cln::cl_I p = cln::numerator(q), d = cln::denominator(q);
  cln::cl_I n = p * d, s = 1;
  for (long k = 2; k <= kSquareFactorTrials; ++k) {
    const cln::cl_I k2 = cln::cl_I(k) * cln::cl_I(k);
    if (k2 > n) break;
    while (cln::zerop(cln::mod(n, k2))) n = cln::exquo(n, k2), s = s * k;
  }
  cln::cl_I root;
  if (cln::isqrt(n, &root)) s = s * root, n = 1;
  return {Rational(s) / d, n};
}

RationalEnclosure enclose_square_root(const Rational& q, int bits) {
  LINKPROOF_ASSERT(cln::plusp(q) && bits > 0, "the enclosure of the square root of a non-positive number");
  // sqrt(q) = sqrt(p d) / d; r = floor(sqrt(p d 4^bits)) <= sqrt(p d) 2^bits < r + 1.
  const cln::cl_I p = cln::numerator(q), d = cln::denominator(q);
  const cln::cl_I scale = cln::ash(cln::cl_I(1), bits);
  cln::cl_I r;
  cln::isqrt(p * d * scale * scale, &r);
  const Rational unit = Rational(1) / (Rational(scale) * d);
  // [r unit, (r + 1) unit] holds sqrt(q); its width is unit <= 2^-bits sqrt(q) since p d >= 1.
  return {(Rational(r) + Rational(1) / 2) * unit, unit / 2};
}

}  // namespace linkproof
