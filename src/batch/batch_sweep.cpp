#include "batch/batch_sweep.h"

#include <chrono>
#include <memory>
#include <new>
#include <optional>

#include <fmt/format.h>

#include "batch/polygon_sweep_job.h"
#include "batch/scene_directory.h"
#include "io/sweep_scene.h"

namespace linkproof {

std::vector<long> shard_cases(const SweepOptions& o, const Shard& shard) {
  return shard_case_numbers(SweepPlan(o).size(), shard);
}

void write_sweep_scene(const std::string& dir, const SweepCase& c) {
  write_scene_file(dir, sweep_scene_name(c.polygon), sweep_scene_yaml(c.polygon));
}

BatchSweepResult run_batch_sweep(const std::vector<Claim>& catalogue, const BatchSweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (!o.scenes_dir.empty()) create_scene_directory(o.scenes_dir);
  LINKPROOF_ASSERT(o.out.empty() || o.exit_status, "a result file's summary line needs the exit status");
  PolygonSweepJob job(catalogue, o);
  BatchSweepResult result;
  static_cast<BatchRun&>(result) = run_batch(job, o, shard_cases(o.sweep, o.shard));
  result.report = job.report();
  result.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace linkproof
