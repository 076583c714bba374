// Reports as a reader sees them: the HTML rendered by headless Chromium (the DOM after KaTeX
// ran, and a screenshot that is not blank), the LaTeX compiled by pdflatex. Each test skips only
// when its tool is not installed (scripts/install_deps.sh installs both, so CI runs them).
// In tests/slow/ (label slow, tests/CMakeLists.txt): a headless browser start costs seconds of
// wall time.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "report/report_checks.h"
#include "slow/browser.h"
#include "support/cli_run.h"
#include "support/temp_dir.h"

namespace linkproof {
namespace {

namespace fs = std::filesystem;
using test::capture;
using test::chromium;
using test::on_path;
using test::run_cli;
using test::slurp;
using test::TempDir;

std::string reader_source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(ReportReader, HtmlReportRendersInChromiumWithMathAndFiguresSlow) {
  if (!on_path("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/install_deps.sh installs it)";
  TempDir dir("html");
  ASSERT_EQ(run_cli({"report", reader_source("verify/scenes/pentagon.yaml"), "--out", dir.path.string()}).code, 0);
  const fs::path page = dir.path / "pentagon.html";
  const std::string before = slurp(page);
  ASSERT_NE(before.find("katex.render"), std::string::npos) << "KaTeX (libjs-katex) was not inlined";
  int status = 0;
  const std::string dom = capture(chromium("--dump-dom file://" + page.string()), status);
  ASSERT_EQ(status, 0) << "chromium failed";
  for (const char* id : {"summary", "derivation", "construction", "terms", "errata", "reproduce"})
    EXPECT_NE(dom.find(std::string("<section id=\"") + id + "\">"), std::string::npos) << id;
  // Every math element was rendered by KaTeX, and none failed.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dom, m, std::regex("data-math-rendered=\"([0-9]+)\""))) << "the render script did not run";
  const size_t rendered = std::stoul(m[1]);
  EXPECT_EQ(rendered, count(before, "class=\"lp-math"));
  EXPECT_GT(rendered, 50u);
  EXPECT_GE(count(dom, "class=\"katex\""), rendered);
  EXPECT_EQ(dom.find("class=\"katex-error\""), std::string::npos) << "a formula KaTeX could not render";
  EXPECT_NE(dom.find("<svg"), std::string::npos);
}

TEST(ReportReader, HtmlReportScreenshotIsNotBlankSlow) {
  if (!on_path("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/install_deps.sh installs it)";
  TempDir dir("shot");
  ASSERT_EQ(run_cli({"report", reader_source("verify/scenes/pentagon.yaml"), "--out", dir.path.string()}).code, 0);
  // A blank page of the same size is the reference: PNG compresses a uniform image to almost
  // nothing, so a page with text, formulas and a figure is many times larger.
  std::ofstream(dir.path / "blank.html") << "<!DOCTYPE html><html><body></body></html>";
  int status = 0;
  for (const char* name : {"pentagon", "blank"}) {
    capture(chromium("--window-size=1000,1400 --screenshot=" + (dir.path / (std::string(name) + ".png")).string() +
                     " file://" + (dir.path / (std::string(name) + ".html")).string()),
            status);
    ASSERT_EQ(status, 0) << name;
  }
  const auto report = fs::file_size(dir.path / "pentagon.png"), blank = fs::file_size(dir.path / "blank.png");
  EXPECT_GT(report, 10 * blank) << "report " << report << " bytes, blank page " << blank << " bytes";
}

TEST(ReportReader, LatexReportsCompileWithPdflatexSlow) {
  if (!on_path("pdflatex")) GTEST_SKIP() << "pdflatex is not installed (scripts/install_deps.sh installs it)";
  TempDir dir("tex");
  ASSERT_EQ(run_cli({"report", reader_source("verify/scenes/pentagon.yaml"), "--format", "tex", "--out", dir.path.string()}).code, 0);
  ASSERT_EQ(run_cli({"report", reader_source("verify/scenes/mechanisms/seed001_fourbar.yaml"), "--plans", "--format", "tex",
                     "--out", dir.path.string()})
                .code,
            0);
  for (const char* stem : {"pentagon", "seed001_fourbar"}) {
    int status = 0;
    const std::string log = capture("cd " + dir.path.string() + " && pdflatex -interaction=nonstopmode -halt-on-error " +
                                        stem + ".tex 2>&1",
                                    status);
    EXPECT_EQ(status, 0) << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
    ASSERT_TRUE(fs::exists(dir.path / (std::string(stem) + ".pdf"))) << stem;
    EXPECT_GT(fs::file_size(dir.path / (std::string(stem) + ".pdf")), 10000u);
  }
}

// A scene whose names and description hold \input{/etc/passwd}, \end{verbatim}, }$, ^^5c,
// HTML and Markdown: pdflatex compiles the report and reads no file of the input.
TEST(ReportReader, HostileSceneLatexCompilesAndReadsNoFileSlow) {
  if (!on_path("pdflatex")) GTEST_SKIP() << "pdflatex is not installed (scripts/install_deps.sh installs it)";
  TempDir dir("tex_hostile");
  std::ofstream(dir.path / "hostile.yaml") << test::hostile_fourbar_scene();
  ASSERT_EQ(run_cli({"report", (dir.path / "hostile.yaml").string(), "--plans", "--format", "tex", "--out",
                     dir.path.string()})
                .code,
            0);
  int status = 0;
  const std::string log =
      capture("cd " + dir.path.string() + " && pdflatex -interaction=nonstopmode -halt-on-error hostile.tex 2>&1", status);
  EXPECT_EQ(status, 0) << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
  EXPECT_TRUE(fs::exists(dir.path / "hostile.pdf"));
  EXPECT_EQ(log.find("(/etc/passwd"), std::string::npos) << "pdflatex opened a file named in the scene";
}

// The same scene's HTML as Chromium builds it: no element the scene wrote (KaTeX is left out,
// so the page has no script at all).
TEST(ReportReader, HostileSceneHtmlHasNoInjectedElementInChromiumSlow) {
  if (!on_path("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/install_deps.sh installs it)";
  TempDir dir("html_hostile");
  std::ofstream(dir.path / "hostile.yaml") << test::hostile_fourbar_scene();
  ASSERT_EQ(run_cli({"report", (dir.path / "hostile.yaml").string(), "--plans", "--katex",
                     (dir.path / "no_katex").string(), "--out", dir.path.string()})
                .code,
            0);
  int status = 0;
  const std::string dom = capture(chromium("--dump-dom file://" + (dir.path / "hostile.html").string()), status);
  ASSERT_EQ(status, 0) << "chromium failed";
  ASSERT_NE(dom.find("alert(1)"), std::string::npos) << "the scene's name is not shown";
  EXPECT_EQ(dom.find("<script"), std::string::npos);
  EXPECT_EQ(dom.find("<img"), std::string::npos);
  EXPECT_EQ(dom.find("<b>"), std::string::npos);
  EXPECT_EQ(count(dom, "<section id="), count(slurp(dir.path / "hostile.html"), "<section id="));
}

}  // namespace
}  // namespace linkproof
