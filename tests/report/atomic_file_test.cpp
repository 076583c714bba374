// write_file_atomically: a file is replaced whole or not at all, and a failure leaves no
// temporary file behind (bench --out used to leave a truncated bench.json on a full disk);
// write_files_atomically: a report and its figures appear all together or not at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "linkproof/core/error.h"
#include "report/atomic_file.h"

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

// The temporary file's name does not grow with the final one: a name of 250 bytes (legal) used
// to need a 270-byte temporary name, and the write failed.
TEST(AtomicFile, ANameNearTheFileSystemLimitIsWritten) {
  const fs::path dir = fresh_dir("atomic_long");
  std::string name(245, 'n');
  name.append(".html");
  const fs::path p = dir / name;
  write_file_atomically(p, "x", "--out");
  EXPECT_EQ(contents(p), "x");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, ASetOfFilesIsWrittenWholeOrNotAtAll) {
  const fs::path dir = fresh_dir("atomic_set");
  write_files_atomically({{dir / "a.html", "a"}, {dir / "b.md", "b"}, {dir / "c.svg", "c"}}, "--out");
  EXPECT_EQ(contents(dir / "a.html") + contents(dir / "b.md") + contents(dir / "c.svg"), "abc");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 3);

  const fs::path empty = fresh_dir("atomic_set_fail");
  EXPECT_THROW(write_files_atomically({{empty / "a.html", "a"}, {empty / "missing" / "b.md", "b"}}, "--out"),
               InputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(empty), fs::directory_iterator()), 0) << "a.html was left behind";
}

TEST(AtomicFile, ADirectoryInTheWayFailsBeforeAnythingIsWritten) {
  const fs::path dir = fresh_dir("atomic_set_dir");
  fs::create_directories(dir / "b.md");
  std::ofstream(dir / "a.html") << "old";
  try {
    write_files_atomically({{dir / "a.html", "new"}, {dir / "b.md", "b"}}, "--out");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--out");
    EXPECT_NE(e.problem().find("b.md"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contents(dir / "a.html"), "old") << "the old file must stay";
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

}  // namespace
}  // namespace linkproof
