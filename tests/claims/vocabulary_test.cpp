// The one vocabulary of both claim languages (claims/vocabulary.h): every word is found by its
// language, name and arity, and every word with a value is evaluated by its language's evaluator,
// so that a table entry without an evaluation fails here.
#include "claims/vocabulary.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "check/check_polygon.h"
#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"

namespace linkproof {
namespace {

const std::vector<Language> kLanguages = {Language::Polygon, Language::Mechanism};

TEST(Vocabulary, EveryWordIsFoundInEachOfItsLanguagesAndNoOther) {
  for (const Word& w : vocabulary())
    for (const Language l : kLanguages) {
      const Word* found = find_word(l, w.name, w.arity());
      if (w.belongs_to(l)) EXPECT_EQ(found, &w) << w.signature;
      else EXPECT_NE(found, &w) << w.signature;
    }
}

TEST(Vocabulary, TheVectorWordsAreOneEntryForBothLanguages) {
  for (const char* name : {"dot", "cross", "norm2", "perp", "vx", "vy"}) {
    const Word* polygon = find_word(Language::Polygon, name, name == std::string("dot") || name == std::string("cross") ? 2 : 1);
    ASSERT_NE(polygon, nullptr) << name;
    EXPECT_EQ(polygon->languages, Languages::Both) << name;
    EXPECT_EQ(find_word(Language::Mechanism, name, polygon->arity()), polygon) << name;
  }
}

TEST(Vocabulary, EachEvaluationCodeBelongsToOneWord) {
  std::set<Evaluation> codes;
  for (const Word& w : vocabulary()) EXPECT_TRUE(codes.insert(w.evaluation).second) << w.signature;
}

TEST(Vocabulary, SignaturesListEveryArityOfANameInOneLanguage) {
  EXPECT_EQ(word_signatures(Language::Mechanism, "omega"), "omega(L), omega(L, M)");
  EXPECT_EQ(word_signatures(Language::Polygon, "omega"), "omega[j]");
  EXPECT_EQ(word_signatures(Language::Mechanism, "r"), "");
  EXPECT_EQ(word_signatures(Language::Polygon, "pos"), "");
}

// A polygon expression that uses the word once (in the order of its arguments' kinds).
std::string polygon_use(const Word& w) {
  if (w.arity() == 0) return w.name;
  if (w.is_indexed()) return w.name + "[1]";
  std::string call = w.name + "(";
  for (int k = 0; k < w.arity(); ++k) {
    const ClaimKind a = w.arguments[static_cast<size_t>(k)];
    // A sum's body uses the indices it binds (sum_j binds j alone).
    const std::string body = w.evaluation == Evaluation::SumJ ? "omega[j]" : "omega[j]*omega[l]";
    call += (k ? ", " : "") + (a == ClaimKind::SumBody ? body : "r[" + std::to_string(k + 1) + "]");
  }
  return call + ")";
}

TEST(Vocabulary, EveryPolygonWordIsEvaluated) {
  GroundTruthEngine engine;
  const Polygon<Rational> pentagon({{0, 0}, {1, 3}, {4, 5}, {8, 3}, {7, -1}});
  const InputRates<Rational> rates{{2, -3}, {1, 5}};
  int evaluated = 0;
  for (const Word& w : vocabulary()) {
    if (!w.belongs_to(Language::Polygon) || w.result == ClaimKind::Index) continue;
    const std::string use = polygon_use(w), body = w.result == ClaimKind::Vector ? "vx(" + use + ")" : use;
    const std::string yaml = "claims:\n  - id: word\n    source: test\n    statement: s\n    lhs: " + body +
                             "\n    rhs: " + body + "\n";
    SCOPED_TRACE(body);
    const ClaimFile file = parse_claim_file(yaml, "vocabulary.yaml");
    const auto check = check_polygon(engine, {to_claim(file.claims.at(0))}, "pentagon", pentagon, rates, Arithmetic::Exact);
    ASSERT_EQ(check.claims.size(), 1u);
    EXPECT_EQ(check.claims[0].error, "");
    EXPECT_EQ(check.claims[0].verdict, Verdict::Holds);
    ++evaluated;
  }
  EXPECT_GT(evaluated, 40);
}

// A mechanism expression that uses the word once, on the inverted slider-crank.
std::string mechanism_use(const Word& w) {
  const std::vector<std::string> links = {"crank", "rocker", "frame"};
  const std::vector<std::string> vectors = {"pos(O2)", "pos(A)", "pos(O4)", "pos(A) + vec(1, 2)"};
  std::string call = w.name + "(";
  for (int k = 0; k < w.arity(); ++k) {
    const auto at = static_cast<size_t>(k);
    std::string a;
    switch (w.arguments[at]) {
      case ClaimKind::Link: a = links[at % links.size()]; break;
      case ClaimKind::Point: a = "A"; break;
      case ClaimKind::Slider: a = "S"; break;
      case ClaimKind::Number: a = std::to_string(k + 1); break;
      default: a = vectors[at]; break;
    }
    call += (k ? ", " : "") + a;
  }
  return call + ")";
}

TEST(Vocabulary, EveryMechanismWordIsEvaluated) {
  const MechanismScene scene =
      load_mechanism_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/inverted_slider_crank.yaml");
  const MechanismSolution<Rational> truth = solve_mechanism_exact(scene);
  const MechanismFrame frame(scene, truth.motion);
  int evaluated = 0;
  for (const Word& w : vocabulary()) {
    if (!w.belongs_to(Language::Mechanism)) continue;
    MechanismDataClaim c;
    c.lhs = MechanismExpression::parse(mechanism_use(w), ExpressionContext{"t.yaml", "claims[0].lhs", false});
    c.rhs = c.lhs;
    bind_mechanism_claim(c, scene);
    SCOPED_TRACE(c.lhs.text());
    // A value, or a quantity undefined at this configuration: never a word without an evaluation.
    try {
      const MechanismValueOf<Rational> v = evaluate_mechanism_expression(c.lhs.root(), frame);
      EXPECT_EQ(v.is_vector, w.result == ClaimKind::Vector);
    } catch (const UndefinedQuantity&) {
    }
    ++evaluated;
  }
  EXPECT_GT(evaluated, 20);
}

}  // namespace
}  // namespace linkproof
