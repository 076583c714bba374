// The three renderers of a report document: escaping, math, figures, sections.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <fstream>

#include "report/render.h"
#include "report/report_checks.h"

namespace linkproof::report {
namespace {

Document small_document() {
  Document d;
  d.title = "T <&> report";
  Section s{"summary", "Summary", {}, {}};
  s.blocks.push_back(paragraph({text("a < b & c_1 50% $"), math("\\omega_{1} = \\frac{1}{2}")}));
  s.blocks.push_back(display_math("\\dot\\omega_{4,5} = \\frac{3755}{1331}"));
  s.blocks.push_back(table_block({{plain("claim"), plain("verdict")}, {{plain("eq|22"), tex("x^2")}}}));
  Drawing dr;
  dr.segments.push_back(Segment{{0, 0}, {1, 1}, "#222222", Stroke::Solid, false, ""});
  s.blocks.push_back(figure_block({"fig-a", "A figure.", dr}));
  Section sub{"sub", "Sub", {code_block("linkproof report x.yaml")}, {}};
  s.subsections.push_back(sub);
  d.sections.push_back(s);
  d.reproduce = {"linkproof report x.yaml --format html", "none", "0.1.0", "abc"};
  add_reproduce_section(d);
  return d;
}

TEST(ReportRender, HtmlEscapesTextAndMarksMathForKatex) {
  const std::string html = render_html(small_document(), KatexAssets{"/*katex*/", "/*css*/", "x"});
  EXPECT_NE(html.find("a &lt; b &amp; c_1"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"lp-math\" data-tex=\"\\omega_{1} = \\frac{1}{2}\">"), std::string::npos);
  EXPECT_NE(html.find("class=\"lp-math lp-display\""), std::string::npos);
  EXPECT_NE(html.find("<section id=\"summary\">"), std::string::npos);
  EXPECT_NE(html.find("<section id=\"reproduce\">"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("/*katex*/"), std::string::npos);
  EXPECT_NE(html.find("katex.render"), std::string::npos);
  EXPECT_EQ(html.find("class=\"lp-nokatex\""), std::string::npos);
}

TEST(ReportRender, HtmlWithoutKatexSaysSoAndLoadsNoScript) {
  const std::string html = render_html(small_document(), std::nullopt);
  EXPECT_NE(html.find("class=\"lp-nokatex\""), std::string::npos);
  EXPECT_EQ(html.find("katex.render"), std::string::npos);
}

TEST(ReportRender, KatexAssetsInlineWoff2FontsAsDataUrlsAndDropOtherFormats) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "linkproof_katex_test";
  fs::create_directories(dir / "fonts");
  std::ofstream(dir / "katex.min.js") << "var katex={};";
  std::ofstream(dir / "katex.min.css")
      << "@font-face{font-family:KaTeX_Main;src:url(fonts/KaTeX_Main-Regular.woff2) format(\"woff2\"),"
         "url(fonts/KaTeX_Main-Regular.woff) format(\"woff\"),url(fonts/KaTeX_Main-Regular.ttf) format(\"truetype\")}";
  std::ofstream(dir / "fonts" / "KaTeX_Main-Regular.woff2") << "abc";
  const auto assets = load_katex_assets(dir.string());
  ASSERT_TRUE(assets);
  EXPECT_NE(assets->stylesheet.find("url(data:font/woff2;base64,YWJj)"), std::string::npos) << assets->stylesheet;
  EXPECT_EQ(assets->stylesheet.find("fonts/"), std::string::npos) << assets->stylesheet;
  EXPECT_FALSE(load_katex_assets((dir / "missing").string()));
  fs::remove_all(dir);
}

TEST(ReportRender, MarkdownUsesDollarMathAndWritesFiguresBeside) {
  std::map<std::string, std::string> files;
  const std::string md = render_markdown(small_document(), files);
  EXPECT_NE(md.find("$\\omega_{1} = \\frac{1}{2}$"), std::string::npos);
  EXPECT_NE(md.find("$$\n\\dot\\omega_{4,5}"), std::string::npos);
  EXPECT_NE(md.find("eq\\|22"), std::string::npos);  // a pipe in a cell does not split it
  EXPECT_NE(md.find("50% \\$"), std::string::npos);    // a plain dollar is not math
  ASSERT_EQ(files.count("fig-a.svg"), 1u);
  EXPECT_NE(md.find("](fig-a.svg)"), std::string::npos);
  EXPECT_EQ(files["fig-a.svg"].rfind("<svg", 0), 0u);
}

TEST(ReportRender, LatexEscapesTextAndKeepsMath) {
  const std::string tex = render_latex(small_document());
  EXPECT_NE(tex.find("\\documentclass"), std::string::npos);
  EXPECT_NE(tex.find("a $<$ b \\& c\\_1 50\\% \\$"), std::string::npos);
  EXPECT_NE(tex.find("$\\omega_{1} = \\frac{1}{2}$"), std::string::npos);
  EXPECT_NE(tex.find("\\begin{longtable}"), std::string::npos);
  EXPECT_NE(tex.find("\\label{reproduce}"), std::string::npos);
  EXPECT_NE(tex.find("\\end{document}"), std::string::npos);
}

// --- hostile plain strings: every renderer escapes them for its language

// A document whose every plain string came from a hostile scene.
Document hostile_document() {
  Document d;
  d.title = "x}$\\input{/etc/passwd}\n# Injected title <script>alert(1)</script>";
  d.subtitle = "```\n<b>";
  Section s{"summary\"><script>alert(2)</script>", "a\n\nb ## ``` <i>", {}, {}};
  s.blocks.push_back(paragraph(plain("    [x]: javascript:alert(3)\n\n# Injected")));
  s.blocks.push_back(table_block({{plain("a|b"), plain("c")}, {{plain("[2pt] x"), plain("y\n| z")}, {plain("*"), plain("w")}}}));
  s.blocks.push_back(list_block({plain("[label] item"), plain("1. x")}));
  s.blocks.push_back(code_block("```\n\\end{verbatim}\n\\input{/etc/passwd}\n<script>alert(4)</script>\n````"));
  d.sections.push_back(s);
  return d;
}

TEST(ReportRender, LatexListingCannotBeClosedFromInside) {
  const std::string tex = render_latex(hostile_document());
  EXPECT_EQ(test::count(tex, "\\begin{verbatim}"), 1u);
  EXPECT_EQ(test::count(tex, "\\end{verbatim}"), 1u) << tex;
  EXPECT_EQ(test::latex_outside_verbatim(tex).find("\\input"), std::string::npos) << tex;
}

TEST(ReportRender, LatexPlainTextHasNoCommandNoBlankLineAndBalancedBraces) {
  const std::string tex = test::latex_outside_verbatim(render_latex(hostile_document()));
  EXPECT_EQ(test::latex_brace_depth_problem(tex), "") << tex;
  EXPECT_EQ(tex.find("\\input"), std::string::npos) << tex;
  // After \\ and \item LaTeX reads an optional [..]: a cell or item that starts with one is shielded.
  EXPECT_NE(tex.find("\\endhead\n{}[2pt] x"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\\\\n{}* & w"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\item {}[label] item"), std::string::npos) << tex;
}

TEST(ReportRender, MarkdownKeepsItsHeadingsFencesAndTablesWhateverTheText) {
  std::map<std::string, std::string> files;
  const std::string md = render_markdown(hostile_document(), files);
  const test::MarkdownOutline o = test::markdown_outline(md);
  EXPECT_EQ(o.fences, 1u) << md;
  EXPECT_FALSE(o.unclosed_fence) << md;
  ASSERT_EQ(o.headings.size(), 2u) << md;  // the title and the one section
  EXPECT_EQ(o.headings[1].rfind("## a  b \\#\\# \\`\\`\\` \\<i>", 0), 0u) << o.headings[1];
  EXPECT_EQ(o.raw_html_other_than_anchors, "") << md;
  EXPECT_EQ(o.bad_table_rows, std::vector<std::string>{}) << md;
  EXPECT_NE(md.find("\n\\[x]: javascript"), std::string::npos) << "a link definition at a paragraph's start" << md;
  EXPECT_NE(md.find("- 1\\. x"), std::string::npos) << md;
}

TEST(ReportRender, HtmlOfHostileStringsHasOnlyTheRenderersElements) {
  const std::string html = render_html(hostile_document(), std::nullopt);
  EXPECT_EQ(html.find("<script"), std::string::npos) << html;
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_EQ(html.find("<i>"), std::string::npos);
  EXPECT_NE(html.find("<section id=\"summary-22-3e-3cscript-3ealert-282-29"), std::string::npos)
      << "an attribute was closed from inside";
}

TEST(ReportRender, HtmlEscapeReplacesWhatXmlForbids) {
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(html_escape(std::string("a\x01") + "b\x7f" + "\xff" + "<\"&>\tc\n"),
            "a" + fffd + "b" + fffd + fffd + "&lt;&quot;&amp;&gt;\tc\n");
  EXPECT_EQ(html_escape("ω̇ K'_1"), "ω̇ K'_1");  // valid UTF-8 is kept
}

// A long value or formula: HTML folds it behind its line in <details>; Markdown and LaTeX show
// math in full and plain text by its line (a fraction of hundreds of digits is for --json).
Document folded_document() {
  Document d;
  d.title = "Folds";
  Section s{"summary", "Summary", {}, {}};
  s.blocks.push_back(table_block({{plain("value"), plain("coefficient")},
                                  {{{folded(text("123456789/1000"), "≈ 123456.789 (exact: 13 digits)")},
                                    {folded(math("x^{2}+y^{2}"), "a rational function")}}}}));
  s.blocks.push_back(display_equation("\\omega_{4,5}", std::string(kFoldTexChars, 'x')));
  s.blocks.push_back(display_equation("\\omega_{3,5}", "x"));
  d.sections.push_back(s);
  return d;
}

TEST(ReportRender, HtmlFoldsALongValueBehindItsLineInDetails) {
  const std::string html = render_html(folded_document(), std::nullopt);
  EXPECT_NE(html.find("<details class=\"lp-fold\"><summary>≈ 123456.789 (exact: 13 digits)</summary><div "
                      "class=\"lp-folded\">123456789/1000</div></details>"),
            std::string::npos);
  EXPECT_NE(html.find("<summary>a rational function</summary><div class=\"lp-folded\"><span class=\"lp-math\""),
            std::string::npos);
}

TEST(ReportRender, DisplayEquationFoldsOnlyALongOne) {
  const std::string html = render_html(folded_document(), std::nullopt);
  size_t folds = 0;
  for (size_t at = html.find("class=\"lp-fold lp-fold-display\""); at != std::string::npos;
       at = html.find("class=\"lp-fold lp-fold-display\"", at + 1))
    ++folds;
  EXPECT_EQ(folds, 1u);  // the long equation only
  EXPECT_NE(html.find("data-tex=\"\\omega_{4,5} = \\ldots\""), std::string::npos);
  EXPECT_NE(html.find("<div class=\"lp-math lp-display\" data-tex=\"\\omega_{3,5} = x\">"), std::string::npos);
}

TEST(ReportRender, MarkdownAndLatexShowFoldedMathInFullAndFoldedTextByItsLine) {
  std::map<std::string, std::string> files;
  const std::string md = render_markdown(folded_document(), files);
  EXPECT_NE(md.find("≈ 123456.789 (exact: 13 digits)"), std::string::npos);
  EXPECT_EQ(md.find("123456789/1000"), std::string::npos);
  EXPECT_NE(md.find("$x^{2}+y^{2}$"), std::string::npos);
  const std::string tex = render_latex(folded_document());
  EXPECT_EQ(tex.find("123456789/1000"), std::string::npos);
  EXPECT_NE(tex.find("$x^{2}+y^{2}$"), std::string::npos);
}

TEST(ReportRender, HtmlPutsAFigureAndTheHeadlineAfterItSideBySide) {
  Document d;
  Section s{"summary", "Summary", {}, {}};
  Drawing dr;
  dr.segments.push_back(Segment{{0, 0}, {1, 1}, "#222222", Stroke::Solid, false, ""});
  s.blocks.push_back(figure_block({"fig-a", "A figure.", dr}));
  s.blocks.push_back(headline_block({plain("17 of 17 true claims hold"), plain("all 30 claims as expected")}));
  d.sections.push_back(s);
  const std::string html = render_html(d, std::nullopt);
  const size_t hero = html.find("<div class=\"lp-hero\">"), figure = html.find("<figure"),
               headline = html.find("<ul class=\"lp-headline\">\n<li>17 of 17 true claims hold</li>");
  ASSERT_NE(hero, std::string::npos);
  EXPECT_LT(hero, figure);
  EXPECT_LT(figure, headline);
  EXPECT_NE(html.find("@media print"), std::string::npos);
  std::map<std::string, std::string> files;
  EXPECT_NE(render_markdown(d, files).find("- 17 of 17 true claims hold\n"), std::string::npos);
  EXPECT_NE(render_latex(d).find("\\item 17 of 17 true claims hold"), std::string::npos);
}

}  // namespace
}  // namespace linkproof::report
