// The catalogue of Dijksman (1966) on the SPEC examples and on random polygons, and the
// comparator's ability to say "no": deliberately wrong formulas are fed through it.
#include <gtest/gtest.h>

#include <map>

#include "dijksman1966.h"
#include "linkproof/eval/check.h"
#include "linkproof/eval/random_polygon.h"
#include "support/polygons.h"

namespace linkproof {
namespace {

constexpr std::uint64_t kSeed = 20261121;

const ClaimOutcome& find_claim(const PolygonCheck& c, const std::string& id) {
  for (const auto& o : c.claims)
    if (o.info.id == id) return o;
  throw std::runtime_error("claim not in check: " + id);
}

TEST(Dijksman1966, EveryTrueClaimHoldsExactlyOnSpecExamples) {
  GroundTruthEngine engine;
  for (const auto& ex : {test::spec_pentagon(), test::spec_hexagon()}) {
    const auto check = check_polygon(engine, dijksman1966::catalogue(), "spec", ex.polygon, ex.rates, Arithmetic::Exact);
    for (const auto& c : check.claims)
      if (c.info.expected == Expectation::Holds) EXPECT_EQ(c.verdict, Verdict::Holds) << c.info.id << " n=" << check.n;
    EXPECT_EQ(exit_status(check), 0);
  }
}

TEST(Dijksman1966, PentagonEq22TermsAndMixedTermMatchSpecA8) {
  GroundTruthEngine engine;
  const auto ex = test::spec_pentagon();
  const auto check = check_polygon(engine, dijksman1966::catalogue(), "p", ex.polygon, ex.rates, Arithmetic::Exact);
  const auto& eq22 = find_claim(check, "dijksman1966.eq22");
  EXPECT_EQ(eq22.headline.lhs, "3755/1331");
  EXPECT_EQ(eq22.headline.rhs, "3755/1331");
  ASSERT_EQ(eq22.terms.size(), 5u);
  EXPECT_EQ(eq22.terms[4].label, "omega[1]*omega[2]");
  EXPECT_EQ(eq22.terms[4].rhs, "-304/1331");
  EXPECT_EQ(find_claim(check, "dijksman1966.eq21").headline.lhs, "608/1331");   // Delta omega-dot_{4,5}
  EXPECT_EQ(find_claim(check, "dijksman1966.eq10").headline.rhs, "3147/1331");  // sum of four-bar parts
}

TEST(Dijksman1966, EveryErratumReadingFailsOnTheSpecPentagonOrHexagon) {
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

struct WrongVariant {
  const char* name;
  dijksman1966::FormulaReading reading;
  bool affects_companion = true;  ///< beta enters (22) only; the companion uses gamma
  bool needs_negative_d = false;  ///< unsigned phi equals signed phi when D > 0
};

std::vector<WrongVariant> wrong_eq22_variants() {
  std::vector<WrongVariant> v;
  dijksman1966::FormulaReading r;
  r.mixed_term_sign = -1;
  v.push_back({"mixed term sign flipped", r});
  r = {};
  r.mixed_term_sign = 0;
  v.push_back({"mixed term dropped", r});
  r = {};
  r.swap_mixed_ratios = true;
  v.push_back({"i_{n-1} and i_{n-2} swapped in the mixed term", r});
  r = {};
  r.ordered_pairs = false;
  v.push_back({"pairs j<l only", r});
  r = {};
  r.signed_phi = false;
  v.push_back({"unsigned phi", r, true, true});
  r = {};
  r.construction.beta_ccw_positive = false;
  v.push_back({"beta sign reversed", r, false, false});
  return v;
}

template <class T>
Verdict judge_sides(const ClaimSides<T>& s) {
  Verdict v = Verdict::Holds;
  for (const auto& c : s.instances) v = combine(v, judge(c).verdict);
  for (const auto& c : s.terms) v = combine(v, judge(c).verdict);
  return v;
}

template <class T>
void expect_wrong_variants_rejected(const char* arith) {
  GroundTruthEngine engine;
  for (const auto& w : wrong_eq22_variants()) {
    int rejected = 0, cases = 0;
    for (int n = 5; n <= 9; ++n) {
      for (int i = 0; i < 8; ++i) {
        const auto rc = generate_random_polygon(kSeed, n, i);
        const auto ctx = build_polygon_context<T>(engine, rc.polygon, rc.rates);
        const Verdict correct22 = judge_sides(dijksman1966::eq22_sides(ctx, {}));
        const Verdict correct_companion = judge_sides(dijksman1966::companion_sides(ctx, {}));
        if (correct22 != Verdict::Holds || correct_companion != Verdict::Holds) continue;  // degenerate draw
        if (w.needs_negative_d && cln::plusp(rc.polygon.dead_centre_determinant())) continue;
        ++cases;
        const Verdict v22 = judge_sides(dijksman1966::eq22_sides(ctx, w.reading));
        const Verdict vc = judge_sides(dijksman1966::companion_sides(ctx, w.reading));
        EXPECT_NE(v22, Verdict::Holds) << arith << ": eq22 with " << w.name << " accepted, n " << n << " i " << i;
        if (w.affects_companion)
          EXPECT_NE(vc, Verdict::Holds) << arith << ": companion with " << w.name << " accepted, n " << n << " i " << i;
        rejected += v22 == Verdict::Fails && (!w.affects_companion || vc == Verdict::Fails);
      }
    }
    EXPECT_GT(cases, 12) << w.name;
    EXPECT_GE(rejected, cases * 9 / 10) << arith << ": " << w.name << " rejected in " << rejected << "/" << cases;
  }
}

TEST(Dijksman1966MustFail, WrongFormulasAreRejectedInExactArithmetic) {
  expect_wrong_variants_rejected<Rational>("exact");
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
  dijksman1966::FormulaReading r;
  r.mixed_term_sign = 0;
  for (const auto& t : dijksman1966::eq22_sides(ctx, r).terms) {
    const Verdict v = judge(t).verdict;
    if (t.label.find('*') != std::string::npos)
      EXPECT_EQ(v, Verdict::Fails) << t.label;
    else
      EXPECT_EQ(v, Verdict::Holds) << t.label;
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
        ASSERT_NE(c.verdict, Verdict::Fails) << c.info.id << " n " << n << " i " << i << ": " << c.headline.lhs << " vs "
                                             << c.headline.rhs << " tol " << c.headline.tolerance;
        ++total;
        holds += c.verdict == Verdict::Holds;
      }
    }
  }
  EXPECT_GE(holds, total * 95 / 100) << holds << "/" << total;
}

}  // namespace
}  // namespace linkproof
