// The mechanism claim language: parsing, kinds and errors at file:line:column.
#include "claims/mechanism_expression.h"

#include <gtest/gtest.h>

#include "claims/vocabulary.h"
#include "linkproof/core/error.h"

namespace linkproof {
namespace {

MechanismExpression parse(const std::string& text) {
  return MechanismExpression::parse(text, ExpressionContext{"c.yaml", "claims[0].lhs", false});
}

// The InputError of parsing `text`: its source ("c.yaml:1:COLUMN") and problem.
std::pair<std::string, std::string> expression_error(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return {e.source(), e.problem()};
  }
  ADD_FAILURE() << "no error for " << text;
  return {};
}

TEST(MechanismExpression, KindsOfWordsAndOperators) {
  EXPECT_EQ(parse("omega(coupler)").kind(), ClaimKind::Number);
  EXPECT_EQ(parse("omega(\"3\", '1')").kind(), ClaimKind::Number);
  EXPECT_EQ(parse("vel(B, \"3\") - omega(\"3\")*perp(pos(B) - pos(A))").kind(), ClaimKind::Vector);
  EXPECT_EQ(parse("dot(acc(P, L, M), vel(P, L))/norm2(pos(P))^2").kind(), ClaimKind::Number);
  EXPECT_EQ(parse("-pos(P)/2 + meet(pos(A), pos(B), pos(C), pos(D))").kind(), ClaimKind::Vector);
  EXPECT_EQ(parse("sliding_v(S)^(-1)").kind(), ClaimKind::Number);
}

TEST(MechanismExpression, NamesAreArgumentsBareOrQuoted) {
  const MechanismExpression e = parse("vel(B, \"3\", frame)");
  ASSERT_EQ(e.root().children.size(), 3u);
  EXPECT_EQ(e.root().children[0].name, "B");
  EXPECT_EQ(e.root().children[0].kind, ClaimKind::Point);
  EXPECT_EQ(e.root().children[1].name, "3");
  EXPECT_EQ(e.root().children[2].kind, ClaimKind::Link);
}

TEST(MechanismExpression, ErrorsNameLineAndColumn) {
  EXPECT_EQ(expression_error("omega(a) + spin(b)").first, "c.yaml:1:12");
  EXPECT_NE(expression_error("omega(a) + spin(b)").second.find("unknown word 'spin'"), std::string::npos);
  const auto arity = expression_error("omega(a, b, c)");
  EXPECT_EQ(arity.first, "c.yaml:1:1");
  EXPECT_NE(arity.second.find("it takes omega(L), omega(L, M)"), std::string::npos) << arity.second;
  const auto vector_as_number = expression_error("omega(a) + pos(P)");
  EXPECT_EQ(vector_as_number.first, "c.yaml:1:10");
  const auto dot_arg = expression_error("dot(omega(a), pos(P))");
  EXPECT_EQ(dot_arg.first, "c.yaml:1:5");
  EXPECT_NE(dot_arg.second.find("a number where a vector is expected"), std::string::npos) << dot_arg.second;
  EXPECT_NE(expression_error("norm2(pos(P))*pos(P) / pos(Q)").second.find("a vector where a number is expected"),
            std::string::npos);
  EXPECT_NE(expression_error("pos(P)*pos(Q)").second.find("dot(a, b) or cross(a, b)"), std::string::npos);
  EXPECT_NE(expression_error("norm2(P)").second.find("'P' is a name"), std::string::npos);
  EXPECT_NE(expression_error("omega(pos(P))").second.find("a link name"), std::string::npos);
  EXPECT_NE(expression_error("omega(a) + 0.5").second.find("decimal"), std::string::npos);
  EXPECT_NE(expression_error("pos(P)^2").second.find("a power of a vector"), std::string::npos);
  EXPECT_NE(expression_error("omega(\"3)").second.find("never closed"), std::string::npos);
  EXPECT_NE(expression_error("omega(a) omega(b)").second.find("an operator is missing"), std::string::npos);
  EXPECT_NE(expression_error("coupler").second.find("unknown word 'coupler'"), std::string::npos);
}

TEST(MechanismVocabulary, EveryWordHasASignatureAndMeaning) {
  for (const Word& w : vocabulary()) {
    if (!w.belongs_to(Language::Mechanism)) continue;
    EXPECT_EQ(find_word(Language::Mechanism, w.name, w.arity()), &w) << w.name;
    EXPECT_EQ(w.signature.substr(0, w.name.size() + 1), w.name + "(") << w.signature;
    EXPECT_FALSE(w.meaning.empty()) << w.name;
  }
  for (const char* word : {"omega", "alpha", "pos", "vel", "acc", "pole", "centre", "centre_at", "sliding_v", "sliding_a",
                           "axis", "dot", "cross", "perp", "norm2", "vx", "vy", "meet"})
    EXPECT_FALSE(word_signatures(Language::Mechanism, word).empty()) << word;
}

}  // namespace
}  // namespace linkproof
