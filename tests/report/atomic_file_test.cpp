// write_file_atomically: a file is replaced whole or not at all, and a failure leaves no
// temporary file behind (bench --out used to leave a truncated bench.json on a full disk).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "linkproof/core/error.h"
#include "linkproof/report/atomic_file.h"

namespace linkproof {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(AtomicFile, ReplacesTheWholeFileAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("atomic_ok");
  const fs::path p = dir / "bench.json";
  std::ofstream(p) << "old contents that are longer than the new ones";
  write_file_atomically(p, "{}\n", "--out");
  EXPECT_EQ(contents(p), "{}\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, AFailedWriteIsBadInputNamingTheOptionAndLeavesNothing) {
  const fs::path dir = fresh_dir("atomic_fail");
  const fs::path p = dir / "missing_subdirectory" / "bench.json";
  try {
    write_file_atomically(p, "{}\n", "--out");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--out");
    EXPECT_NE(e.problem().find("bench.json"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(p));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
}

}  // namespace
}  // namespace linkproof
