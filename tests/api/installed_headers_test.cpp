// The installed API is small and documented: every header under include/linkproof/ is named in
// docs/api.md's stable-surface table, there are at most 25 of them, and none includes a private
// header (the build target linkproof_public_headers compiles each one with only include/ on the
// path; this test names the offending line instead of a compiler error).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> installed_headers() {
  const fs::path root = fs::path(LINKPROOF_SOURCE_DIR) / "include";
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() == ".h") out.push_back(fs::relative(e.path(), root).generic_string());
  return out;
}

TEST(InstalledHeaders, AreAtMostTwentyFive) {
  EXPECT_LE(installed_headers().size(), 25u);
  EXPECT_GE(installed_headers().size(), 10u);  // the walk found the folder
}

TEST(InstalledHeaders, EachIsNamedInTheStableSurfaceOfDocsApi) {
  const std::string api = read(fs::path(LINKPROOF_SOURCE_DIR) / "docs/api.md");
  for (const std::string& h : installed_headers()) {
    const std::string base = fs::path(h).filename().string();
    const bool named = api.find("`" + h + "`") != std::string::npos || api.find("`" + base + "`") != std::string::npos ||
                       (h.starts_with("linkproof/testing/") && api.find("`linkproof/testing/*.h`") != std::string::npos);
    EXPECT_TRUE(named) << h << " is installed but docs/api.md does not name it";
  }
}

TEST(InstalledHeaders, IncludeOnlyInstalledHeadersOfLinkproof) {
  const std::regex quoted(R"re(#include\s+[<"]([^>"]+)[>"])re");
  const std::vector<std::string> headers = installed_headers();
  for (const std::string& h : headers) {
    std::istringstream in(read(fs::path(LINKPROOF_SOURCE_DIR) / "include" / h));
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::smatch m;
      if (!std::regex_search(line, m, quoted)) continue;
      const std::string target = m[1];
      if (target.find('/') == std::string::npos || target.ends_with(".hpp")) continue;  // <vector>, <rapidcheck.h>
      if (target.starts_with("cln/") || target.starts_with("gmock/") || target.starts_with("gtest/") ||
          target.starts_with("rapidcheck/"))
        continue;
      EXPECT_TRUE(target.starts_with("linkproof/") && fs::exists(fs::path(LINKPROOF_SOURCE_DIR) / "include" / target))
          << h << ":" << n << " includes " << target << ", which is not installed";
    }
  }
}

}  // namespace
