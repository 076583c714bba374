// A sweep of a mechanism topology (`linkproof sweep --topology SCENE --claims CLAIMS --count K`;
// proof/topology_sweep.h) as a batch job (batch/batch_job.h): case i is configuration i, every
// claim judged on it; its line is report/topology_sweep_lines.h's. Run, resumed, sharded and
// merged like a polygon sweep (batch/batch_run.h, batch/merge.h), with the same guarantee: the
// result file and the report do not depend on --jobs, shards or resumed runs. The verdicts and
// counterexamples are drawn from the cases once, after the last (finish_topology_sweep).
#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "batch/batch_job.h"
#include "batch/batch_run.h"
#include "report/claims_status.h"
#include "report/topology_sweep_lines.h"

namespace linkproof {

/// The program's decisions on a report (cli/exit_status.h), recorded in the summary line.
using TopologySweepStatus = std::function<ClaimsStatus(const TopologySweepReport&)>;

class TopologySweepJob final : public BatchJob {
 public:
  /// `scene`, `claims` (bound to the scene) and `status` must outlive the job; `id` names the
  /// sweep (its seed, count and arithmetic are the sweep's).
  TopologySweepJob(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                   const TopologySweepIdentity& id, const TopologySweepStatus& status);

  void set_file(ResultFile* file) override { file_ = file; }
  void run_case(long k) override;
  std::string case_line(long k) override;
  void take_worker_line(const std::string& line, long k, long i) override;
  bool read(const std::string& line, const std::string& file, long number) override;
  void take_read_back(const std::string& line, long k, const std::string& file, long number) override;
  void take_merged(long k, const std::string& file, const std::string& where) override;
  std::string summary_line(const Shard& shard) const override;
  long cases_done() const override { return tally_.cases(); }
  long unexpected_cases() const override { return tally_.unexpected_cases(); }

  /// The report of the cases taken: verdicts drawn, counterexamples shrunk (computed once).
  const TopologySweepReport& report() const;
  const TopologySweepIdentity& identity() const { return id_; }

 private:
  void take(const TopologySweepCase& c, bool write);

  TopologySweepIdentity id_;
  const TopologySweepStatus& status_;
  std::vector<std::string> claim_ids_;
  TopologyConfigurations configurations_;
  TopologySweepTally tally_;
  ResultFile* file_ = nullptr;
  TopologySweepLine pending_;
  mutable std::optional<TopologySweepReport> report_;
};

/// `linkproof sweep --topology`: the sweep `id` of `claims` on `scene`, as a batch job.
struct TopologyBatchOptions : BatchRunOptions {
  TopologySweepIdentity id;
  TopologySweepStatus status;  ///< required
  /// A complete run writes the shrunk counterexample of each disproved claim here as a scene
  /// (batch/scene_directory.h); empty: none.
  std::string scenes_dir;
};

struct TopologyBatchResult : BatchRun {
  TopologySweepReport report;
  double seconds = 0;  ///< of this run
};

/// Runs (or continues) the sweep: errors as run_batch's (batch/batch_run.h), and InputError
/// (field "scene directory") for a scenes_dir that cannot be created or written.
TopologyBatchResult run_topology_sweep(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                       const TopologyBatchOptions& options);

/// `linkproof merge --topology SCENE --claims CLAIMS`: the result files of shards 1..N of one
/// sweep of `claims` on `scene` (in any order) merged into `out` (the file one run writes);
/// InputError naming the file for a file of another scene or claim file (`id` gives their
/// digests and names), or as merge_batch_lines. The sweep's seed, count and arithmetic are the
/// shards'; `id` returns the merged sweep's identity. The whole sweep's counterexamples are
/// written to `scenes_dir` as run_topology_sweep writes them (empty: none).
TopologyBatchResult merge_topology_files(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                         TopologySweepIdentity& id, const std::vector<std::string>& files,
                                         const std::string& out, const std::string& scenes_dir,
                                         const TopologySweepStatus& status);

/// True if `line` (the last line of a result file) is the summary of a topology sweep: how
/// `merge` tells a topology file from a polygon one.
bool is_topology_summary_line(const std::string& line);

}  // namespace linkproof
