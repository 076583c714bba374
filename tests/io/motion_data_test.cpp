// Recorded motion CSV: exact numbers, the uncertainty of their digits, and errors that name the
// file, the line and the column.
#include <gtest/gtest.h>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "linkproof/io/motion_data.h"

namespace linkproof {
namespace {

MechanismScene fourbar() {
  return parse_mechanism_scene(R"(name: fourbar
mechanism:
  ground: g
  joints:
    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}
    - {name: A, type: revolute, links: [crank, coupler], at: [3, 4]}
    - {name: B, type: revolute, links: [coupler, rocker], at: [11, 10]}
    - {name: O4, type: revolute, links: [rocker, g], at: [11, 0]}
  inputs:
    - {link: crank, omega: 2, omega_dot: 5}
)", "fourbar.yaml");
}

const char* kHeader = "sample,O2.x,O2.y,A.x,A.y,B.x,B.y,O4.x,O4.y,omega.crank,alpha.crank,alpha.coupler,alpha.rocker\n";

std::string error_of(const std::string& csv) {
  try {
    parse_motion_data(csv, "data.csv", fourbar());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MotionData, DigitsGiveTheUncertaintyOfEachNumber) {
  EXPECT_EQ(decimal_uncertainty("7", Rational(7)), 0);
  EXPECT_EQ(decimal_uncertainty("7/3", Rational(7) / 3), 0);
  EXPECT_DOUBLE_EQ(decimal_uncertainty("2.005", parse_rational("2.005")), 0.0005);
  EXPECT_DOUBLE_EQ(decimal_uncertainty("-212.328906", parse_rational("-212.328906")), 5e-7);
  EXPECT_DOUBLE_EQ(decimal_uncertainty("1.5e-3", parse_rational("1.5e-3")), 5e-5);
  // 17 significant digits: a printed double, one ulp of it (2^-51 at 2.72).
  EXPECT_DOUBLE_EQ(decimal_uncertainty("-2.7200000000000002", parse_rational("-2.7200000000000002")), std::ldexp(1.0, -51));
  // ... or one ulp of the row's scale when that is larger (2^-47 at 60).
  EXPECT_DOUBLE_EQ(decimal_uncertainty("-2.7200000000000002", parse_rational("-2.7200000000000002"), 60), std::ldexp(1.0, -47));
  EXPECT_EQ(rational_uncertainty(Rational(12)), 0);
  EXPECT_EQ(rational_uncertainty(Rational(1) / 3), 0);
  EXPECT_DOUBLE_EQ(rational_uncertainty(parse_rational("117.349")), 0.0005);
}

TEST(MotionData, ReadsRowsExactlyAndLeavesEmptyUserCellsUnrecorded) {
  const MotionData d = parse_motion_data(std::string("# comment\n") + kHeader + "s1,0,0,3,4,11,10,11,0,2,5,0.39375,\n",
                                         "data.csv", fourbar());
  ASSERT_EQ(d.samples.size(), 1u);
  const MotionSample& s = d.samples[0];
  EXPECT_EQ(s.label, "s1");
  EXPECT_EQ(s.line, 3);
  EXPECT_EQ(s.rate_dot[0].value, 5);
  ASSERT_TRUE(s.user_alpha[2].has_value());
  EXPECT_EQ(s.user_alpha[2]->value, Rational(63) / 160);
  EXPECT_FALSE(s.user_alpha[3].has_value());
}

TEST(MotionData, ErrorsNameTheLineColumnAndProblem) {
  EXPECT_NE(error_of(std::string(kHeader) + "s1,0,0,3,4,11,zz,11,0,2,5,1,1\n").find("data.csv: line 2, column 7 (`B.y`)"),
            std::string::npos)
      << error_of(std::string(kHeader) + "s1,0,0,3,4,11,zz,11,0,2,5,1,1\n");
  EXPECT_NE(error_of(std::string(kHeader) + "s1,0,0,3,4,11,10,11,0,2,5,1\n").find("line 2"), std::string::npos);
  EXPECT_NE(error_of("sample,O2.x,Q.x\n").find("column 3 (`Q.x`)"), std::string::npos);
  EXPECT_NE(error_of("sample,O2.x,O2.x\n").find("duplicate column"), std::string::npos);
  EXPECT_NE(error_of("O2.x,O2.y\n").find("missing column `A.x`"), std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader)).find("no data rows"), std::string::npos);
  EXPECT_NE(error_of("O2.x,O2.y,A.x,A.y,B.x,B.y,O4.x,O4.y,omega.crank,alpha.crank\n0,0,3,4,11,10,11,0,2,5\n")
                .find("no column to check"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) + "s1,0,0,3,4,11,10,11,0,2,5,nan,1\n").find("column 12 (`alpha.coupler`)"),
            std::string::npos);
}

}  // namespace
}  // namespace linkproof
