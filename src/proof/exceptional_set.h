// The exceptional set of a symbolic proof: the factors of every divisor that the compared
// expressions contain, each named where it matches a degeneracy of conventions §A6. Private to src/proof.
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "claims/polygon_context.h"
#include "proof/prove.h"
#include "rational_normal.h"
#include "symbolic_polygon.h"

namespace linkproof::proof_detail {

/// Every divisor in the expressions as built, before any simplification: the bases of negative
/// powers, found by walking each expression once (shared subexpressions visited once). normal()
/// would cancel some of them (x/x = 1); that is why they are read off the unsimplified trees.
std::vector<GiNaC::ex> divisors_in(const std::vector<GiNaC::ex>& expressions);

/// Polynomials whose zero sets have a name (a degeneracy), in the proof's symbols.
using NamedDegeneracies = std::vector<std::pair<GiNaC::ex, std::string>>;

/// An irreducible factor of a divisor, and the name of the degeneracy it divides ("" if none).
struct NamedFactor {
  GiNaC::ex factor;
  std::string meaning;
};

/// The irreducible factors of the divisors' numerators (up to constants, each once). Each list of
/// named degeneracies, built only while some numerator still has an unnamed part, names the
/// factors it shares with them (found by exact division, so that only what is left is factored).
/// `all_meanings`: a factor that several degeneracies share is named by all of them ("; "),
/// else by the first.
std::vector<NamedFactor> divisor_factors(const std::vector<GiNaC::ex>& divisors,
                                         const std::vector<std::function<NamedDegeneracies()>>& named_lists,
                                         RationalNormalizer& normalizer, bool all_meanings = false);

/// The irreducible factors of the divisors' numerators (up to constants, each once), named with
/// the sides as `names` prints them. With `l_as_j` (the base of a proof for every n, where input
/// 2 stands for any l and input 1 for any j), a factor about input l is the same family as the
/// one about j: it is printed with l's symbols replaced by j's and kept once.
/// `normalizer` (that of the proof, whose memo holds the divisors already) gives the numerators;
/// a named degeneracy is factored only if it has a common factor (a gcd) with some numerator.
std::vector<ExceptionalSet> exceptional_sets(const PolygonContext<GiNaC::ex>& c, const std::vector<GiNaC::ex>& divisors,
                                             const SideNames& names, const GiNaC::exmap* l_as_j,
                                             RationalNormalizer& normalizer);

}  // namespace linkproof::proof_detail
