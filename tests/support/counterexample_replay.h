// A mechanism claim's counterexample scene (`counterexample.scene_yaml` of check-claim --topology
// or prove --topology) must re-fail when the claim file is checked on it with --scene.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "support/cli_run.h"

namespace linkproof::test {

inline void expect_counterexample_refails(const std::string& claims_file, const std::string& id,
                                          const std::string& scene_yaml, const std::string& file_prefix) {
  const std::string path = ::testing::TempDir() + file_prefix + id + ".yaml";
  std::ofstream(path) << scene_yaml;
  const CliRun replay = run_cli({"check-claim", claims_file, "--scene", path, "--json"});
  const auto replayed = nlohmann::json::parse(replay.out);
  bool found = false;
  for (const auto& rc : replayed["claims"])
    if (rc["id"] == id) {
      found = true;
      EXPECT_EQ(rc["verdict"], "fails") << id << "\n" << scene_yaml;
    }
  EXPECT_TRUE(found) << id;
}

}  // namespace linkproof::test
