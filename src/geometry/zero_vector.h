// The zero test of a plane vector over any scalar type, symbolic ones included (private: it needs
// the scalar traits).
#pragma once

#include "core/scalar.h"
#include "linkproof/geometry/vec2.h"

namespace linkproof {

/// Both components zero. For symbolic coordinates one zero test of |a|^2 (zero over the reals
/// iff a = 0), so that a proof records "these two points coincide", not "one coordinate is 0".
template <class T> bool is_zero_vector(const Vec2<T>& a) {
  if constexpr (requires { ScalarTraits<T>::is_symbolic; })
    return linkproof::is_zero(a.x * a.x + a.y * a.y);
  else
    return linkproof::is_zero(a.x) && linkproof::is_zero(a.y);
}

}  // namespace linkproof
