// Six-bar claims that need both loop closures are proved symbolically for every configuration of
// the topology, within the budget. Before the expansions of proof/rational_normal.cpp were taken
// one partial product at a time, GiNaC's quadratic expansion made the Stephenson dyad's
// acceleration closure run 463 s on a 60 s budget and end with only a randomized identity test.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "linkproof/io/mechanism_scene.h"
#include "proof/mechanism_proof.h"
#include "support/topology_claims.h"

namespace linkproof {
namespace {

std::string sixbar_source(const std::string& rel) { return std::string(LINKPROOF_SOURCE_DIR) + "/" + rel; }

TEST(SixBarTopologyProof, TheStephensonDyadsAccelerationClosureIsProvedSymbolically) {
  const MechanismScene scene =
      load_mechanism_scene(sixbar_source("verify/scenes/mechanisms/pmks_stephenson_iii_example_2_0.yaml"));
  const std::vector<MechanismDataClaim> claims =
      test::bound_claims(scene, sixbar_source("verify/claims/mechanisms/sixbar_stephenson.yaml"),
                         {"sixbar_stephenson.dyad_acceleration_closure"});
  ASSERT_EQ(claims.size(), 1u);
  TopologyProofOptions options;
  options.seconds = 300;  // wall clock on a loaded CI machine; 0.1 s of work (20 s with GiNaC's expansion)
  const TopologyProofRun run = prove_topology(scene, claims, options);
  ASSERT_EQ(run.claims.size(), 1u);
  const TopologyProof& p = run.claims.front();
  EXPECT_EQ(p.verdict, ProofVerdict::ProvedGenerically) << p.error << (p.argument.empty() ? "" : p.argument.front());
  EXPECT_TRUE(test::names_dead_centre(p)) << "det A = 0 is where the proof does not reach";
}

}  // namespace
}  // namespace linkproof
