#include "linkproof/core/exact.h"

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/integer_io.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace linkproof {

std::string format_decimal(const Rational& q, int digits) {
  if (cln::zerop(q)) return "0";
  if (cln::denominator(q) == 1) return format_rational(q);
  const bool negative = cln::minusp(q);
  const Rational m = cln::abs(q);
  // Exponent e with 10^e <= m < 10^(e+1), found from the double estimate and corrected exactly.
  const double estimate = std::log10(cln::double_approx(m));
  long e = std::isfinite(estimate)
               ? static_cast<long>(std::floor(estimate))
               // beyond double's range: from the bit lengths (off by at most one or two, corrected below)
               : static_cast<long>(static_cast<double>(static_cast<long>(cln::integer_length(cln::numerator(m))) -
                                                       static_cast<long>(cln::integer_length(cln::denominator(m)))) *
                                   0.30102999566398120);
  while (cln::expt(Rational(10), e) > m) --e;
  while (cln::expt(Rational(10), e + 1) <= m) ++e;
  const long shift = digits - 1 - e;
  const cln::cl_I scaled = cln::round1(m * cln::expt(Rational(10), shift));  // ties to even: fine for messages
  std::ostringstream digits_text;
  cln::print_integer(digits_text, 10, scaled);
  std::string s = digits_text.str();
  // Rounding may carry to one more digit (9.99.. -> 10.0..).
  long exponent = e + static_cast<long>(s.size()) - digits;
  s = s.substr(0, static_cast<size_t>(digits));
  std::string out;
  if (exponent >= 0 && exponent < digits) {
    out = s.substr(0, static_cast<size_t>(exponent + 1)) + "." + s.substr(static_cast<size_t>(exponent + 1));
  } else if (exponent < 0 && exponent > -6) {
    out = "0." + std::string(static_cast<size_t>(-exponent - 1), '0') + s;
  } else {
    out = s.substr(0, 1) + "." + s.substr(1) + "e" + std::to_string(exponent);
  }
  if (out.back() == '.') out.pop_back();
  return (negative ? "-" : "") + out;
}

Rational rational_from_double(double x) {
  // CLN's cl_DF has no subnormals (it throws "floating point underflow"): scale a subnormal by
  // 2^200, exactly, and divide the rational by the same power.
  if (x != 0 && std::abs(x) < std::numeric_limits<double>::min())
    return cln::rational(cln::cl_DF(std::ldexp(x, 200))) / cln::expt(Rational(2), 200);
  return cln::rational(cln::cl_DF(x));
}

}  // namespace linkproof
