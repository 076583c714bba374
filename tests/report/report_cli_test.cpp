// `linkproof report` in-process on the bundled scenes and the paper's claim file: the files
// written, their sections in order, exact values from the check, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli_run.h"
#include "support/temp_dir.h"

namespace linkproof {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::run_cli;
using test::slurp;
using test::TempDir;

std::string source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

// The positions of the sections (by id) in the HTML, which must be increasing.
void expect_sections_in_order(const std::string& html, const std::vector<std::string>& ids) {
  size_t last = 0;
  for (const auto& id : ids) {
    const size_t at = html.find("<section id=\"" + id + "\">");
    ASSERT_NE(at, std::string::npos) << "section " << id;
    EXPECT_GT(at, last) << "section " << id << " out of order";
    last = at;
  }
}

TEST(ReportCli, PentagonHtmlHasTheSectionsInOrderWithExactValues) {
  TempDir dir("pentagon");
  const CliRun r = run_cli({"report", source("verify/scenes/pentagon.yaml"), "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = slurp(dir.path / "pentagon.html");
  expect_sections_in_order(html, {"summary", "derivation", "construction", "terms", "errata", "reproduce"});
  EXPECT_EQ(html.find("<section id=\"numerics\">"), std::string::npos);  // not asked
  EXPECT_NE(html.find("\\frac{7331}{2662}"), std::string::npos);         // omega-dot_{3,5} (conventions §A8)
  EXPECT_NE(html.find("\\frac{3755}{1331}"), std::string::npos) << "omega-dot_{4,5}";
  EXPECT_NE(html.find("\\frac{26}{5} = 5.2</span>, <span class=\"lp-math\" data-tex=\"\\frac{23}{5} = 4.6"),
            std::string::npos)
      << "Q_1";
  EXPECT_NE(html.find("-\\frac{705}{2662}"), std::string::npos) << "lambda_1";
  EXPECT_NE(html.find("\\cot\\varphi = -\\frac{2}{11}"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("linkproof report " + source("verify/scenes/pentagon.yaml") + " --format html"),
            std::string::npos);
  EXPECT_NE(html.find("dijksman1966.eq22"), std::string::npos);
}

// A report is the same bytes in every run: GiNaC's own LaTeX printer follows an operand order
// seeded by addresses that ASLR moves (and normal() picks a fraction's signs by it), so the
// derivation's formulas once differed from run to run (report/canonical_latex.h). Each run is a
// new process with its own address layout.
TEST(ReportCli, DerivationIsTheSameBytesInEveryRun) {
  TempDir dir("pentagon_runs");
  std::string first;
  for (int run = 0; run < 4; ++run) {
    const CliRun r = run_cli({"report", source("verify/scenes/hexagon.yaml"), "--format", "md", "--out", dir.path.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string md = slurp(dir.path / "hexagon.md");
    ASSERT_NE(md.find("L_1 \\cos(\\theta_{1})+L_2 \\cos(\\theta_{2})"), std::string::npos) << "loop closure in side order";
    if (run == 0)
      first = md;
    else
      EXPECT_EQ(md, first) << "run " << run << " differs from the first";
  }
}

TEST(ReportCli, PentagonMarkdownAndLatexAreWrittenWithFigures) {
  TempDir dir("pentagon_all");
  const CliRun r =
      run_cli({"report", source("verify/scenes/pentagon.yaml"), "--format", "all", "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string md = slurp(dir.path / "pentagon.md");
  EXPECT_NE(md.find("<a id=\"derivation\"></a>\n\n## Derivation"), std::string::npos);
  EXPECT_NE(md.find("](pentagon-construction.svg)"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir.path / "pentagon-construction.svg"));
  const std::string tex = slurp(dir.path / "pentagon.tex");
  EXPECT_NE(tex.find("\\section{Construction}\\label{construction}"), std::string::npos);
  EXPECT_NE(tex.find("\\begin{picture}"), std::string::npos);
}

// Issue 27: every exact value with its decimal, the summary opening with the drawing beside the
// headline, long formulas folded.
TEST(ReportCli, PentagonShowsEachExactValueWithItsDecimal) {
  TempDir dir("pentagon_decimals");
  const CliRun r =
      run_cli({"report", source("verify/scenes/pentagon.yaml"), "--format", "all", "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* file : {"pentagon.html", "pentagon.md", "pentagon.tex"}) {
    const std::string text = slurp(dir.path / file);
    EXPECT_NE(text.find("\\frac{3755}{1331} \\approx 2.821187077"), std::string::npos) << file << ": omega-dot_{4,5}";
    EXPECT_NE(text.find("\\frac{7331}{2662} \\approx 2.753944403"), std::string::npos) << file << ": omega-dot_{3,5}";
    EXPECT_NE(text.find("-\\frac{705}{2662} \\approx -0.2648384673"), std::string::npos) << file << ": lambda_1";
  }
}

TEST(ReportCli, SummaryOpensWithTheDrawingBesideTheClaimsAtAGlance) {
  TempDir dir("pentagon_hero");
  ASSERT_EQ(run_cli({"report", source("verify/scenes/pentagon.yaml"), "--out", dir.path.string()}).code, 0);
  const std::string html = slurp(dir.path / "pentagon.html");
  const size_t summary = html.find("<section id=\"summary\">"), hero = html.find("<div class=\"lp-hero\">", summary),
               figure = html.find("id=\"fig-pentagon-construction\"", summary), table = html.find("<table", summary);
  ASSERT_NE(hero, std::string::npos);
  EXPECT_LT(hero, figure);
  EXPECT_LT(figure, table);
  EXPECT_NE(html.find("<li>17 of 17 true claims hold</li>"), std::string::npos);
  EXPECT_NE(html.find("<li>12 of 13 erratum readings fail, as expected (1 coincides with the truth on this scene)</li>"),
            std::string::npos);
  // The long derived formulas are folded: no displayed equation wider than the page.
  EXPECT_NE(html.find("class=\"lp-fold lp-fold-display\""), std::string::npos);
}

TEST(ReportCli, SliderCrankFromDimensionsShowsLongFractionsByTheirDecimals) {
  TempDir dir("slider_crank");
  const CliRun r = run_cli({"report", source("verify/scenes/mechanisms/dimensions_slider_crank.yaml"), "--format", "all",
                            "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  // Before: fractions of hundreds of digits in the tables (a page thousands of pixels wide).
  for (const char* file : {"dimensions_slider_crank.md", "dimensions_slider_crank.tex"}) {
    const std::string text = slurp(dir.path / file);
    size_t run = 0, longest = 0;
    for (const char c : text) longest = std::max(longest, run = (c >= '0' && c <= '9') ? run + 1 : 0);
    EXPECT_LT(longest, 70u) << file << ": a number of " << longest << " digits";
    // (LaTeX writes the ≈ as $\\approx$)
    EXPECT_NE(text.find(" -209.4395102 (exact: 118 digits)"), std::string::npos) << file << ": omega of the crank";
  }
  const std::string html = slurp(dir.path / "dimensions_slider_crank.html");
  EXPECT_NE(html.find("<summary>≈ -209.4395102 (exact: 118 digits)</summary>"), std::string::npos);
  EXPECT_NE(html.find("id=\"fig-slider-crank-from-dimensions-velocities\""), std::string::npos);
  EXPECT_NE(html.find("id=\"fig-slider-crank-from-dimensions-accelerations\""), std::string::npos);
}

// Issue 27: a slot is one joint in the reports. The reader solves it with a block link P.block
// and a pin joint P.pin, which appear in no table, drawing or count; P's row says what it is
// and a paragraph gives its sliding rates and Coriolis term.
TEST(ReportCli, GenevaReportShowsTheSlotAsOneJointWithoutItsBlockLink) {
  TempDir dir("geneva");
  const CliRun r = run_cli({"report", source("verify/scenes/mechanisms/geneva.yaml"), "--format", "all", "--out",
                            dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* file : {"geneva.md", "geneva.html", "geneva.tex", "geneva-six-slot-linkage.svg",
                           "geneva-six-slot-velocities.svg"}) {
    const std::string text = slurp(dir.path / file);
    EXPECT_EQ(text.find("P.block"), std::string::npos) << file;
    EXPECT_EQ(text.find("P.pin"), std::string::npos) << file;
  }
  const std::string md = slurp(dir.path / "geneva.md");
  EXPECT_NE(md.find("| P (pin of crank in a slot of wheel) |"), std::string::npos);
  EXPECT_NE(md.find("- mobility 1: 3 links, 3 joints, 1 independent loop"), std::string::npos);
  const size_t slot = md.find("Slot P: a pin of crank in a slot of wheel");
  ASSERT_NE(slot, std::string::npos);
  EXPECT_NE(md.find("$\\dot\\sigma =$", slot), std::string::npos) << "sliding rate";
  EXPECT_NE(md.find("$\\ddot\\sigma =$", slot), std::string::npos) << "sliding acceleration";
  EXPECT_NE(md.find("its Coriolis acceleration", slot), std::string::npos);
  const std::string html = slurp(dir.path / "geneva.html");
  EXPECT_NE(html.find("<td>wheel</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>P (pin of crank in a slot of wheel)</td>"), std::string::npos);
  // check's text: the placement table has the slot P and no row for its pin.
  const CliRun check = run_cli({"check", source("verify/scenes/mechanisms/geneva.yaml")});
  ASSERT_EQ(check.code, 0) << check.err;
  EXPECT_EQ(check.out.find("\nP.pin "), std::string::npos) << check.out;
  EXPECT_EQ(check.out.find("\nP.block "), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("\nP                polar"), std::string::npos) << check.out;
  // The rationalised scene's distance to the dimensioned values is said beside the statement.
  EXPECT_NE(r.err.find("distance to the dimensioned values: omega <= "), std::string::npos) << r.err;
}

TEST(ReportCli, NumericsSectionOnlyWhenAsked) {
  TempDir dir("numerics");
  const CliRun r = run_cli({"report", source("verify/scenes/pentagon.yaml"), "--numerics", "--format", "md", "--out",
                            dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string md = slurp(dir.path / "pentagon.md");
  EXPECT_NE(md.find("<a id=\"numerics\"></a>"), std::string::npos);
  EXPECT_NE(md.find("| double |"), std::string::npos);
  EXPECT_NE(md.find("| mp100 |"), std::string::npos);
}

TEST(ReportCli, EightBarReportDrawsTheLinkageAndListsExactRates) {
  TempDir dir("eightbar");
  const CliRun r = run_cli({"report", source("verify/scenes/mechanisms/fig5_eightbar.yaml"), "--format", "html",
                            "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = slurp(dir.path / "fig5_eightbar.html");
  expect_sections_in_order(html, {"summary", "mechanism", "reproduce"});
  EXPECT_NE(html.find("-\\frac{279}{317} \\approx -0.880126183"), std::string::npos);  // omega of link 6 (conventions §A8)
  EXPECT_NE(html.find("<polygon"), std::string::npos);  // a plate (link with three joints)
  EXPECT_EQ(html.find("<section id=\"plans\">"), std::string::npos);
}

TEST(ReportCli, Seed001FourBarPlansDrawTheTextbookAccelerationPolygon) {
  TempDir dir("seed001");
  const CliRun r = run_cli({"report", source("verify/scenes/mechanisms/seed001_fourbar.yaml"), "--plans", "--format",
                            "html", "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = slurp(dir.path / "seed001_fourbar.html");
  expect_sections_in_order(html, {"summary", "mechanism", "plans", "tables", "reproduce"});
  EXPECT_NE(html.find("id=\"fig-fourbar-seed001-acceleration-polygon\""), std::string::npos);
  EXPECT_NE(html.find("\\frac{3109}{800} = 3.88625"), std::string::npos);  // alpha4 (conventions §B)
  // the curvature centre of P, (10923/1222, 17083/1222)
  EXPECT_NE(html.find("\\frac{10923}{1222} \\approx 8.938625205"), std::string::npos);
  EXPECT_NE(html.find("\\frac{17083}{1222} \\approx 13.97954173"), std::string::npos);
}

TEST(ReportCli, Seed003MechanismReportIsWritten) {
  TempDir dir("seed003");
  const CliRun r = run_cli({"report", source("verify/scenes/mechanisms/seed003_class3.yaml"), "--format", "tex",
                            "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string tex = slurp(dir.path / "seed003_class3.tex");
  EXPECT_NE(tex.find("mechanism.driver\\_inversion"), std::string::npos);
  EXPECT_NE(tex.find("guide D"), std::string::npos);
}

TEST(ReportCli, ClaimFileReportProvesAndShowsCounterexampleOfAnErratum) {
  TempDir dir("claims");
  const CliRun r = run_cli({"report", source("verify/claims/dijksman1966.yaml"), "--claim", "eq5", "--claim",
                            "eq4.printed", "--ladder-seconds", "0", "--format", "html", "--out", dir.path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = slurp(dir.path / "dijksman1966.html");
  expect_sections_in_order(html, {"summary", "proof", "counterexamples", "reproduce"});
  EXPECT_NE(html.find("id=\"proof-dijksman1966.eq5\""), std::string::npos);
  EXPECT_NE(html.find("id=\"fig-counterexample-dijksman1966.eq4.printed\""), std::string::npos);
  EXPECT_NE(html.find("The argument, step by step"), std::string::npos);
  EXPECT_NE(html.find("(counterexample search)"), std::string::npos);  // the seed in the reproduce line
}

TEST(ReportCli, BadFormatAndMissingFileAreBadInput) {
  const CliRun bad = run_cli({"report", source("verify/scenes/pentagon.yaml"), "--format", "pdf"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--format"), std::string::npos) << bad.err;
  const CliRun missing = run_cli({"report", "/nonexistent/scene.yaml"});
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/scene.yaml"), std::string::npos) << missing.err;
}

TEST(ReportCli, UnwritableOutputDirectoryIsBadInput) {
  const CliRun r = run_cli({"report", source("verify/scenes/pentagon.yaml"), "--out", "/proc/linkproof_no"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
