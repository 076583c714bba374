// conventions §E: the PMKS_Verification six-bars (Watt I, Stephenson III) at the samples where MATLAB
// and PMKS disagreed. The exact engine must reproduce alpha_exact and omega_exact (25 digits).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <fstream>

#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_catalogue.h"
#include "mechanism/mechanism_test_support.h"

namespace linkproof {
namespace {

// |x - printed| <= half a unit in the 25th significant digit of `printed` (exactly).
bool agrees_to_printed_digits(const Rational& x, const std::string& printed, int digits) {
  const Rational p = parse_rational(printed);
  if (cln::zerop(p)) return cln::zerop(x);
  // 10^e <= |p| < 10^(e+1)
  int e = 0;
  const Rational a = cln::abs(p);
  while (cln::expt(Rational(10), e + 1) <= a) ++e;
  while (cln::expt(Rational(10), e) > a) --e;
  return cln::abs(x - p) <= cln::expt(Rational(10), e - digits + 1) / 2;
}

TEST(PmksSixBar, ExactEngineReproducesAlphaExactOfEveryDisputedSample) {
  std::ifstream in(std::string(LINKPROOF_SOURCE_DIR) + "/verify/data/pmks_sixbar_disputed.json");
  ASSERT_TRUE(in.good());
  const auto data = nlohmann::json::parse(in);
  int configurations = 0;
  for (const auto& [case_name, d] : data.items()) {
    for (size_t k = 0; k < d["configurations"].size(); ++k) {
      const std::string scene = fmt::format("pmks_{}_{}.yaml", case_name, k);
      const MechanismScene s = load_mechanism_scene(testing::mechanism_scene_path(scene));
      const auto& cfg = d["configurations"][k];
      const MechanismSolution<Rational> m = solve_mechanism_exact(s);
      for (const auto& [link, alpha] : cfg["alpha_exact"].items()) {
        const Rational x = m.motion.omega_dot[static_cast<size_t>(*s.linkage.find_link(link))];
        EXPECT_TRUE(agrees_to_printed_digits(x, alpha.get<std::string>(), 25))
            << scene << " alpha " << link << ": " << cln::double_approx(x) << " vs " << alpha;
      }
      for (const auto& [link, omega] : cfg["omega_exact"].items()) {
        const Rational x = m.motion.omega[static_cast<size_t>(*s.linkage.find_link(link))];
        EXPECT_TRUE(agrees_to_printed_digits(x, omega.get<std::string>(), 25)) << scene << " omega " << link;
      }
      ++configurations;
    }
  }
  EXPECT_EQ(configurations, 8);
}

TEST(PmksSixBar, AgreementTestCanFail) {
  EXPECT_TRUE(agrees_to_printed_digits(parse_rational("1.2345"), "1.234", 4));
  EXPECT_FALSE(agrees_to_printed_digits(parse_rational("1.2346"), "1.234", 4));
  EXPECT_FALSE(agrees_to_printed_digits(parse_rational("-8.934593051317965"), "-8.934593051317962575840725", 25));
}

}  // namespace
}  // namespace linkproof
