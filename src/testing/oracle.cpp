#include "linkproof/testing/oracle.h"

namespace linkproof::testing {

std::string failure_report(const MechanismCase& c, const RateComparison& comparison) {
  const std::string what = comparison.rate == Rate::Omega ? "angular velocities" : "angular accelerations";
  return what + " differ from linkproof's exact truth on a " + c.family + " case:\n" +
         comparison.report() + "--- scene ---\n" + mechanism_scene_to_yaml(c.scene) + "--- end scene ---\n" +
         "(save the scene as case.yaml and run `linkproof check case.yaml` for the exact motion)";
}

}  // namespace linkproof::testing
