// The three renderers of a report document: escaping, math, figures, sections.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "linkproof/report/render.h"

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

}  // namespace
}  // namespace linkproof::report
