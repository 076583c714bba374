#include "linkproof/eval/arithmetic.h"

namespace linkproof {

std::string_view to_string(Arithmetic a) {
  switch (a) {
    case Arithmetic::Exact: return "exact";
    case Arithmetic::Double: return "double";
    case Arithmetic::LongDouble: return "long-double";
  }
  return "exact";
}

std::optional<Arithmetic> parse_arithmetic(std::string_view s) {
  if (s == "exact") return Arithmetic::Exact;
  if (s == "double") return Arithmetic::Double;
  if (s == "long-double") return Arithmetic::LongDouble;
  return std::nullopt;
}

}  // namespace linkproof
