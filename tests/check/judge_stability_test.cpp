// Stability claims (issue 5, item 6): near a singularity of the construction a floating-point
// claim is `inconclusive`, never a false `fails`, and says how its tolerance was derived and
// what to trust instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "numerics/extreme_families.h"

namespace linkproof {
namespace {

Rational ten_to_minus(int k) {
  Rational p = 1;
  for (int i = 0; i < k; ++i) p = p / 10;
  return p;
}

TEST(JudgeStability, NearAPoleOfTheConstructionTrueClaimsAreInconclusiveNotFailsAndNameWhatToTrust) {
  GroundTruthEngine engine;
  for (const char* family : {"q_infinity", "beta_zero", "p_infinity", "dead_centre"}) {
    for (int k : {8, 12, 14}) {
      SCOPED_TRACE(std::string(family) + " at eps = 1e-" + std::to_string(k));
      const ExtremeCase c = find_extreme_family(family)->make(ten_to_minus(k));
      const PolygonCheck r =
          check_polygon(engine, dijksman1966::catalogue(), family, c.polygon, c.rates, Arithmetic::Double);
      int inconclusive = 0;
      for (const ClaimOutcome& claim : r.claims) {
        if (claim.info.expected == Expectation::Holds) {
          EXPECT_NE(claim.verdict, Verdict::Fails) << claim.info.id;
        }
        for (const auto* list : {&claim.instances, &claim.terms}) {
          for (const ComparisonOutcome& o : *list) {
            if (o.floating.has_value()) {
              EXPECT_NE(tolerance_derivation_text(o).find("condition(lhs)"), std::string::npos);
            }
            if (o.verdict == Verdict::Inconclusive) {
              ++inconclusive;
              EXPECT_NE(trust_route_text(o).find("exact arithmetic"), std::string::npos) << claim.info.id;
            }
          }
        }
      }
      if (k >= 12) {
        EXPECT_GT(inconclusive, 0);
      }
    }
  }
}

// Q_1 at infinity (conventions §A6) at eps = 1e-14: the construction loses ~1e-16/eps relative in
// double, so double is inconclusive there; mp1000 (u = 2^-3392) loses the same factor of a far
// smaller u and decides every comparison exactly as exact arithmetic does.
TEST(JudgeStability, Mp1000DecidesWhereDoubleIsInconclusiveNearQAtInfinity) {
  GroundTruthEngine engine;
  const ExtremeCase c = find_extreme_family("q_infinity")->make(ten_to_minus(14));
  const auto run = [&](Arithmetic a) {
    return check_polygon(engine, dijksman1966::catalogue(), "q_infinity", c.polygon, c.rates, a);
  };
  const PolygonCheck exact = run(Arithmetic::Exact), dbl = run(Arithmetic::Double), mp = run(Arithmetic::Mp1000);
  int double_inconclusive = 0;
  for (size_t k = 0; k < exact.claims.size(); ++k) {
    const ClaimOutcome& e = exact.claims[k];
    ASSERT_NE(e.verdict, Verdict::Inconclusive);
    double_inconclusive += dbl.claims[k].verdict == Verdict::Inconclusive;
    if (dbl.claims[k].verdict != Verdict::Inconclusive) {
      EXPECT_EQ(dbl.claims[k].verdict, e.verdict) << e.info.id;  // never a false holds/fails
    }
    EXPECT_EQ(mp.claims[k].verdict, e.verdict) << e.info.id << ": " << reason_text(mp.claims[k].headline);
    for (size_t i = 0; i < e.instances.size(); ++i)
      EXPECT_EQ(mp.claims[k].instances[i].verdict, e.instances[i].verdict) << e.info.id << " " << e.instances[i].label;
  }
  EXPECT_GT(double_inconclusive, 0);
}

// The same guarantee in CLN long floats: at eps = 1e-40 (below mp30's u = 2^-128 ~ 3e-39) mp30
// is where double is at 1e-14. Every comparison either agrees with exact arithmetic or is
// inconclusive; it is never a false holds or fails.
TEST(JudgeStability, Mp30NearSingularitiesIsInconclusiveNeverWrong) {
  GroundTruthEngine engine;
  for (const char* family : {"q_infinity", "beta_zero", "p_infinity", "dead_centre"}) {
    SCOPED_TRACE(family);
    const ExtremeCase c = find_extreme_family(family)->make(ten_to_minus(40));
    const PolygonCheck exact =
        check_polygon(engine, dijksman1966::catalogue(), family, c.polygon, c.rates, Arithmetic::Exact);
    const PolygonCheck mp = check_polygon(engine, dijksman1966::catalogue(), family, c.polygon, c.rates, Arithmetic::Mp30);
    int inconclusive = 0;
    for (size_t k = 0; k < exact.claims.size(); ++k) {
      for (size_t i = 0; i < exact.claims[k].instances.size(); ++i) {
        const ComparisonOutcome& m = mp.claims[k].instances[i];
        const ComparisonOutcome& e = exact.claims[k].instances[i];
        if (m.verdict == Verdict::Inconclusive) {
          ++inconclusive;
          EXPECT_NE(tolerance_derivation_text(m).find("u = 2^-128"), std::string::npos);
          EXPECT_FALSE(trust_route_text(m).empty());
        } else {
          EXPECT_EQ(m.verdict, e.verdict) << exact.claims[k].info.id << " " << e.label;
        }
      }
    }
    EXPECT_GT(inconclusive, 0);
  }
}

// Far from every pole (q_infinity at eps = 1): eq22 is present, compared, and holds in double
// with a tolerance derived from the condition and nothing to trust instead. The claim must be
// found and must have compared something: a catalogue without eq22 fails here.
TEST(JudgeStability, WellConditionedDoubleChecksStillHoldWithADerivedTolerance) {
  GroundTruthEngine engine;
  const ExtremeCase c = find_extreme_family("q_infinity")->make(1);
  const PolygonCheck r = check_polygon(engine, dijksman1966::catalogue(), "q1", c.polygon, c.rates, Arithmetic::Double);
  int found = 0, comparisons = 0;
  for (const ClaimOutcome& claim : r.claims) {
    if (claim.info.id != "dijksman1966.eq22") continue;
    ++found;
    EXPECT_EQ(claim.verdict, Verdict::Holds);
    EXPECT_FALSE(tolerance_derivation_text(claim.headline).empty());
    EXPECT_TRUE(trust_route_text(claim.headline).empty());
    for (const auto* list : {&claim.instances, &claim.terms}) {
      for (const ComparisonOutcome& o : *list) {
        ++comparisons;
        EXPECT_EQ(o.verdict, Verdict::Holds) << o.label;
        EXPECT_FALSE(tolerance_derivation_text(o).empty()) << o.label;
      }
    }
  }
  EXPECT_EQ(found, 1) << "dijksman1966.eq22 is not in the catalogue's check of this polygon";
  EXPECT_GT(comparisons, 0) << "dijksman1966.eq22 compared nothing";
}

// trust_route names the side and the quantity that made a comparison inconclusive
// (check/inconclusive_cause.h): D near the dead centre, where no route is better; a quantity of
// the construction near one of its poles. It used to blame the construction every time.
std::vector<ComparisonOutcome> inconclusive_comparisons(const char* family, int k) {
  GroundTruthEngine engine;
  const ExtremeCase c = find_extreme_family(family)->make(ten_to_minus(k));
  const PolygonCheck r = check_polygon(engine, dijksman1966::catalogue(), family, c.polygon, c.rates, Arithmetic::Double);
  std::vector<ComparisonOutcome> out;
  for (const ClaimOutcome& claim : r.claims)
    for (const auto* list : {&claim.instances, &claim.terms})
      for (const ComparisonOutcome& o : *list)
        if (o.verdict == Verdict::Inconclusive) out.push_back(o);
  return out;
}

TEST(TrustRoute, NearTheDeadCentreItNamesDAndSendsNobodyToAnotherFloatingPointRoute) {
  const auto inconclusive = inconclusive_comparisons("dead_centre", 14);
  ASSERT_FALSE(inconclusive.empty());
  for (const ComparisonOutcome& o : inconclusive) {
    EXPECT_EQ(inconclusive_quantity(o), "D = r_{n-2} x r_{n-1}") << o.label << ": " << trust_route_text(o);
    ASSERT_TRUE(o.floating.has_value()) << o.label;
    EXPECT_NE(o.floating->wider_side, Side::None) << o.label;
    EXPECT_EQ(trust_route_text(o).rfind(std::string(to_string(o.floating->wider_side)) + ":", 0), 0U) << trust_route_text(o);
    EXPECT_EQ(trust_route_text(o).find("closed forms"), std::string::npos) << trust_route_text(o);
    EXPECT_NE(trust_route_text(o).find("exact arithmetic"), std::string::npos) << trust_route_text(o);
  }
}

TEST(TrustRoute, NearQAtInfinityItNamesAQuantityOfTheConstruction) {
  const auto inconclusive = inconclusive_comparisons("q_infinity", 14);
  ASSERT_FALSE(inconclusive.empty());
  int construction = 0;
  for (const ComparisonOutcome& o : inconclusive) {
    EXPECT_NE(inconclusive_quantity(o), "D = r_{n-2} x r_{n-1}") << o.label;
    if (inconclusive_quantity(o).find("(construction") != std::string::npos) {
      ++construction;
      EXPECT_NE(trust_route_text(o).find("closed forms and the engine keep full accuracy"), std::string::npos);
    } else {
      EXPECT_NE(trust_route_text(o).find("the claim's own arithmetic"), std::string::npos) << trust_route_text(o);
    }
  }
  EXPECT_GT(construction, 0);
}

// The claims of a check share one context, and a quantity is named as a cause only if the
// claim itself read it (PolygonContext::reads). Checked against each claim checked alone, on a
// context of its own: every inconclusive comparison names the same cause, on every extreme
// family in double and long double (the catalogue's claims read different quantities: the
// engine, the closed forms, the construction under several readings, the four-bars alone).
TEST(TrustRoute, EachClaimNamesTheCauseItNamesWhenCheckedAlone) {
  GroundTruthEngine engine;
  const std::vector<Claim>& catalogue = dijksman1966::catalogue();
  int named = 0, construction = 0, own = 0;
  for (const ExtremeFamily& family : extreme_families()) {
    for (const Rational& value : family.quick_values) {
      const ExtremeCase c = family.make(value);
      for (Arithmetic a : {Arithmetic::Double, Arithmetic::LongDouble}) {
        const PolygonCheck all = check_polygon(engine, catalogue, family.name, c.polygon, c.rates, a);
        ASSERT_FALSE(all.claims.empty());
        for (const ClaimOutcome& shared : all.claims) {  // the claims that apply at this n
          const auto k = static_cast<size_t>(
              std::find_if(catalogue.begin(), catalogue.end(), [&](const Claim& x) { return x.info.id == shared.info.id; }) -
              catalogue.begin());
          ASSERT_LT(k, catalogue.size()) << shared.info.id;
          bool inconclusive = false;
          for (const auto* list : {&shared.instances, &shared.terms})
            for (const ComparisonOutcome& o : *list) inconclusive = inconclusive || o.cause.has_value();
          if (!inconclusive) continue;
          const PolygonCheck alone = check_polygon(engine, {catalogue[k]}, family.name, c.polygon, c.rates, a);
          ASSERT_EQ(alone.claims.size(), 1u);
          const ClaimOutcome& own_context = alone.claims[0];
          ASSERT_EQ(own_context.terms.size(), shared.terms.size()) << shared.info.id;
          for (int g = 0; g < 2; ++g) {
            const auto& x = g == 0 ? shared.instances : shared.terms;
            const auto& y = g == 0 ? own_context.instances : own_context.terms;
            ASSERT_EQ(x.size(), y.size()) << shared.info.id;
            for (size_t m = 0; m < x.size(); ++m) {
              const std::string where = family.name + " " + shared.info.id + " " + x[m].label;
              ASSERT_EQ(x[m].cause.has_value(), y[m].cause.has_value()) << where;
              if (!x[m].cause) continue;
              EXPECT_EQ(x[m].cause->kind, y[m].cause->kind) << where;
              EXPECT_EQ(x[m].cause->quantity, y[m].cause->quantity) << where;
              EXPECT_EQ(x[m].cause->relative_bound, y[m].cause->relative_bound) << where;
              ++named;
              if (x[m].cause->kind == InconclusiveCause::Kind::Construction) ++construction;
              if (x[m].cause->kind == InconclusiveCause::Kind::OwnArithmetic) ++own;
            }
          }
        }
      }
    }
  }
  std::printf("%d causes named, %d of the construction, %d of the claim's own arithmetic\n", named, construction, own);
  EXPECT_GT(construction, 0);
  EXPECT_GT(own, 0);  // claims that did not read the construction while others had computed it
}

}  // namespace
}  // namespace linkproof
