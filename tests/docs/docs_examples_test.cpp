// The code a page shows is the code CI builds: docs/testing.md's worked example is the whole of
// tests/oracle_consumer/fourbar_oracle.cpp, which scripts/test_consumer.sh builds against the
// installed package and runs.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string read(const std::string& rel) {
  std::ifstream in(std::string(LINKPROOF_SOURCE_DIR) + "/" + rel);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(DocsExamples, TestingPageShowsTheWholeOracleConsumerFile) {
  const std::string page = read("docs/testing.md");
  const std::string file = read("tests/oracle_consumer/fourbar_oracle.cpp");
  ASSERT_FALSE(file.empty());
  EXPECT_NE(page.find("```cpp\n" + file + "```\n"), std::string::npos)
      << "docs/testing.md's cpp block differs from tests/oracle_consumer/fourbar_oracle.cpp: copy the file into the page";
}

}  // namespace
