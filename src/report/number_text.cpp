#include "report/number_text.h"

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
