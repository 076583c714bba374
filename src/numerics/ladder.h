// The arithmetic ladder: every arithmetic the stability study runs in, cheapest first.
//
//   double, long double          IEEE (p = 53, 64 bits)
//   MpFloat<30|50|100|1000>      CLN long floats (p = 128, 192, 384, 3392 bits)
//   Rational                     exact (CLN cl_RA)
//
// One algorithm for all of them: for_each_arithmetic calls a generic callable once per type,
//   for_each_arithmetic([&]<class T>() { ... compute_by_route<T>(...) ... });
// so a route is instantiated per type from its single template, never copied.
#pragma once

#include <limits>
#include <string>
#include <tuple>

#include "core/multiprecision.h"
#include "core/scalar.h"

namespace linkproof {

using LadderTypes = std::tuple<double, long double, MpFloat<30>, MpFloat<50>, MpFloat<100>, MpFloat<1000>, Rational>;

/// Number of rungs of the ladder.
inline constexpr size_t kLadderSize = std::tuple_size_v<LadderTypes>;

/// Mantissa bits p of arithmetic T (unit roundoff 2^-p); 0 for exact arithmetic.
template <class T>
int precision_bits() {
  if constexpr (ScalarTraits<T>::is_exact) {
    return 0;
  } else if constexpr (std::is_floating_point_v<T>) {
    return std::numeric_limits<T>::digits;
  } else {
    return T::precision_bits();
  }
}

/// The arithmetic's name as printed in reports ("double", "long double", "mp30", ..., "exact").
template <class T>
std::string arithmetic_name() {
  return std::string(ScalarTraits<T>::name);
}

namespace ladder_detail {
template <class F, size_t... I>
void for_each(F& f, std::index_sequence<I...>) {
  (f.template operator()<std::tuple_element_t<I, LadderTypes>>(), ...);
}
}  // namespace ladder_detail

/// Calls f.template operator()<T>() for every T of the ladder, in ladder order.
template <class F>
void for_each_arithmetic(F&& f) {
  ladder_detail::for_each(f, std::make_index_sequence<kLadderSize>{});
}

}  // namespace linkproof
