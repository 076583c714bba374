// mechanism_scene_to_yaml: what it writes, the reader reads back as the same mechanism.
#include <gtest/gtest.h>

#include "linkproof/io/mechanism_scene.h"

namespace linkproof {
namespace {

std::string scene_path(const std::string& name) {
  return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/" + name;
}

void expect_same(const MechanismScene& a, const MechanismScene& b) {
  ASSERT_EQ(a.name, b.name);
  ASSERT_EQ(a.linkage.link_names(), b.linkage.link_names());
  EXPECT_EQ(a.linkage.ground(), b.linkage.ground());
  ASSERT_EQ(a.linkage.joint_count(), b.linkage.joint_count());
  for (int j = 0; j < a.linkage.joint_count(); ++j) {
    const LinkageJoint &x = a.linkage.joint(j), &y = b.linkage.joint(j);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.links[0], y.links[0]);
    EXPECT_EQ(x.links[1], y.links[1]);
    EXPECT_TRUE(x.at.x == y.at.x && x.at.y == y.at.y) << x.name;
    EXPECT_TRUE(x.axis.x == y.axis.x && x.axis.y == y.axis.y) << x.name;
  }
  ASSERT_EQ(a.inputs.size(), b.inputs.size());
  for (size_t k = 0; k < a.inputs.size(); ++k) {
    EXPECT_EQ(a.inputs[k].kind, b.inputs[k].kind);
    EXPECT_EQ(a.inputs[k].index, b.inputs[k].index);
    EXPECT_EQ(a.inputs[k].rate, b.inputs[k].rate);
    EXPECT_EQ(a.inputs[k].rate_dot, b.inputs[k].rate_dot);
  }
  EXPECT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.dimensions.size(), b.dimensions.size());
  EXPECT_EQ(a.tolerance.has_value(), b.tolerance.has_value());
  EXPECT_EQ(a.catalogues, b.catalogues);
}

TEST(MechanismSceneWriter, EveryBundledMechanismSceneReadsBackTheSame) {
  for (const char* name : {"fig5_eightbar.yaml", "seed001_fourbar.yaml", "seed003_class3.yaml", "pmks_watt_i_1.yaml"}) {
    SCOPED_TRACE(name);
    const MechanismScene s = load_mechanism_scene(scene_path(name));
    const std::string text = mechanism_scene_to_yaml(s);
    expect_same(s, parse_mechanism_scene(text, s.source));
  }
}

TEST(MechanismSceneWriter, WritesFractionsExactlyAndQuotesNames) {
  const MechanismScene s = load_mechanism_scene(scene_path("seed003_class3.yaml"));
  const std::string text = mechanism_scene_to_yaml(s);
  EXPECT_NE(text.find("\"401/200\""), std::string::npos) << text;  // 2.005 written exactly
  EXPECT_NE(text.find("prismatic"), std::string::npos);
  EXPECT_NE(text.find("catalogue: [koshel_class3]"), std::string::npos) << text;
}

}  // namespace
}  // namespace linkproof
