#include "report/number_text.h"

#include <cln/rational.h>
#include <fmt/format.h>

#include "core/multiprecision.h"
#include "core/scalar.h"

namespace linkproof {

std::string number_text(const ResultNumber& x) {
  return std::visit(
      [](const auto& v) -> std::string {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, Rational>) {
          return format_rational(v);
        } else if constexpr (std::is_same_v<V, cln::cl_F>) {
          return format_cln_float(v);
        } else {
          return format_float(v);
        }
      },
      x);
}

namespace {

// The decimal of an exact value, trailing zeros of the mantissa dropped; `exponent` receives
// the "e..." part ("" for none).
std::string trimmed_decimal(const Rational& q, int digits, std::string& exponent) {
  const std::string decimal = format_decimal(q, digits);
  const size_t e = decimal.find('e');
  std::string mantissa = decimal.substr(0, e);
  exponent = e == std::string::npos ? "" : decimal.substr(e);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  return mantissa;
}

}  // namespace

std::string decimal_text(const ResultNumber& x, int digits) {
  const Rational* q = std::get_if<Rational>(&x);
  if (!q) return number_text(x);
  if (cln::denominator(*q) == 1 && format_rational(*q).size() <= kLongFraction) return format_rational(*q);
  std::string exponent;
  const std::string mantissa = trimmed_decimal(*q, digits, exponent);
  return mantissa + exponent;
}

bool is_long_fraction(const ResultNumber& x) {
  const Rational* q = std::get_if<Rational>(&x);
  return q && format_rational(*q).size() > kLongFraction;
}

size_t fraction_digits(const ResultNumber& x) {
  size_t figures = 0;
  for (const char c : number_text(x)) figures += c >= '0' && c <= '9';
  return figures;
}

std::string readable_number(const ResultNumber& x, int digits) {
  const Rational* q = std::get_if<Rational>(&x);
  if (!q) return number_text(x);
  const std::string exact = format_rational(*q);
  if (cln::denominator(*q) == 1 && exact.size() <= kLongFraction) return exact;
  const std::string decimal = decimal_text(x, digits);
  if (exact.size() > kLongFraction)
    return fmt::format("≈ {} (exact: a fraction of {} digits, see --json)", decimal, fraction_digits(x));
  const bool is_value = decimal.find('e') == std::string::npos && parse_rational(decimal) == *q;
  return fmt::format("{} {} {}", exact, is_value ? "=" : "≈", decimal);
}

std::string compact_number(const ResultNumber& x, int digits) {
  if (!is_long_fraction(x)) return readable_number(x, digits);
  return "≈ " + decimal_text(x, digits) + kLongFractionMark;
}

std::string long_fraction_note(int digits, const std::string& where) {
  return fmt::format("{} a long exact fraction (more than {} characters), shown by its decimal to {} significant "
                     "digits; every exact value: {}",
                     kLongFractionMark, kLongFraction, digits, where);
}

std::string radius_text(const ResultRadius& r) {
  return std::visit(
      [](const auto& v) -> std::string {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, WideBound>) {
          return v.to_string();
        } else {
          return format_float(v);
        }
      },
      r);
}

std::string radius_short_text(const ResultRadius& r) {
  return std::visit(
      [](const auto& v) -> std::string {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, WideBound>) {
          return v.to_short_string();
        } else {
          return fmt::format("{:.3g}", static_cast<double>(v));
        }
      },
      r);
}

}  // namespace linkproof
