// The arithmetic a check runs in, chosen at run time (the CLI's --arith).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace linkproof {

enum class Arithmetic {
  Exact,       ///< CLN rationals: a residual is zero or it is not
  Double,      ///< IEEE double with running error bounds (Tracked<double>)
  LongDouble,  ///< x87 long double with running error bounds (Tracked<long double>)
};

std::string_view to_string(Arithmetic a);
/// "exact", "double", "long-double"; nullopt for anything else.
std::optional<Arithmetic> parse_arithmetic(std::string_view s);

/// Calls f.template operator()<T>() with the scalar type of arithmetic a.
template <class F>
decltype(auto) with_scalar_type(Arithmetic a, F&& f);

}  // namespace linkproof

#include "linkproof/core/scalar.h"

namespace linkproof {
template <class F>
decltype(auto) with_scalar_type(Arithmetic a, F&& f) {
  switch (a) {
    case Arithmetic::Double: return f.template operator()<Tracked<double>>();
    case Arithmetic::LongDouble: return f.template operator()<Tracked<long double>>();
    case Arithmetic::Exact: break;
  }
  return f.template operator()<Rational>();
}
}  // namespace linkproof
