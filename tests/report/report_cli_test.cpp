// `linkproof report` in-process on the bundled scenes and the paper's claim file: the files
// written, their sections in order, exact values from the check, and bad input.
#include <gtest/gtest.h>

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
  EXPECT_NE(html.find("7331/2662"), std::string::npos);                  // omega-dot_{3,5} (conventions §A8)
  EXPECT_NE(html.find("3755/1331"), std::string::npos) << "omega-dot_{4,5}";
  EXPECT_NE(html.find("(\\frac{26}{5},\\ \\frac{23}{5})"), std::string::npos) << "Q_1";
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
  EXPECT_NE(html.find("-279/317"), std::string::npos);  // omega of link 6 (conventions §A8)
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
  EXPECT_NE(html.find("3109/800"), std::string::npos);            // alpha4 (conventions §B)
  EXPECT_NE(html.find("(10923/1222, 17083/1222)"), std::string::npos);  // curvature centre of P
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
