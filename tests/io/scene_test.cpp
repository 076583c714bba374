#include "linkproof/io/scene.h"

#include <gtest/gtest.h>

#include <cln/integer.h>
#include <cln/rational_io.h>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "linkproof/core/error.h"

namespace linkproof {
namespace {

Rational rational_of(long p, long d = 1) { return Rational(cln::cl_I(p)) / cln::cl_I(d); }

std::string scene_file_path(const std::string& file) {
  return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/" + file;
}

const std::string kPentagonJoints = "[[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]";

// A pentagon scene with the given fields spliced in as written (YAML flow text).
std::string pentagon_text(const std::string& joints = kPentagonJoints,
                          const std::string& omega = "[2, -1]", const std::string& omega_dot = "[1, 3]") {
  return "name: test\npolygon:\n  joints: " + joints + "\n  omega: " + omega +
         "\n  omega_dot: " + omega_dot + "\n";
}

// Succeeds iff parsing throws InputError with source "test.yaml", exactly `field`, and a problem
// containing every one of `words`.
testing::AssertionResult FailsWith(const std::string& yaml, const std::string& field,
                                   std::initializer_list<std::string> words) {
  try {
    parse_polygon_scene(yaml, "test.yaml");
  } catch (const InputError& e) {
    if (e.source() != "test.yaml") return testing::AssertionFailure() << "source: " << e.source();
    if (e.field() != field)
      return testing::AssertionFailure() << "field '" << e.field() << "', expected '" << field
                                         << "' (problem: " << e.problem() << ")";
    for (const auto& w : words)
      if (e.problem().find(w) == std::string::npos)
        return testing::AssertionFailure() << "problem '" << e.problem() << "' lacks '" << w << "'";
    return testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return testing::AssertionFailure() << "threw something else: " << e.what();
  }
  return testing::AssertionFailure() << "no exception for:\n" << yaml;
}

void expect_joints(const PolygonScene& s, std::initializer_list<std::pair<Rational, Rational>> k) {
  ASSERT_EQ(s.polygon.n(), static_cast<int>(k.size()));
  int j = 1;
  for (const auto& [x, y] : k) {
    EXPECT_EQ(s.polygon.joint(j).x, x) << "K_" << j;
    EXPECT_EQ(s.polygon.joint(j).y, y) << "K_" << j;
    ++j;
  }
}

bool same_scene(const PolygonScene& a, const PolygonScene& b) {
  if (a.name != b.name || a.source != b.source || a.polygon.n() != b.polygon.n()) return false;
  for (int j = 1; j <= a.polygon.n(); ++j)
    if (a.polygon.joint(j).x != b.polygon.joint(j).x || a.polygon.joint(j).y != b.polygon.joint(j).y)
      return false;
  return a.rates.omega == b.rates.omega && a.rates.omega_dot == b.rates.omega_dot;
}

// ---- valid scenes ----------------------------------------------------------------------------

TEST(BundledScene, PentagonParsesToExactValues) {
  const std::string path = scene_file_path("pentagon.yaml");
  const PolygonScene s = load_polygon_scene(path);
  EXPECT_EQ(s.name, "pentagon");
  EXPECT_EQ(s.source, path);
  expect_joints(s, {{rational_of(0), rational_of(0)}, {rational_of(1), rational_of(4)}, {rational_of(5), rational_of(5)}, {rational_of(7), rational_of(1)}, {rational_of(3), rational_of(-2)}});
  EXPECT_EQ(s.rates.omega, (std::vector<Rational>{rational_of(2), rational_of(-1)}));
  EXPECT_EQ(s.rates.omega_dot, (std::vector<Rational>{rational_of(1), rational_of(3)}));
  EXPECT_EQ(s.polygon.dead_centre_determinant(), rational_of(-22));  // conventions §A8: D = -22
}

TEST(BundledScene, HexagonParsesToExactValues) {
  const PolygonScene s = load_polygon_scene(scene_file_path("hexagon.yaml"));
  EXPECT_EQ(s.name, "hexagon");
  expect_joints(s, {{rational_of(0), rational_of(0)}, {rational_of(0), rational_of(4)}, {rational_of(3), rational_of(6)}, {rational_of(7), rational_of(5)}, {rational_of(8), rational_of(1)}, {rational_of(4), rational_of(-2)}});
  EXPECT_EQ(s.rates.omega, (std::vector<Rational>{rational_of(1), rational_of(-2), rational_of(3)}));
  EXPECT_EQ(s.rates.omega_dot, (std::vector<Rational>{rational_of(1, 2), rational_of(-1), rational_of(2)}));
}

TEST(BundledScene, DeadCentrePentagonParsesWithZeroDeterminant) {
  const PolygonScene s = load_polygon_scene(scene_file_path("pentagon_dead_centre.yaml"));
  EXPECT_EQ(s.name, "pentagon-dead-centre");
  EXPECT_EQ(s.polygon.n(), 5);
  EXPECT_EQ(cross(s.polygon.side(3), s.polygon.side(4)), rational_of(0));
  EXPECT_EQ(s.polygon.dead_centre_determinant(), rational_of(0));
}

TEST(ParsePolygonScene, ReadsDecimalsAndFractionsExactlyQuotedOrNot) {
  const PolygonScene s = parse_polygon_scene(
      pentagon_text("[[0.1, '7/3'], [1, 4], [\"5\", 5e0], [7, 1], [3, -2.50]]", "[1/3, '-0.5']",
                    "[2.5e-3, +4]"),
      "test.yaml");
  expect_joints(s, {{rational_of(1, 10), rational_of(7, 3)}, {rational_of(1), rational_of(4)}, {rational_of(5), rational_of(5)}, {rational_of(7), rational_of(1)}, {rational_of(3), rational_of(-5, 2)}});
  EXPECT_EQ(s.rates.omega, (std::vector<Rational>{rational_of(1, 3), rational_of(-1, 2)}));
  EXPECT_EQ(s.rates.omega_dot, (std::vector<Rational>{rational_of(1, 400), rational_of(4)}));
  EXPECT_EQ(s.source, "test.yaml");
}

TEST(ParsePolygonScene, AcceptsQuadrilateralWithOneInput) {
  const PolygonScene s = parse_polygon_scene(pentagon_text("[[0, 0], [1, 3], [4, 4], [5, 0]]", "[1]", "[-1]"), "t");
  EXPECT_EQ(s.polygon.n(), 4);
  EXPECT_EQ(s.rates.omega, (std::vector<Rational>{rational_of(1)}));
  EXPECT_EQ(s.rates.omega_dot, (std::vector<Rational>{rational_of(-1)}));
}

TEST(PolygonSceneToYaml, RoundTripsBundledScenesExactly) {
  for (const char* file : {"pentagon.yaml", "hexagon.yaml", "pentagon_dead_centre.yaml"}) {
    const PolygonScene s = load_polygon_scene(scene_file_path(file));
    const std::string yaml = polygon_scene_to_yaml(s);
    EXPECT_TRUE(same_scene(parse_polygon_scene(yaml, s.source), s)) << file << ":\n" << yaml;
  }
}

TEST(PolygonSceneToYaml, WritesFractionsAsExactStringsAndRoundTripsAwkwardNames) {
  PolygonScene s;
  s.name = "null: \"#x\" \\ ~";
  s.source = "api";
  s.polygon = Polygon<Rational>({{rational_of(1, 3), rational_of(-7, 2)}, {rational_of(2), rational_of(0)}, {rational_of(5, 4), rational_of(9)}, {rational_of(-1, 10), rational_of(2, 3)}});
  s.rates.omega = {rational_of(6, 4)};
  s.rates.omega_dot = {rational_of(-1, 400)};
  const std::string yaml = polygon_scene_to_yaml(s);
  EXPECT_NE(yaml.find("\"1/3\""), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("\"3/2\""), std::string::npos) << yaml;
  EXPECT_TRUE(same_scene(parse_polygon_scene(yaml, "api"), s)) << yaml;
}

// ---- the file --------------------------------------------------------------------------------

TEST(LoadPolygonScene, RejectsMissingFileNamingThePath) {
  const std::string path = (std::filesystem::temp_directory_path() / "linkproof-no-such-scene.yaml").string();
  try {
    load_polygon_scene(path);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), path);
    EXPECT_EQ(e.field(), "");
    EXPECT_EQ(e.problem().rfind("cannot read file: ", 0), 0u) << e.problem();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
}

TEST(LoadPolygonScene, RejectsDirectory) {
  EXPECT_THROW(load_polygon_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes"), InputError);
}

// ---- document structure ----------------------------------------------------------------------

TEST(ParsePolygonScene, RejectsMalformedYamlWithLineAndColumn) {
  EXPECT_TRUE(FailsWith("name: x\npolygon:\n  joints: [[0, 0], [1, 4]\n", "(yaml line 4, column 1)",
                        {"malformed YAML", "end of sequence flow not found"}));
  EXPECT_TRUE(FailsWith("name: a: b\n", "(yaml line 1, column 8)", {"malformed YAML", "illegal map value"}));
}

// yaml-cpp 0.7's LoadAll never returns on this input (it allocates until memory runs out).
TEST(ParsePolygonScene, RejectsStrayTopLevelCommaWithoutHanging) {
  EXPECT_TRUE(FailsWith("," + pentagon_text(), "(yaml line 1, column 1)", {"malformed YAML", "unexpected `,`"}));
  EXPECT_TRUE(FailsWith("---\n,\n", "(yaml line 2, column 1)", {"malformed YAML", "unexpected `,`"}));
}

TEST(ParsePolygonScene, RejectsDeeplyNestedYamlWithoutCrashing) {
  const std::string deep = "name: x\npolygon: " + std::string(100000, '[') + "\n";
  try {
    parse_polygon_scene(deep, "test.yaml");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field().rfind("(yaml", 0), 0u) << e.field();
  }
}

TEST(ParsePolygonScene, RejectsEmptyDocument) {
  EXPECT_TRUE(FailsWith("", "", {"empty document"}));
  EXPECT_TRUE(FailsWith("# only a comment\n", "", {"empty document"}));
}

TEST(ParsePolygonScene, RejectsTopLevelListOrScalar) {
  EXPECT_TRUE(FailsWith("- name\n", "", {"expected a map", "got a list"}));
  EXPECT_TRUE(FailsWith("pentagon\n", "", {"expected a map", "`pentagon`"}));
}

TEST(ParsePolygonScene, RejectsMultipleDocuments) {
  EXPECT_TRUE(FailsWith(pentagon_text() + "---\n" + pentagon_text(), "", {"one YAML document", "second one at line 6"}));
}

TEST(ParsePolygonScene, RejectsMissingName) {
  EXPECT_TRUE(FailsWith("polygon:\n  joints: [[0, 0], [1, 4], [5, 5], [7, 1]]\n  omega: [1]\n  omega_dot: [1]\n",
                        "name", {"missing required field `name`"}));
}

TEST(ParsePolygonScene, RejectsEmptyOrNonStringName) {
  EXPECT_TRUE(FailsWith("name: ''\n" + pentagon_text().substr(11), "name", {"non-empty string"}));
  EXPECT_TRUE(FailsWith("name:\n" + pentagon_text().substr(11), "name", {"non-empty string", "null"}));
  EXPECT_TRUE(FailsWith("name: [a]\n" + pentagon_text().substr(11), "name", {"non-empty string", "list"}));
}

TEST(ParsePolygonScene, RejectsMissingPolygon) {
  EXPECT_TRUE(FailsWith("name: x\n", "polygon", {"missing required field `polygon`"}));
  EXPECT_TRUE(FailsWith("name: x\npolygon: [1, 2]\n", "polygon", {"expected a map", "got a list"}));
}

TEST(ParsePolygonScene, RejectsMissingJoints) {
  EXPECT_TRUE(FailsWith("name: x\npolygon:\n  omega: [1]\n  omega_dot: [1]\n", "polygon.joints",
                        {"missing required field `joints`"}));
}

TEST(ParsePolygonScene, RejectsMissingOmega) {
  EXPECT_TRUE(FailsWith("name: x\npolygon:\n  joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]\n"
                        "  omega_dot: [1, 3]\n",
                        "polygon.omega", {"missing required field `omega`", "2 values", "n = 5"}));
}

TEST(ParsePolygonScene, RejectsMissingOmegaDot) {
  EXPECT_TRUE(FailsWith("name: x\npolygon:\n  joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]\n"
                        "  omega: [2, -1]\n",
                        "polygon.omega_dot", {"missing required field `omega_dot`", "omega-dot_{j,n}"}));
}

TEST(ParsePolygonScene, RejectsUnknownTopLevelField) {
  EXPECT_TRUE(FailsWith(pentagon_text() + "colour: red\n", "colour",
                        {"unknown field `colour`", "name, description, polygon"}));
}

TEST(ParsePolygonScene, RejectsUnknownPolygonField) {
  EXPECT_TRUE(FailsWith(pentagon_text() + "  alpha: [1, 2]\n", "polygon.alpha",
                        {"unknown field `alpha`", "joints, omega, omega_dot"}));
}

TEST(ParsePolygonScene, RejectsMechanismScenesWithItsOwnMessage) {
  EXPECT_TRUE(FailsWith("name: eight-bar\nmechanism:\n  links: 8\n", "mechanism",
                        {"this is a mechanism scene (top-level `mechanism`)", "`linkproof check SCENE` reads both kinds"}));
  EXPECT_TRUE(FailsWith("zzz: 1\nmechanism: {}\n", "mechanism", {"mechanism scene"}));
}

TEST(ParsePolygonScene, RejectsFieldGivenTwice) {
  EXPECT_TRUE(FailsWith(pentagon_text() + "name: again\n", "name", {"given twice"}));
}

TEST(ParsePolygonScene, RejectsNonStringFieldName) {
  EXPECT_TRUE(FailsWith(pentagon_text() + "? [a]\n: 1\n", "", {"field name", "list"}));
}

// ---- joints ----------------------------------------------------------------------------------

TEST(ParsePolygonScene, RejectsTriangle) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5, 5]]", "[]", "[]"), "polygon.joints",
                        {"at least 4 joints", "got 3"}));
}

TEST(ParsePolygonScene, RejectsTooManyJoints) {
  std::string joints = "[";
  for (int i = 0; i <= kMaxSceneJoints; ++i) joints += "[" + std::to_string(i) + ", 0],";
  joints.back() = ']';
  EXPECT_TRUE(FailsWith(pentagon_text(joints), "polygon.joints", {"at most"}));
}

TEST(ParsePolygonScene, RejectsJointsThatAreNotAList) {
  EXPECT_TRUE(FailsWith(pentagon_text("{a: 1}"), "polygon.joints", {"list of joints", "got a map"}));
}

TEST(ParsePolygonScene, RejectsJointWithOneCoordinate) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5], [7, 1], [3, -2]]"), "polygon.joints[2]",
                        {"expected 2 coordinates", "K_3", "got 1"}));
}

TEST(ParsePolygonScene, RejectsJointWithThreeCoordinates) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5, 5], [7, 1, 0], [3, -2]]"), "polygon.joints[3]",
                        {"expected 2 coordinates", "K_4", "got 3"}));
}

TEST(ParsePolygonScene, RejectsJointThatIsNotAList) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], 7, [5, 5], [7, 1], [3, -2]]"), "polygon.joints[1]",
                        {"K_2", "list of 2 numbers", "`7`"}));
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], {x: 1, y: 4}, [5, 5], [7, 1], [3, -2]]"), "polygon.joints[1]",
                        {"K_2", "got a map"}));
}

TEST(ParsePolygonScene, RejectsCoincidentAdjacentJointsAsZeroLengthSide) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [1, 4], [7, 1], [3, -2]]"), "polygon.joints",
                        {"K_2 and K_3", "coincide", "r_2 has zero length"}));
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5, 5], [7, 1], [0, 0]]"), "polygon.joints",
                        {"K_1 and K_5", "r_5 has zero length"}));
}

TEST(ParsePolygonScene, RejectsCoincidentNonAdjacentJoints) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5, 5], [0, 0], [3, -2]]"), "polygon.joints",
                        {"K_1 and K_4", "coincide"}));
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5, 5], ['2/2', 4.0], [3, -2]]"), "polygon.joints",
                        {"K_2 and K_4", "coincide"}));
}

// ---- rates -----------------------------------------------------------------------------------

TEST(ParsePolygonScene, RejectsOmegaOfWrongLength) {
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[2, -1, 5]"), "polygon.omega",
                        {"expected 2 values (omega_{j,n} for j = 1..n-3 with n = 5), got 3"}));
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "2"), "polygon.omega", {"expected a list"}));
}

TEST(ParsePolygonScene, RejectsOmegaDotOfWrongLength) {
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[2, -1]", "[1]"), "polygon.omega_dot",
                        {"expected 2 values (omega-dot_{j,n} for j = 1..n-3 with n = 5), got 1"}));
}

// ---- numbers ---------------------------------------------------------------------------------

TEST(ParsePolygonScene, RejectsNonNumericValue) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, 4], [5, abc], [7, 1], [3, -2]]"), "polygon.joints[2][1]",
                        {"y coordinate of K_3", "'abc' is not an exact number"}));
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[2, 0x10]"), "polygon.omega[1]",
                        {"omega_{2,5}", "not an exact number"}));
}

TEST(ParsePolygonScene, RejectsNan) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[.nan, 0], [1, 4], [5, 5], [7, 1], [3, -2]]"), "polygon.joints[0][0]",
                        {"x coordinate of K_1", "`.nan`", "not finite"}));
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[2, -1]", "['nan', 1]"),
                        "polygon.omega_dot[0]", {"omega-dot_{1,5}", "not finite"}));
}

TEST(ParsePolygonScene, RejectsInfinity) {
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[.inf, 1]"), "polygon.omega[0]",
                        {"omega_{1,5}", "`.inf`", "not finite"}));
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[1, -.inf]"), "polygon.omega[1]",
                        {"not finite"}));
}

TEST(ParsePolygonScene, RejectsBoolean) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [true, 4], [5, 5], [7, 1], [3, -2]]"), "polygon.joints[1][0]",
                        {"x coordinate of K_2", "the boolean `true`"}));
}

TEST(ParsePolygonScene, RejectsNull) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, ~], [5, 5], [7, 1], [3, -2]]"), "polygon.joints[1][1]",
                        {"y coordinate of K_2", "null"}));
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[null, 1]"), "polygon.omega[0]", {"null"}));
}

TEST(ParsePolygonScene, RejectsNestedListWhereNumberBelongs) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1, [4]], [5, 5], [7, 1], [3, -2]]"), "polygon.joints[1][1]",
                        {"expected an exact number", "got a list"}));
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[2, -1]", "[{a: 1}, 3]"),
                        "polygon.omega_dot[0]", {"expected an exact number", "got a map"}));
}

TEST(ParsePolygonScene, RejectsFractionWithZeroDenominator) {
  EXPECT_TRUE(FailsWith(pentagon_text(kPentagonJoints, "[1/0, 1]"), "polygon.omega[0]",
                        {"denominator 0"}));
}

TEST(ParsePolygonScene, RejectsDecimalExponentTooLarge) {
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1e5000, 4], [5, 5], [7, 1], [3, -2]]"), "polygon.joints[1][0]",
                        {"exponent out of range"}));
  EXPECT_TRUE(FailsWith(pentagon_text("[[0, 0], [1e99999999, 4], [5, 5], [7, 1], [3, -2]]"),
                        "polygon.joints[1][0]", {"exponent out of range"}));
}

TEST(ParsePolygonScene, ErrorMessageNamesSourceFieldAndProblem) {
  try {
    parse_polygon_scene(pentagon_text(kPentagonJoints, "[2]"), "scenes/p.yaml");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("scenes/p.yaml: polygon.omega: expected 2 values", 0), 0u) << what;
  }
}

}  // namespace
}  // namespace linkproof
