#include "linkproof/check/arithmetic.h"

#include <array>
#include <utility>

#include "check/arithmetic_types.h"

namespace linkproof {

namespace {
#define LINKPROOF_ARITHMETIC_NAME(enumerator, name, type) std::pair{Arithmetic::enumerator, std::string_view(name)},
constexpr std::array kNames{LINKPROOF_FOR_EACH_ARITHMETIC(LINKPROOF_ARITHMETIC_NAME)};
#undef LINKPROOF_ARITHMETIC_NAME
static_assert(kNames.size() == std::tuple_size_v<ArithmeticScalarTypes>);
constexpr bool in_enum_order() {
  for (size_t k = 0; k < kNames.size(); ++k)
    if (static_cast<size_t>(kNames[k].first) != k) return false;
  return true;
}
static_assert(in_enum_order(), "LINKPROOF_FOR_EACH_ARITHMETIC must list the arithmetics in the enum's order");
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
