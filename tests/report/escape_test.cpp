// report/escape.h: the one escaping function per output language, on plain names (kept as they
// are, so bundled reports do not change) and on any string (properties).
#include "report/escape.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cctype>

#include "report/report_checks.h"

namespace linkproof::report {
namespace {

TEST(ReportEscape, PlainNamesAreKeptInEveryLanguage) {
  for (const std::string s : {"pentagon", "fourbar-seed001", "dijksman1966.eq4.printed", "O2", "guide D"}) {
    EXPECT_EQ(html_escape(s), s);
    EXPECT_EQ(latex_math_escape(s), s);
    EXPECT_EQ(markdown_escape(s), s);
  }
  EXPECT_EQ(file_stem("pentagon-construction"), "pentagon-construction");
  EXPECT_EQ(anchor_id("proof-dijksman1966.eq5"), "proof-dijksman1966.eq5");
  EXPECT_EQ(latex_escape("K'_j at (−8, 31) ω̇"), "K'\\_j at (-8, 31) $\\dot\\omega$");
  EXPECT_EQ(latex_escape("docs/conventions.md §A3"), "docs/conventions.md \\S{}A3");  // the citations
  EXPECT_EQ(latex_verbatim("§A8 \xce\xb2"), "\\begin{verbatim}\nsec. A8 ?\n\\end{verbatim}\n");
}

TEST(ReportEscape, FileStemOfAPathIsOneNameInsideTheDirectory) {
  EXPECT_EQ(file_stem("../../x"), "_.._x");
  EXPECT_EQ(file_stem("/etc/passwd"), "_etc_passwd");
  EXPECT_EQ(file_stem("a/b"), "a_b");
  EXPECT_EQ(file_stem("..\\..\\x"), "_.._x");
  EXPECT_EQ(file_stem(".hidden"), "hidden");
  EXPECT_EQ(file_stem("-rf"), "rf");
  EXPECT_EQ(file_stem(".."), "unnamed");
  EXPECT_EQ(file_stem(""), "unnamed");
  EXPECT_EQ(file_stem("ωβ x"), "___x");  // one '_' per character, not per byte
}

TEST(ReportEscape, FileStemOfALongNameIsBoundedAndKeepsNamesApart) {
  const std::string a = file_stem(std::string(300, 'n') + "a"), b = file_stem(std::string(300, 'n') + "b");
  EXPECT_EQ(a.size(), kMaxFileStemBytes);
  EXPECT_NE(a, b);
  EXPECT_EQ(a, file_stem(std::string(300, 'n') + "a"));  // deterministic
  EXPECT_EQ(a.rfind(std::string(kMaxFileStemBytes - 17, 'n') + "-", 0), 0u) << a;
}

TEST(ReportEscape, AnchorIdKeepsOnlyInertCharacters) {
  EXPECT_EQ(anchor_id("a\"><script>"), "a-22-3e-3cscript-3e");
  EXPECT_EQ(anchor_id("x}\\input{y}"), "x-7d-5cinput-7by-7d");
}

TEST(ReportEscape, MarkdownBlockStartIsEscaped) {
  EXPECT_EQ(markdown_escape("    - x", true), "\\- x");
  EXPECT_EQ(markdown_escape("[a]: javascript:x", true), "\\[a]: javascript:x");
  EXPECT_EQ(markdown_escape("12) x", true), "12\\) x");
  EXPECT_EQ(markdown_escape("> q", true), "\\> q");
  EXPECT_EQ(markdown_escape("- x"), "- x");  // not at a block's start: nothing to escape
  EXPECT_EQ(markdown_escape("[t](javascript:x) [t][r]"), "[t\\](javascript:x) [t\\][r]");
  EXPECT_EQ(markdown_escape("a\nb\r\tc\x01"), "a b  c?");
}

TEST(ReportEscape, MarkdownFenceIsLongerThanAnyBacktickRun) {
  EXPECT_EQ(markdown_code_block("x"), "```\nx\n```\n");
  EXPECT_EQ(markdown_code_block("a ```` b\n```"), "`````\na ```` b\n```\n`````\n");
}

TEST(ReportEscape, LatexVerbatimIsBrokenBeforeItsEndMarker) {
  const std::string v = latex_verbatim("a\\end{verbatim}b\r\nc\x0c\xce\xb2");
  EXPECT_EQ(v, "\\begin{verbatim}\na\\end{verbatim\n}b\nc??\n\\end{verbatim}\n");
  EXPECT_EQ(test::count(v, "\\end{verbatim}"), 1u);
}

// Properties over any bytes: the invariants each escaper promises.
RC_GTEST_PROP(ReportEscape, LatexEscapeOfAnyStringIsInertAscii, (const std::string& s)) {
  const std::string e = latex_escape(s);
  for (char c : e) RC_ASSERT((c >= 0x20 && c < 0x7f));
  RC_ASSERT(test::latex_brace_depth_problem("{" + e + "}").empty());
  RC_ASSERT(e.find("^^") == std::string::npos);
  RC_ASSERT(test::latex_structure(e).empty());  // only what escaping makes: no command of s
}

RC_GTEST_PROP(ReportEscape, LatexMathEscapeOfAnyStringIsInert, (const std::string& s, bool superscript)) {
  const std::string e = latex_math_escape(s, superscript);
  RC_ASSERT(test::latex_brace_depth_problem("{" + e + "}").empty());
  RC_ASSERT(e.find("^^") == std::string::npos);
  RC_ASSERT(e.find('$') == std::string::npos || e.find("\\$") != std::string::npos);
  RC_ASSERT(test::latex_structure(e).empty());
}

RC_GTEST_PROP(ReportEscape, LatexVerbatimOfAnyStringHasOneEnd, (const std::string& s)) {
  const std::string v = latex_verbatim(s);
  RC_ASSERT(test::count(v, "\\end{verbatim}") == 1u);
  RC_ASSERT(v.size() >= 15 && v.compare(v.size() - 15, 15, "\\end{verbatim}\n") == 0);
}

RC_GTEST_PROP(ReportEscape, MarkdownEscapeOfAnyStringIsOneInertLine, (const std::string& s)) {
  const std::string e = markdown_escape(s, true);
  RC_ASSERT(e.find('\n') == std::string::npos && e.find('\r') == std::string::npos);
  const test::MarkdownOutline o = test::markdown_outline(e + "\n");
  RC_ASSERT(o.headings.empty());
  RC_ASSERT(o.fences == 0u);
  RC_ASSERT(o.raw_html_other_than_anchors.empty());
}

RC_GTEST_PROP(ReportEscape, MarkdownCodeBlockOfAnyStringIsOneClosedFence, (const std::string& s)) {
  const test::MarkdownOutline o = test::markdown_outline(markdown_code_block(s));
  RC_ASSERT(o.fences == 1u);
  RC_ASSERT(!o.unclosed_fence);
}

RC_GTEST_PROP(ReportEscape, FileStemOfAnyStringIsOneBoundedName, (const std::string& s)) {
  const std::string f = file_stem(s);
  RC_ASSERT(!f.empty() && f.size() <= kMaxFileStemBytes);
  RC_ASSERT(f[0] != '.' && f[0] != '-');
  for (char c : f)
    RC_ASSERT((std::isalnum(static_cast<unsigned char>(c)) || std::string("._+-").find(c) != std::string::npos));
  RC_ASSERT(f == file_stem(s));
}

RC_GTEST_PROP(ReportEscape, HtmlEscapeOfAnyStringHasNoMarkup, (const std::string& s)) {
  const std::string e = html_escape(s);
  RC_ASSERT(e.find('<') == std::string::npos && e.find('>') == std::string::npos && e.find('"') == std::string::npos);
  for (char c : e) RC_ASSERT((static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r'));
}

}  // namespace
}  // namespace linkproof::report
