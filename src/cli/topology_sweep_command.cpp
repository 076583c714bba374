// linkproof sweep --topology SCENE --claims CLAIMS --count K [--seed S] [--arith A] [--json]
//                 [--jobs N] [--out FILE [--resume]] [--shard K/N]
//
// Mechanism claims on the random configurations 0..K-1 of a scene's topology, as a batch job
// (batch/topology_sweep_job.h; docs/sweeps.md, "Sweeps of a mechanism topology"). --count is the
// number of configurations drawn, not (as for check-claim --topology --count) the number each
// claim must be compared on.
#include <unistd.h>

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

namespace {

// Refuses the options of a polygon sweep, and a half-given topology sweep, naming the option.
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
  if (!a.scenes.empty())
    throw InputError("<command line>", "--scenes",
                     "writes polygon cases; a topology sweep's counterexamples are in its report "
                     "(counterexample.scene_yaml)");
  if (a.count < 1 || a.count > 1000000) throw InputError("<command line>", "--count", "must be between 1 and 1000000");
  if (a.resume && a.out.empty()) throw InputError("<command line>", "--resume", "needs --out FILE (the file to continue)");
}

}  // namespace

std::string file_digest(const std::string& path, const std::string& option) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, option, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return sweep_line_digest(text.str());
}

int run_topology_sweep_command(const SweepCommandArgs& a, std::ostream& out, std::ostream& err) {
  check_topology_options(a);
  TopologyBatchOptions o;
  o.id.seed = a.seed;
  o.id.count = a.count;
  o.id.arithmetic = arithmetic_or_throw(a.arith);
  o.jobs = a.jobs.value_or(default_jobs());
  if (o.jobs < 1 || o.jobs > 1024) throw InputError("<command line>", "--jobs", "must be between 1 and 1024");
  if (!a.shard.empty()) o.shard = parse_shard(a.shard);
  o.out = a.out;
  o.resume = a.resume;
  const MechanismScene scene = load_mechanism_scene(a.topology);
  const std::vector<MechanismDataClaim> claims = mechanism_claims_for(a.claims, scene, a.topology);
  o.id.topology = scene.name;
  o.id.scene_digest = file_digest(a.topology, "--topology");
  o.id.claims_digest = file_digest(a.claims, "--claims");
  o.status = topology_sweep_status;
  if (&err == &std::cerr && ::isatty(STDERR_FILENO)) o.progress = &err;
  const TopologyBatchResult r = naming_sweep_options([&] { return run_topology_sweep(scene, claims, o); });
  if (r.status != BatchRun::Status::Complete) return report_stopped_sweep(r, a.out, err, exit_status(r));
  const ClaimsStatus status = topology_sweep_status(r.report);
  if (a.json)
    out << json_text(to_json(r.report, o.id, o.shard, status, r.seconds)) << "\n";
  else
    write_text(out, r.report, o.id, o.shard, status, r.seconds);
  return status.exit_status;
}

}  // namespace linkproof::cli
