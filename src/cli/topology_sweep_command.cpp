// linkproof sweep --topology SCENE --claims CLAIMS --count K [--seed S] [--arith A] [--json]
//                 [--jobs N] [--out FILE [--resume]] [--shard K/N] [--scenes DIR]
//
// Mechanism claims on the random configurations 0..K-1 of a scene's topology, as a batch job
// (batch/topology_sweep_job.h; docs/sweeps.md, "Sweeps of a mechanism topology"). --count is the
// number of configurations drawn, not (as for check-claim --topology --count) the number each
// claim must be compared on.
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "batch/topology_sweep_job.h"
#include "batch/worker_pool.h"
#include "linkproof/io/mechanism_scene.h"
#include "report/json_report.h"
#include "report/topology_sweep_report.h"
#include "sweep_args.h"

namespace linkproof::cli {

void check_topology_options(const SweepCommandArgs& a) {
  if (a.topology.empty())
    throw InputError("<command line>", "--claims", "judges mechanism claims on a topology: give --topology SCENE too");
  if (a.claims.empty())
    throw InputError("<command line>", "--topology",
                     "needs --claims CLAIMS: the mechanism claim file judged on every configuration");
  if (a.n_given)
    throw InputError("<command line>", "--n",
                     "is the number of sides of random polygons; a sweep of a topology (--topology) draws "
                     "configurations of the scene: --count K of them");
  if (a.index) throw InputError("<command line>", "--index", "replays a polygon case; not with --topology");
  if (a.count < 1 || a.count > 1000000) throw InputError("<command line>", "--count", "must be between 1 and 1000000");
  if (a.resume && a.out.empty()) throw InputError("<command line>", "--resume", "needs --out FILE (the file to continue)");
}

std::string file_digest(const std::string& path, const std::string& option) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, option, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return sweep_line_digest(text.str());
}

TopologySweepInput load_topology_sweep(const std::string& topology, const std::string& claims) {
  TopologySweepInput in;
  in.scene = load_mechanism_scene(topology);
  in.claims = mechanism_claims_for(claims, in.scene, topology);
  in.id.topology = in.scene.name;
  in.id.scene_digest = file_digest(topology, "--topology");
  in.id.claims_digest = file_digest(claims, "--claims");
  return in;
}

int print_topology_sweep_report(std::ostream& out, const TopologySweepReport& report, const TopologySweepIdentity& id,
                                const Shard& shard, double seconds, bool json) {
  const ClaimsStatus status = topology_sweep_status(report);
  if (json)
    out << json_text(to_json(report, id, shard, status, seconds)) << "\n";
  else
    write_text(out, report, id, shard, status, seconds);
  return status.exit_status;
}

int run_topology_sweep_command(const SweepCommandArgs& a, std::ostream& out, std::ostream& err) {
  check_topology_options(a);
  TopologyBatchOptions o;
  const Arithmetic arithmetic = arithmetic_or_throw(a.arith);
  static_cast<BatchRunOptions&>(o) = batch_run_options_or_throw(a, err);
  o.scenes_dir = a.scenes;
  const TopologySweepInput in = load_topology_sweep(a.topology, a.claims);
  o.id = in.id;
  o.id.seed = a.seed;
  o.id.count = a.count;
  o.id.arithmetic = arithmetic;
  o.status = topology_sweep_status;
  const TopologyBatchResult r = naming_sweep_options([&] { return run_topology_sweep(in.scene, in.claims, o); });
  if (r.status != BatchRun::Status::Complete) return report_stopped_sweep(r, a.out, err, exit_status(r));
  return print_topology_sweep_report(out, r.report, o.id, o.shard, r.seconds, a.json);
}

}  // namespace linkproof::cli
