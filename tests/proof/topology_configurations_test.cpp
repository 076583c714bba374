// TopologyConfigurations (proof/topology_configurations.h): which random configurations of a
// topology can be written as a scene that replays.
#include "proof/topology_configurations.h"

#include <gtest/gtest.h>

#include "linkproof/io/mechanism_scene.h"

namespace linkproof {
namespace {

bool reader_accepts(const MechanismScene& s) {
  try {
    parse_mechanism_scene(mechanism_scene_to_yaml(s), s.source);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// is_replayable decides on the values (a driven link of zero length) what writing the scene and
// reading it back decides: the same answer on every bundled topology, refusals included.
TEST(TopologyConfigurations, ReplayableIsWhatTheSceneReaderAccepts) {
  const std::vector<MechanismDataClaim> no_claims;
  int refused = 0;
  for (const char* name : {"seed001_fourbar", "dimensions_slider_crank", "inverted_slider_crank", "pmks_watt_i_0",
                           "pmks_stephenson_iii_example_2_0", "seed003_class3", "geneva", "fig5_eightbar"}) {
    const MechanismScene scene =
        load_mechanism_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/" + name + ".yaml");
    TopologySampling o;
    o.seed = 1;
    o.coordinate_range = 2;  // coincident joints are frequent on a 5 x 5 grid
    const TopologyConfigurations configurations(scene, no_claims, o);
    const TopologyLayout layout = topology_layout(scene);
    for (int i = 0; i < 400; ++i) {
      const bool replayable = configurations.is_replayable(i);
      ASSERT_EQ(replayable, reader_accepts(topology_configuration(scene, layout, configurations.values(i),
                                                                  configurations.name(i))))
          << name << ", configuration " << i << " of seed " << o.seed << ", range 2";
      refused += !replayable;
    }
  }
  EXPECT_GT(refused, 0);  // refusals were met: both answers were exercised
}

}  // namespace
}  // namespace linkproof
