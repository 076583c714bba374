// Claim statements typeset (report/statement_tex.h): formulas as math, words as text, and any
// statement with a character outside the formula alphabet left as plain text.
#include "report/statement_tex.h"

#include <gtest/gtest.h>

namespace linkproof::report {
namespace {

std::string joined(const Rich& r, bool math_only) {
  std::string out;
  for (const Span& s : r)
    if (!math_only || s.math) out += (s.math ? "$" + s.text + "$" : s.text);
  return out;
}

TEST(StatementTex, FormulaBecomesMathWithGreekLettersAndSums) {
  EXPECT_EQ(formula_tex("omega_{n-1,n} = sum_j i_{n-1,j} omega_{j,n}"),
            "\\omega_{n-1,n} = \\sum_j i_{n-1,j} \\omega_{j,n}");
  EXPECT_EQ(formula_tex("omega-dot_{j,n}"), "\\dot\\omega_{j,n}");
  EXPECT_EQ(formula_tex("sum_{j!=l}"), "\\sum_{j\\neq l}");
  EXPECT_EQ(formula_tex("omega_out/omega_in"), "\\omega_{\\mathrm{out}}/\\omega_{\\mathrm{in}}");
  EXPECT_EQ(formula_tex("Q_jK'_j / Q_jK_n"), "Q_jK'_j / Q_jK_n");
  EXPECT_EQ(formula_tex("|r_{n-1}|^2"), "\\vert r_{n-1}\\vert^2");
  EXPECT_EQ(formula_tex("j < l"), "j \\lt l");
  EXPECT_EQ(formula_tex("_j omega-dot_{n-1,n}"), "{}_j \\dot\\omega_{n-1,n}");
  // A left subscript after a sum's own: a new atom, not a double subscript (pdflatex stopped).
  EXPECT_EQ(formula_tex("sum_j _j omega-dot_{n-1,n}"), "\\sum_j {}_j \\dot\\omega_{n-1,n}");
  EXPECT_EQ(formula_tex("omega_{n-1,n}^2 r_{n-1}"), "\\omega_{n-1,n}^2 r_{n-1}");
}

TEST(StatementTex, StatementKeepsItsWordsAsText) {
  const Rich r = statement_rich("i_{n-1,j} = Q_jK'_j / Q_jK_n (directed) equals omega_out/omega_in of four-bar j");
  EXPECT_EQ(joined(r, false),
            "$i_{n-1,j} = Q_jK'_j / Q_jK_n$ (directed) equals $\\omega_{\\mathrm{out}}/\\omega_{\\mathrm{in}}$ of "
            "four-bar $j$");
}

TEST(StatementTex, AStatementOutsideTheFormulaAlphabetStaysPlainText) {
  for (const char* hostile : {"x = \\input{/etc/passwd}", "a}$ b", "x^^5c", "50% of x", "a_{b", "a}b{", "x_a_b",
                              "x^a^b", "x_", "a & b", "#1", "x ~ y", "é = 1"}) {
    const Rich r = statement_rich(hostile);
    ASSERT_EQ(r.size(), 1u) << hostile;
    EXPECT_FALSE(r[0].math) << hostile;
    EXPECT_EQ(r[0].text, hostile);
  }
}

TEST(StatementTex, MathHoldsNoCommandOfTheInput) {
  // Every backslash in the math is one the translation wrote.
  const Rich r = statement_rich("Delta omega-dot_{n-1,n} = -cot phi S_1 - (r_{n-2}/(r_{n-1} sin phi)) S_2, phi signed (ccw)");
  for (const Span& s : r)
    if (s.math)
      for (size_t at = s.text.find('\\'); at != std::string::npos; at = s.text.find('\\', at + 1)) {
        const std::string command = s.text.substr(at + 1, s.text.find_first_not_of("abcdefghijklmnopqrstuvwxyzDelta", at + 1) - at - 1);
        EXPECT_TRUE(command == "Delta" || command == "dot" || command == "omega" || command == "cot" || command == "phi" ||
                    command == "sin")
            << command;
      }
  EXPECT_NE(joined(r, true).find("\\cot \\phi"), std::string::npos) << joined(r, false);
}

TEST(StatementTex, TermLabelsOfTheEngineAreTypeset) {
  EXPECT_EQ(term_label_rich("omega[1]*omega[2]")[0].text, "\\omega_{1}\\omega_{2}");
  EXPECT_EQ(term_label_rich("omega_dot[2]")[0].text, "\\dot\\omega_{2}");
  EXPECT_EQ(term_label_rich("j=1: omega[1]^2")[0].text, "j=1:\\ \\omega_{1}^2");
  EXPECT_TRUE(term_label_rich("omega[1]^2")[0].math);
  for (const char* other : {"total", "j=1", "omega[1]\\input", "x_{1}"}) {
    const Rich r = term_label_rich(other);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_FALSE(r[0].math) << other;
    EXPECT_EQ(r[0].text, other);
  }
}

}  // namespace
}  // namespace linkproof::report
