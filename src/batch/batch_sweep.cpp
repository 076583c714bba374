#include "batch/batch_sweep.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <optional>

#include <fmt/format.h>

#include "batch/polygon_sweep_job.h"
#include "io/sweep_scene.h"

namespace linkproof {

std::vector<long> shard_cases(const SweepOptions& o, const Shard& shard) {
  return shard_case_numbers(SweepPlan(o).size(), shard);
}

void write_sweep_scene(const std::string& dir, const SweepCase& c) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string path = (std::filesystem::path(dir) / (sweep_scene_name(c.polygon) + ".yaml")).string();
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << sweep_scene_yaml(c.polygon);
  f.close();
  if (!f) throw InputError(path, "scene directory", "cannot write the scene file");
}


BatchSweepResult run_batch_sweep(const std::vector<Claim>& catalogue, const BatchSweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (!o.scenes_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.scenes_dir, ec);
    if (ec) throw InputError(o.scenes_dir, "scene directory", "cannot create the directory: " + ec.message());
  }
  LINKPROOF_ASSERT(o.out.empty() || o.exit_status, "a result file's summary line needs the exit status");
  PolygonSweepJob job(catalogue, o);
  BatchRunOptions run;
  run.cases = shard_cases(o.sweep, o.shard);
  run.shard = o.shard;
  run.jobs = o.jobs;
  run.out = o.out;
  run.resume = o.resume;
  run.progress = o.progress;
  BatchSweepResult result;
  static_cast<BatchRun&>(result) = run_batch(job, run);
  result.report = job.report();
  result.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace linkproof
