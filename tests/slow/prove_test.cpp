// The prover: true claims proved for every n in symbolic coordinates, errata and deliberately
// wrong variants disproved by exact counterexamples that really fail when re-checked.
#include <gtest/gtest.h>

#include "dijksman1966.h"
#include "proof/prove.h"

namespace linkproof {
namespace {

const DataClaim& claim(const std::string& id) {
  for (const auto& c : dijksman1966::claim_file().claims)
    if (c.info.id == id) return c;
  throw std::runtime_error("no claim " + id);
}

ProveOptions quick() {
  ProveOptions o;
  o.ladder_seconds = 0;
  return o;
}

TEST(Prove, Eq22IsProvedForEveryNExceptWhereNamedDegeneraciesVanish) {
  GroundTruthEngine engine;
  const ProofResult r = prove_claim(engine, claim("dijksman1966.eq22"), quick());
  EXPECT_EQ(r.verdict, ProofVerdict::ProvedGenerically) << r.error;
  EXPECT_EQ(r.scope, "every n >= 4");
  EXPECT_TRUE(r.not_local.empty());
  bool dead_centre = false, q_infinity = false;
  for (const auto& e : r.except) {
    dead_centre = dead_centre || e.meaning.find("dead centre") != std::string::npos;
    q_infinity = q_infinity || e.meaning.find("Q_j at infinity") != std::string::npos;
    EXPECT_EQ(e.meaning.find("unnamed"), std::string::npos) << e.polynomial;
  }
  EXPECT_TRUE(dead_centre);
  EXPECT_TRUE(q_infinity);
}

TEST(Prove, EveryTrueClaimIsProvedAndEveryErratumDisproved) {
  GroundTruthEngine engine;
  for (const auto& c : dijksman1966::claim_file().claims) {
    SCOPED_TRACE(c.info.id);
    const ProofResult r = prove_claim(engine, c, quick());
    EXPECT_TRUE(r.is_as_expected()) << to_string(r.verdict) << " " << r.error;
    if (c.info.expected == Expectation::Fails) {
      ASSERT_TRUE(r.counterexample.has_value());
      // The counterexample really fails when re-checked exactly.
      const ClaimOutcome again = check_data_claim(engine, c, r.counterexample->polygon, r.counterexample->rates);
      EXPECT_EQ(again.verdict, Verdict::Fails);
    }
  }
}

TEST(Prove, PerNProofOfTheWholeIdentityAtN7) {
  GroundTruthEngine engine;
  const PerNProof p = prove_for_n(engine, claim("dijksman1966.companion"), 7);
  EXPECT_TRUE(p.proved) << p.first_nonzero;
  EXPECT_EQ(p.monomials, 14);  // 4 omega-dot_j, 4 omega_j^2, 6 pairs
  EXPECT_GT(p.tree_size, p.dag_size);
}

TEST(Prove, EveryWrongVariantIsDisprovedWithASmallCounterexample) {
  GroundTruthEngine engine;
  const ClaimFile f = load_claim_file(std::string(LINKPROOF_SOURCE_DIR) + "/verify/claims/wrong_variants.yaml");
  ASSERT_GE(f.claims.size(), 20u);
  for (const auto& c : f.claims) {
    SCOPED_TRACE(c.info.id);
    const ProofResult r = prove_claim(engine, c, quick());
    ASSERT_EQ(r.verdict, ProofVerdict::Disproved) << r.error;
    ASSERT_TRUE(r.counterexample.has_value());
    const auto& cx = *r.counterexample;
    EXPECT_LE(cx.polygon.n(), 6);
    for (int k = 1; k <= cx.polygon.n(); ++k) {
      EXPECT_TRUE(cln::denominator(cx.polygon.joint(k).x) == 1 && cln::abs(cx.polygon.joint(k).x) <= 10);
      EXPECT_TRUE(cln::denominator(cx.polygon.joint(k).y) == 1 && cln::abs(cx.polygon.joint(k).y) <= 10);
    }
    EXPECT_EQ(check_data_claim(engine, c, cx.polygon, cx.rates).verdict, Verdict::Fails);
  }
}

}  // namespace
}  // namespace linkproof
