// The scalar type of each arithmetic (private: the types are the library's own).
#pragma once

#include "linkproof/check/arithmetic.h"
#include "core/multiprecision.h"
#include "core/scalar.h"

namespace linkproof {
template <class F>
decltype(auto) with_scalar_type(Arithmetic a, F&& f) {
  switch (a) {
    case Arithmetic::Double: return f.template operator()<Tracked<double>>();
    case Arithmetic::LongDouble: return f.template operator()<Tracked<long double>>();
    case Arithmetic::Mp30: return f.template operator()<Tracked<MpFloat<30>>>();
    case Arithmetic::Mp50: return f.template operator()<Tracked<MpFloat<50>>>();
    case Arithmetic::Mp100: return f.template operator()<Tracked<MpFloat<100>>>();
    case Arithmetic::Mp1000: return f.template operator()<Tracked<MpFloat<1000>>>();
    case Arithmetic::Exact: break;
  }
  return f.template operator()<Rational>();
}
}  // namespace linkproof
