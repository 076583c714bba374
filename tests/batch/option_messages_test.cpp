// Error messages name only options of the command that prints them (issue 24, item 13):
// `merge --out /dev/null` suggested `--resume`, which `merge` does not have.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "batch/sweep_files.h"

namespace linkproof {
namespace {

using test::fresh_dir;
using test::read_file;
using test::run_cli;

/// The options `linkproof COMMAND --help` lists, and the resource options every command takes.
std::set<std::string> options_of(const std::string& command) {
  std::set<std::string> options = {"--max-seconds", "--max-memory-mb", "--help"};
  const std::string help = run_cli({command, "--help"}).out;
  const std::regex option("--[a-z][a-z0-9-]*");
  for (auto it = std::sregex_iterator(help.begin(), help.end(), option); it != std::sregex_iterator(); ++it)
    options.insert(it->str());
  return options;
}

/// Every "--option" in `text` that is not an option of `command`.
std::vector<std::string> foreign_options(const std::string& command, const std::string& text) {
  const std::set<std::string> own = options_of(command);
  std::vector<std::string> foreign;
  const std::regex option("--[a-z][a-z0-9-]*");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
    if (!own.count(it->str())) foreign.push_back(it->str());
  return foreign;
}

struct Shards {
  std::string dir, s1, s2;
};

const Shards& shards() {
  static const Shards s = [] {
    Shards x{fresh_dir("option_messages"), "", ""};
    x.s1 = x.dir + "/s1.jsonl";
    x.s2 = x.dir + "/s2.jsonl";
    for (const auto& [k, f] : {std::pair{"1/2", x.s1}, std::pair{"2/2", x.s2}})
      EXPECT_EQ(run_cli({"sweep", "--n", "5", "--count", "4", "--jobs", "1", "--shard", k, "--out", f}).code, 0);
    return x;
  }();
  return s;
}

void expect_own_options_only(const std::vector<std::string>& args) {
  SCOPED_TRACE(::testing::PrintToString(args));
  const test::CliRun r = run_cli(args);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(foreign_options(args.front(), r.err), std::vector<std::string>{}) << r.err;
}

TEST(MergeMessages, MergeOutDevNullIsRefusedWithoutSuggestingResume) {
  const test::CliRun r = run_cli({"merge", "--out", "/dev/null", shards().s1, shards().s2});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/null"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--resume"), std::string::npos) << r.err;
}

TEST(MergeMessages, EveryRefusalNamesOnlyMergesOptions) {
  const std::string existing = shards().dir + "/existing.jsonl";
  std::ofstream(existing) << "precious\n";
  const std::string incomplete = shards().dir + "/incomplete.jsonl";
  std::string text = read_file(shards().s2);
  text.erase(text.rfind('\n', text.size() - 2) + 1);  // no summary line
  std::ofstream(incomplete, std::ios::binary) << text;
  for (const std::string& out : {std::string("/dev/null"), existing, shards().dir, std::string("/nonexistent/m.jsonl")})
    expect_own_options_only({"merge", "--out", out, shards().s1, shards().s2});
  expect_own_options_only({"merge", "--out", shards().dir + "/m.jsonl", shards().s1, incomplete});
  EXPECT_EQ(read_file(existing), "precious\n");
}

TEST(SweepMessages, EveryRefusalOfOutNamesOnlySweepsOptions) {
  const std::string existing = shards().dir + "/existing_sweep.jsonl";
  std::ofstream(existing) << "precious\n";
  for (const std::string& out : {std::string("/dev/null"), existing, shards().dir, std::string("/nonexistent/s.jsonl")})
    expect_own_options_only({"sweep", "--n", "5", "--count", "2", "--jobs", "1", "--out", out});
  // Without --resume an existing file is refused, and the message says how to continue it.
  const test::CliRun r = run_cli({"sweep", "--n", "5", "--count", "2", "--jobs", "1", "--out", existing});
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
