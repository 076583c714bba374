// What `sweep --resume` (and `merge`) accept from a result file (issue 24, item 8): each case
// line must be what this sweep would have written for that case, or the run is refused with
// exit 2 naming the file, the line and the problem. An edited verdict, a claim moved to
// not_applicable or an unknown claim was carried into the summary before.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <functional>

#include "batch/sweep_files.h"

namespace linkproof {
namespace {

using nlohmann::json;
using test::fresh_dir;
using test::read_file;
using test::run_cli;

const std::vector<std::string> kSweep = {"sweep", "--n", "4..6", "--count", "4", "--seed", "11", "--jobs", "1"};

std::vector<std::string> with(std::vector<std::string> extra) {
  std::vector<std::string> a = kSweep;
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

/// The lines of one uninterrupted run (12 cases, then the summary), computed once.
const std::vector<std::string>& reference_lines() {
  static const std::vector<std::string> lines = [] {
    const std::string dir = fresh_dir("resume_validation_ref");
    const auto run = run_cli(with({"--out", dir + "/ref.jsonl"}));
    EXPECT_EQ(run.code, 0) << run.err;
    std::vector<std::string> out;
    std::istringstream in(read_file(dir + "/ref.jsonl"));
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  }();
  return lines;
}

/// The digest docs/sweeps.md documents: FNV-1a (64 bits) of the line without its "digest"
/// member, in 16 lowercase hex digits. Written here from the documentation, not taken from
/// the library, so that a test can play the part of someone who edits a line and recomputes it.
std::string documented_digest(json line) {
  line.erase("digest");
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : line.dump()) h = (h ^ c) * 0x100000001b3ULL;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, h);
  return hex;
}

/// The first `cases` case lines with line `edited` (1-based) changed by `edit`; when `redigest`,
/// its digest is recomputed so that only the structural checks can find the edit.
std::string edited_file(int cases, int edited, const std::function<void(json&)>& edit, bool redigest) {
  std::string text;
  for (int i = 0; i < cases; ++i) {
    std::string line = reference_lines().at(static_cast<size_t>(i));
    if (i + 1 == edited) {
      json j = json::parse(line);
      edit(j);
      if (redigest) j["digest"] = documented_digest(j);
      line = j.dump();
    }
    text += line + "\n";
  }
  return text;
}

/// A claim id with a verdict in `line` (the first, in id order).
std::string some_claim(const json& line) { return line["verdicts"].begin().key(); }

struct ResumeRun {
  test::CliRun run;
  std::string file;
};

ResumeRun resume_with(const std::string& name, const std::string& text) {
  const std::string file = fresh_dir("resume_validation_" + name) + "/r.jsonl";
  std::ofstream(file, std::ios::binary) << text;
  return {run_cli(with({"--out", file, "--resume", "--json"})), file};
}

void expect_refused(const ResumeRun& r, int line, const std::string& problem) {
  EXPECT_EQ(r.run.code, 2) << r.run.err << r.run.out;
  EXPECT_NE(r.run.err.find(r.file), std::string::npos) << r.run.err;
  EXPECT_NE(r.run.err.find("line " + std::to_string(line)), std::string::npos) << r.run.err;
  EXPECT_NE(r.run.err.find(problem), std::string::npos) << r.run.err;
  EXPECT_EQ(r.run.out.find("\"summary\""), std::string::npos) << "no report from a refused file";
}

void remove_a_verdict(json& j) { j["verdicts"].erase(some_claim(j)); }
void move_a_claim_to_not_applicable(json& j) {
  const std::string id = some_claim(j);
  j["verdicts"].erase(id);
  j["not_applicable"].push_back(id);
}
void add_an_unknown_claim(json& j) { j["verdicts"]["dijksman1966.eq99"] = "holds"; }
void turn_a_verdict_inconclusive(json& j) { j["verdicts"][some_claim(j)] = "inconclusive"; }

TEST(ResumeValidation, AnEditedCaseLineIsRefusedNamingFileAndLine) {
  for (const auto& [name, edit] : std::vector<std::pair<std::string, std::function<void(json&)>>>{
           {"removed", remove_a_verdict},
           {"not_applicable", move_a_claim_to_not_applicable},
           {"unknown", add_an_unknown_claim},
           {"inconclusive", turn_a_verdict_inconclusive}}) {
    SCOPED_TRACE(name);
    expect_refused(resume_with("edit_" + name, edited_file(6, 4, edit, false)), 4, "digest");
  }
}

TEST(ResumeValidation, AVerdictRemovedIsRefusedEvenWithItsDigestRecomputed) {
  expect_refused(resume_with("forged_removed", edited_file(6, 3, remove_a_verdict, true)), 3,
                 "has no verdict of dijksman1966.");
}

TEST(ResumeValidation, AClaimMovedToNotApplicableIsRefusedEvenWithItsDigestRecomputed) {
  expect_refused(resume_with("forged_na", edited_file(6, 2, move_a_claim_to_not_applicable, true)), 2,
                 "applies at n = 4");
}

TEST(ResumeValidation, AnUnknownClaimIsRefusedEvenWithItsDigestRecomputed) {
  expect_refused(resume_with("forged_unknown", edited_file(6, 5, add_an_unknown_claim, true)), 5,
                 "unknown claim dijksman1966.eq99");
}

TEST(ResumeValidation, ALineWithoutItsDigestIsRefused) {
  expect_refused(resume_with("no_digest", edited_file(6, 1, [](json& j) { j.erase("digest"); }, false)), 1, "digest");
}

TEST(ResumeValidation, AnExampleTheRunDoesNotKeepIsRefusedEvenWithItsDigestRecomputed) {
  // Evidence of a claim that holds: a run keeps evidence only of unexpected outcomes and of
  // erratum readings that fail, so this line is not one the sweep writes.
  const auto add_example = [](json& j) {
    std::string id;
    for (const auto& [claim, verdict] : j["verdicts"].items())
      if (id.empty() && verdict == "holds") id = claim;
    ASSERT_FALSE(id.empty());
    j["examples"].push_back(json{{"claim", id}, {"verdict", "holds"},
                                 {"evidence", json{{"label", "total"}, {"verdict", "holds"}, {"lhs", "1"},
                                                   {"rhs", "1"}, {"residual", "0"}}}});
  };
  expect_refused(resume_with("forged_example", edited_file(6, 2, add_example, true)), 2,
                 "is not the line this sweep writes for case 1");
}

TEST(ResumeValidation, ValidLinesStillGiveTheBytesOfOneRun) {
  const std::string file = fresh_dir("resume_validation_ok") + "/r.jsonl";
  std::string text, whole;
  for (size_t i = 0; i < reference_lines().size(); ++i) {
    if (i < 7) text += reference_lines()[i] + "\n";
    whole += reference_lines()[i] + "\n";
  }
  std::ofstream(file, std::ios::binary) << text;
  const auto run = run_cli(with({"--out", file, "--resume"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_file(file), whole);
}

TEST(ResumeValidation, EveryCaseLineCarriesTheDocumentedDigest) {
  for (size_t i = 0; i + 1 < reference_lines().size(); ++i) {
    const json j = json::parse(reference_lines()[i]);
    ASSERT_TRUE(j.contains("digest")) << reference_lines()[i];
    EXPECT_EQ(j["digest"], documented_digest(j)) << "line " << i + 1;
  }
}

// merge reads shard files the same way: an edited shard line is refused.
TEST(MergeValidation, AnEditedShardLineIsRefusedNamingFileAndLine) {
  const std::string dir = fresh_dir("merge_validation");
  const std::string s1 = dir + "/s1.jsonl", s2 = dir + "/s2.jsonl";
  ASSERT_EQ(run_cli(with({"--shard", "1/2", "--out", s1})).code, 0);
  ASSERT_EQ(run_cli(with({"--shard", "2/2", "--out", s2})).code, 0);
  std::istringstream in(read_file(s2));
  std::string text;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    if (++number == 3) {
      json j = json::parse(line);
      move_a_claim_to_not_applicable(j);
      line = j.dump();
    }
    text += line + "\n";
  }
  std::ofstream(s2, std::ios::binary | std::ios::trunc) << text;
  const auto r = run_cli({"merge", "--out", dir + "/m.jsonl", s1, s2});
  EXPECT_EQ(r.code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find(s2), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 3"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace linkproof
