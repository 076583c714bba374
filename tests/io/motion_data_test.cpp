// Recorded motion CSV: exact numbers, the uncertainty of their digits, and errors that name the
// file, the line and the column.
#include <gtest/gtest.h>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "io/motion_data.h"

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

std::string motion_data_error(const std::string& csv) {
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
}

// A scene is a definition, not a measurement: its coordinates are exact, except a value of 16+
// significant digits (a printed double), uncertain by one ulp at the scene's scale.
TEST(MotionData, SceneCoordinatesAreExactUnlessPrintedDoubles) {
  EXPECT_EQ(scene_coordinate_uncertainty(Rational(12)), 0);
  EXPECT_EQ(scene_coordinate_uncertainty(Rational(1) / 3), 0);
  EXPECT_EQ(scene_coordinate_uncertainty(Rational(1) / 2), 0);
  EXPECT_EQ(scene_coordinate_uncertainty(parse_rational("117.349")), 0);
  EXPECT_DOUBLE_EQ(scene_coordinate_uncertainty(parse_rational("-2.7200000000000002")), std::ldexp(1.0, -51));
  EXPECT_DOUBLE_EQ(scene_coordinate_uncertainty(parse_rational("-2.7200000000000002"), 60), std::ldexp(1.0, -47));
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
  EXPECT_NE(motion_data_error(std::string(kHeader) + "s1,0,0,3,4,11,zz,11,0,2,5,1,1\n").find("data.csv: line 2, column 7 (`B.y`)"),
            std::string::npos)
      << motion_data_error(std::string(kHeader) + "s1,0,0,3,4,11,zz,11,0,2,5,1,1\n");
  EXPECT_NE(motion_data_error(std::string(kHeader) + "s1,0,0,3,4,11,10,11,0,2,5,1\n").find("line 2"), std::string::npos);
  EXPECT_NE(motion_data_error("sample,O2.x,Q.x\n").find("column 3 (`Q.x`)"), std::string::npos);
  EXPECT_NE(motion_data_error("sample,O2.x,O2.x\n").find("duplicate column"), std::string::npos);
  EXPECT_NE(motion_data_error("O2.x,O2.y\n").find("missing column `A.x`"), std::string::npos);
  EXPECT_NE(motion_data_error(std::string(kHeader)).find("no data rows"), std::string::npos);
  EXPECT_NE(motion_data_error("O2.x,O2.y,A.x,A.y,B.x,B.y,O4.x,O4.y,omega.crank,alpha.crank\n0,0,3,4,11,10,11,0,2,5\n")
                .find("no column to check"),
            std::string::npos);
  EXPECT_NE(motion_data_error(std::string(kHeader) + "s1,0,0,3,4,11,10,11,0,2,5,nan,1\n").find("column 12 (`alpha.coupler`)"),
            std::string::npos);
  EXPECT_NE(motion_data_error(std::string(kHeader) + "s1,0,0,3,4,11,10,11,0,2,5,-7e400,1\n").find("beyond the range of binary64"),
            std::string::npos);
  EXPECT_NE(motion_data_error("sample,alpha.g\n").find("the ground link has no rates"), std::string::npos);
  EXPECT_NE(motion_data_error("sample,alpha.nolink\n").find("unknown link `nolink`"), std::string::npos);
}

// Columns are matched whole against the scene's names: a name with two meanings in one scene is
// refused, naming both, instead of being read as one of them.
TEST(MotionData, AColumnNameWithTwoMeaningsInTheSceneIsRefusedNamingBoth) {
  const MechanismScene slider = parse_mechanism_scene(R"(name: slider
mechanism:
  ground: g
  joints:
    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}
    - {name: v, type: revolute, links: [crank, coupler], at: [3, 4]}
    - {name: B, type: revolute, links: [coupler, slider], at: [11, 0]}
    - {name: x, type: prismatic, links: [g, slider], at: [11, 0], axis: [1, 0]}
  inputs:
    - {link: crank, omega: 2, omega_dot: 5}
)", "slider.yaml");
  std::string error = "no error";
  try {
    parse_motion_data("sample,v.x,v.y\n", "data.csv", slider);
  } catch (const InputError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("column 2 (`v.x`): ambiguous column"), std::string::npos) << error;
  EXPECT_NE(error.find("the x of joint `v`"), std::string::npos) << error;
  EXPECT_NE(error.find("the sliding velocity of joint `x`"), std::string::npos) << error;
}

}  // namespace
}  // namespace linkproof
