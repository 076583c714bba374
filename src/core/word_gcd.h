// Greatest common divisors of machine words (64 and 128 bits): what InlineRational reduces its
// word values with, without going to CLN.
//
// Why not Stein's plain binary gcd: it was 18 % of an exact pentagon check (perf, 2026-11-28),
// in two loops whose every step waits on the step before (trailing zeros, shift, compare,
// subtract). Here:
// - 64 bits: the binary gcd in the form that takes the trailing zeros of the difference before
//   the difference's absolute value is chosen, so that the two proceed in parallel (the
//   "branchless binary gcd", e.g. Algorithmica's "Binary GCD"), about twice as fast;
// - 128 bits: Stein's steps only while both operands are above 2^64; once one of them fits in a
//   word, one Euclidean remainder (128 by 64 bits) brings the other below it, and the rest is
//   the 64-bit gcd. Most operands here are products of two words whose other part fits, so the
//   remainder usually comes at once, in place of some 45 steps on two words.
// WordGcd.* compares both with CLN's gcd on random operands of every size.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

namespace linkproof {

// GCC's 128-bit unsigned integers (__extension__: -Wpedantic knows they are not ISO C++).
__extension__ typedef unsigned __int128 WideWord;

/// gcd(u, v) of two 64-bit words; gcd(0, v) = v.
inline std::uint64_t word_gcd(std::uint64_t u, std::uint64_t v) {
  if (u == 0) return v;
  if (v == 0) return u;
  int u_zeros = std::countr_zero(u);
  const int shift = std::min(u_zeros, std::countr_zero(v));
  v >>= std::countr_zero(v);
  // Invariant: v odd, u != 0 with u_zeros its trailing zeros; gcd unchanged by each step.
  while (u != 0) {
    u >>= u_zeros;
    const std::uint64_t difference = v - u;  // modulo 2^64: as many trailing zeros as |v - u|
    // |v - u| as -difference where v < u, by a mask and not a branch (which GCC emits for
    // `u > v ? u - v : v - u`, and which mispredicts at random).
    const std::uint64_t negate = 0 - static_cast<std::uint64_t>(v < u);
    u_zeros = std::countr_zero(difference);  // 64 for u = v, where the loop ends
    v = std::min(u, v);
    u = (difference ^ negate) - negate;
  }
  return v << shift;
}

/// gcd(u, v) of two 128-bit words; gcd(0, v) = v.
inline WideWord wide_gcd(WideWord u, WideWord v) {
  const auto trailing_zeros = [](WideWord x) {  // x != 0
    const auto low = static_cast<std::uint64_t>(x);
    return low != 0 ? std::countr_zero(low) : 64 + std::countr_zero(static_cast<std::uint64_t>(x >> 64));
  };
  if (u == 0) return v;
  if (v == 0) return u;
  const int shift = trailing_zeros(u | v);
  u >>= trailing_zeros(u);
  v >>= trailing_zeros(v);
  // Both odd. Stein's steps while both are above 2^64.
  while (u >> 64 != 0 && v >> 64 != 0) {
    if (u == v) return u << shift;
    if (u < v) std::swap(u, v);
    u -= v;  // even and nonzero
    u >>= trailing_zeros(u);
  }
  if (u < v) std::swap(u, v);  // v < 2^64
  const auto w = static_cast<std::uint64_t>(v);
  const auto r = static_cast<std::uint64_t>(u >> 64 == 0 ? u : u % w);  // Euclid's step when u is wide
  return static_cast<WideWord>(word_gcd(r, w)) << shift;
}

}  // namespace linkproof
