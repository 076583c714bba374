// The drawing model: the view keeps the linkage readable, and both renderers draw every primitive.
#include <gtest/gtest.h>

#include <cstdio>

#include "report/drawing.h"

namespace linkproof::report {
namespace {

Drawing unit_square_with(Point2 far) {
  Drawing d;
  d.segments.push_back(Segment{{0, 0}, {1, 0}, "#222222", Stroke::Solid, false, ""});
  d.segments.push_back(Segment{{1, 0}, {1, 1}, "#222222", Stroke::Solid, false, ""});
  d.markers.push_back({{0, 0}, "K_1", "#222222", true, false});
  d.markers.push_back({far, "Q_1", "#aa0000", false, true});
  return d;
}

TEST(ReportDrawing, ViewIncludesNearConstructionPoints) {
  const View v = compute_view(unit_square_with({3, 2}));
  EXPECT_LE(v.x0, 0);
  EXPECT_GE(v.x1, 3);
  EXPECT_GE(v.y1, 2);
  EXPECT_TRUE(v.off_view.empty());
}

TEST(ReportDrawing, FarConstructionPointIsListedNotShrinkingTheLinkage) {
  const View v = compute_view(unit_square_with({1e6, 0}));
  EXPECT_LT(v.x1, 10);  // the unit square keeps most of the figure
  ASSERT_EQ(v.off_view.size(), 1u);
  EXPECT_NE(v.off_view[0].find("Q_1"), std::string::npos);
}

// The construction draws lines to Q_j: a line to a far point must not widen the view either
// (before, every segment's ends counted, so Q_j near infinity shrank the linkage to a dot).
TEST(ReportDrawing, FarConstructionPointReachedByALineDoesNotShrinkTheLinkage) {
  Drawing d = unit_square_with({1e6, 0});
  d.segments.push_back(Segment{{1, 0}, {1e6, 0}, "#aa0000", Stroke::Dashed, false, ""});
  const View v = compute_view(d);
  EXPECT_LT(v.x1, 10);
  ASSERT_EQ(v.off_view.size(), 1u);
}

TEST(ReportDrawing, NearConstructionPointsKeepOnePanel) {
  EXPECT_FALSE(detail_view(unit_square_with({3, 2})).has_value());
  EXPECT_EQ(render_svg(unit_square_with({3, 2})).find("the linkage enlarged"), std::string::npos);
}

TEST(ReportDrawing, AConstructionMuchLargerThanTheLinkageGetsAnEnlargedPanel) {
  Drawing d = unit_square_with({5, 5});
  d.segments.push_back(Segment{{1, 1}, {5, 5}, "#aa0000", Stroke::Dashed, false, ""});
  const auto detail = detail_view(d);
  ASSERT_TRUE(detail.has_value());
  EXPECT_LT(detail->x1 - detail->x0, 2);  // the unit square with a margin
  const std::string svg = render_svg(d);
  EXPECT_NE(svg.find("the linkage enlarged"), std::string::npos);
  size_t panels = 0;
  for (size_t at = svg.find("<svg x="); at != std::string::npos; at = svg.find("<svg x=", at + 1)) ++panels;
  EXPECT_EQ(panels, 2u);
}

TEST(ReportDrawing, LatexPictureOfAConstructionMuchLargerThanTheLinkageHasTheLinkageEnlargedBeside) {
  Drawing d = unit_square_with({5, 5});
  d.segments.push_back(Segment{{1, 1}, {5, 5}, "#aa0000", Stroke::Dashed, false, ""});
  const std::string tex = render_latex_picture(d);
  size_t pictures = 0;
  for (size_t at = tex.find("\\begin{picture}"); at != std::string::npos; at = tex.find("\\begin{picture}", at + 1)) ++pictures;
  EXPECT_EQ(pictures, 2u);
  EXPECT_EQ(render_latex_picture(unit_square_with({3, 2})).find("\\quad"), std::string::npos);
}

TEST(ReportDrawing, SvgWritesGreekNamesOfLabelsAsLetters) {
  Drawing d = unit_square_with({3, 2});
  d.angles.push_back({{0, 0}, {1, 0}, {0, 1}, "beta_1", "#aa3300"});
  const std::string svg = render_svg(d);
  EXPECT_NE(svg.find(">β<tspan baseline-shift=\"sub\" font-size=\"75%\">1</tspan>"), std::string::npos);
  EXPECT_EQ(svg.find(">beta<"), std::string::npos);
}

TEST(ReportDrawing, SvgHasEverySegmentMarkerAndSubscriptLabel) {
  const std::string svg = render_svg(unit_square_with({3, 2}));
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  size_t lines = 0, circles = 0;
  for (size_t at = svg.find("<line"); at != std::string::npos; at = svg.find("<line", at + 1)) ++lines;
  for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(lines, 2u);
  EXPECT_EQ(circles, 2u);
  EXPECT_NE(svg.find("K<tspan baseline-shift=\"sub\""), std::string::npos);
}

TEST(ReportDrawing, SvgPutsWorldYUpwards) {
  Drawing d;
  d.segments.push_back(Segment{{0, 0}, {0, 10}, "#222222", Stroke::Solid, false, ""});
  const std::string svg = render_svg(d, 100);
  // The world point (0, 10) is above (0, 0): a smaller SVG y.
  double y1 = 0, y2 = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + svg.find("y1=\""), "y1=\"%lf\"", &y1), 1);
  ASSERT_EQ(std::sscanf(svg.c_str() + svg.find("y2=\""), "y2=\"%lf\"", &y2), 1);
  EXPECT_LT(y2, y1);
}

TEST(ReportDrawing, LatexPictureDrawsWithPdfLiteralAndTypesetsLabels) {
  Drawing d = unit_square_with({3, 2});
  d.angles.push_back({{3, 2}, {-1, 0}, {0, -1}, "beta_1"});
  const std::string tex = render_latex_picture(d);
  EXPECT_NE(tex.find("\\begin{picture}"), std::string::npos);
  EXPECT_NE(tex.find("\\pdfliteral{"), std::string::npos);
  EXPECT_NE(tex.find("$K_{1}$"), std::string::npos);
  EXPECT_NE(tex.find("$\\beta_{1}$"), std::string::npos);
}

TEST(ReportDrawing, LabelTexMapsGreekNamesAndSubscripts) {
  EXPECT_EQ(label_tex("K'_1"), "K'_{1}");
  EXPECT_EQ(label_tex("beta_2"), "\\beta_{2}");
  EXPECT_EQ(label_tex("O_A"), "O_{A}");
  EXPECT_EQ(label_tex("P"), "P");
}

// A link or joint name is a user string: in the LaTeX picture it is math, and no character of
// it may end the math, open a group or start a command (also through TeX's ^^5c notation).
TEST(ReportDrawing, LabelTexOfHostileNamesHasNoCommandOfTheName) {
  for (const std::string name : {"}$\\input{/etc/passwd}$", "O^^5cinput{/etc/passwd}", "A_}$\\input{x}", "x%y#z&w~v",
                                 "A_B_C", "a^b^c", "P\\section{Injected}"}) {
    const std::string tex = label_tex(name);
    EXPECT_EQ(tex.find("\\input"), std::string::npos) << tex;
    EXPECT_EQ(tex.find("\\section"), std::string::npos) << tex;
    EXPECT_EQ(tex.find("^^"), std::string::npos) << tex;
    long depth = 0, dollars = 0;
    for (size_t i = 0; i < tex.size(); ++i) {
      if (tex[i] == '\\') {
        ++i;
        continue;
      }
      depth += tex[i] == '{' ? 1 : tex[i] == '}' ? -1 : 0;
      EXPECT_GE(depth, 0) << tex;
      dollars += tex[i] == '$';
      EXPECT_TRUE(tex[i] != '%' && tex[i] != '#' && tex[i] != '&') << tex;  // a comment, a parameter, a tab
    }
    EXPECT_EQ(depth, 0) << tex;
    EXPECT_EQ(dollars, 0) << tex;
  }
  EXPECT_EQ(label_tex("A_B_C"), "A_{B\\_C}");  // one subscript: a second _ is shown, not a double subscript
  EXPECT_EQ(label_tex("A_BA^t"), "A_{BA^t}");   // the program's own superscript stays
}

TEST(ReportDrawing, SvgOfHostileLabelsAndColoursHasNoInjectedElement) {
  Drawing d;
  d.segments.push_back(
      Segment{{0, 0}, {1, 1}, "\"/><script>alert(1)</script><x a=\"", Stroke::Solid, false, "<script>"});
  d.markers.push_back({{0, 0}, "<img src=x>_<b>", "#222222", true, false});
  const std::string svg = render_svg(d);
  EXPECT_EQ(svg.find("<script"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("<img"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("<b>"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("<x "), std::string::npos) << svg;
}

TEST(ReportDrawing, LatexPictureOfAColourThatIsNotHexIsDrawnBlack) {
  Drawing d;
  d.segments.push_back(Segment{{0, 0}, {1, 1}, "#zzzzzz", Stroke::Solid, false, ""});
  std::string tex;
  EXPECT_NO_THROW(tex = render_latex_picture(d));  // std::stoi threw std::invalid_argument
  EXPECT_NE(tex.find("0 0 0 RG"), std::string::npos) << tex;
}

}  // namespace
}  // namespace linkproof::report
