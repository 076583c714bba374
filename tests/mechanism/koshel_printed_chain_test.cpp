// Koshel et al.'s printed arithmetic chain (conventions §C): every step consistent within its printed
// digits except (7), whose printed 52.9 is 0.225 below 25^2 * 0.085 = 53.125.
#include <gtest/gtest.h>

#include "mechanism_catalogues.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof {
namespace {

ClaimSides<Rational> evaluate(const MechanismClaim& c) {
  const MechanismScene scene;
  const MechanismSolution<Rational> truth;
  return c.evaluate(MechanismContext{scene, truth});
}

TEST(KoshelPrintedChain, EveryPrintedStepIsConsistentExceptSeven) {
  const auto claims = catalogues::koshel_printed_chain();
  ASSERT_EQ(claims.size(), 13u);  // (2), (3), (5), (7) corrected and printed, (8)-(10), (12), (14)-(17)
  for (const auto& c : claims) {
    const auto sides = evaluate(c);
    ASSERT_EQ(sides.instances.size(), 1u) << c.info.id;
    const auto& i = sides.instances[0];
    const bool equal = i.lhs.get() == i.rhs.get();
    if (c.info.id == "koshel.eq7.printed") {
      EXPECT_EQ(c.info.expected, Expectation::Fails);
      EXPECT_FALSE(equal);
      EXPECT_EQ(i.lhs.get() - i.rhs.get(), Rational(-9) / 40) << "52.9 - 53.125";
    } else {
      EXPECT_EQ(c.info.expected, Expectation::Holds) << c.info.id;
      EXPECT_TRUE(equal) << c.info.id << ": " << i.full_label();
    }
  }
}

TEST(KoshelPrintedChain, ToleranceIsHalfAUnitOfTheLastPrintedDigit) {
  for (const auto& c : catalogues::koshel_printed_chain()) {
    const std::string label = evaluate(c).instances[0].full_label();
    if (c.info.id == "koshel.eq3") {
      EXPECT_NE(label.find("(tolerance 1/2)"), std::string::npos) << label;
    } else if (c.info.id == "koshel.eq2") {
      EXPECT_NE(label.find("(tolerance 1/200)"), std::string::npos) << label;
    } else if (c.info.id == "koshel.eq17") {
      EXPECT_NE(label.find("(tolerance 1/20)"), std::string::npos) << label;
    }
  }
}

}  // namespace
}  // namespace linkproof
