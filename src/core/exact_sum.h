// The sum of many exact numbers, added in a balanced tree.
//
// Why: an exact rational sum grows: a sum of terms with different denominators has a
// denominator that is (up to cancellation) the lcm of theirs, and every addition costs time in
// the size of its operands (cross products and the gcd that reduces the result). Added one
// after the other, each of N terms meets the whole partial sum: O(N * size of the total). In a
// balanced tree each addition meets partial sums of its own subtree only: O(size * log N) per
// level. A rate polynomial's value at n = 1000 (500,000 terms omega_j omega_l, each rate with
// its own denominator) spent a quarter of an exact check adding to one growing sum.
//
// Exact types only: the value of an exact sum does not depend on the order of its terms, so
// every result and its text stay the same; a floating-point sum's rounding does, and its order
// is kept (its results are compared byte for byte).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "core/scalar.h"

namespace linkproof {

/// Whether a scalar type adds exactly with values that grow (rationals; not a symbolic
/// expression, whose sums GiNaC keeps as one flat node anyway).
template <class T>
concept GrowingExactNumber = ScalarTraits<T>::is_exact && !requires { ScalarTraits<T>::is_symbolic; };

/// The sum of terms[0..size) in a balanced tree: pairs of neighbours, then pairs of those. The
/// terms are overwritten (their storage is the tree's), so a caller may reuse the vector.
template <GrowingExactNumber T>
T balanced_sum(std::vector<T>& terms) {
  if (terms.empty()) return from_int<T>(0);
  for (size_t width = terms.size(); width > 1;) {
    const size_t half = width / 2;
    for (size_t i = 0; i < half; ++i) terms[i] = terms[2 * i] + terms[2 * i + 1];
    if (width % 2 != 0) terms[half] = std::move(terms[width - 1]);
    width = half + width % 2;
  }
  return std::move(terms[0]);
}

}  // namespace linkproof
