// `linkproof report` on hostile input: a scene whose name, description, link, joint and point
// names hold LaTeX commands, verbatim ends, math delimiters, HTML elements, Markdown fences and
// line breaks gives LaTeX with no command of the input, Markdown with its headings and fences
// intact and HTML with no injected element; a scene name that is a path, absolute, or too long
// for a file name writes inside --out; and a report is written whole or not at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "support/cli_run.h"
#include "report/report_checks.h"
#include "support/temp_dir.h"

namespace linkproof {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::run_cli;
using test::slurp;
using test::TempDir;

std::string write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// Every regular file under `dir`, as paths relative to it.
std::set<std::string> files_under(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out.insert(fs::relative(e.path(), dir).string());
  return out;
}

TEST(ReportOutputSafety, LatexOfAHostileMechanismHasNoCommandOfTheInput) {
  TempDir dir("safety_tex");
  const std::string scene = write_file(dir.path, "hostile.yaml", test::hostile_fourbar_scene());
  const CliRun r = run_cli({"report", scene, "--format", "tex", "--out", (dir.path / "out").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string tex = slurp(dir.path / "out" / "hostile.tex");
  // The description is shown in the listing of the counterexample scene, whole.
  ASSERT_NE(tex.find("Injected heading"), std::string::npos) << "the scene text is not in the report";
  EXPECT_EQ(test::count(tex, "\\begin{verbatim}"), test::count(tex, "\\end{verbatim}"));
  const std::string outside = test::latex_outside_verbatim(tex);
  EXPECT_EQ(outside.find("\\input"), std::string::npos) << "an \\input of the input is active";
  EXPECT_EQ(outside.find("\\section{Injected"), std::string::npos);
  EXPECT_EQ(outside.find("^^"), std::string::npos) << "TeX's ^^5c notation would make a backslash";
  EXPECT_EQ(test::latex_brace_depth_problem(outside), "") << "braces out of balance";
  // The figure labels are math: no $ of a name may end the math early.
  for (const std::string& line : test::lines_starting_with(outside, "\\put(")) {
    if (line.find("\\pdfliteral") != std::string::npos) continue;
    EXPECT_EQ(test::count(line, "$") - test::count(line, "\\$"), 2u) << line;
  }
}

TEST(ReportOutputSafety, LatexOfAHostileMechanismHasTheCommandsOfABenignOne) {
  std::vector<std::string> structure[2];
  int k = 0;
  for (const std::string& text : {test::hostile_fourbar_scene(), test::benign_fourbar_scene()}) {
    TempDir dir("safety_tex_twin" + std::to_string(k));
    const std::string scene = write_file(dir.path, "scene.yaml", text);
    const CliRun r = run_cli({"report", scene, "--format", "tex", "--out", dir.path.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    structure[k++] = test::latex_structure(test::latex_outside_verbatim(slurp(dir.path / "scene.tex")));
  }
  EXPECT_EQ(structure[0], structure[1]) << "a command of the input is active";
}

TEST(ReportOutputSafety, MarkdownOfAHostileMechanismKeepsItsHeadingsAndFences) {
  TempDir dir("safety_md");
  const std::string scene = write_file(dir.path, "hostile.yaml", test::hostile_fourbar_scene());
  const CliRun r = run_cli({"report", scene, "--format", "md", "--out", (dir.path / "out").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string md = slurp(dir.path / "out" / "hostile.md");
  ASSERT_NE(md.find("Injected heading"), std::string::npos) << "the scene text is not in the report";
  const test::MarkdownOutline o = test::markdown_outline(md);
  EXPECT_EQ(o.unclosed_fence, false);
  EXPECT_EQ(o.fences, 2u) << "the scene text and the reproduce command, one code block each";
  // One heading per section and the title, nothing else: no heading of the input.
  EXPECT_EQ(o.headings.size(), test::count(md, "<a id=\"") + 1) << md.substr(0, 3000);
  EXPECT_EQ(o.headings[0].rfind("# Mechanism report: H", 0), 0u) << o.headings[0];
  for (size_t k = 1; k < o.headings.size(); ++k) EXPECT_EQ(o.headings[k].find("Injected"), std::string::npos) << o.headings[k];
  // Outside code blocks no < of the input is raw HTML (only the section anchors are).
  EXPECT_EQ(o.raw_html_other_than_anchors, "");
  EXPECT_EQ(o.bad_table_rows, std::vector<std::string>{}) << "a name split a table cell";
}

TEST(ReportOutputSafety, HtmlOfAHostileMechanismHasNoInjectedElement) {
  TempDir dir("safety_html");
  const std::string scene = write_file(dir.path, "hostile.yaml", test::hostile_fourbar_scene());
  const CliRun r = run_cli({"report", scene, "--format", "html", "--katex", (dir.path / "no_katex").string(), "--out",
                            (dir.path / "out").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = slurp(dir.path / "out" / "hostile.html");
  ASSERT_NE(html.find("Injected heading"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "no KaTeX asked, so no script at all";
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)"), std::string::npos);
}

// The velocity and acceleration plans draw the joints in the scene's order: renaming a joint so
// that it sorts elsewhere changes no element of the page (the plans once followed name order, so
// a subscripted name moved its <tspan>; found by fuzz_report).
TEST(ReportOutputSafety, PlansDrawJointsInSceneOrderWhateverTheirNames) {
  std::string renamed = test::benign_fourbar_scene();
  for (const std::string from : {"\"A_x\"", "\"O\""}) {
    const std::string to = from == "\"O\"" ? "\"Z\"" : "\"Y_x\"";
    for (auto at = renamed.find(from); at != std::string::npos; at = renamed.find(from, at + 1)) renamed.replace(at, from.size(), to);
  }
  std::vector<std::string> elements[2];
  int k = 0;
  for (const std::string& text : {test::benign_fourbar_scene(), renamed}) {
    TempDir dir("plans_order" + std::to_string(k));
    const std::string scene = write_file(dir.path, "scene.yaml", text);
    const CliRun r = run_cli({"report", scene, "--plans", "--format", "html", "--katex",
                              (dir.path / "no_katex").string(), "--out", dir.path.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string html = slurp(dir.path / "scene.html");
    ASSERT_NE(html.find("velocity-plan"), std::string::npos) << "no plan drawn";
    elements[k++] = test::html_elements(html);
  }
  ASSERT_NE(renamed, test::benign_fourbar_scene());
  EXPECT_EQ(elements[0], elements[1]);
}

TEST(ReportOutputSafety, ClaimFileTextsAreEscapedInEveryFormat) {
  TempDir dir("safety_claims");
  const std::string claims = write_file(
      dir.path, "claims.yaml",
      "claims:\n"
      "  - id: c1\n"
      "    source: \"[x]: javascript:alert(1)\"\n"
      "    statement: \"<script>alert(2)</script> } \\\\input{/etc/passwd} $\"\n"
      "    note: \"1. ``` # not a heading\"\n"
      "    lhs: omega_out\n"
      "    rhs: omega_out\n");
  const CliRun r = run_cli({"report", claims, "--format", "all", "--ladder-seconds", "0", "--katex",
                            (dir.path / "no_katex").string(), "--out", (dir.path / "out").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string tex = test::latex_outside_verbatim(slurp(dir.path / "out" / "claims.tex"));
  EXPECT_EQ(tex.find("\\input"), std::string::npos);
  EXPECT_EQ(test::latex_brace_depth_problem(tex), "");
  const std::string md = slurp(dir.path / "out" / "claims.md");
  EXPECT_NE(md.find("\\[x]: javascript"), std::string::npos) << "a link definition at a paragraph's start";
  EXPECT_NE(md.find("Note: 1. \\`\\`\\` \\# not a heading"), std::string::npos) << md;
  EXPECT_EQ(test::markdown_outline(md).raw_html_other_than_anchors, "");
  EXPECT_EQ(slurp(dir.path / "out" / "claims.html").find("<script"), std::string::npos);
}

// --- file names: every file inside --out, whatever the scene's name

struct NamedScene {
  std::string label;
  std::string yaml_name;  // the `name:` value as written in YAML
};

class ReportFileNames : public ::testing::TestWithParam<NamedScene> {};

TEST_P(ReportFileNames, FigureFilesOfAnyNameAreWrittenInsideOut) {
  TempDir dir("names_" + GetParam().label);
  const fs::path out = dir.path / "a" / "b" / "out";
  const std::string scene =
      write_file(dir.path, "scene.yaml", "name: " + GetParam().yaml_name + "\n" + test::pentagon_polygon_yaml());
  const CliRun r = run_cli({"report", scene, "--format", "all", "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  // Nothing outside out/ (the scene file itself is the only other file).
  std::set<std::string> outside = files_under(dir.path);
  std::set<std::string> inside;
  for (const auto& f : files_under(out)) inside.insert(f);
  EXPECT_EQ(outside.size(), inside.size() + 1) << r.out;
  for (const auto& f : inside) {
    EXPECT_EQ(fs::path(f).parent_path(), fs::path()) << f << ": not directly in --out";
    EXPECT_LE(fs::path(f).filename().string().size(), 255u) << f;
    EXPECT_NE(f[0], '.') << f;
  }
  EXPECT_EQ(inside.count("scene.html") + inside.count("scene.md") + inside.count("scene.tex"), 3u);
  EXPECT_EQ(inside.size(), 4u) << "the three reports and the construction figure";
  // The Markdown refers to the figure by the name it was written under.
  const std::string md = slurp(out / "scene.md");
  for (const auto& f : inside) {
    if (fs::path(f).extension() == ".svg") {
      EXPECT_NE(md.find("](" + f + ")"), std::string::npos) << f;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    HostileNames, ReportFileNames,
    ::testing::Values(NamedScene{"dotdot", "\"../../x\""}, NamedScene{"absolute", "\"/tmp/linkproof_absolute_name\""},
                      NamedScene{"slash", "\"a/b\""}, NamedScene{"long", std::string(300, 'n')},
                      NamedScene{"dots", "\"...\""}, NamedScene{"backslash", "\"..\\\\..\\\\x\""}),
    [](const ::testing::TestParamInfo<NamedScene>& p) { return p.param.label; });

TEST(ReportFileNames, TwoLongNamesWithTheSameBeginningGetDifferentFiles) {
  TempDir dir("names_long_two");
  std::set<std::string> svgs;
  for (const char* tail : {"1", "2"}) {
    const std::string scene = write_file(dir.path, std::string("s") + tail + ".yaml",
                                         "name: " + std::string(300, 'n') + tail + "\n" + test::pentagon_polygon_yaml());
    const CliRun r = run_cli({"report", scene, "--format", "md", "--out", (dir.path / "out").string()});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  for (const auto& f : files_under(dir.path / "out"))
    if (fs::path(f).extension() == ".svg") svgs.insert(f);
  EXPECT_EQ(svgs.size(), 2u);
}

// --- all or nothing

TEST(ReportAtomicity, AFileThatCannotBeWrittenLeavesNoPartOfTheReport) {
  TempDir dir("atomic_report");
  const fs::path out = dir.path / "out";
  fs::create_directories(out / "pentagon.tex");  // in the way of the last file
  const CliRun r = run_cli({"report", std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/pentagon.yaml", "--format",
                            "all", "--out", out.string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("pentagon.tex"), std::string::npos) << r.err;
  EXPECT_EQ(files_under(out), std::set<std::string>{}) << "the HTML, Markdown or figure was left behind";
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace linkproof
