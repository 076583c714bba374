// LaTeX of a GiNaC expression that is the same in every run.
//
// GiNaC orders the operands of sums and products by hash values seeded with addresses (ASLR
// moves them: symbolic/canonical_order.h), so its own LaTeX printer writes the same expression
// differently from one run to the next. Reports must be the same bytes in every run, so they
// print through this: the operands of sums and products in the order of their canonical text
// (CanonicalOrder::text), a numeric factor first, factors with negative exponents as a \frac.
#pragma once

#include <ginac/ginac.h>

#include <string>

namespace linkproof::report {

std::string canonical_latex(const GiNaC::ex& e);

}  // namespace linkproof::report
