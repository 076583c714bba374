// ::testing::TempDir() is /tmp/ in every test process. ctest runs each test in a process of its
// own, two at a time or more, and the test runs of other checkouts on the machine share /tmp:
// helpers that write a fixed name there (bad_input_cd_fourbar.yaml, check_data_hostile_*.yaml,
// ...) raced, one test truncating a file another was reading (a spurious "empty document").
// Linked into every test executable (tests/CMakeLists.txt): before main, a process whose
// TEST_TMPDIR is not set (GoogleTest's TempDir() honours it) gets its own directory,
// /tmp/linkproof_test_<pid>/, removed when it exits. A child test process (a re-exec of the
// test binary) inherits its parent's directory; a forked child never removes it.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace {

std::filesystem::path& own_directory() {
  static std::filesystem::path dir;
  return dir;
}

pid_t& owner() {
  static pid_t pid = 0;
  return pid;
}

void remove_own_directory() {
  if (::getpid() != owner() || own_directory().empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(own_directory(), ignored);
}

const bool kPerProcessTempDir = [] {
  if (const char* set = std::getenv("TEST_TMPDIR"); set != nullptr && *set != '\0') return false;
  std::error_code error;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path(error) / ("linkproof_test_" + std::to_string(::getpid()));
  if (error) return false;
  std::filesystem::create_directories(dir, error);  // may exist: a dead process's, of the same pid
  if (error) return false;
  own_directory() = dir;
  owner() = ::getpid();
  ::setenv("TEST_TMPDIR", (dir.string() + "/").c_str(), 1);
  std::atexit(remove_own_directory);
  return true;
}();

}  // namespace
