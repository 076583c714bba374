#include "linkproof/core/exact.h"

#include <cln/integer.h>
#include <cln/integer_io.h>
#include <cln/rational.h>
#include <cln/rational_io.h>

#include <cctype>
#include <sstream>
#include <stdexcept>

#include "core/tracked.h"

namespace linkproof {

namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

cln::cl_I parse_digits(std::string_view digits) {
  return cln::cl_I(std::string(digits).c_str());
}

constexpr long kMaxDecimalExponent = 4000;  // 10^4000 is already far beyond any linkage; stops DoS input

}  // namespace

Rational parse_rational(std::string_view text) {
  std::string_view s = text;
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (s.empty()) throw std::invalid_argument("empty, expected a number");

  bool negative = false;
  std::string_view body = s;
  if (body.front() == '+' || body.front() == '-') {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  const auto fail = [&](const char* what) {
    throw std::invalid_argument("'" + std::string(text) + "' is not an exact number (" + what +
                                "; use an integer, a fraction \"p/q\" or a decimal)");
  };
  if (body.empty()) fail("sign without digits");

  // Fraction p/q.
  if (auto slash = body.find('/'); slash != std::string_view::npos) {
    std::string_view p = body.substr(0, slash), q = body.substr(slash + 1);
    if (!all_digits(p) || !all_digits(q)) fail("numerator and denominator must be digits");
    cln::cl_I den = parse_digits(q);
    if (cln::zerop(den)) throw std::invalid_argument("'" + std::string(text) + "' has denominator 0");
    Rational r = parse_digits(p) / den;
    return negative ? -r : r;
  }

  // Decimal with optional exponent: digits [. digits] [e|E [+-] digits].
  std::string_view mantissa = body, exponent;
  if (auto e = body.find_first_of("eE"); e != std::string_view::npos) {
    mantissa = body.substr(0, e);
    exponent = body.substr(e + 1);
    if (exponent.empty()) fail("empty exponent");
  }
  std::string_view int_part = mantissa, frac_part;
  if (auto dot = mantissa.find('.'); dot != std::string_view::npos) {
    int_part = mantissa.substr(0, dot);
    frac_part = mantissa.substr(dot + 1);
  }
  if (int_part.empty() && frac_part.empty()) fail("no digits");
  if ((!int_part.empty() && !all_digits(int_part)) || (!frac_part.empty() && !all_digits(frac_part)))
    fail("unexpected character");

  long exp10 = 0;
  if (!exponent.empty()) {
    bool exp_negative = false;
    if (exponent.front() == '+' || exponent.front() == '-') {
      exp_negative = exponent.front() == '-';
      exponent.remove_prefix(1);
    }
    if (!all_digits(exponent)) fail("exponent must be digits");
    if (exponent.size() > 6) fail("exponent out of range");
    exp10 = std::stol(std::string(exponent));
    if (exp_negative) exp10 = -exp10;
  }
  exp10 -= static_cast<long>(frac_part.size());
  if (exp10 > kMaxDecimalExponent || exp10 < -kMaxDecimalExponent) fail("exponent out of range (|e| <= 4000)");

  std::string digits = std::string(int_part) + std::string(frac_part);
  Rational r = parse_digits(digits);
  if (exp10 > 0) r = r * cln::expt_pos(cln::cl_I(10), exp10);
  if (exp10 < 0) r = r / cln::expt_pos(cln::cl_I(10), -exp10);
  return negative ? -r : r;
}

std::string format_rational(const Rational& q) {
  // Numbers that fit a machine word (most of a check's) without a stream: constructing an
  // ostringstream (its locale) cost more than printing (~7 % of an exact pentagon check).
  const cln::cl_I p = cln::numerator(q), d = cln::denominator(q);
  if (cln::integer_length(p) < 63 && cln::integer_length(d) < 63) {
    std::string s = std::to_string(cln::cl_I_to_long(p));
    if (d != 1) s += "/" + std::to_string(cln::cl_I_to_long(d));
    return s;
  }
  std::ostringstream out;
  cln::fprint(out, q);  // CLN prints reduced p/q, and integers without a denominator
  return out.str();
}

double nearest_double(const Rational& q) { return round_rational<double>(q); }

}  // namespace linkproof
