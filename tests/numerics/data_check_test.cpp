// check-data on the PMKS six-bars (conventions §E): the exact alphas at the recorded positions are
// alpha_exact to 25 digits, MATLAB agrees everywhere, the old PMKS analyser's clipped samples
// differ, and positions that do not keep the links rigid are flagged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>
#include <sstream>

#include "linkproof/io/mechanism_scene.h"
#include "linkproof/core/exact.h"
#include "io/motion_data.h"
#include "exit_status.h"
#include "numerics/data_check.h"

namespace linkproof {
namespace {

std::string path(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

std::string read(const std::string& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Case {
  const char* name;  // key in the JSON
  const char* scene;
};
const Case kCases[] = {{"watt_i", "pmks_watt_i_0.yaml"}, {"stephenson_iii_example_2", "pmks_stephenson_iii_example_2_0.yaml"}};

DataCheck run(const Case& c, const std::string& analyser) {
  const MechanismScene scene = load_mechanism_scene(path(std::string("verify/scenes/mechanisms/") + c.scene));
  return check_motion_data(scene, load_motion_data(path(std::string("verify/data/pmks_") + c.name + "_" + analyser + ".csv"), scene));
}

/// The JSON configuration that lists `sample`.
const nlohmann::json& configuration(const nlohmann::json& cases, const char* name, const std::string& sample) {
  for (const auto& cfg : cases[name]["configurations"])
    for (const auto& s : cfg["samples"])
      if (s == sample) return cfg;
  throw std::runtime_error("no configuration lists " + sample);
}

TEST(DataCheck, PmksMatlabDataAgreesAndReproducesAlphaExactTo25Digits) {
  const auto json = nlohmann::json::parse(read(path("verify/data/pmks_sixbar_disputed.json")));
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    const DataCheck r = run(c, "matlab");
    EXPECT_EQ(r.differing, 0);
    EXPECT_EQ(r.inconsistent, 0);
    EXPECT_EQ(cli::exit_status(r), 0);
    EXPECT_GE(r.samples.size(), 5u);
    for (const SampleCheck& s : r.samples) {
      const auto& cfg = configuration(json, c.name, s.label);
      for (const auto& [link, value] : cfg["alpha_exact"].items()) {
        const size_t l = static_cast<size_t>(std::find(r.link_names.begin(), r.link_names.end(), link) - r.link_names.begin());
        ASSERT_LT(l, r.link_names.size());
        // The JSON prints 25 digits without trailing zeros.
        std::string mine = format_decimal(s.alpha[l], 25);
        while (mine.find('.') != std::string::npos && mine.back() == '0') mine.pop_back();
        EXPECT_EQ(mine, value.get<std::string>()) << s.label << " " << link;
      }
      // The derived tolerances are tiny next to the disputed differences (units of rad/s^2).
      for (const auto& chk : s.checks) EXPECT_LT(chk.tolerance, 1e-7) << s.label;
    }
  }
}

TEST(DataCheck, PmksOldAnalyserDiffersExactlyWhereItsValuesAreFarFromTheTruth) {
  const auto json = nlohmann::json::parse(read(path("verify/data/pmks_sixbar_disputed.json")));
  int differing = 0;
  for (const Case& c : kCases) {
    const DataCheck r = run(c, "pmks");
    EXPECT_EQ(r.inconsistent, 0);
    for (const SampleCheck& s : r.samples) {
      const auto& cfg = configuration(json, c.name, s.label);
      for (const auto& chk : s.checks) {
        // Independent reading: the JSON's 25-digit alpha_exact against the printed PMKS value.
        const double exact = std::stod(cfg["alpha_exact"][chk.name].get<std::string>());
        const double pmks = cfg["alpha_pmks_upstream_model"][chk.name].get<double>();
        EXPECT_EQ(chk.agrees(), std::abs(pmks - exact) <= 5e-7) << s.label << " " << chk.name << " " << pmks << " vs " << exact;
        differing += chk.agrees() ? 0 : 1;
      }
    }
    EXPECT_EQ(cli::exit_status(r), 1);
  }
  EXPECT_GT(differing, 10);
}

TEST(DataCheck, FlagsPositionsThatDoNotCloseTheLoopsAndAValueOffBy1e9) {
  const Case& c = kCases[0];
  const MechanismScene scene = load_mechanism_scene(path(std::string("verify/scenes/mechanisms/") + c.scene));
  std::string csv = read(path("verify/data/pmks_watt_i_matlab.csv"));
  // Row matlab_0016: move C.x (1.8919859785858406) by 1e-9, far beyond its digits.
  const std::string from = "1.8919859785858406", to = "1.8919859795858406";
  ASSERT_NE(csv.find(from), std::string::npos);
  csv.replace(csv.find(from), from.size(), to);
  // Row matlab_0000: BCD's alpha (-8.934593051317965) off by 1e-9.
  const std::string a_from = "-8.934593051317965", a_to = "-8.934593050317965";
  ASSERT_NE(csv.find(a_from), std::string::npos);
  csv.replace(csv.find(a_from), a_from.size(), a_to);
  const DataCheck r = check_motion_data(scene, parse_motion_data(csv, "edited.csv", scene));
  int inconsistent = 0;
  for (const SampleCheck& s : r.samples) {
    if (s.label == "matlab_0016") {
      EXPECT_FALSE(s.consistent);
      EXPECT_NE(s.closure_worst.find('C'), std::string::npos) << s.closure_worst;
      EXPECT_GT(s.closure_residual, 1e-10);
      ++inconsistent;
    } else {
      EXPECT_TRUE(s.consistent) << s.label << " " << s.closure_worst << " " << s.closure_residual;
    }
    if (s.label == "matlab_0000") {
      EXPECT_FALSE(s.agrees());
    }
  }
  EXPECT_EQ(inconsistent, 1);
  EXPECT_EQ(r.inconsistent, 1);
}

// The outcome rule, decided exactly: a finite tolerance below |exact| decides agreement; one that
// reaches |exact| (or is not finite) cannot, whatever the user's value.
TEST(DataCheck, CompareRecordedIsExactAndNeverAgreesWithoutAFiniteToleranceBelowTheExactValue) {
  const Rational exact = Rational(3109) / 800;
  EXPECT_EQ(compare_recorded(exact, exact, 0), RateOutcome::Agrees);
  EXPECT_EQ(compare_recorded(exact + Rational(1) / 1000, exact, 0.0011), RateOutcome::Agrees);
  EXPECT_EQ(compare_recorded(exact + Rational(1) / 1000, exact, 0.0009), RateOutcome::Differs);
  // 1e-400 off with tolerance 0: differs, although the double difference rounds to 0.
  EXPECT_EQ(compare_recorded(exact + parse_rational("1e-400"), exact, 0), RateOutcome::Differs);
  for (const double t : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_EQ(compare_recorded(exact, exact, t), RateOutcome::Inconclusive) << t;
    EXPECT_EQ(compare_recorded(parse_rational("2e309"), exact, t), RateOutcome::Inconclusive) << t;
  }
  EXPECT_EQ(compare_recorded(parse_rational("2e309"), exact, 1e308), RateOutcome::Differs);
  // Near a toggle: exact -5e17, recorded 7, tolerance 3.5e18.
  EXPECT_EQ(compare_recorded(Rational(7), Rational(-500000000000000000), 3.5e18), RateOutcome::Inconclusive);
  EXPECT_EQ(compare_recorded(Rational(0), Rational(0), 1e-15), RateOutcome::Inconclusive);
}

TEST(DataCheck, SampleVerdictOrdersDiffersThenInconclusiveAndNeedsAComparedValue) {
  SampleCheck s;
  EXPECT_EQ(s.verdict(), SampleVerdict::NothingCompared);
  EXPECT_FALSE(s.agrees());
  RecordedRateCheck c;
  c.outcome = RateOutcome::Agrees;
  s.checks.push_back(c);
  EXPECT_EQ(s.verdict(), SampleVerdict::Agrees);
  c.outcome = RateOutcome::Inconclusive;
  s.checks.push_back(c);
  EXPECT_EQ(s.verdict(), SampleVerdict::Inconclusive);
  c.outcome = RateOutcome::Differs;
  s.checks.push_back(c);
  EXPECT_EQ(s.verdict(), SampleVerdict::Differs);
  s.error = "locked";
  EXPECT_EQ(s.verdict(), SampleVerdict::Unsolvable);
  DataCheck none;
  none.samples.push_back(SampleCheck{});
  none.nothing_compared = 1;
  EXPECT_EQ(cli::exit_status(none), 1);
}

}  // namespace
}  // namespace linkproof
