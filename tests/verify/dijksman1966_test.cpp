// The catalogue of Dijksman (1966) on the worked examples (conventions §A8) and on random polygons, and the
// comparator's ability to say "no": deliberately wrong formulas are fed through it.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "exit_status.h"
#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "check/random_polygon.h"
#include "io/claim_file.h"
#include "linkproof/io/scene.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

constexpr std::uint64_t kSeed = 20261121;

const ClaimOutcome& find_outcome(const PolygonCheck& c, const std::string& id) {
  for (const auto& o : c.claims)
    if (o.info.id == id) return o;
  throw std::runtime_error("claim not in check: " + id);
}

TEST(Dijksman1966, EveryTrueClaimHoldsExactlyOnWorkedExamples) {
  GroundTruthEngine engine;
  for (const auto& ex : {test::spec_pentagon(), test::spec_hexagon()}) {
    const auto check = check_polygon(engine, dijksman1966::catalogue(), "spec", ex.polygon, ex.rates, Arithmetic::Exact);
    for (const auto& c : check.claims) {
      if (c.info.expected == Expectation::Holds) {
        EXPECT_EQ(c.verdict, Verdict::Holds) << c.info.id << " n=" << check.n;
      }
    }
    EXPECT_EQ(cli::exit_status(check.claims), 0);
  }
}

TEST(Dijksman1966, PentagonEq22TermsAndMixedTermMatchConventionsA8) {
  GroundTruthEngine engine;
  const auto ex = test::spec_pentagon();
  const auto check = check_polygon(engine, dijksman1966::catalogue(), "p", ex.polygon, ex.rates, Arithmetic::Exact);
  const auto& eq22 = find_outcome(check, "dijksman1966.eq22");
  EXPECT_EQ(lhs_text(eq22.headline), "3755/1331");
  EXPECT_EQ(rhs_text(eq22.headline), "3755/1331");
  ASSERT_EQ(eq22.terms.size(), 5u);
  std::map<std::string, std::string> rhs;
  for (const auto& t : eq22.terms) rhs[t.label] = rhs_text(t);
  EXPECT_EQ(rhs["omega_dot[1]"], "6/11");
  EXPECT_EQ(rhs["omega[1]^2"], "-705/2662");
  EXPECT_EQ(rhs["omega_dot[2]"], "9/11");
  EXPECT_EQ(rhs["omega[2]^2"], "564/1331");
  EXPECT_EQ(rhs["omega[1]*omega[2]"], "-304/1331");
  EXPECT_EQ(lhs_text(find_outcome(check, "dijksman1966.eq21").headline), "608/1331");   // Delta omega-dot_{4,5}
  EXPECT_EQ(rhs_text(find_outcome(check, "dijksman1966.eq10").headline), "3147/1331");  // sum of four-bar parts
}

TEST(Dijksman1966, EveryErratumReadingFailsOnTheA8PentagonOrHexagon) {
  GroundTruthEngine engine;
  std::map<std::string, bool> failed;
  for (const auto& ex : {test::spec_pentagon(), test::spec_hexagon()}) {
    const auto check = check_polygon(engine, dijksman1966::catalogue(), "spec", ex.polygon, ex.rates, Arithmetic::Exact);
    for (const auto& c : check.claims)
      if (c.info.expected == Expectation::Fails) failed[c.info.id] |= c.verdict == Verdict::Fails;
  }
  for (const auto& claim : dijksman1966::catalogue()) {
    if (claim.info.expected != Expectation::Fails) continue;
    if (claim.info.id == "dijksman1966.eq4.unsigned_ratio") continue;  // all ratios positive in both examples
    EXPECT_TRUE(failed[claim.info.id]) << claim.info.id;
  }
}

// Random exact polygons, n = 4..12, three families, both numbering directions.
TEST(Dijksman1966, TrueClaimsHoldAndErrataFailOnRandomPolygons) {
  GroundTruthEngine engine;
  std::map<std::string, int> erratum_failures, holds;
  int clockwise = 0, counter = 0;
  for (int n = 4; n <= 12; ++n) {
    for (int i = 0; i < 24; ++i) {
      const auto rc = generate_random_polygon(kSeed, n, i);
      (rc.clockwise_numbering ? clockwise : counter)++;
      const auto check = check_polygon(engine, dijksman1966::catalogue(), "r", rc.polygon, rc.rates, Arithmetic::Exact);
      for (const auto& c : check.claims) {
        ASSERT_NE(c.verdict, Verdict::Error) << c.info.id << ": " << c.error;
        if (c.info.expected == Expectation::Holds) {
          ASSERT_NE(c.verdict, Verdict::Fails) << c.info.id << " replay: linkproof sweep --seed " << kSeed << " --n " << n
                                               << " --index " << i;
          holds[c.info.id] += c.verdict == Verdict::Holds;
        } else {
          erratum_failures[c.info.id] += c.verdict == Verdict::Fails;
        }
      }
    }
  }
  EXPECT_GT(clockwise, 20);
  EXPECT_GT(counter, 20);
  for (const auto& claim : dijksman1966::catalogue()) {
    if (claim.info.expected == Expectation::Fails)
      EXPECT_GT(erratum_failures[claim.info.id], 0) << claim.info.id << " was never disproved";
    else
      EXPECT_GT(holds[claim.info.id], 0) << claim.info.id << " never held";
  }
}

// --- Must-fail: wrong formulas through the same comparator -----------------------------------
// verify/claims/wrong_variants.yaml: 24 deliberately wrong variants of (22), (18)-(21) and the
// companion (sign flips, swapped indices, a missing factor 2, wrong beta, dropped terms).

const ClaimFile& wrong_variants() {
  static const ClaimFile f = load_claim_file(std::string(LINKPROOF_SOURCE_DIR) + "/verify/claims/wrong_variants.yaml");
  return f;
}

std::string describe_draw(int n, int i, const InputRates<Rational>& r) {
  std::string s = "n " + std::to_string(n) + " index " + std::to_string(i) + " omega";
  for (const Rational& x : r.omega) s += " " + format_rational(x);
  s += " omega_dot";
  for (const Rational& x : r.omega_dot) s += " " + format_rational(x);
  return s;
}

/// Every wrong variant on random polygons (seed kSeed, n = 5..9, 6 draws each) in arithmetic T:
/// it must fail on every draw, and hold on none. There is no allowance: exact arithmetic has no
/// rounding to hide behind, so one wrong formula accepted on one draw is a bug of the comparator
/// (or a variant that is not wrong: fix the variant). Floating point may in addition be
/// inconclusive (skipped, like an undefined draw) but never holds either: its tolerance is a
/// rigorous bound. (An allowance of 20 % accepted used to stand here; no variant ever used it.)
template <class T>
void expect_wrong_variants_rejected(const char* arith) {
  GroundTruthEngine engine;
  ASSERT_GE(wrong_variants().claims.size(), 20u);
  for (const DataClaim& w : wrong_variants().claims) {
    const Claim claim = to_claim(w);
    int rejected = 0, cases = 0;
    std::string accepted_on;
    for (int n = std::max(5, w.info.min_n); n <= 9; ++n) {
      for (int i = 0; i < 6; ++i) {
        const auto rc = generate_random_polygon(kSeed, n, i);
        const auto ctx = build_polygon_context<T>(engine, rc.polygon, rc.rates);
        const ClaimOutcome o = run_claim(claim, ctx);
        if (o.verdict == Verdict::Undefined || o.verdict == Verdict::Inconclusive) continue;  // degenerate draw
        ++cases;
        rejected += o.verdict == Verdict::Fails;
        if (o.verdict != Verdict::Fails)
          accepted_on += "\n  " + std::string(to_string(o.verdict)) + " on " + describe_draw(n, i, rc.rates);
      }
    }
    EXPECT_GT(cases, 12) << arith << ": " << w.info.id;
    EXPECT_EQ(rejected, cases) << arith << ": " << w.info.id << " rejected in " << rejected << "/" << cases
                               << accepted_on;
  }
}

TEST(Dijksman1966MustFail, WrongFormulasAreRejectedInExactArithmetic) {
  expect_wrong_variants_rejected<ScalarTypeOf<Arithmetic::Exact>>("exact");
}

TEST(Dijksman1966MustFail, WrongFormulasAreRejectedInDouble) {
  expect_wrong_variants_rejected<Tracked<double>>("double");
}

TEST(Dijksman1966MustFail, WrongTermIsNamedNotJustTheTotal) {
  // Dropping the mixed term leaves omega-dot_j and omega_j^2 terms right and every
  // omega_j omega_l term wrong: the comparator must say which.
  GroundTruthEngine engine;
  const auto ex = test::spec_hexagon();
  const auto ctx = build_polygon_context<Rational>(engine, ex.polygon, ex.rates);
  const DataClaim* dropped = nullptr;
  for (const auto& c : wrong_variants().claims)
    if (c.info.id == "wrong.eq22.mixed_dropped") dropped = &c;
  ASSERT_NE(dropped, nullptr);
  const auto sides = evaluate_data_claim(*dropped, ctx);
  int pair_terms = 0;
  for (const auto& t : sides.terms) {
    const Verdict v = judge(t).verdict;
    if (t.full_label().find("omega[") != t.full_label().rfind("omega[")) {
      ++pair_terms;
      EXPECT_EQ(v, Verdict::Fails) << t.full_label();
    } else {
      EXPECT_EQ(v, Verdict::Holds) << t.full_label();
    }
  }
  EXPECT_EQ(pair_terms, 3);  // omega_1 omega_2, omega_1 omega_3, omega_2 omega_3
}

TEST(Dijksman1966MustFail, WrongFormulasAreRejectedInMp30) {
  expect_wrong_variants_rejected<Tracked<MpFloat<30>>>("mp30");
}

// The bundled pentagon (conventions §A8) in CLN long floats with running error bounds: every verdict is
// the exact one. All 17 true claims hold; every erratum reading fails except
// eq4.unsigned_ratio, which coincides with the truth where all ratios are positive (as exactly).
TEST(Dijksman1966Mp, PentagonVerdictsInMp30AndMp1000AreTheExactOnes) {
  GroundTruthEngine engine;
  const PolygonScene s = load_polygon_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/pentagon.yaml");
  const auto exact = check_polygon(engine, dijksman1966::catalogue(), s.name, s.polygon, s.rates, Arithmetic::Exact);
  for (const auto& [arith, bits] : {std::pair{Arithmetic::Mp30, "2^-128"}, std::pair{Arithmetic::Mp1000, "2^-3392"}}) {
    SCOPED_TRACE(std::string(to_string(arith)));
    const auto check = check_polygon(engine, dijksman1966::catalogue(), s.name, s.polygon, s.rates, arith);
    ASSERT_EQ(check.claims.size(), exact.claims.size());
    int true_claims_holding = 0, errata_failing = 0;
    for (size_t k = 0; k < check.claims.size(); ++k) {
      const ClaimOutcome& c = check.claims[k];
      EXPECT_EQ(c.verdict, exact.claims[k].verdict) << c.info.id;
      if (c.info.expected == Expectation::Holds) true_claims_holding += c.verdict == Verdict::Holds;
      if (c.info.expected == Expectation::Fails) {
        errata_failing += c.verdict == Verdict::Fails;
        if (c.info.id != "dijksman1966.eq4.unsigned_ratio") {
          EXPECT_EQ(c.verdict, Verdict::Fails) << c.info.id;
        }
      }
      EXPECT_NE(tolerance_derivation_text(c.headline).find(std::string("u = ") + bits), std::string::npos) << c.info.id;
    }
    EXPECT_EQ(true_claims_holding, 17);
    EXPECT_EQ(errata_failing, 12);
    EXPECT_EQ(cli::exit_status(check.claims), 0);
  }
}

TEST(Dijksman1966Double, TrueClaimsNeverFailAndMostHoldInDouble) {
  GroundTruthEngine engine;
  int holds = 0, total = 0;
  for (int n = 4; n <= 12; ++n) {
    for (int i = 0; i < 10; ++i) {
      const auto rc = generate_random_polygon(kSeed, n, i);
      const auto check = check_polygon(engine, dijksman1966::catalogue(), "r", rc.polygon, rc.rates, Arithmetic::Double);
      for (const auto& c : check.claims) {
        if (c.info.expected != Expectation::Holds) continue;
        ASSERT_NE(c.verdict, Verdict::Fails) << c.info.id << " n " << n << " i " << i << ": " << lhs_text(c.headline) << " vs "
                                             << rhs_text(c.headline) << " tol " << tolerance_text(c.headline);
        ++total;
        holds += c.verdict == Verdict::Holds;
      }
    }
  }
  EXPECT_GE(holds, total * 95 / 100) << holds << "/" << total;
}

}  // namespace
}  // namespace linkproof
