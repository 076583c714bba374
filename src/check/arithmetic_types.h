// The one list of arithmetics: each value of Arithmetic (check/arithmetic.h), its name on the
// command line and in JSON, and its scalar type. Everything per arithmetic is made from this list:
// the names (check/arithmetic.cpp), the type tuple every claim is compiled for (claims/claim.h),
// the dispatch below and the explicit instantiations (LINKPROOF_FOR_EACH_ARITHMETIC in a .cpp).
// Adding an arithmetic is one line here and one enumerator there.
#pragma once

#include <tuple>

#include "core/inline_rational.h"
#include "core/multiprecision.h"
#include "core/scalar.h"
#include "linkproof/check/arithmetic.h"

// X(enumerator, name, scalar type), in the enum's order: exact first, then the floating-point
// arithmetics (which carry error bounds).
#define LINKPROOF_FOR_EACH_ARITHMETIC(X) \
  X(Exact, "exact", ::linkproof::InlineRational) \
  LINKPROOF_FOR_EACH_FLOATING_ARITHMETIC(X)
#define LINKPROOF_FOR_EACH_FLOATING_ARITHMETIC(X)                    \
  X(Double, "double", ::linkproof::Tracked<double>)                  \
  X(LongDouble, "long-double", ::linkproof::Tracked<long double>)    \
  X(Mp30, "mp30", ::linkproof::Tracked<::linkproof::MpFloat<30>>)     \
  X(Mp50, "mp50", ::linkproof::Tracked<::linkproof::MpFloat<50>>)     \
  X(Mp100, "mp100", ::linkproof::Tracked<::linkproof::MpFloat<100>>)  \
  X(Mp1000, "mp1000", ::linkproof::Tracked<::linkproof::MpFloat<1000>>)

namespace linkproof {

namespace arithmetic_detail {
template <class First, class... T>
struct DropFirst {
  using type = std::tuple<T...>;
};
#define LINKPROOF_ARITHMETIC_TYPE_ARGUMENT(enumerator, name, type) , type
}  // namespace arithmetic_detail

/// The scalar types of every arithmetic, in the enum's order.
using ArithmeticScalarTypes =
    typename arithmetic_detail::DropFirst<void LINKPROOF_FOR_EACH_ARITHMETIC(LINKPROOF_ARITHMETIC_TYPE_ARGUMENT)>::type;
#undef LINKPROOF_ARITHMETIC_TYPE_ARGUMENT

/// The scalar type of arithmetic `a`.
template <Arithmetic a>
using ScalarTypeOf = std::tuple_element_t<static_cast<size_t>(a), ArithmeticScalarTypes>;

/// Calls f.template operator()<T>() with the scalar type T of arithmetic a.
template <class F>
decltype(auto) with_scalar_type(Arithmetic a, F&& f) {
  switch (a) {
#define LINKPROOF_ARITHMETIC_CASE(enumerator, name, type) \
  case Arithmetic::enumerator:                             \
    return f.template operator()<type>();
    LINKPROOF_FOR_EACH_ARITHMETIC(LINKPROOF_ARITHMETIC_CASE)
#undef LINKPROOF_ARITHMETIC_CASE
  }
  return f.template operator()<ScalarTypeOf<Arithmetic::Exact>>();  // not reached: every enumerator has its case
}

}  // namespace linkproof
