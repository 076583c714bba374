// The HTML report laid out by a reader's browser: headless Chromium at 1200 x 900 px opens the
// report of the pentagon, the Fig. 5 eight-bar and a slider-crank placed from its dimensions.
//
// How it is measured: the test appends a script to a copy of the page; once KaTeX has rendered
// and the (inlined) fonts are ready, the script writes the browser's own layout numbers into the
// page (document scroll width against the window's inner width, the page-coordinate boxes of
// the summary's figure and headline, every box whose content is wider than the box), and
// `chromium --dump-dom` prints the page with them. What a closed <details> holds (a folded long
// formula or fraction) is not on the screen until the reader opens it, and is not measured; its
// summary line is. Layout numbers are exact where pixel tests
// are not (anti-aliasing, fonts); a screenshot of the same window checks that the page is not
// blank (PNG compresses a uniform image to almost nothing). With LINKPROOF_SCREENSHOT_DIR set,
// the screenshots are kept there to be looked at.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>

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

constexpr int kWindowWidth = 1200, kFold = 900;

// Appended to the page: the layout as JSON in <pre id="lp-layout">.
constexpr const char* kMeasure = R"(<script>
window.addEventListener('load', function () {
  document.fonts.ready.then(function () {
    function box(e) {
      if (!e) return null;
      var r = e.getBoundingClientRect();
      return {top: r.top + window.scrollY, bottom: r.bottom + window.scrollY, left: r.left, right: r.right};
    }
    var m = {innerWidth: window.innerWidth, scrollWidth: document.documentElement.scrollWidth,
             figure: box(document.querySelector('#summary figure')),
             headline: box(document.querySelector('#summary .lp-headline')),
             text: document.body.innerText.length, wide: []};
    document.querySelectorAll('section, p, ul, li, figure, svg, .lp-table, .lp-display, pre, table').forEach(function (e) {
      var r = e.getBoundingClientRect();
      var fold = e.closest('details:not([open])');
      if (r.width === 0 || (fold && !e.closest('summary'))) return;  /* folded away until the reader opens it */
      if (e.scrollWidth > e.clientWidth + 1 || r.right > window.innerWidth + 0.5)
        m.wide.push(e.tagName.toLowerCase() + '.' + String(e.className.baseVal !== undefined ? e.className.baseVal : e.className) +
                    ' in #' + ((e.closest('section') || {}).id || '') + ': ' + e.scrollWidth + ' px of content in ' +
                    e.clientWidth + ' px, right edge ' + Math.round(r.right));
    });
    var pre = document.createElement('pre');
    pre.id = 'lp-layout';
    pre.textContent = JSON.stringify(m);
    document.body.appendChild(pre);
  });
});
</script>
)";

std::string source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

std::string unescape_html(std::string s) {
  for (const auto& [from, to] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}}) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) s.replace(at, std::string(from).size(), to);
  }
  return s;
}

struct Scene {
  const char* name;  ///< the test's name
  const char* path;  ///< the scene, relative to the source tree
  const char* stem;  ///< the report's file stem
};

// The scene's name in test listings (not GoogleTest's bytes of the struct).
void PrintTo(const Scene& s, std::ostream* os) { *os << s.name; }

class ReportLayout : public ::testing::TestWithParam<Scene> {};

TEST_P(ReportLayout, DrawingAndHeadlineAreAboveTheFoldAndNothingIsWiderThanTheWindowSlow) {
  if (!on_path("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/install_deps.sh installs it)";
  const Scene& scene = GetParam();
  TempDir dir(std::string("layout_") + scene.name);
  ASSERT_EQ(run_cli({"report", source(scene.path), "--out", dir.path.string()}).code, 0);
  const fs::path page = dir.path / (std::string(scene.stem) + ".html");
  std::string html = slurp(page);
  const size_t end = html.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  std::ofstream(dir.path / "measured.html") << html.insert(end, kMeasure);

  int status = 0;
  const std::string window = "--window-size=" + std::to_string(kWindowWidth) + "," + std::to_string(kFold) + " ";
  const std::string dom = capture(chromium(window + "--dump-dom file://" + (dir.path / "measured.html").string()), status);
  ASSERT_EQ(status, 0) << "chromium failed";
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dom, m, std::regex("<pre id=\"lp-layout\">([^<]*)</pre>"))) << "the measuring script did not run";
  const nlohmann::json layout = nlohmann::json::parse(unescape_html(m[1].str()));
  SCOPED_TRACE(layout.dump());

  EXPECT_EQ(layout["innerWidth"].get<int>(), kWindowWidth);
  EXPECT_LE(layout["scrollWidth"].get<int>(), layout["innerWidth"].get<int>()) << "the page scrolls sideways";
  EXPECT_TRUE(layout["wide"].empty()) << "boxes wider than their room";
  EXPECT_GT(layout["text"].get<int>(), 500) << "almost no text";
  ASSERT_TRUE(layout["figure"].is_object()) << "no figure in the summary";
  ASSERT_TRUE(layout["headline"].is_object()) << "no headline in the summary";
  EXPECT_LE(layout["figure"]["bottom"].get<double>(), kFold) << "the drawing is not whole above the fold";
  EXPECT_GT(layout["figure"]["bottom"].get<double>() - layout["figure"]["top"].get<double>(), 150) << "the drawing is small";
  EXPECT_LE(layout["headline"]["bottom"].get<double>(), kFold) << "the headline is not above the fold";

  // The screenshot of the same window is not blank: many times a blank page's PNG.
  std::ofstream(dir.path / "blank.html") << "<!DOCTYPE html><html><body></body></html>";
  for (const char* name : {"shot", "blank"}) {
    const std::string html_name = std::string(name) == "shot" ? std::string(scene.stem) + ".html" : "blank.html";
    capture(chromium(window + "--screenshot=" + (dir.path / (std::string(name) + ".png")).string() + " file://" +
                     (dir.path / html_name).string()),
            status);
    ASSERT_EQ(status, 0) << name;
  }
  const auto shot = fs::file_size(dir.path / "shot.png"), blank = fs::file_size(dir.path / "blank.png");
  EXPECT_GT(shot, 10 * blank) << "screenshot " << shot << " bytes, blank page " << blank << " bytes";
  if (const char* keep = std::getenv("LINKPROOF_SCREENSHOT_DIR"); keep && *keep) {
    fs::create_directories(keep);
    fs::copy_file(dir.path / "shot.png", fs::path(keep) / (std::string(scene.name) + ".png"),
                  fs::copy_options::overwrite_existing);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReportLayout,
                         ::testing::Values(Scene{"pentagon", "verify/scenes/pentagon.yaml", "pentagon"},
                                           Scene{"eightbar", "verify/scenes/mechanisms/fig5_eightbar.yaml",
                                                 "fig5_eightbar"},
                                           Scene{"slider_crank",
                                                 "verify/scenes/mechanisms/dimensions_slider_crank.yaml",
                                                 "dimensions_slider_crank"}),
                         [](const ::testing::TestParamInfo<Scene>& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace linkproof
