// An order of the operands of GiNaC sums and products that does not depend on the run.
//
// GiNaC keeps the operands of a sum or product sorted by hash values that are seeded with
// addresses (type-info pointers, so ASLR moves them), so a floating-point evaluation that adds
// or multiplies in GiNaC's order gives different roundings, and different error bounds, in two
// runs of the same program. Evaluators that must give the same bytes in every run (the Tape,
// the claim evaluator) visit the operands in the order given here instead:
//
//   key(e)     a 64-bit key of the structure of e: symbols by name, numbers by value, the
//              operands of sums and products as a multiset (their GiNaC order does not enter),
//              the operands of anything else in order; memoised per distinct subexpression.
//   order(e)   the operand indices of e sorted by key; equal keys (a hash collision, or
//              distinct symbols of the same name) are ordered by text(), the full canonical text.
//
// Equal expressions get equal keys in every run. Not thread-safe (GiNaC is not).
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace linkproof {

class CanonicalOrder {
 public:
  /// The key of e (see above).
  std::uint64_t key(const GiNaC::ex& e);
  /// The operand indices 0..e.nops()-1 sorted by key, then by text.
  std::vector<size_t> order(const GiNaC::ex& e);
  /// A text of e that does not depend on GiNaC's order of operands: sums and products list their
  /// operands' texts sorted. Size O(tree size): used only to break ties of key().
  static std::string text(const GiNaC::ex& e);

 private:
  std::unordered_map<GiNaC::ex, std::uint64_t, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> keys_;
};

}  // namespace linkproof
