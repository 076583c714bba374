// Index checks of a claim against its range of n, when the claim is read: every indexed word
// (omega[j], r[n-1], K[2], ...) must name an input (1..n-3) or a side (1..n) for every n of the
// claim's range and every value its sums give j and l. A claim that would read outside its
// polygon at some n is refused at load time, naming FILE:LINE:COLUMN of the word, instead of
// failing (or being "disproved") later at that n.
//
// How "every n" is covered: an index must be an integer affine function of n, j, l. Over the
// values a sum gives j (1..n-3) or (j, l) (j != l, or j < l), an affine function takes its
// extremes at the vertices of that polytope ((1, 2), (1, n-3), (n-4, n-3), and mirrored), which
// are themselves affine in n from n = 6 on. So each bound (k >= 1, k <= n-3 or n) is an affine
// function of n at each vertex: checked exactly for every n from the claim's first to 7, and for
// an unbounded range also its slope (value at 8 minus value at 7 >= 0), which covers all n >= 7.
#pragma once

#include "claims/claim_expression.h"

namespace linkproof {

/// Throws InputError(FILE:LINE:COLUMN, field, problem) for the first index of `e` that is not
/// an integer affine function of n, j, l, or that leaves its range at some n with
/// min_n <= n <= max_n (max_n = 0: no upper bound).
void check_claim_indices(const ClaimExpression& e, int min_n, int max_n);

}  // namespace linkproof
