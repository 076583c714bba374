// The word gcds (core/word_gcd.h) against CLN's gcd, on random operands of every size pair from
// 0 to 128 bits (so every path: both above 2^64, one above and one below, both below, equal
// operands, powers of two and zero), with common factors planted so that the gcd is rarely 1.
#include <gtest/gtest.h>

#include <cln/integer.h>
#include <cln/integer_io.h>

#include <cstdint>
#include <random>

#include "core/word_gcd.h"

namespace linkproof {
namespace {

cln::cl_I wide_to_cln(WideWord x) {
  return cln::ash(cln::cl_I(static_cast<unsigned long long>(x >> 64)), 64) + cln::cl_I(static_cast<unsigned long long>(x));
}

// A number below 2^bits (0 for bits = 0).
WideWord draw_wide(std::mt19937_64& g, int bits) {
  const WideWord x = static_cast<WideWord>(g()) << 64 | g();
  return bits == 0 ? 0 : bits == 128 ? x : x & ((static_cast<WideWord>(1) << bits) - 1);
}

TEST(WordGcd, WideGcdIsClnsGcdAtEverySizePair) {
  std::mt19937_64 g(20261128);  // printed on failure through the operands
  int checked = 0;
  for (int bu = 0; bu <= 128; bu += 4)
    for (int bv = 0; bv <= 128; bv += 4)
      for (int trial = 0; trial < 12; ++trial) {
        WideWord u = draw_wide(g, bu), v = draw_wide(g, bv);
        // A planted common factor (odd, even or a power of two) where it keeps both in range.
        const WideWord f = trial % 3 == 0 ? draw_wide(g, 20) | 1 : trial % 3 == 1 ? static_cast<WideWord>(1) << (g() % 30) : 1;
        if (bu <= 96 && bv <= 96) {
          u *= f;
          v *= f;
        }
        if (trial == 11) v = u;  // equal operands
        const WideWord r = wide_gcd(u, v);
        ASSERT_EQ(wide_to_cln(r), cln::gcd(wide_to_cln(u), wide_to_cln(v))) << "u = " << wide_to_cln(u) << ", v = " << wide_to_cln(v);
        ++checked;
      }
  EXPECT_EQ(checked, 33 * 33 * 12);
}

TEST(WordGcd, WordGcdIsClnsGcdOnRandomAndExtremeWords) {
  std::mt19937_64 g(1128);
  const std::uint64_t extremes[] = {0, 1, 2, 3, UINT64_MAX, UINT64_MAX - 1, std::uint64_t{1} << 63, (std::uint64_t{1} << 63) - 1};
  for (std::uint64_t a : extremes)
    for (std::uint64_t b : extremes)
      ASSERT_EQ(cln::cl_I(static_cast<unsigned long long>(word_gcd(a, b))),
                cln::gcd(cln::cl_I(static_cast<unsigned long long>(a)), cln::cl_I(static_cast<unsigned long long>(b))))
          << a << " " << b;
  for (int trial = 0; trial < 20000; ++trial) {
    const int bits_a = 1 + static_cast<int>(g() % 64), bits_b = 1 + static_cast<int>(g() % 64);
    const std::uint64_t f = trial % 2 ? (g() & 0xfffff) | 1 : 1;
    const std::uint64_t a = (g() >> (64 - bits_a)) * (bits_a <= 40 ? f : 1), b = (g() >> (64 - bits_b)) * (bits_b <= 40 ? f : 1);
    ASSERT_EQ(cln::cl_I(static_cast<unsigned long long>(word_gcd(a, b))),
              cln::gcd(cln::cl_I(static_cast<unsigned long long>(a)), cln::cl_I(static_cast<unsigned long long>(b))))
        << a << " " << b;
  }
}

}  // namespace
}  // namespace linkproof
