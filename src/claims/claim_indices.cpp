#include "claims/claim_indices.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "claims/vocabulary.h"
#include "linkproof/core/error.h"

namespace linkproof {

namespace {

constexpr long kMaxIndexCoefficient = 1000000;

/// The (j, l) values at which an affine index takes its extremes, at n sides (l = 0: unused).
std::vector<std::pair<int, int>> vertices(IndexBinding b, int n) {
  const int m = n - 3;  // inputs
  std::vector<std::pair<int, int>> v;
  switch (b) {
    case IndexBinding::None: v = {{0, 0}}; break;
    case IndexBinding::ForEachJ:
    case IndexBinding::SumJ: v = {{1, 0}, {m, 0}}; break;
    case IndexBinding::SumPairsLt: v = {{1, 2}, {1, m}, {m - 1, m}}; break;
    case IndexBinding::SumPairs: v = {{1, 2}, {1, m}, {m - 1, m}, {2, 1}, {m, 1}, {m, m - 1}}; break;
  }
  return v;
}

/// The first n at which the use is read at all: a pair sum has no terms below n = 5.
int first_n_read(IndexBinding b, int min_n) {
  return b == IndexBinding::SumPairs || b == IndexBinding::SumPairsLt ? std::max(min_n, 5) : min_n;
}

struct Bounds {
  long low_margin, high_margin;  // k - 1 and (n-3 or n) - k: both >= 0 when in range
};

}  // namespace

void check_claim_indices(const ClaimExpression& e, int min_n, int max_n) {
  using claim_atoms::index_symbol;
  const GiNaC::symbol &n_sym = index_symbol(Evaluation::IndexN), &j_sym = index_symbol(Evaluation::IndexJ),
                      &l_sym = index_symbol(Evaluation::IndexL);
  for (const IndexUse& u : e.index_uses()) {
    const std::string written = u.word + "[" + u.index_text + "]";
    const auto refuse = [&](const std::string& problem) { throw InputError(u.where, e.field(), problem); };
    // Affine with integer coefficients: every first derivative is an integer constant.
    const GiNaC::ex k = GiNaC::expand(u.index);
    for (const GiNaC::symbol* s : {&n_sym, &j_sym, &l_sym}) {
      const GiNaC::ex d = k.diff(*s);
      if (!GiNaC::is_exactly_a<GiNaC::numeric>(d) || !GiNaC::ex_to<GiNaC::numeric>(d).is_integer())
        refuse("the index of " + written + " must be an integer affine function of n, j and l (such as j, n-1, 2)");
    }
    const GiNaC::ex k0 = k.subs(GiNaC::lst{n_sym == 0, j_sym == 0, l_sym == 0});
    if (!GiNaC::is_exactly_a<GiNaC::numeric>(k0) || !GiNaC::ex_to<GiNaC::numeric>(k0).is_integer())
      refuse("the index of " + written + " must be an integer affine function of n, j and l (such as j, n-1, 2)");
    // Every coefficient a small integer: read as a machine integer below (to_long), a larger one
    // would wrap (2^64 + 1 read as 1) and name another side.
    for (const GiNaC::ex& c : {k0, k.diff(n_sym), k.diff(j_sym), k.diff(l_sym)})
      if (GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(c)) > kMaxIndexCoefficient)
        refuse("the index of " + written + " has a coefficient beyond " + std::to_string(kMaxIndexCoefficient) +
               " in magnitude; no polygon has that many sides (docs/limits.md)");
    const std::string range = u.input_index ? "1..n-3 (an input)" : "1..n (a side or joint)";
    const auto bounds_at = [&](int n, std::pair<int, int> jl) {
      const GiNaC::ex v = k.subs(GiNaC::lst{n_sym == n, j_sym == jl.first, l_sym == jl.second});
      const long value = GiNaC::ex_to<GiNaC::numeric>(v).to_long();
      return std::pair<long, Bounds>{value, Bounds{value - 1, (u.input_index ? n - 3 : n) - value}};
    };
    const auto where_in_sum = [&](std::pair<int, int> jl) {
      std::string s;
      if (jl.first) s += ", j = " + std::to_string(jl.first);
      if (jl.second) s += ", l = " + std::to_string(jl.second);
      return s;
    };
    const int lo = first_n_read(u.binding, min_n);
    const int last_checked = max_n == 0 ? std::max(lo, 7) : max_n;
    for (int n = lo; n <= last_checked; ++n)
      for (const auto& jl : vertices(u.binding, n)) {
        const auto [value, b] = bounds_at(n, jl);
        if (b.low_margin < 0 || b.high_margin < 0)
          refuse(written + " is " + u.word + "[" + std::to_string(value) + "] at n = " + std::to_string(n) +
                 where_in_sum(jl) + ", outside " + range + "; the claim's range is n = " + std::to_string(min_n) +
                 (max_n == 0 ? ".." : ".." + std::to_string(max_n)) + " (state `n:` to narrow it)");
      }
    if (max_n != 0 || last_checked < 7) continue;
    // Unbounded: the margins are affine in n at each vertex from n = 6 on; none may decrease.
    const auto at7 = vertices(u.binding, 7), at8 = vertices(u.binding, 8);
    for (size_t v = 0; v < at7.size(); ++v) {
      const Bounds b7 = bounds_at(7, at7[v]).second, b8 = bounds_at(8, at8[v]).second;
      if (b8.low_margin < b7.low_margin || b8.high_margin < b7.high_margin)
        refuse(written + " leaves " + range + " for large n" + where_in_sum(at8[v]) +
               "; the claim's range has no upper bound (state `n:` to bound it)");
    }
  }
}

}  // namespace linkproof
