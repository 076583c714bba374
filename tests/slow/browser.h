// Headless Chromium for the slow tests of reports as a reader sees them (report_reader_test,
// report_layout_test): whether a tool is installed, a shell command's output, and the
// browser's command line. The pages are self-contained: no network is used.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace linkproof::test {

inline bool on_path(const std::string& tool) {
  return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

/// Runs a shell command; its standard output, and the exit status in `status`.
inline std::string capture(const std::string& command, int& status) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) {
    status = -1;
    return out;
  }
  char buf[65536];
  size_t got;
  while ((got = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, got);
  status = pclose(p);
  return out;
}

/// Headless Chromium with `args` (as root it needs --no-sandbox); the virtual time budget lets
/// the page's scripts (KaTeX, a measuring script) finish before the DOM or screenshot is taken.
inline std::string chromium(const std::string& args) {
  return "chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run "
         "--virtual-time-budget=10000 " + args + " 2>/dev/null";
}

}  // namespace linkproof::test
