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

std::string readable_number(const ResultNumber& x, int digits) {
  const Rational* q = std::get_if<Rational>(&x);
  if (!q) return number_text(x);
  const std::string exact = format_rational(*q);
  if (cln::denominator(*q) == 1 && exact.size() <= kLongFraction) return exact;
  std::string decimal = format_decimal(*q, digits);
  const size_t e = decimal.find('e');
  std::string mantissa = decimal.substr(0, e), exponent = e == std::string::npos ? "" : decimal.substr(e);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  decimal = mantissa + exponent;
  if (exact.size() > kLongFraction) {
    size_t figures = 0;
    for (const char c : exact) figures += c >= '0' && c <= '9';
    return fmt::format("≈ {} (exact: a fraction of {} digits, see --json)", decimal, figures);
  }
  const bool is_value = exponent.empty() && parse_rational(decimal) == *q;
  return fmt::format("{} {} {}", exact, is_value ? "=" : "≈", decimal);
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
