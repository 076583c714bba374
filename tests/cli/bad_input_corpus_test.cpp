// The bad-input corpus of issue 12: one row per hostile input (every class of the issue's
// table: crash, exit 3 on user input, unbounded work, wrong answer, silent acceptance, output,
// messages), with the exit code and a fragment of the message the program must give. Each row
// failed before the hardening (a crash, a hang, exit 0 or 3, or an unhelpful message).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "report/report_checks.h"
#include "support/cli_run.h"
#include "support/motion_csv.h"

namespace linkproof {
namespace {

std::string source_file(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "bad_input_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string polygon_scene(const std::string& name, const std::string& joints) {
  return "name: " + name + "\npolygon:\n  joints: " + joints + "\n  omega: [2, -1]\n  omega_dot: [1, 3]\n";
}
const std::string kPentagonJoints = "[[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]";

std::string claim_file(const std::string& rhs) {
  return "claims:\n  - id: c1\n    source: test\n    statement: s\n    lhs: omega_out\n    rhs: \"" + rhs + "\"\n";
}

// A mechanism claim file with one claim (lhs and rhs written in double quotes).
std::string mechanism_claim(const std::string& lhs, const std::string& rhs) {
  return "claims:\n  - id: c1\n    source: test\n    statement: s\n    lhs: \"" + lhs + "\"\n    rhs: \"" + rhs + "\"\n";
}

// The seed-001 four-bar with its crank O2-A given as `crank_a` and every coordinate times `scale`.
std::string fourbar(const std::string& a, const std::string& b, const std::string& o4) {
  return "name: fourbar\nmechanism:\n  ground: \"1\"\n  joints:\n"
         "    - {name: O2, type: revolute, links: [\"1\", \"2\"], at: [0, 0]}\n"
         "    - {name: A,  type: revolute, links: [\"2\", \"3\"], at: " + a + "}\n"
         "    - {name: B,  type: revolute, links: [\"3\", \"4\"], at: " + b + "}\n"
         "    - {name: O4, type: revolute, links: [\"4\", \"1\"], at: " + o4 + "}\n"
         "  inputs:\n    - {link: \"2\", omega: 2, omega_dot: 5}\n";
}

// A six-slot Geneva drive whose slot P has the axis `axis` and the links `links`.
std::string geneva_slot(const std::string& axis, const std::string& links) {
  return "name: geneva\nmechanism:\n  ground: frame\n  joints:\n"
         "    - {name: O2, type: revolute, links: [frame, crank], at: [0, 0]}\n"
         "    - {name: O4, type: revolute, links: [wheel, frame], at: [100, 0]}\n"
         "    - {name: P, type: slot, links: " + links + ", at: [40, 30], axis: " + axis + "}\n"
         "  inputs:\n    - {link: crank, omega: 2, omega_dot: 0}\n";
}

// A small sweep's result file (3 cases of n = 5) with the text of line 2 changed by `edit`, and
// the command line that resumes it.
std::vector<std::string> resume_of_edited_sweep_text(const std::string& name, const std::function<void(std::string&)>& edit) {
  const std::string path = write_temp(name + ".jsonl", "");
  std::remove(path.c_str());
  const std::vector<std::string> sweep = {"sweep", "--n", "5", "--count", "3", "--jobs", "1", "--out", path};
  test::run_cli(sweep);
  std::ifstream in(path, std::ios::binary);
  std::string text, line;
  for (int number = 1; number <= 2 && std::getline(in, line); ++number) {
    if (number == 2) edit(line);
    text += line + "\n";
  }
  in.close();
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  std::vector<std::string> resume = sweep;
  resume.insert(resume.end(), {"--resume", "--json"});
  return resume;
}

// ... with line 2 changed as JSON.
std::vector<std::string> resume_of_edited_sweep(const std::string& name,
                                                const std::function<void(nlohmann::json&)>& edit) {
  return resume_of_edited_sweep_text(name, [&](std::string& line) {
    nlohmann::json j = nlohmann::json::parse(line);
    edit(j);
    line = j.dump();
  });
}

// check-data (issue 24): a four-bar scene with plain names, a CSV row of it, and the Watt I
// row matlab_0000 mirrored (every x negated).
const std::string kCheckDataHeader = "sample,O2.x,O2.y,A.x,A.y,B.x,B.y,O4.x,O4.y,omega.crank,alpha.crank,alpha.coupler\n";
std::string check_data_fourbar(const std::string& a) {
  return "name: fourbar\nmechanism:\n  ground: g\n  joints:\n"
         "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
         "    - {name: A, type: revolute, links: [crank, coupler], at: " + a + "}\n"
         "    - {name: B, type: revolute, links: [coupler, rocker], at: [11, 10]}\n"
         "    - {name: O4, type: revolute, links: [rocker, g], at: [11, 0]}\n"
         "  inputs:\n    - {link: crank, omega: 2, omega_dot: 5}\n";
}
std::string mirrored_watt_row() {
  std::ifstream in(source_file("verify/data/pmks_watt_i_matlab.csv"));
  std::stringstream text;
  text << in.rdbuf();
  return test::mirrored_first_row(text.str());
}

struct Case {
  std::string name;
  std::function<std::vector<std::string>()> args;  // builds its files when run
  int code;
  std::string err_fragment;  // expected in stderr ("" = nothing required)
  std::string out_fragment;  // expected in stdout ("" = nothing required)
  std::string out_absent;    // must not appear in stdout ("" = nothing required)
};

std::ostream& operator<<(std::ostream& o, const Case& c) { return o << c.name; }

const std::vector<Case>& corpus() {
  static const std::vector<Case> cases = {
      // --- crash
      {"NestedParentheses8000",
       [] { return std::vector<std::string>{"check-claim", write_temp("paren.yaml", claim_file(std::string(8000, '(') + "omega_out" + std::string(8000, ')')))}; },
       2, "nested more than 100 levels", "", ""},
      {"LeadingMinusSigns20000",
       [] { return std::vector<std::string>{"check-claim", write_temp("minus.yaml", claim_file(std::string(20000, '-') + "omega_out"))}; },
       2, "the limit is 20000", "", ""},
      // An alias inside its own anchor: a cycle the YAML parser's nesting limit does not see;
      // the walk for repeated keys followed it until the stack overflowed (SIGSEGV).
      {"CyclicAliasAsTheListOfClaims",
       [] { return std::vector<std::string>{"check-claim", write_temp("cycle.yaml", "claims: &c [*c]\n"), "--json"}; },
       2, "an alias inside its own anchor", "", ""},
      {"CyclicAliasInsideAClaim",
       [] {
         return std::vector<std::string>{"prove", "--file",
                                         write_temp("cycle2.yaml", "claims:\n  - {id: c1, source: t, statement: t, lhs: omega_out, "
                                                                   "rhs: omega_out, reading: &r [*r]}\n")};
       },
       2, "an alias inside its own anchor", "", ""},
      // A tracer point named like a joint, or like another point: claims silently read the other.
      {"TracerPointNamedLikeAJoint",
       [] {
         return std::vector<std::string>{
             "check", write_temp("point_joint.yaml", fourbar("[3, 4]", "[11, 10]", "[11, 0]") +
                                                         "  points:\n    - {name: A, link: \"3\", at: [9, 14]}\n")};
       },
       2, "mechanism.points[0].name: `A` is the name of a joint", "", ""},
      {"TwoTracerPointsOfOneName",
       [] {
         return std::vector<std::string>{
             "check", write_temp("point_twice.yaml", fourbar("[3, 4]", "[11, 10]", "[11, 0]") +
                                                         "  points:\n    - {name: P, link: \"3\", at: [9, 14]}\n"
                                                         "    - {name: P, link: \"3\", at: [5, 5]}\n")};
       },
       2, "mechanism.points[1].name: the point `P` is given twice", "", ""},
      // Each power within the limits, the whole a 52-million-digit number: the run formed and
      // printed it for as long as its budget allowed.
      {"NestedPowersOfALongIntegerInAMechanismClaim",
       [] {
         return std::vector<std::string>{
             "check-claim",
             write_temp("pow3.yaml", mechanism_claim("omega(\\\"3\\\")", "((" + std::string(199, '9') + "^64)^64)^64")),
             "--scene", write_temp("pow3_scene.yaml", fourbar("[3, 4]", "[11, 10]", "[11, 0]"))};
       },
       2, "has degree (digits of numbers included) above 1024", "", ""},
      {"LeadingMinusSigns100",
       [] { return std::vector<std::string>{"check-claim", write_temp("minus100.yaml", claim_file(std::string(100, '-') + "omega_out"))}; },
       2, "100 signs in a row", "", ""},
      // --- exit 3 on user input
      {"Huge1e400WithLongDouble",
       [] { return std::vector<std::string>{"check", write_temp("e400.yaml", polygon_scene("big", "[[0, 0], [1e400, 4], [5, 5], [7, 1], [3, -2]]")), "--arith", "long-double"}; },
       0, "", "long double", ""},
      {"Huge1e400WithDoubleIsInconclusive",
       [] { return std::vector<std::string>{"check", write_temp("e400d.yaml", polygon_scene("big", "[[0, 0], [1e400, 4], [5, 5], [7, 1], [3, -2]]")), "--arith", "double"}; },
       0, "", "a side overflowed", ""},
      {"InvalidUtf8InSceneNameWithJson",
       [] { return std::vector<std::string>{"check", write_temp("utf8.yaml", polygon_scene("\"pent\xff\xfe\"", kPentagonJoints)), "--json"}; },
       0, "", "pent\\\\xff\\\\xfe", ""},
      {"InvalidUtf8InClaimStatementWithJson",
       [] {
         return std::vector<std::string>{
             "check-claim",
             write_temp("utf8claim.yaml", "claims:\n  - id: c1\n    source: test\n    statement: \"s \xff\"\n    lhs: omega_out\n    rhs: omega_out\n"),
             "--scene", source_file("verify/scenes/pentagon.yaml"), "--json"};
       },
       0, "", "s \\\\xff", ""},
      // --- unbounded work
      {"ExponentTenToTheTenToTheTen",
       [] { return std::vector<std::string>{"check-claim", write_temp("pow1.yaml", claim_file("10^(10^10)"))}; },
       2, "exponent of '^' must be an integer from -64 to 64", "", ""},
      {"ExponentTwoToTheTwoToThe30",
       [] { return std::vector<std::string>{"check-claim", write_temp("pow2.yaml", claim_file("2^(2^30)"))}; },
       2, "exponent of '^'", "", ""},
      {"NestedPowersBeyondTheDegreeBudget",
       [] { return std::vector<std::string>{"check-claim", write_temp("pow4.yaml", claim_file("((omega_out^64)^64)^64"))}; },
       2, "degree", "", ""},
      // A claim that is not well formed is the input's fault: exit 2, quoting the claim as
      // written (these were exit 3, "internal error", and quoted lp_word1(32,1)).
      {"AVectorWhereANumberIsExpected",
       [] { return std::vector<std::string>{"check-claim", write_temp("vec.yaml", claim_file("r[1]"))}; },
       2, "a vector where a number is expected: r[1]", "", ""},
      {"DivisionByTheRates",
       [] { return std::vector<std::string>{"check-claim", write_temp("divrate.yaml", claim_file("1/omega[1]"))}; },
       2, "division by an expression that contains rates", "", ""},
      {"AVectorClaimOnAScene",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("vec2.yaml", claim_file("dot(r[1], r[2]) * K[1]")),
                                         "--scene", source_file("verify/scenes/pentagon.yaml")};
       },
       2, "a vector where a number is expected", "", ""},
      {"AnIllFormedClaimGivenToProve",
       [] { return std::vector<std::string>{"prove", "--file", write_temp("vec3.yaml", claim_file("r[2]"))}; },
       2, "claim 'c1': a vector where a number is expected: r[2]", "", ""},
      {"AnIllFormedClaimGivenToReport",
       [] {
         return std::vector<std::string>{"report", write_temp("vec4.yaml", claim_file("1/omega[1]")), "--out",
                                         ::testing::TempDir() + "ill_formed_report"};
       },
       2, "division by an expression that contains rates", "", ""},
      // Ill formed at every n, also where its sum has no terms: on a four-bar (no pairs) the sum
      // was 0 and the claim was judged as if well formed (with lhs 0 it "held") until claims
      // were compiled, and typed, once (ClaimProgram.*).
      {"AProductOfVectorsInASumOverNoPairs",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("vec5.yaml", claim_file("sum_pairs(r[j]*r[l])")),
                                         "--scene", write_temp("fourbar.yaml", "name: fourbar\npolygon:\n  joints: [[0,0],[1,3],[4,4],[5,0]]\n  omega: [2]\n  omega_dot: [1]\n")};
       },
       2, "claim 'c1': product of two vectors", "", ""},
      {"ATermOfDegreeNineInTheRates",  // RatePoly's monomials hold 8 rates (docs/limits.md)
       [] { return std::vector<std::string>{"check-claim", write_temp("deg9.yaml", claim_file("omega[1]^9"))}; },
       2, "degree 9 in the rates", "", ""},
      {"DevZero", [] { return std::vector<std::string>{"check", "/dev/zero"}; }, 2, "larger than the limit", "", ""},
      {"TenMegabyteScene",
       [] {
         std::string joints = "[";
         for (int i = 0; i < 700000; ++i) joints += "[" + std::to_string(i) + ", " + std::to_string(i % 977) + "], ";
         joints += "[0, 1]]";
         return std::vector<std::string>{"check", write_temp("10mb.yaml", polygon_scene("big", joints))};
       },
       2, "larger than the limit", "", ""},
      {"OneMegabyteInteger",
       [] { return std::vector<std::string>{"check", write_temp("1mb.yaml", polygon_scene("big", "[[0, 0], [" + std::string(1000000, '7') + ", 4], [5, 5], [7, 1], [3, -2]]"))}; },
       2, "the limit is 200", "", ""},
      {"LadderSecondsNaN",
       [] { return std::vector<std::string>{"prove", "--claim", "eq22", "--ladder-seconds", "nan"}; },
       2, "not a time budget", "", ""},
      {"LadderSecondsNaNInReport",  // report's option had no check: the ladder ran to the run's budget
       [] {
         return std::vector<std::string>{"report", write_temp("ok_report.yaml", claim_file("omega_out")), "--ladder-seconds",
                                         "nan", "--out", ::testing::TempDir() + "nan_report"};
       },
       2, "not a time budget", "", ""},
      {"LadderSecondsInfinityInCheckClaim",
       [] { return std::vector<std::string>{"check-claim", write_temp("ok.yaml", claim_file("omega_out")), "--ladder-seconds", "inf"}; },
       2, "not a time budget", "", ""},
      {"PolygonAboveTheCheckLimit",
       [] {
         const int n = 201;
         std::string joints = "[", rates = "[";
         for (int i = 0; i < n; ++i) joints += (i ? ", [" : "[") + std::to_string(i) + ", " + std::to_string(i * i) + "]";
         for (int j = 0; j < n - 3; ++j) rates += (j ? ", " : "") + std::string("1");
         const std::string text = "name: big\npolygon:\n  joints: " + joints + "]\n  omega: " + rates + "]\n  omega_dot: " + rates + "]\n";
         return std::vector<std::string>{"check", write_temp("n201.yaml", text)};
       },
       2, "at most 200 joints", "", ""},
      // --- silent acceptance
      {"DuplicateKeyInClaimFile",
       [] {
         return std::vector<std::string>{
             "check-claim", write_temp("dup.yaml", "claims:\n  - id: c1\n    source: t\n    statement: s\n    lhs: omega_out\n    rhs: omega_out\n    rhs: 2*omega_out\n")};
       },
       2, "`rhs` is given twice", "", ""},
      {"SeedMinusOne", [] { return std::vector<std::string>{"sweep", "--n", "5", "--count", "1", "--seed", "-1"}; }, 2, "not a seed", "", ""},
      {"SeedAbove2To64",
       [] { return std::vector<std::string>{"sweep", "--n", "5", "--count", "1", "--seed", "18446744073709551616"}; },
       2, "not a seed", "", ""},
      {"ProveNMaxNegative", [] { return std::vector<std::string>{"prove", "--claim", "eq22", "--n-max", "-5"}; }, 2, "--n-max", "", ""},
      {"ZeroLengthCrank",
       [] { return std::vector<std::string>{"check", write_temp("crank.yaml", fourbar("[0, 0]", "[11, 10]", "[11, 0]"))}; },
       2, "zero length", "", ""},
      // --- wrong answer: the floating route must not overrule the exact mobility
      {"MechanismNear1e200InDouble",
       [] { return std::vector<std::string>{"check", write_temp("e200.yaml", fourbar("[3e200, 4e200]", "[11e200, 10e200]", "[11e200, 0]")), "--arith", "double"}; },
       0, "", "the motion shown is the exact one", ""},
      // --- output
      {"ControlCharactersInSceneName",
       [] { return std::vector<std::string>{"check", write_temp("ctrl.yaml", polygon_scene("\"pent\\nFAKE: all claims hold\\e[31m\"", kPentagonJoints))}; },
       0, "", "pent\\nFAKE: all claims hold\\x1b[31m", "\nFAKE"},
      {"FailedRunWithJsonPrintsAnErrorObject",
       [] { return std::vector<std::string>{"check", "/nonexistent/scene.yaml", "--json"}; },
       2, "cannot read file", "\"exit_status\": 2", ""},
      // --- messages
      {"UnknownSubcommandWithArguments", [] { return std::vector<std::string>{"reprot", "x.yaml"}; }, 2, "unknown subcommand 'reprot'", "", ""},
      {"TabInIndentation",
       [] { return std::vector<std::string>{"check", write_temp("tab.yaml", "name: p\npolygon:\n\tjoints: " + kPentagonJoints + "\n  omega: [2, -1]\n  omega_dot: [1, 3]\n")}; },
       2, "tab character", "", ""},
      {"NulByte",
       [] { return std::vector<std::string>{"check", write_temp("nul.yaml", polygon_scene(std::string("\"pe\0nt\"", 7), kPentagonJoints))}; },
       2, "NUL byte", "", ""},
      {"ChainedPowerMessage",
       [] { return std::vector<std::string>{"check-claim", write_temp("pow3.yaml", claim_file("10^10^10"))}; },
       2, "a power of a power needs brackets", "", ""},
      {"MechanismSceneGivenToScene",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("ok2.yaml", claim_file("omega_out")), "--scene",
                                         source_file("verify/scenes/mechanisms/seed001_fourbar.yaml")};
       },
       2, "this is a mechanism scene (top-level `mechanism`)", "", ""},
      // --- issue 24: claims (divisors as written, claims undefined everywhere, rational counterexamples)
      {"ZeroOverZeroClaimIsBadInputNotProved",
       [] {
         const std::string z = "(norm2(r[n-2] + r[n-1]) - norm2(r[n-2]) - norm2(r[n-1]) - 2*dot(r[n-2], r[n-1]))";
         return std::vector<std::string>{"prove", "--file", write_temp("zz.yaml", claim_file("omega_out*" + z + "/" + z)),
                                         "--ladder-seconds", "0"};
       },
       2, "is identically zero", "", "proved"},
      {"AlwaysUndefinedClaimIsBadInputNotExit3",
       [] { return std::vector<std::string>{"prove", "--file", write_temp("undef.yaml", claim_file("omega_out + 1/dot(r[1], perp(r[1]))")), "--ladder-seconds", "0"}; },
       2, "dot(r[1], perp(r[1])) (", "", ""},
      {"ADivisorTimesZeroMakesTheClaimUndefinedWhereItVanishes",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("zerotimes.yaml", claim_file("omega_out + 0*(1/vx(r[n-1]))")), "--scene",
                                         write_temp("x0.yaml", polygon_scene("x0", "[[0, 0], [1, 4], [5, 5], [3, 1], [3, -2]]"))};
       },
       0, "", "the divisor vx(r[n-1]) of the claim as written", ""},
      {"AProofAtN200IsRefusedBeforeTheWork",
       [] { return std::vector<std::string>{"prove", "--claim", "eq22", "--n", "200"}; },
       2, "limited to n <= 20", "", ""},
      {"ACheckClaimProofAtN200IsRefusedBeforeTheWork",
       [] { return std::vector<std::string>{"check-claim", write_temp("n200.yaml", claim_file("omega_out")), "--n", "200"}; },
       2, "limited to n <= 20", "", ""},
      {"AWrongTermZeroAtEverySmallIntegerIsDisproved",
       [] {
         std::string f = "vx(K[n])";
         for (int k = 1; k <= 7; ++k) f += "*(vx(K[n])^2 - " + std::to_string(k * k) + ")";
         return std::vector<std::string>{"prove", "--file", write_temp("intzero.yaml", claim_file("omega_out + omega[1]*" + f)), "--ladder-seconds", "0"};
       },
       1, "", "disproved", ""},
      // --- issue 24: report output safety. Figure files are named after the scene: a name that
      // is a path wrote outside --out, a name with '/' or of 300 bytes failed after the HTML and
      // Markdown were written; now every name becomes one file name inside --out.
      {"ReportSceneNameWithDotDot",
       [] {
         return std::vector<std::string>{"report", write_temp("dotdot.yaml", polygon_scene("\"../../x\"", kPentagonJoints)),
                                         "--format", "md", "--out", ::testing::TempDir() + "corpus_dotdot/a/b"};
       },
       0, "", "corpus_dotdot/a/b/_.._x-construction.svg", "/../"},
      {"ReportAbsoluteSceneName",
       [] {
         return std::vector<std::string>{"report",
                                         write_temp("abs.yaml", polygon_scene("\"/tmp/linkproof_corpus_abs\"", kPentagonJoints)),
                                         "--format", "md", "--out", ::testing::TempDir() + "corpus_abs_out"};
       },
       0, "", "corpus_abs_out/_tmp_linkproof_corpus_abs-construction.svg", ""},
      {"ReportSceneNameWithSlash",
       [] {
         return std::vector<std::string>{"report", write_temp("slash.yaml", polygon_scene("\"a/b\"", kPentagonJoints)),
                                         "--format", "all", "--out", ::testing::TempDir() + "corpus_slash"};
       },
       0, "", "corpus_slash/a_b-construction.svg", ""},
      {"ReportSceneName300Bytes",
       [] {
         return std::vector<std::string>{"report", write_temp("long.yaml", polygon_scene(std::string(300, 'n'), kPentagonJoints)),
                                         "--format", "all", "--out", ::testing::TempDir() + "corpus_long"};
       },
       0, "", "corpus_long/" + std::string(183, 'n') + "-", std::string(184, 'n')},
      // Names, description and link names that are LaTeX, HTML and Markdown: written, escaped
      // (tests/report/report_output_safety_test.cpp checks the three files).
      {"ReportHostileMechanismNames",
       [] {
         return std::vector<std::string>{"report", write_temp("hostile.yaml", test::hostile_fourbar_scene()), "--format",
                                         "all", "--out", ::testing::TempDir() + "corpus_hostile"};
       },
       0, "", "corpus_hostile/bad_input_hostile.tex", ""},
      {"ReportWithADirectoryInTheWay",
       [] {
         const std::string out = ::testing::TempDir() + "corpus_in_the_way";
         std::filesystem::create_directories(out + "/pentagon.tex");
         return std::vector<std::string>{"report", source_file("verify/scenes/pentagon.yaml"), "--format", "all",
                                         "--out", out};
       },
       2, "pentagon.tex': a directory of that name is in the way", "", "wrote"},
      // --- issue 24, items 9, 13, 14: options and inputs read but not honoured, overflow named
      {"MechanismNear1e400InDoubleNamesTheOverflowNotTheMobility",
       [] { return std::vector<std::string>{"check", write_temp("e400m.yaml", fourbar("[3e400, 4e400]", "[11e400, 10e400]", "[11e400, 0]")), "--arith", "double"}; },
       0, "", "velocity constraints overflows", "mobility 3"},
      {"MechanismNear1e400InDoubleHasNoConditionNumber",
       [] { return std::vector<std::string>{"check", write_temp("e400j.yaml", fourbar("[3e400, 4e400]", "[11e400, 10e400]", "[11e400, 0]")), "--arith", "double", "--json"}; },
       0, "", "\"condition\": null", "needs 3 input"},
      {"MechanismNear1e200InDoubleSaysTheRoundedSolveDisagrees",
       [] { return std::vector<std::string>{"check", write_temp("e200b.yaml", fourbar("[3e200, 4e200]", "[11e200, 10e200]", "[11e200, 0]")), "--arith", "double"}; },
       0, "", "rounded solve disagrees with the exact one", "has mobility"},
      {"AnInputWithoutOmegaDotNamesTheField",
       [] {
         std::string scene = fourbar("[3, 4]", "[11, 10]", "[11, 0]");
         scene.replace(scene.find(", omega_dot: 5"), 14, "");
         return std::vector<std::string>{"check", write_temp("no_omega_dot.yaml", scene)};
       },
       2, "mechanism.inputs[0].omega_dot: missing required field", "", ""},
      {"AnEmptyClaimsListInAskIsRefused",
       [] { return std::vector<std::string>{"check", write_temp("ask_empty.yaml", polygon_scene("p", kPentagonJoints) + "ask: [claims: []]\n")}; },
       2, "ask[0].claims: the list of claim ids is empty", "", ""},
      {"TheSameSideAskedAsFourAndZeroFourIsRefused",
       [] { return std::vector<std::string>{"check", write_temp("ask_04.yaml", polygon_scene("p", kPentagonJoints) + "ask: [omega_dot(4), omega_dot(04)]\n")}; },
       2, "`omega_dot(4)` is asked twice", "", ""},
      {"CurvatureOfA100LoopChainIsRefusedBeforeTheWork",
       [] {
         std::string scene = "name: chain\nmechanism:\n  ground: g\n  joints:\n"
                             "    - {name: O, type: revolute, links: [g, c], at: [0, 0]}\n"
                             "    - {name: A, type: revolute, links: [c, l1], at: [1, 3]}\n"
                             "    - {name: B1, type: revolute, links: [l1, r1], at: [5, 4]}\n"
                             "    - {name: G1, type: revolute, links: [r1, g], at: [6, 0]}\n";
         for (int i = 2; i <= 100; ++i) {
           const std::string k = std::to_string(i), p = std::to_string(i - 1), x = std::to_string(5 * (i - 1));
           scene += "    - {name: P" + k + ", type: revolute, links: [r" + p + ", l" + k + "], at: [" + x + ", 2]}\n";
           scene += "    - {name: B" + k + ", type: revolute, links: [l" + k + ", r" + k + "], at: [" + x + "4, 5]}\n";
           scene += "    - {name: G" + k + ", type: revolute, links: [r" + k + ", g], at: [" + x + "6, 0]}\n";
         }
         scene += "  inputs:\n    - {link: c, omega: 1, omega_dot: 0}\n";
         return std::vector<std::string>{"curvature", write_temp("chain100.yaml", scene)};
       },
       2, "accepts at most 200 links", "", ""},
      // --- issue 25: an option that does not apply is refused, not ignored
      {"NoTermsOnAMechanismSceneIsRefused",
       [] { return std::vector<std::string>{"check", source_file("verify/scenes/mechanisms/seed001_fourbar.yaml"), "--no-terms"}; },
       2, "--no-terms: applies to polygon scenes only", "", ""},
      // --- issue 24: sweeps, result files, merge
      {"ResumeOfAResultFileWithAnEditedVerdict",  // was carried into the summary (exit 0)
       [] { return resume_of_edited_sweep("edited_verdict", [](nlohmann::json& j) { j["verdicts"].begin().value() = "inconclusive"; }); },
       2, "line 2.digest: does not match", "", "\"cases\""},
      {"ResumeOfAResultFileWithAClaimMovedToNotApplicable",
       [] {
         return resume_of_edited_sweep("moved_claim", [](nlohmann::json& j) {
           const std::string id = j["verdicts"].begin().key();
           j["verdicts"].erase(id);
           j["not_applicable"].push_back(id);
         });
       },
       2, "line 2", "", "\"cases\""},
      {"ResumeOfALineWithANumberBeyondDouble",
       [] {
         // nlohmann's out_of_range (number overflow), not a parse_error: it was an internal error, exit 3.
         return resume_of_edited_sweep_text("number_beyond_double", [](std::string& line) {
           const auto at = line.find("\"case\":");
           line.insert(at + 7, "1e400,\"was\":");
         });
       },
       2, "not a result line", "", ""},
      {"ResumeOfAResultFileWithAnUnknownClaim",
       [] { return resume_of_edited_sweep("unknown_claim", [](nlohmann::json& j) { j["verdicts"]["dijksman1966.eq99"] = "holds"; }); },
       2, "line 2", "", "\"cases\""},
      {"MergeOutDevNullNamesNoOptionMergeLacks",  // suggested --resume, which merge does not have
       [] {
         const std::string s1 = write_temp("merge_s1.jsonl", ""), s2 = write_temp("merge_s2.jsonl", "");
         std::remove(s1.c_str());
         std::remove(s2.c_str());
         test::run_cli({"sweep", "--n", "5", "--count", "2", "--jobs", "1", "--shard", "1/2", "--out", s1});
         test::run_cli({"sweep", "--n", "5", "--count", "2", "--jobs", "1", "--shard", "2/2", "--out", s2});
         return std::vector<std::string>{"merge", "--out", "/dev/null", s1, s2};
       },
       2, "/dev/null: --out: is not a regular file", "", ""},
      {"SweepNAboveTheLimit", [] { return std::vector<std::string>{"sweep", "--n", "599", "--count", "1"}; }, 2, "<= 200", "", ""},
      {"SweepNOfAMillion", [] { return std::vector<std::string>{"sweep", "--n", "4..1000000", "--count", "1"}; }, 2, "<= 200", "", ""},
      // --- check-data (issue 24): false passes, a crash, unreadable messages
      {"CheckDataSlideAccelerationOfAJointBeyondTheLinkCountIsCompared",
       [] {
         return std::vector<std::string>{
             "check-data", source_file("verify/scenes/mechanisms/seed003_class3.yaml"),
             write_temp("cd_slider.csv",
                        "sample,O1.x,O1.y,A.x,A.y,B.x,B.y,C.x,C.y,D.x,D.y,K.x,K.y,O2.x,O2.y,E.x,E.y,M.x,M.y,H.x,H.y,"
                        "omega.1,alpha.1,alpha.2,a.H\ns,0,0,2.005,-24.919,59.410,-42.375,117.349,-26.785,117.349,-26.785,"
                        "101.468,31.075,157.223,53.243,50.583,-9.368,68.199,47.987,68.199,47.987,100,0,0,0\n")};
       },
       1, "", "a      H", ""},
      {"CheckDataAlpha2e309IsRefused",
       [] {
         return std::vector<std::string>{"check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
                                         write_temp("cd_inf.csv", kCheckDataHeader + "s,0,0,3,4,11,10,11,0,2,5,2e309\n")};
       },
       2, "column 12 (`alpha.coupler`): `2e309` is beyond the range of binary64", "", ""},
      {"CheckDataPositions1e200AreInconsistent",
       [] {
         return std::vector<std::string>{"check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
                                         write_temp("cd_1e200.csv", kCheckDataHeader + "s,0,0,3,4,1e200,10,11,0,2,5,1000\n")};
       },
       1, "", "INCONSISTENT", " agrees\n"},
      {"CheckDataSceneFractionIsExact",
       [] {
         return std::vector<std::string>{
             "check-data", write_temp("cd_frac.yaml", check_data_fourbar("[\"3/10\", \"2/5\"]")),
             write_temp("cd_frac.csv", kCheckDataHeader + "s,0,0,33/100,11/25,11,10,11,0,2,5,1\n")};
       },
       1, "", "INCONSISTENT", ""},
      {"CheckDataToleranceBeyondTheExactValueIsInconclusive",
       [] {
         return std::vector<std::string>{
             "check-data",
             write_temp("cd_toggle.yaml",
                        "name: toggle\nmechanism:\n  ground: g\n  joints:\n"
                        "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
                        "    - {name: A, type: revolute, links: [crank, coupler], at: [0, 1]}\n"
                        "    - {name: B, type: revolute, links: [coupler, rocker], at: [1.5, 0.51]}\n"
                        "    - {name: O4, type: revolute, links: [rocker, g], at: [3, 0]}\n"
                        "  inputs:\n    - {link: crank, omega: 2, omega_dot: 5}\n"),
             write_temp("cd_toggle.csv", kCheckDataHeader + "s,0.00,0.00,0.00,1.00,1.50,0.51,3.00,0.00,2,5,7\n")};
       },
       1, "", "INCONCLUSIVE", " agrees\n"},
      {"CheckDataMirroredTernaryLinkIsInconsistent",
       [] {
         return std::vector<std::string>{"check-data", source_file("verify/scenes/mechanisms/pmks_watt_i_0.yaml"),
                                         write_temp("cd_mirror.csv", mirrored_watt_row())};
       },
       1, "", "worst orientation of", ""},
      {"CheckDataNothingComparedIsNotAPass",
       [] {
         return std::vector<std::string>{"check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
                                         write_temp("cd_empty.csv", kCheckDataHeader + "s,0,0,3,4,11,10,11,0,2,5,\n")};
       },
       1, "", "nothing compared in the whole file", ""},
      {"CheckDataJointNamedLikeAPrefix",
       [] {
         std::string scene = check_data_fourbar("[3, 4]");
         const std::vector<std::pair<std::string, std::string>> renames = {{"name: O2,", "name: a,"},
                                                                             {"name: A,", "name: omega,"}};
         for (const auto& [from, to] : renames) scene.replace(scene.find(from), from.size(), to);
         return std::vector<std::string>{
             "check-data", write_temp("cd_names.yaml", scene),
             write_temp("cd_names.csv", "a.x,a.y,omega.x,omega.y,B.x,B.y,O4.x,O4.y,omega.crank,alpha.crank,alpha.coupler\n"
                                        "0,0,3,4,11,10,11,0,2,5,1\n")};
       },
       1, "", "alpha  coupler", ""},
      {"CheckDataMegabyteCellIsCut",
       [] {
         return std::vector<std::string>{
             "check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
             write_temp("cd_mega.csv", kCheckDataHeader + "s,0,0,3,4,11,10,11,0,2,5," + std::string(1 << 20, '1') + "\n")};
       },
       2, "a cell of 1048576 bytes; the limit is 4096", "", ""},
      {"CheckDataExponent5000IsRefused",
       [] {
         return std::vector<std::string>{"check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
                                         write_temp("cd_e5000.csv", kCheckDataHeader + "s,0,0,3,4,11,10,11,0,2,5,1e5000\n")};
       },
       2, "column 12 (`alpha.coupler`): `1e5000` is not an exact number (exponent out of range", "", ""},
      {"CheckDataControlCharactersInALabelAreEscaped",
       [] {
         return std::vector<std::string>{"check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
                                         write_temp("cd_esc.csv", kCheckDataHeader + "\x1b]0;owned\x07,0,0,3,4,11,10,11,0,2,5,1\n")};
       },
       1, "", "\\x1b]0;owned\\x07 (line 2)", "\x1b"},
      {"CheckDataTooManyColumns",
       [] {
         std::string header = "sample";
         for (int k = 0; k < 20001; ++k) header += ",c" + std::to_string(k);
         return std::vector<std::string>{"check-data", write_temp("cd_fourbar.yaml", check_data_fourbar("[3, 4]")),
                                         write_temp("cd_columns.csv", header + "\n")};
       },
       2, "20002 columns; the limit is 20000", "", ""},
      // --- issue 27: mechanisms from dimensions; a scene that cannot be placed names the joint
      {"DimensionsDyadThatDoesNotAssembleNamesTheMissDistance",
       [] {
         return std::vector<std::string>{
             "check", write_temp("dims_dyad.yaml",
                                 "name: fb\nmechanism:\n  ground: g\n  joints:\n"
                                 "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
                                 "    - {name: A, type: revolute, links: [crank, coupler], polar: {from: O2, length: 40, angle: 180deg}}\n"
                                 "    - {name: B, type: revolute, links: [coupler, rocker], dyad: {from: [A, 120], to: [O4, 80], side: left}}\n"
                                 "    - {name: O4, type: revolute, links: [rocker, g], at: [210, 0]}\n"
                                 "  inputs:\n    - {link: crank, omega: 1500rpm, omega_dot: 0}\n")};
       },
       2, "mechanism.joints[2].dyad: joint `B` cannot be placed: the circle about `A` (radius 120) and the circle "
          "about `O4` (radius 80) do not meet: their centres are 250 apart, more than 120 + 80 = 200; the dyad misses by 50",
       "", ""},
      {"DimensionsSlideThatDoesNotAssembleNamesTheMissDistance",
       [] {
         return std::vector<std::string>{
             "check", write_temp("dims_slide.yaml",
                                 "name: sc\nmechanism:\n  ground: g\n  joints:\n"
                                 "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
                                 "    - {name: A, type: revolute, links: [crank, rod], polar: {from: O2, length: 50, angle: 60deg}}\n"
                                 "    - {name: B, type: revolute, links: [rod, slider], slide: {line: [O2, 0deg], from: [A, 40], pick: ahead}}\n"
                                 "    - {name: D, type: prismatic, links: [g, slider], at: B, axis: 0deg}\n"
                                 "  inputs:\n    - {link: crank, omega: -2000rpm, omega_dot: 0}\n")};
       },
       2, "joint `B` cannot be placed: the line through `O2` at the angle 0deg passes 43.3013 from `A`, farther than "
          "the length 40: it misses the circle by 3.30127",
       "", ""},
      {"DimensionsMissAsJsonNamesTheField",
       [] {
         return std::vector<std::string>{
             "check", "--json", write_temp("dims_slide_json.yaml",
                                           "name: sc\nmechanism:\n  ground: g\n  joints:\n"
                                           "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
                                           "    - {name: A, type: revolute, links: [crank, rod], at: [3, 4]}\n"
                                           "    - {name: B, type: revolute, links: [rod, slider], slide: {line: [O2, 0deg], from: [A, 3], pick: ahead}}\n"
                                           "    - {name: D, type: prismatic, links: [g, slider], at: B, axis: [1, 0]}\n"
                                           "  inputs:\n    - {link: crank, omega: 1, omega_dot: 0}\n")};
       },
       2, "misses the circle by 1", "\"field\": \"mechanism.joints[2].slide\"", ""},
      {"DimensionsCycleNamesTheJoint",
       [] {
         return std::vector<std::string>{
             "check", write_temp("dims_cycle.yaml",
                                 "name: fb\nmechanism:\n  ground: g\n  joints:\n"
                                 "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
                                 "    - {name: A, type: revolute, links: [crank, coupler], polar: {from: B, length: 5, angle: 0}}\n"
                                 "    - {name: B, type: revolute, links: [coupler, rocker], dyad: {from: [A, 10], to: [O4, 10], side: left}}\n"
                                 "    - {name: O4, type: revolute, links: [rocker, g], at: [11, 0]}\n"
                                 "  inputs:\n    - {link: crank, omega: 2, omega_dot: 5}\n")};
       },
       2, "mechanism.joints[1].polar: joint `A` cannot be placed from placed joints: its position depends on itself (A -> B -> A)",
       "", ""},
      {"DimensionsUnknownJointIsNamed",
       [] { return std::vector<std::string>{"check", write_temp("dims_unknown.yaml", fourbar("[3, 4]", "O5", "[11, 0]"))}; },
       2, "mechanism.joints[2].at: unknown joint `O5`: joint `B` is placed from it", "", ""},
      // --- slot joints (issue 27): a pin in a straight slot, refused naming file, field and problem
      {"SlotWithAZeroAxisNamesFileFieldAndProblem",
       [] { return std::vector<std::string>{"check", write_temp("slot_zero.yaml", geneva_slot("[0, 0]", "[wheel, crank]"))}; },
       2, "bad_input_slot_zero.yaml: mechanism.joints[2].axis: zero axis: the slot's direction must be non-zero", "", ""},
      {"SlotOnOneLinkNamesFileFieldAndProblem",
       [] { return std::vector<std::string>{"check", write_temp("slot_one_link.yaml", geneva_slot("{from: O4}", "[wheel, wheel]"))}; },
       2, "bad_input_slot_one_link.yaml: mechanism.joints[2].links: joint `P` names the same link twice", "", ""},
      {"SlotAxisFromItsOwnPointNamesTheProblem",
       [] { return std::vector<std::string>{"check", write_temp("slot_self.yaml", geneva_slot("{from: P}", "[wheel, crank]"))}; },
       2, "bad_input_slot_self.yaml: mechanism.joints[2].axis: zero axis: joint `P` is at the joint `P` itself", "", ""},
      {"SlotAxisFromAnUnknownJointNamesIt",
       [] { return std::vector<std::string>{"check", write_temp("slot_unknown.yaml", geneva_slot("{from: Q}", "[wheel, crank]"))}; },
       2, "bad_input_slot_unknown.yaml: mechanism.joints[2].axis.from: unknown joint `Q`", "", ""},
      {"SlotAxisWithAnUnknownKeyIsRefused",
       [] { return std::vector<std::string>{"check", write_temp("slot_key.yaml", geneva_slot("{towards: O4}", "[wheel, crank]"))}; },
       2, "bad_input_slot_key.yaml: mechanism.joints[2].axis.towards: unknown field", "", ""},
      {"SlotWithoutAnAxisIsRefused",
       [] {
         std::string scene = geneva_slot("[1, 0]", "[wheel, crank]");
         scene.replace(scene.find(", axis: [1, 0]"), 14, "");
         return std::vector<std::string>{"check", write_temp("slot_no_axis.yaml", scene)};
       },
       2, "bad_input_slot_no_axis.yaml: mechanism.joints[2].axis: missing required field", "", ""},
      {"DimensionsAngleInDegreesSpelledOutIsRefused",
       [] {
         std::string scene = fourbar("[3, 4]", "[11, 10]", "[11, 0]");
         scene.replace(scene.find("at: [3, 4]"), 10, "polar: {from: O2, length: 5, angle: 53 degrees}");
         return std::vector<std::string>{"check", write_temp("dims_degrees.yaml", scene)};
       },
       2, "mechanism.joints[1].polar.angle: expected an angle for the direction from `from`", "", ""},
      {"DimensionsAngleOfTenMillionRadiansIsRefused",
       [] {
         std::string scene = fourbar("[3, 4]", "[11, 10]", "[11, 0]");
         scene.replace(scene.find("at: [3, 4]"), 10, "polar: {from: O2, length: 5, angle: 1e7}");
         return std::vector<std::string>{"check", write_temp("dims_1e7.yaml", scene)};
       },
       2, "the angle `1e7` is beyond 1000000 rad in size", "", ""},
      {"DimensionsRpmIsNotASlidingVelocity",
       [] {
         return std::vector<std::string>{
             "check", write_temp("dims_v_rpm.yaml",
                                 "name: sc\nmechanism:\n  ground: g\n  joints:\n"
                                 "    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}\n"
                                 "    - {name: A, type: revolute, links: [crank, rod], at: [3, 4]}\n"
                                 "    - {name: B, type: revolute, links: [rod, slider], at: [6, 0]}\n"
                                 "    - {name: D, type: prismatic, links: [g, slider], at: B, axis: [1, 0]}\n"
                                 "  inputs:\n    - {joint: D, v: 1500rpm, a: 0}\n")};
       },
       2, "mechanism.inputs[0].v: expected a sliding rate", "", ""},
      {"DimensionsRpmPerSecondIsNotAnOmega",
       [] {
         std::string scene = fourbar("[3, 4]", "[11, 10]", "[11, 0]");
         scene.replace(scene.find("omega: 2,"), 9, "omega: 1500rpm/s,");
         return std::vector<std::string>{"check", write_temp("dims_omega_rpms.yaml", scene)};
       },
       2, "the unit `rpm/s` is for an angular acceleration; an angular velocity takes `rpm` or no unit", "", ""},
      // --- issue 26: mechanism claims; a bad claim names file, claim, line and column
      {"MechanismClaimUnknownLink",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_link.yaml", mechanism_claim("omega(coupler)", "0")),
                                         "--scene", source_file("verify/scenes/mechanisms/seed001_fourbar.yaml")};
       },
       2, "mc_link.yaml:5:17: claims[0].lhs (claim 'c1'): unknown link 'coupler' (the scene's links: 1, 2, 3, 4)", "", ""},
      {"MechanismClaimWrongArity",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_arity.yaml", mechanism_claim("omega(\\\"3\\\", \\\"1\\\", \\\"2\\\")", "0")),
                                         "--scene", source_file("verify/scenes/mechanisms/seed001_fourbar.yaml")};
       },
       2, "claims[0].lhs (claim 'c1'): 'omega' with 3 arguments: it takes omega(L), omega(L, M)", "", ""},
      {"MechanismClaimVectorWhereANumberIsDue",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_kind.yaml", mechanism_claim("1", "omega(A) + pos(A)")),
                                         "--topology", source_file("verify/scenes/mechanisms/seed001_fourbar.yaml")};
       },
       2, "mc_kind.yaml:6:20: claims[0].rhs (claim 'c1'): '+' between a number and a vector", "", "holds_on_samples"},
      {"MechanismClaimSidesOfDifferentKinds",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_sides.yaml", mechanism_claim("pos(A)", "1")),
                                         "--scene", source_file("verify/scenes/mechanisms/seed001_fourbar.yaml")};
       },
       2, "lhs is a vector and rhs a number: a claim compares two numbers or two vectors", "", ""},
      {"MechanismClaimSlidingRateOfARevoluteJoint",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_slide.yaml", mechanism_claim("sliding_v(A)", "0")),
                                         "--topology", source_file("verify/scenes/mechanisms/dimensions_slider_crank.yaml")};
       },
       2, "joint 'A' is revolute: sliding rates need a prismatic joint", "", ""},
      {"MechanismClaimsOnAPolygonTopology",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_poly.yaml", mechanism_claim("omega(a)", "0")),
                                         "--topology", source_file("verify/scenes/pentagon.yaml")};
       },
       2, "mechanism", "", ""},
      {"MechanismClaimSceneAndTopologyTogether",
       [] {
         const std::string scene = source_file("verify/scenes/mechanisms/seed001_fourbar.yaml");
         return std::vector<std::string>{"check-claim", write_temp("mc_both.yaml", mechanism_claim("omega(\\\"3\\\")", "0")),
                                         "--scene", scene, "--topology", scene};
       },
       2, "give --scene or --topology, not both", "", ""},
      {"MechanismClaimDecimalNumber",
       [] {
         return std::vector<std::string>{"check-claim", write_temp("mc_dec.yaml", mechanism_claim("omega(\\\"3\\\")", "0.75")),
                                         "--scene", source_file("verify/scenes/mechanisms/seed001_fourbar.yaml")};
       },
       2, "is a decimal number", "", ""},
  };
  return cases;
}

class BadInputCorpus : public ::testing::TestWithParam<Case> {};

TEST_P(BadInputCorpus, ExitsWithTheStatedCodeAndMessage) {
  const Case& c = GetParam();
  const test::CliRun r = test::run_cli(c.args());
  EXPECT_EQ(r.code, c.code) << "stderr: " << r.err.substr(0, 2000) << "\nstdout: " << r.out.substr(0, 2000);
  if (!c.err_fragment.empty()) {
    EXPECT_NE(r.err.find(c.err_fragment), std::string::npos) << r.err.substr(0, 2000);
  }
  if (!c.out_fragment.empty()) {
    EXPECT_NE(r.out.find(c.out_fragment), std::string::npos) << r.out.substr(0, 4000);
  }
  if (!c.out_absent.empty()) {
    EXPECT_EQ(r.out.find(c.out_absent), std::string::npos) << r.out.substr(0, 4000);
  }
  EXPECT_NE(r.code, 3) << "user input must never give an internal error";
}

INSTANTIATE_TEST_SUITE_P(Issue12, BadInputCorpus, ::testing::ValuesIn(corpus()),
                         [](const ::testing::TestParamInfo<Case>& param) { return param.param.name; });

// --json: every failed run prints one JSON object with the error's place and kind.
TEST(ErrorsAsData, JsonErrorNamesFileLineColumnAndField) {
  const std::string path = write_temp("json_err.yaml", claim_file("omega_out + bogus"));
  const test::CliRun r = test::run_cli({"check-claim", path, "--json"});
  ASSERT_EQ(r.code, 2) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["exit_status"], 2);
  EXPECT_EQ(j["error"]["kind"], "input");
  EXPECT_EQ(j["error"]["file"], path);
  EXPECT_EQ(j["error"]["line"], 6);
  EXPECT_EQ(j["error"]["column"], 23);
  EXPECT_EQ(j["error"]["field"], "claims[0].rhs");
  EXPECT_NE(j["error"]["message"].get<std::string>().find("unknown name 'bogus'"), std::string::npos);
}

TEST(ErrorsAsData, JsonErrorOfACommandLineProblem) {
  const test::CliRun r = test::run_cli({"sweep", "--seed", "-1", "--json"});
  ASSERT_EQ(r.code, 2) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["error"]["file"], "<command line>");
  EXPECT_TRUE(j["error"]["line"].is_null());
}

// `check ... --json > /dev/full` exited 0: the report never reached its reader.
TEST(Outputs, AFailedWriteToStandardOutputIsExitTwo) {
  std::ofstream full("/dev/full");
  ASSERT_TRUE(full.is_open());
  std::ostringstream err;
  const int code =
      cli::run({"check", source_file("verify/scenes/pentagon.yaml"), "--json"}, full, err);
  EXPECT_EQ(code, 2);
  EXPECT_NE(err.str().find("cannot write the report"), std::string::npos) << err.str();
}

}  // namespace
}  // namespace linkproof
