#include "report/number_rich.h"

#include <fmt/format.h>

#include <stdexcept>

namespace linkproof::report {

std::string rational_tex(const Rational& q) {
  const std::string t = format_rational(q);
  const auto slash = t.find('/');
  if (slash == std::string::npos) return t;
  const bool neg = t[0] == '-';
  return std::string(neg ? "-" : "") + "\\frac{" + t.substr(neg ? 1 : 0, slash - (neg ? 1 : 0)) + "}{" +
         t.substr(slash + 1) + "}";
}

std::string decimal_tex(const std::string& decimal) {
  const auto e = decimal.find_first_of("eE");
  if (e == std::string::npos) return decimal;
  std::string exponent = decimal.substr(e + 1);
  if (!exponent.empty() && exponent[0] == '+') exponent.erase(0, 1);
  return decimal.substr(0, e) + " \\times 10^{" + exponent + "}";
}

std::string number_tex(const Rational& q, int digits) {
  const std::string decimal = decimal_text(q, digits);
  if (is_long_fraction(q))
    return fmt::format("\\approx {}\\ (\\text{{exact: {} digits}})", decimal_tex(decimal), fraction_digits(q));
  if (cln::denominator(q) == 1) return rational_tex(q);
  const bool is_value = decimal.find_first_of("eE") == std::string::npos && parse_rational(decimal) == q;
  return rational_tex(q) + (is_value ? " = " : " \\approx ") + decimal_tex(decimal);
}

Rich number_rich(const ResultNumber& x, int digits) {
  const Rational* q = std::get_if<Rational>(&x);
  if (!q) return plain(number_text(x));
  if (is_long_fraction(x))
    return {folded(text(format_rational(*q)),
                   fmt::format("≈ {} (exact: {} digits)", decimal_text(x, digits), fraction_digits(x)))};
  return tex(number_tex(*q, digits));
}

Rich point_rich(const Vec2<Rational>& p, int digits) {
  Rich out = plain("(");
  for (const Span& s : number_rich(p.x, digits)) out.push_back(s);
  out.push_back(text(", "));
  for (const Span& s : number_rich(p.y, digits)) out.push_back(s);
  out.push_back(text(")"));
  return out;
}

namespace {

// Only the program's own spellings of a number: an optional sign, digits, one optional "/".
bool is_number_text(const std::string& value) {
  bool number = !value.empty();
  size_t slashes = 0;
  for (size_t k = 0; k < value.size() && number; ++k) {
    const char c = value[k];
    if (c == '/') ++slashes;
    number = (c >= '0' && c <= '9') || (c == '-' && k == 0) || (c == '/' && k > 0 && k + 1 < value.size());
  }
  return number && slashes <= 1;
}

}  // namespace

Rich value_rich(const std::string& value, int digits) {
  // A point "(x, y)" of two numbers: each with its decimal.
  if (value.size() > 2 && value.front() == '(' && value.back() == ')') {
    const std::string inner = value.substr(1, value.size() - 2);
    const size_t comma = inner.find(", ");
    if (comma != std::string::npos && is_number_text(inner.substr(0, comma)) && is_number_text(inner.substr(comma + 2))) {
      try {
        return point_rich({parse_rational(inner.substr(0, comma)), parse_rational(inner.substr(comma + 2))}, digits);
      } catch (const std::exception&) {
        return plain(value);
      }
    }
  }
  if (!is_number_text(value)) return plain(value);
  try {
    return number_rich(parse_rational(value), digits);
  } catch (const std::exception&) {
    return plain(value);
  }
}

}  // namespace linkproof::report
