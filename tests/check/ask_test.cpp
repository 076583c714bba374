// Scenes that say what they ask (check/ask.h): the polygon reader, the claims chosen, and a
// check that computes only what the asked items need, with the same numbers as a whole check.
#include <gtest/gtest.h>

#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "report/number_text.h"
#include "linkproof/io/scene.h"

namespace linkproof {
namespace {

std::string text_of(const std::optional<ResultNumber>& x) { return x ? number_text(*x) : "(none)"; }

const std::string kPentagon = R"(name: p
polygon:
  joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]
  omega: [2, -1]
  omega_dot: [1, 3]
)";

PolygonScene with_ask(const std::string& ask) { return parse_polygon_scene(kPentagon + "ask: " + ask + "\n", "s.yaml"); }

// The InputError's text for a scene with this ask ("" if it is accepted).
std::string ask_error(const std::string& ask) {
  try {
    with_ask(ask);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// One engine for every check: each n is derived once per process.
PolygonCheck run(const PolygonScene& s, Arithmetic a = Arithmetic::Exact) {
  static GroundTruthEngine engine;
  return check_polygon(engine, asked_claims(dijksman1966::catalogue(), s.ask, s.source), s.name, s.polygon, s.rates, a,
                       Evidence::All, s.ask);
}

TEST(SceneAsk, ReadsRatesClaimsAndArithmeticInTheIssuesSpelling) {
  const PolygonScene s = with_ask("[omega_dot(4), omega( 1 ), claims: [eq22, eq9], arithmetic: double]");
  ASSERT_TRUE(s.ask);
  ASSERT_EQ(s.ask->rates.size(), 2u);
  EXPECT_TRUE(s.ask->rates[0].dot);
  EXPECT_EQ(s.ask->rates[0].subject.name, "4");
  EXPECT_FALSE(s.ask->rates[1].dot);
  EXPECT_EQ(s.ask->rates[1].subject.name, "1");
  ASSERT_TRUE(s.ask->claims);
  EXPECT_EQ(s.ask->claims->size(), 2u);
  EXPECT_EQ(s.ask->arithmetic, Arithmetic::Double);
  EXPECT_TRUE(s.ask->restricts());
  EXPECT_FALSE(with_ask("[arithmetic: mp30]").ask->restricts());
}

TEST(SceneAsk, BadItemsAreInputErrorsNamingTheField) {
  EXPECT_NE(ask_error("[omega_dot(6)]").find("ask[0]"), std::string::npos);
  EXPECT_NE(ask_error("[omega_dot(6)]").find("side 1..5"), std::string::npos);
  EXPECT_NE(ask_error("[omega_dot(0)]").find("side 1..5"), std::string::npos);
  EXPECT_NE(ask_error("[omega_dot(x)]").find("side 1..5"), std::string::npos);
  EXPECT_NE(ask_error("[alpha(4)]").find("expected an item"), std::string::npos);
  EXPECT_NE(ask_error("[omega_dot(4), omega_dot(4)]").find("asked twice"), std::string::npos);
  EXPECT_NE(ask_error("[]").find("empty"), std::string::npos);
  EXPECT_NE(ask_error("omega_dot(4)").find("expected a list"), std::string::npos);
  EXPECT_NE(ask_error("[claims: [eq22], claims: [eq9]]").find("ask[1].claims"), std::string::npos);
  EXPECT_NE(ask_error("[arithmetic: float]").find("ask[0].arithmetic"), std::string::npos);
  EXPECT_NE(ask_error("[colour: red]").find("unknown item"), std::string::npos);
  EXPECT_NE(ask_error("[links: [\"5\"]]").find("mechanism scenes"), std::string::npos);
  EXPECT_NE(ask_error("[{claims: [eq22], arithmetic: double}]").find("expected an item"), std::string::npos);
}

// An empty list asks for nothing, and a side is a number: both were accepted, contrary to
// docs/ask.md ("an empty list", "an item given twice" are exit 2).
TEST(SceneAsk, EmptyListsAndTheSameSideWrittenTwoWaysAreRefused) {
  EXPECT_NE(ask_error("[claims: []]").find("ask[0].claims"), std::string::npos);
  EXPECT_NE(ask_error("[claims: []]").find("empty"), std::string::npos);
  EXPECT_NE(ask_error("[links: []]").find("empty"), std::string::npos);
  EXPECT_NE(ask_error("[points: []]").find("empty"), std::string::npos);
  EXPECT_NE(ask_error("[omega_dot(4), omega_dot(04)]").find("asked twice"), std::string::npos);
  EXPECT_NE(ask_error("[omega_dot(4), omega_dot(04)]").find("ask[1]"), std::string::npos);
  // Written with a leading zero alone, the side is read as the number it is.
  EXPECT_EQ(with_ask("[omega_dot(004)]").ask->rates[0].subject.name, "4");
  EXPECT_EQ(ask_error("[omega_dot(4), omega(04)]"), "");
}

TEST(SceneAsk, UnknownClaimNamesItsFieldAndTheClaimsThereAre) {
  const PolygonScene s = with_ask("[claims: [eq22, eq99]]");
  try {
    asked_claims(dijksman1966::catalogue(), s.ask, s.source);
    FAIL() << "eq99 accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("s.yaml"), std::string::npos) << m;
    EXPECT_NE(m.find("ask[0].claims[1]"), std::string::npos) << m;
    EXPECT_NE(m.find("dijksman1966.eq22"), std::string::npos) << m;
  }
}

TEST(SceneAsk, ClaimsAreChosenByIdOrItsEndingInCatalogueOrder) {
  const auto chosen = asked_claims(dijksman1966::catalogue(), with_ask("[claims: [eq9, dijksman1966.eq4]]").ask, "s");
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_EQ(chosen[0].info.id, "dijksman1966.eq4");
  EXPECT_EQ(chosen[1].info.id, "dijksman1966.eq9");
  EXPECT_TRUE(asked_claims(dijksman1966::catalogue(), with_ask("[omega(1)]").ask, "s").empty());
  EXPECT_EQ(asked_claims(dijksman1966::catalogue(), with_ask("[arithmetic: double]").ask, "s").size(),
            dijksman1966::catalogue().size());
}

TEST(SceneAsk, TheWriterWritesTheAskBack) {
  const PolygonScene s = with_ask("[omega_dot(4), claims: [eq22], arithmetic: mp30]");
  const PolygonScene back = parse_polygon_scene(polygon_scene_to_yaml(s), "s.yaml");
  ASSERT_TRUE(back.ask);
  EXPECT_EQ(back.ask->describe(), s.ask->describe());
}

TEST(AskedCheck, AnInputRateNeedsNoEngineAndNoClaim) {
  const PolygonCheck c = run(with_ask("[omega(1), omega_dot(2), omega(5)]"));
  EXPECT_FALSE(c.computed.truth);
  EXPECT_FALSE(c.computed.construction);
  EXPECT_FALSE(c.computed.closed_forms);
  EXPECT_TRUE(c.claims.empty());
  EXPECT_EQ(text_of(c.omega[0]), "2");
  EXPECT_EQ(text_of(c.omega_dot[1]), "3");
  EXPECT_EQ(text_of(c.omega[4]), "0");
  EXPECT_FALSE(c.omega[3]);  // not asked, not computed
}

TEST(AskedCheck, ASolvedRateHasTheWholeChecksValueWithoutTheConstruction) {
  const PolygonScene whole = parse_polygon_scene(kPentagon, "s.yaml");
  const PolygonCheck all = run(whole);
  EXPECT_TRUE(all.computed.construction);
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Double}) {
    const PolygonCheck c = run(with_ask("[omega_dot(4), omega(3)]"), a);
    const PolygonCheck full = run(whole, a);
    EXPECT_TRUE(c.computed.truth);
    EXPECT_FALSE(c.computed.construction);
    EXPECT_FALSE(c.computed.four_bar_truth);
    EXPECT_EQ(c.omega_dot[3], full.omega_dot[3]);
    EXPECT_EQ(c.omega[2], full.omega[2]);
    EXPECT_EQ(c.determinant, full.determinant);
  }
  EXPECT_EQ(text_of(run(with_ask("[omega_dot(4)]")).omega_dot[3]), "3755/1331");
}

TEST(AskedCheck, AskedClaimsHaveTheWholeChecksVerdictsAndEvidence) {
  const PolygonCheck all = run(parse_polygon_scene(kPentagon, "s.yaml"));
  const PolygonCheck c = run(with_ask("[claims: [eq22, eq5]]"));
  ASSERT_EQ(c.claims.size(), 2u);
  for (const ClaimOutcome& o : c.claims) {
    const auto same = std::find_if(all.claims.begin(), all.claims.end(), [&](const auto& x) { return x.info.id == o.info.id; });
    ASSERT_NE(same, all.claims.end());
    EXPECT_EQ(o.verdict, same->verdict);
    EXPECT_EQ(lhs_text(o.headline), lhs_text(same->headline));
    EXPECT_EQ(o.terms.size(), same->terms.size());
  }
  // eq5 and eq22 read no four-bar solved on its own.
  EXPECT_FALSE(c.computed.four_bar_truth);
  EXPECT_TRUE(all.computed.four_bar_truth);
}

TEST(AskedCheck, AtTheDeadCentreAnAskedInputIsKnownAndASolvedRateUndefined) {
  const PolygonScene s = parse_polygon_scene(R"(name: d
polygon:
  joints: [[0, 0], [2, 0], [3, 1], [4, 2], [5, 3]]
  omega: [1, 2]
  omega_dot: [0, 0]
ask: [omega(1), omega_dot(4)]
)",
                                             "d.yaml");
  const PolygonCheck c = run(s);
  ASSERT_TRUE(c.dead_centre);
  EXPECT_EQ(text_of(c.omega[0]), "1");
  EXPECT_FALSE(c.omega_dot[3]);
}

}  // namespace
}  // namespace linkproof
