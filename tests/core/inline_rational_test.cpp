// InlineRational (the exact arithmetic's scalar) against CLN's rationals: every operation on
// random operands of every size, from a few bits to past the word boundary, gives cl_RA's value,
// and the representation is the word form exactly when the value fits.
#include <gtest/gtest.h>

#include <cln/integer.h>
#include <cln/integer_io.h>
#include <cln/rational_io.h>

#include <cstdint>
#include <random>
#include <sstream>
#include <vector>

#include "core/inline_rational.h"

namespace linkproof {
namespace {

constexpr std::int64_t kMax = INT64_MAX;

// True where the value's reduced numerator and denominator both lie in [-(2^63-1), 2^63-1].
bool fits_words(const Rational& q) {
  const cln::cl_I lim(static_cast<long>(kMax));
  return cln::abs(cln::numerator(q)) <= lim && cln::denominator(q) <= lim;
}

// An integer of about `bits` bits (at least 1), either sign, sometimes exactly at a word limit.
cln::cl_I draw_integer(std::mt19937_64& g, int bits) {
  switch (g() % 16) {
    case 0: return cln::cl_I(static_cast<long>(kMax));
    case 1: return cln::cl_I(static_cast<long>(kMax)) + 1;  // 2^63: one past the word form
    case 2: return -cln::cl_I(static_cast<long>(kMax)) - 1;  // -2^63
    default: break;
  }
  cln::cl_I x = 0;
  for (int b = 0; b < bits; b += 32) x = x * cln::cl_I(4294967296L) + cln::cl_I(static_cast<long>(g() & 0xffffffffu));
  x = cln::ldb(x, cln::cl_byte(static_cast<uintC>(std::max(bits, 1)), 0));
  return g() % 2 ? -x : x;
}

Rational draw_rational(std::mt19937_64& g) {
  static constexpr int kBits[] = {1, 3, 8, 20, 31, 32, 33, 48, 61, 62, 63, 64, 65, 90, 130};
  const int nb = kBits[g() % std::size(kBits)], db = kBits[g() % std::size(kBits)];
  cln::cl_I d = cln::abs(draw_integer(g, db));
  if (cln::zerop(d)) d = 1;
  return Rational(draw_integer(g, nb)) / d;
}

void expect_same(const InlineRational& x, const Rational& expected, const char* op, const Rational& a, const Rational& b) {
  ASSERT_EQ(x.to_rational(), expected) << op << " of " << a << " and " << b;
  ASSERT_EQ(x.is_word(), fits_words(expected)) << op << " of " << a << " and " << b << " = " << expected;
}

TEST(InlineRationalOps, EveryOperationGivesCLNsValueOnRandomOperandsOfEverySize) {
  constexpr std::uint64_t kSeed = 20261128;
  std::printf("InlineRationalOps seed %llu\n", static_cast<unsigned long long>(kSeed));
  std::mt19937_64 g(kSeed);
  int words = 0;
  constexpr int kCases = 100000;
  for (int k = 0; k < kCases; ++k) {
    const Rational a = draw_rational(g), b = draw_rational(g);
    const InlineRational x(a), y(b);
    expect_same(x, a, "conversion", a, b);
    words += x.is_word() && y.is_word();
    expect_same(x + y, a + b, "sum", a, b);
    expect_same(x - y, a - b, "difference", a, b);
    expect_same(x * y, a * b, "product", a, b);
    if (!cln::zerop(b)) expect_same(x / y, a / b, "quotient", a, b);
    expect_same(-x, -a, "negation", a, b);
    expect_same(ScalarTraits<InlineRational>::abs(x), cln::abs(a), "abs", a, b);
    ASSERT_EQ(x == y, a == b) << a << " == " << b;
    ASSERT_EQ(x < y, a < b) << a << " < " << b;
    ASSERT_EQ(x.sign(), cln::minusp(a) ? -1 : cln::zerop(a) ? 0 : 1) << a;
    ASSERT_EQ(to_text(x), format_rational(a));
  }
  // Both routes were exercised: most pairs are words, many are not.
  EXPECT_GT(words, kCases / 4);
  EXPECT_LT(words, kCases * 3 / 4);
}

TEST(InlineRationalOps, TheWordFormEndsExactlyAtTheWordLimits) {
  const Rational max(cln::cl_I(static_cast<long>(kMax)));
  EXPECT_TRUE(InlineRational(max).is_word());
  EXPECT_TRUE(InlineRational(-max).is_word());
  EXPECT_TRUE(InlineRational(1 / max).is_word());
  EXPECT_FALSE(InlineRational(max + 1).is_word());
  EXPECT_FALSE(InlineRational(-max - 1).is_word());
  EXPECT_FALSE(InlineRational(std::int64_t{INT64_MIN}).is_word());
  EXPECT_FALSE(InlineRational(1 / (max + 1)).is_word());
  // A sum that leaves the words, and a product that comes back into them.
  const InlineRational past = InlineRational(kMax) + InlineRational(std::int64_t{1});
  EXPECT_FALSE(past.is_word());
  EXPECT_EQ(past.to_rational(), max + 1);
  const InlineRational back = past / InlineRational(std::int64_t{2});
  EXPECT_TRUE(back.is_word());
  EXPECT_EQ(back, InlineRational(std::int64_t{1} << 62));
  // Sums that cancel to zero are the word 0/1 (equal to every other zero).
  EXPECT_EQ(InlineRational(Rational(1) / 6) - InlineRational(Rational(1) / 6), InlineRational());
  EXPECT_EQ(InlineRational(Rational(1) / 6) + InlineRational(Rational(-2) / 12), InlineRational());
  EXPECT_EQ(InlineRational(Rational(1) / 4) - InlineRational(Rational(1) / 4), InlineRational(std::int64_t{0}));
}

// A word result that does not fit even reduced becomes a CLN value built from its reduced
// 128-bit parts: it must be CLN's own canonical value (an integer where the denominator is 1,
// a reduced ratio otherwise), or cl_RA's equality and text would differ from CLN's.
TEST(InlineRationalOps, ResultsPastTheWordsAreCLNsCanonicalValues) {
  const Rational two64 = cln::expt_pos(cln::cl_I(2), 64);
  const InlineRational product = InlineRational(std::int64_t{1} << 62) * InlineRational(std::int64_t{4});
  ASSERT_FALSE(product.is_word());
  EXPECT_TRUE(cln::equal(product.to_rational(), two64));
  EXPECT_EQ(cln::denominator(product.to_rational()), 1);
  // (2^62 / 3) * (6 / 5) = 2^63 / 5: reduced by the 128-bit gcd, numerator past the words.
  const InlineRational q = InlineRational(Rational(std::int64_t{1} << 62) / 3) * InlineRational(Rational(6) / 5);
  ASSERT_FALSE(q.is_word());
  EXPECT_TRUE(cln::equal(q.to_rational(), Rational(cln::expt_pos(cln::cl_I(2), 63)) / 5));
  EXPECT_EQ(cln::denominator(q.to_rational()), 5);
  // A sum past the words, with a denominator: (2^63 - 1)/7 + 1/7 = 2^63 / 7.
  const Rational max(cln::cl_I(static_cast<long>(kMax)));
  const InlineRational s = InlineRational(max / 7) + InlineRational(Rational(1) / 7);
  ASSERT_FALSE(s.is_word());
  EXPECT_TRUE(cln::equal(s.to_rational(), (max + 1) / 7));
  EXPECT_EQ(s.to_rational() - (max + 1) / 7, 0);
}

// A word value is kept unreduced (6/12); read as a CLN rational it is reduced by the word gcd
// and built from its coprime parts: CLN's canonical value, an integer where the reduced
// denominator is 1.
TEST(InlineRationalOps, UnreducedWordValuesReadAsCLNsCanonicalValues) {
  auto word = [](long n, long d) { return InlineRational(Rational(n) / d); };
  const InlineRational half = word(2, 3) * word(3, 4), minus_half = word(-2, 3) * word(3, 4);
  const InlineRational one = word(3, 4) * word(4, 3), zero = word(0, 1) * word(3, 4);
  for (const InlineRational* x : {&half, &minus_half, &one, &zero}) ASSERT_TRUE(x->is_word());
  EXPECT_TRUE(cln::equal(half.to_rational(), Rational(1) / 2));
  EXPECT_EQ(cln::denominator(half.to_rational()), 2);
  EXPECT_EQ(cln::numerator(minus_half.to_rational()), -1);
  EXPECT_EQ(cln::denominator(minus_half.to_rational()), 2);
  EXPECT_TRUE(cln::equal(one.to_rational(), Rational(1)));
  EXPECT_EQ(cln::denominator(one.to_rational()), 1);
  EXPECT_TRUE(cln::zerop(zero.to_rational()));
  std::ostringstream text;
  text << half.to_rational() << " " << one.to_rational() << " " << minus_half.to_rational();
  EXPECT_EQ(text.str(), "1/2 1 -1/2");
  // The largest parts: (2^63 - 1) / (2^63 - 1) is 1, and their product with 2/2 is too.
  const Rational max(cln::cl_I(static_cast<long>(kMax)));
  EXPECT_EQ(cln::denominator((InlineRational(max) / InlineRational(max)).to_rational()), 1);
}

TEST(InlineRationalOps, DivisionByZeroThrowsWhatCLNThrows) {
  EXPECT_THROW(Rational(1) / Rational(0), cln::division_by_0_exception);
  EXPECT_THROW(InlineRational(std::int64_t{1}) / InlineRational(), cln::division_by_0_exception);
  EXPECT_THROW(InlineRational(cln::expt_pos(cln::cl_I(2), 100)) / InlineRational(), cln::division_by_0_exception);
}

TEST(InlineRationalOps, SmallIntegersAndFractionsConvertWithoutCLN) {
  EXPECT_EQ(from_int<InlineRational>(-7).to_rational(), Rational(-7));
  EXPECT_TRUE(from_int<InlineRational>(-7).is_word());
  EXPECT_EQ(from_fraction<InlineRational>(6, 4).to_rational(), Rational(3) / 2);
  EXPECT_EQ(from_fraction<InlineRational>(-9, 12).to_rational(), Rational(-3) / 4);
}

}  // namespace
}  // namespace linkproof
