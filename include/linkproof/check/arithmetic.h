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
  Mp30,        ///< CLN long float, 128 bits, with running error bounds (Tracked<MpFloat<30>>)
  Mp50,        ///< 192 bits (Tracked<MpFloat<50>>)
  Mp100,       ///< 384 bits (Tracked<MpFloat<100>>)
  Mp1000,      ///< 3392 bits (Tracked<MpFloat<1000>>)
};

/// "exact", "double", "long-double", "mp30", "mp50", "mp100", "mp1000" (the mp names are
/// those of the stability ladder, numerics/ladder.h).
std::string_view to_string(Arithmetic a);
/// The inverse of to_string; nullopt for anything else.
std::optional<Arithmetic> parse_arithmetic(std::string_view s);
/// Every name, comma-separated, for help texts and error messages.
std::string arithmetic_names();

}  // namespace linkproof
