// A quick, one-sided zero test for expressions: their value modulo a prime at a fixed
// pseudo-random point.
//
// A symbolic zero test (normal(), proof/rational_normal.h) is what decides "identically zero";
// it costs gcds of large polynomials. Most expressions tested are not zero, and a single point
// shows it: if every denominator of e is non-zero at the point a (mod p), then e is defined at
// a over the rationals and e(a) mod p is its value reduced mod p; a non-zero residue means
// e(a) != 0, so e is not identically zero. The converse does not hold (e may vanish at a, or a
// denominator may vanish mod p): then the point says nothing and the symbolic test decides.
// So the point can only reject a zero claim, never confirm one (the soundness rule of proofs).
//
// p = 2^61 - 1 (a Mersenne prime: reduction by shifts); a symbol's coordinate is a hash of its
// name and the seed, the same in every run. Expressions are walked as DAGs (each shared node
// once, by address). Numbers are reduced mod p (a denominator divisible by p: no value).
// Functions other than +, *, integer powers: no value.
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>

namespace linkproof {

class ModularPoint {
 public:
  static constexpr std::uint64_t kPrime = (std::uint64_t{1} << 61) - 1;

  explicit ModularPoint(std::uint64_t seed = 0x9e3779b97f4a7c15ULL) : seed_(seed) {}

  /// e(a) mod p, or nullopt where the point says nothing (a denominator vanishes mod p, or e is
  /// not built from rational numbers, symbols, +, * and integer powers).
  std::optional<std::uint64_t> value(const GiNaC::ex& e);

  /// True only if e is certainly not identically zero (its value at the point is defined and
  /// non-zero). False means "unknown", not "zero".
  bool shows_nonzero(const GiNaC::ex& e) {
    const auto v = value(e);
    return v && *v != 0;
  }

 private:
  std::optional<std::uint64_t> compute(const GiNaC::ex& e);
  std::uint64_t seed_;
  // By address; the expression is held so that the address cannot be reused (op() of a sum
  // builds its terms afresh).
  std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, std::optional<std::uint64_t>>> memo_;
};

}  // namespace linkproof
