// Library errors name the quantity they are about, never a command-line option: the library
// serves several commands (sweep, merge and linkproof_mpi write result files; bench and prove
// are also library calls), and each command names its own option where it catches the error
// (cli/command.h, rethrow_naming_option), so what the user reads is unchanged.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "batch/result_file.h"
#include "batch/sweep_files.h"
#include "numerics/bench_study.h"

namespace linkproof {
namespace {

using test::fresh_dir;
using test::run_cli;

void ignore_line(const std::string&, long) {}

TEST(ResultFile, ErrorsNameTheResultFileAndNoOption) {
  const std::string dir = fresh_dir("result_file_errors");
  try {
    ResultFile f(dir, false, ignore_line);
    FAIL() << "a directory was opened as a result file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), dir);
    EXPECT_EQ(e.field(), "result file");
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  }
  const std::string used = dir + "/used.jsonl";
  std::ofstream(used) << "{}\n";
  try {
    ResultFile f(used, false, ignore_line);
    FAIL() << "a non-empty result file was reopened without resume";
  } catch (const ResultFileExists& e) {
    EXPECT_EQ(e.field(), "result file");
  }
}

// Resuming cuts off a last line without its newline (a crash while writing it), but only after
// lines the run accepted: a file of one line without a newline (a JSON document given to --out by
// mistake) was emptied and overwritten by the sweep, exit 0.
TEST(ResultFile, AFileWithoutACompleteLineIsNeverCutOnResume) {
  const std::string dir = fresh_dir("result_file_no_line");
  const std::string precious = dir + "/precious.json";
  const std::string content = "{\"my\": \"precious data, one line, no trailing newline\"}";
  std::ofstream(precious, std::ios::binary) << content;
  long visited = 0;
  try {
    ResultFile f(precious, true, [&](const std::string&, long) { ++visited; });
    FAIL() << "a file without a complete line was taken for a result file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no complete line"), std::string::npos) << e.what();
  }
  EXPECT_EQ(visited, 0);
  std::ifstream in(precious, std::ios::binary);
  const std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(after, content);
  const auto sweep = run_cli({"sweep", "--n", "4", "--count", "1", "--jobs", "1", "--out", precious, "--resume"});
  EXPECT_EQ(sweep.code, 2) << sweep.out;
  std::ifstream again(precious, std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>()), content);
  // After a complete line the cut-off rule still applies: the partial line goes, the line stays.
  const std::string cut = dir + "/cut.jsonl";
  std::ofstream(cut, std::ios::binary) << "{\"line\": 1}\n{\"partial";
  { ResultFile f(cut, true, ignore_line); }
  std::ifstream cut_in(cut, std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(cut_in)), std::istreambuf_iterator<char>()), "{\"line\": 1}\n");
}

TEST(ResultFile, TheCommandsNameTheirOutOptionWhereTheyCatchTheErrors) {
  const std::string dir = fresh_dir("result_file_cli");
  const auto sweep = run_cli({"sweep", "--n", "5", "--count", "1", "--jobs", "1", "--out", dir});
  EXPECT_EQ(sweep.code, 2);
  EXPECT_NE(sweep.err.find(dir + ": --out: is not a regular file"), std::string::npos) << sweep.err;
  const std::string shard = dir + "/s.jsonl";
  ASSERT_EQ(run_cli({"sweep", "--n", "5", "--count", "1", "--jobs", "1", "--out", shard}).code, 0);
  const auto again = run_cli({"sweep", "--n", "5", "--count", "1", "--jobs", "1", "--out", shard});
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.err.find(shard + ": --out: exists and is not empty"), std::string::npos) << again.err;
  const auto merge = run_cli({"merge", "--out", dir, shard});
  EXPECT_EQ(merge.code, 2);
  EXPECT_NE(merge.err.find(dir + ": --out: is not a regular file"), std::string::npos) << merge.err;
}

TEST(BenchStudy, AnUnknownFamilyIsNamedAsTheLibraryFieldAndAsTheOptionByTheCommand) {
  BenchOptions o;
  o.families = {"no_such_family"};
  try {
    (void)run_bench(o);
    FAIL() << "an unknown family was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "<api>");
    EXPECT_EQ(e.field(), "families");
  }
  const auto r = run_cli({"bench", "--families", "no_such_family", "--quiet"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("<command line>: --families: unknown family 'no_such_family'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
