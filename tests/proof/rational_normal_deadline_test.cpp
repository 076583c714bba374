// The time budget of a symbolic normal form (proof/rational_normal.h) holds while the work is
// combining parts already normalized. A proof over the Dijksman (1984) eight-bar spent 1012 s on
// one claim of a 60 s budget: its expressions repeat the same meets and poles, every part was
// memoized, and the deadline was looked at only when a part was not, so a long sum of memoized
// parts ran to the end.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "proof/rational_normal.h"

namespace linkproof::proof_detail {
namespace {

using Clock = std::chrono::steady_clock;

TEST(RationalNormalDeadline, ASumOfMemoizedPartsStopsAtTheDeadline) {
  // 1/(x1 + 1) + ... + 1/(x13 + 1): its common denominator has 2^13 terms, well past any
  // few-millisecond budget, while each part is normalized in microseconds and memoized first.
  RationalNormalizer n(false);
  GiNaC::ex sum = 0;
  for (int i = 1; i <= 13; ++i) {
    const GiNaC::ex part = 1 / (GiNaC::symbol("x" + std::to_string(i)) + 1);
    n.normal(part);
    sum += part;
  }
  const auto start = Clock::now();
  n.set_deadline(start + std::chrono::milliseconds(5));
  EXPECT_THROW(n.normal(sum), NormalizerOutOfTime);
  // Stopped at the first combination past the deadline, not at the end of the sum.
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 0.5);
}

}  // namespace
}  // namespace linkproof::proof_detail
