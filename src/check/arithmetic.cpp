#include "linkproof/check/arithmetic.h"

#include <array>
#include <utility>

namespace linkproof {

namespace {
constexpr std::array<std::pair<Arithmetic, std::string_view>, 7> kNames{{
    {Arithmetic::Exact, "exact"},
    {Arithmetic::Double, "double"},
    {Arithmetic::LongDouble, "long-double"},
    {Arithmetic::Mp30, "mp30"},
    {Arithmetic::Mp50, "mp50"},
    {Arithmetic::Mp100, "mp100"},
    {Arithmetic::Mp1000, "mp1000"},
}};
}  // namespace

std::string_view to_string(Arithmetic a) {
  for (const auto& [value, name] : kNames)
    if (value == a) return name;
  return "exact";
}

std::optional<Arithmetic> parse_arithmetic(std::string_view s) {
  for (const auto& [value, name] : kNames)
    if (name == s) return value;
  return std::nullopt;
}

std::string arithmetic_names() {
  std::string out;
  for (const auto& [value, name] : kNames) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

}  // namespace linkproof
