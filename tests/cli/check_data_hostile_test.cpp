// check-data against a hostile reviewer (issue 24): every input here was a false pass (exit 0,
// "agrees" or "consistent" where nothing was shown), a crash, or an unreadable message before
// the fix. Each test runs the command line and reads its JSON or text.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_run.h"
#include "support/motion_csv.h"

namespace linkproof {
namespace {

using test::run_cli;

std::string hostile_source_file(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

std::string hostile_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "check_data_hostile_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string read(const std::string& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A four-bar O2-A-B-O4 with the given joint names and coordinates (scene text as written).
std::string fourbar_scene(const std::vector<std::string>& names, const std::vector<std::string>& at) {
  std::string s = "name: fourbar\nmechanism:\n  ground: g\n  joints:\n";
  const char* links[4][2] = {{"g", "crank"}, {"crank", "coupler"}, {"coupler", "rocker"}, {"rocker", "g"}};
  for (size_t j = 0; j < 4; ++j)
    s += "    - {name: \"" + names[j] + "\", type: revolute, links: [" + links[j][0] + ", " + links[j][1] + "], at: " +
         at[j] + "}\n";
  return s + "  inputs:\n    - {link: crank, omega: 2, omega_dot: 5}\n";
}
const std::vector<std::string> kNames = {"O2", "A", "B", "O4"};

nlohmann::json json_of(const test::CliRun& r) {
  try {
    return nlohmann::json::parse(r.out);
  } catch (const std::exception&) {
    ADD_FAILURE() << "not JSON (exit " << r.code << "): " << r.out.substr(0, 2000) << r.err.substr(0, 2000);
    return nlohmann::json::object();
  }
}

// ---- item 1: recorded slider rates are compared with the exact sliding rates

// The class-III mechanism of Koshel et al. (conventions §C): sliders D (joint 4) and H (joint 9, beyond the 8 links),
// with the user's alpha of link 2 (a rotating link) and the sliding rates v.D, a.H.
const std::string kClass3 = hostile_source_file("verify/scenes/mechanisms/seed003_class3.yaml");
std::string class3_csv(const std::string& alpha2, const std::string& vd, const std::string& ah) {
  return "sample,O1.x,O1.y,A.x,A.y,B.x,B.y,C.x,C.y,D.x,D.y,K.x,K.y,O2.x,O2.y,E.x,E.y,M.x,M.y,H.x,H.y,"
         "omega.1,alpha.1,alpha.2,v.D,a.H\n"
         "s,0,0,2.005,-24.919,59.410,-42.375,117.349,-26.785,117.349,-26.785,101.468,31.075,157.223,53.243,"
         "50.583,-9.368,68.199,47.987,68.199,47.987,100,0," + alpha2 + "," + vd + "," + ah + "\n";
}

TEST(CheckDataSliders, AWrongSlidingRateOfANonInputSliderDiffersAndAJointBeyondTheLinkCountDoesNotCrash) {
  // v.D = 0 was read as omega of link 4 (index of joint D), a translating slider: "agrees".
  const auto r = run_cli({"check-data", kClass3, hostile_temp("class3_wrong.csv", class3_csv("0", "0", "0")), "--json"});
  ASSERT_EQ(r.code, 1) << r.err << r.out.substr(0, 3000);
  const auto j = json_of(r);
  const auto& checks = j["samples"][0]["checks"];
  std::vector<std::string> slides;
  std::string alpha2;
  for (const auto& c : checks) {
    EXPECT_EQ(c["outcome"], "differs") << c.dump();
    EXPECT_EQ(c["agrees"], false) << c.dump();
    if (c.contains("joint")) slides.push_back(c["quantity"].get<std::string>() + "." + c["joint"].get<std::string>());
    if (c.contains("link") && c["link"] == "2") alpha2 = c["exact_rational"];
  }
  EXPECT_EQ(slides, (std::vector<std::string>{"v.D", "a.H"}));
  ASSERT_EQ(checks.size(), 3u) << checks.dump();
  // The exact rates, recorded as exact fractions, agree.
  const std::string vd = checks[1]["exact_rational"], ah = checks[2]["exact_rational"];
  const auto ok = run_cli({"check-data", kClass3, hostile_temp("class3_exact.csv", class3_csv(alpha2, vd, ah)), "--json"});
  EXPECT_EQ(ok.code, 0) << ok.out.substr(0, 3000);
  const auto ok_json = json_of(ok);  // a range-for over a temporary's member reads freed memory (ASan)
  for (const auto& c : ok_json["samples"][0]["checks"]) EXPECT_EQ(c["outcome"], "agrees") << c.dump();
}

// ---- item 2: infinities and overflow never agree

const std::string kFourbar = fourbar_scene(kNames, {"[0, 0]", "[3, 4]", "[11, 10]", "[11, 0]"});
const std::string kHeader = "sample,O2.x,O2.y,A.x,A.y,B.x,B.y,O4.x,O4.y,omega.crank,alpha.crank,alpha.coupler\n";

TEST(CheckDataOverflow, ARecordedValueBeyondBinary64IsRefusedNamingLineAndColumn) {
  const std::string scene = hostile_temp("fourbar.yaml", kFourbar);
  for (const std::string big : {"2e309", "-7e400"}) {
    const auto r = run_cli({"check-data", scene, hostile_temp("big.csv", kHeader + "s,0,0,3,4,11,10,11,0,2,5," + big + "\n")});
    EXPECT_EQ(r.code, 2) << big << r.out;
    EXPECT_NE(r.err.find("line 2, column 12 (`alpha.coupler`)"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("agrees"), std::string::npos) << r.out;
  }
}

TEST(CheckDataOverflow, PositionsWhoseSquaredLengthsOverflowAreInconsistentNotSkipped) {
  const std::string scene = hostile_temp("fourbar.yaml", kFourbar);
  const std::string huge = "1" + std::string(300, '0');
  for (const std::string& bx : {std::string("1e200"), huge}) {
    const auto r = run_cli(
        {"check-data", scene, hostile_temp("huge.csv", kHeader + "s,0,0,3,4," + bx + ",10,11,0,2,5,1000\n"), "--json"});
    EXPECT_EQ(r.code, 1) << r.out.substr(0, 2000) << r.err;
    const auto j = json_of(r);
    EXPECT_EQ(j["samples"][0]["consistent"], false) << j.dump();
    for (const auto& c : j["samples"][0]["checks"]) EXPECT_NE(c["outcome"], "agrees") << c.dump();
  }
}

TEST(CheckDataOverflow, AConsistentMechanismAtScale1e300IsNeverAPass) {
  // Every coordinate times 10^300: the links are rigid (same shape), the rates are the same, but
  // a double computation of the tolerance overflows: nothing can agree.
  const std::string e = std::string(300, '0');
  const std::string scene = hostile_temp(
      "fourbar_1e300.yaml", fourbar_scene(kNames, {"[0, 0]", "[3e300, 4e300]", "[11e300, 10e300]", "[11e300, 0]"}));
  for (const std::string user : {"1000", "-1000"}) {
    const auto r = run_cli({"check-data", scene,
                            hostile_temp("scaled.csv", kHeader + "s,0,0,3" + e + ",4" + e + ",11" + e + ",10" + e + ",11" +
                                                         e + ",0,2,5," + user + "\n"),
                            "--json"});
    EXPECT_EQ(r.code, 1) << r.out.substr(0, 2000) << r.err;
    const auto j = json_of(r);
    for (const auto& c : j["samples"][0]["checks"]) EXPECT_NE(c["outcome"], "agrees") << c.dump();
    EXPECT_EQ(j["summary"]["agreeing"], 0);
  }
}

// ---- item 3: a scene's coordinates are exact

TEST(CheckDataSceneExactness, ACrankTenPercentLongerThanTheScenesFractionIsInconsistent) {
  // Scene crank O2-A = (3/10, 2/5), length 1/2; the sample's crank (33/100, 11/25) is 11/20.
  const std::string scene =
      hostile_temp("fraction.yaml", fourbar_scene(kNames, {"[0, 0]", "[\"3/10\", \"2/5\"]", "[\"11/10\", 1]", "[\"11/10\", 0]"}));
  const auto r = run_cli({"check-data", scene,
                          hostile_temp("longer.csv", kHeader + "s,0,0,33/100,11/25,11/10,1,11/10,0,2,5,1\n"), "--json"});
  EXPECT_EQ(r.code, 1) << r.out.substr(0, 2000) << r.err;
  EXPECT_EQ(json_of(r)["samples"][0]["consistent"], false) << r.out.substr(0, 2000);
  // The scene's own positions (as fractions) stay consistent.
  const auto same = run_cli({"check-data", scene,
                             hostile_temp("same.csv", kHeader + "s,0,0,3/10,2/5,11/10,1,11/10,0,2,5,1\n"), "--json"});
  EXPECT_EQ(json_of(same)["samples"][0]["consistent"], true) << same.out.substr(0, 2000);
}

// ---- item 4: a tolerance that cannot tell the sign is inconclusive, not agreement

TEST(CheckDataInconclusive, NearAToggleATolerancePastTheExactValueIsInconclusiveAndExitOne) {
  // Coupler A-B and rocker B-O4 nearly in line (B 0.01 off the line A-O4), positions to two
  // decimals: within the digits the mechanism may pass through the toggle.
  const std::string scene =
      hostile_temp("toggle.yaml", fourbar_scene(kNames, {"[0, 0]", "[0, 1]", "[1.5, 0.51]", "[3, 0]"}));
  const auto r = run_cli(
      {"check-data", scene, hostile_temp("toggle.csv", kHeader + "s,0.00,0.00,0.00,1.00,1.50,0.51,3.00,0.00,2,5,7\n"), "--json"});
  EXPECT_EQ(r.code, 1) << r.out.substr(0, 3000) << r.err;
  const auto j = json_of(r);
  const auto& c = j["samples"][0]["checks"][0];
  EXPECT_EQ(c["outcome"], "inconclusive") << c.dump();
  EXPECT_EQ(c["agrees"], false) << c.dump();
  EXPECT_EQ(j["samples"][0]["verdict"], "inconclusive");
  EXPECT_EQ(j["summary"]["inconclusive"], 1);
  EXPECT_EQ(j["summary"]["agreeing"], 0);
  const auto text = run_cli({"check-data", scene, hostile_temp("toggle.csv", kHeader + "s,0.00,0.00,0.00,1.00,1.50,0.51,3.00,0.00,2,5,7\n")});
  EXPECT_NE(text.out.find("1 inconclusive"), std::string::npos) << text.out;
}

// ---- item 5: a mirrored link is not a rigid motion; nothing compared is not agreement

TEST(CheckDataOrientation, AMirroredRecordingKeepsEveryDistanceButIsInconsistent) {
  // The Watt I row matlab_0000 with every x negated: all distances kept, every triangle reversed.
  const std::string out = test::mirrored_first_row(read(hostile_source_file("verify/data/pmks_watt_i_matlab.csv")));
  const auto r = run_cli({"check-data", hostile_source_file("verify/scenes/mechanisms/pmks_watt_i_0.yaml"),
                          hostile_temp("mirrored.csv", out), "--json"});
  EXPECT_EQ(r.code, 1) << r.out.substr(0, 2000) << r.err;
  const auto j = json_of(r);
  EXPECT_EQ(j["samples"][0]["consistent"], false) << j["samples"][0].dump();
  EXPECT_NE(j["samples"][0]["closure"]["worst"].get<std::string>().find("orientation"), std::string::npos)
      << j["samples"][0]["closure"].dump();
}

TEST(CheckDataNothingCompared, RowsWithEveryCheckedCellEmptyAreNotAgreementAndAFileComparingNothingIsNotAPass) {
  const std::string scene = hostile_temp("fourbar.yaml", kFourbar);
  const auto r = run_cli({"check-data", scene,
                          hostile_temp("empty.csv", kHeader + "s1,0,0,3,4,11,10,11,0,2,5,\ns2,0,0,3,4,11,10,11,0,2,5,\n")});
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_EQ(r.out.find("2 agree"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing compared"), std::string::npos) << r.out;
  const auto j = json_of(run_cli({"check-data", scene,
                                  hostile_temp("empty.csv", kHeader + "s1,0,0,3,4,11,10,11,0,2,5,\ns2,0,0,3,4,11,10,11,0,2,5,\n"),
                                  "--json"}));
  EXPECT_EQ(j["summary"]["agreeing"], 0);
  EXPECT_EQ(j["summary"]["nothing_compared"], 2);
  EXPECT_EQ(j["samples"][0]["verdict"], "nothing compared");
}

// ---- item 13: CSV hygiene

TEST(CheckDataColumns, JointsNamedLikeTheRatePrefixesAreReadAsPositions) {
  const std::string scene = hostile_temp(
      "prefix_names.yaml", fourbar_scene({"a", "v", "omega", "alpha"}, {"[0, 0]", "[3, 4]", "[11, 10]", "[11, 0]"}));
  const auto r = run_cli({"check-data", scene,
                          hostile_temp("prefix_names.csv",
                                     "sample,a.x,a.y,v.x,v.y,omega.x,omega.y,alpha.x,alpha.y,omega.crank,alpha.crank,"
                                     "alpha.coupler\ns,0,0,3,4,11,10,11,0,2,5,1\n"),
                          "--json"});
  ASSERT_NE(r.code, 2) << r.err;
  const auto j = json_of(r);
  ASSERT_EQ(j["samples"][0]["checks"].size(), 1u);
  EXPECT_EQ(j["samples"][0]["checks"][0]["link"], "coupler");
  EXPECT_EQ(j["samples"][0]["consistent"], true);
}

TEST(CheckDataMessages, AMegabyteCellIsRefusedWithAShortMessageNamingTheLimit) {
  const std::string scene = hostile_temp("fourbar.yaml", kFourbar);
  const auto r = run_cli({"check-data", scene,
                          hostile_temp("mega.csv", kHeader + "s,0,0,3,4,11,10,11,0,2,5," + std::string(1 << 20, '7') + "x\n")});
  EXPECT_EQ(r.code, 2);
  EXPECT_LT(r.err.size(), 1000u) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("line 2, column 12 (`alpha.coupler`)"), std::string::npos) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("4096"), std::string::npos) << r.err.substr(0, 2000);
}

TEST(CheckDataMessages, ControlCharactersInLabelsAreEscapedInTheTextReport) {
  const std::string scene = hostile_temp("fourbar.yaml", kFourbar);
  const auto r = run_cli(
      {"check-data", scene, hostile_temp("esc.csv", kHeader + "\x1b[2Jevil\rX\x07,0,0,3,4,11,10,11,0,2,5,1\n")});
  EXPECT_NE(r.code, 2) << r.err;
  for (const char c : {'\x1b', '\r', '\x07'}) EXPECT_EQ(r.out.find(c), std::string::npos) << int(c);
  EXPECT_NE(r.out.find("\\x1b[2Jevil\\rX\\x07"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace linkproof
