// linkproof merge --out FILE SHARD_FILE... [--scenes DIR] [--json]
// linkproof merge --topology SCENE --claims CLAIMS --out FILE SHARD_FILE... [--scenes DIR] [--json]
//   (shards of sweep --topology)
#include <fstream>

#include "command.h"
#include "dijksman1966.h"
#include "batch/merge.h"
#include "batch/topology_sweep_job.h"
#include "linkproof/io/mechanism_scene.h"
#include "report/topology_sweep_report.h"
#include "sweep_args.h"
#include "report/json_report.h"
#include "report/text_report.h"

namespace linkproof::cli {

namespace {

struct MergeArgs {
  std::vector<std::string> files;
  std::string topology, claims;
  std::string out;
  std::string scenes;
  bool json = false;
};

// The shards of a sweep of a topology (sweep --topology SCENE --claims CLAIMS --shard K/N --out):
// merged with the scene and the claims they were run on.
int run_topology_merge(const MergeArgs& a, std::ostream& out) {
  if (a.topology.empty() || a.claims.empty())
    throw InputError("<command line>", a.topology.empty() ? "--topology" : "--claims",
                     "the shards are of a sweep of a topology: give the scene (--topology SCENE) and the claim file "
                     "(--claims CLAIMS) it was run with");
  TopologySweepInput in = load_topology_sweep(a.topology, a.claims);
  const TopologySweepStatus status = topology_sweep_status;
  const TopologyBatchResult r = naming_options(kSweepOptionNames, [&] {
    return merge_topology_files(in.scene, in.claims, in.id, a.files, a.out, a.scenes, status);
  });
  return print_topology_sweep_report(out, r.report, in.id, Shard{}, r.seconds, a.json);
}

// True if the first shard file ends with the summary of a sweep of a topology.
bool is_topology_merge(const MergeArgs& a) {
  if (!a.topology.empty() || !a.claims.empty()) return true;
  if (a.files.empty()) return false;
  std::ifstream in(a.files.front(), std::ios::binary);
  std::string line, last;
  while (std::getline(in, line))
    if (!in.eof()) last = line;
  return !last.empty() && is_topology_summary_line(last);
}

int run_merge_command(const MergeArgs& a, std::ostream& out, std::ostream&) {
  if (is_topology_merge(a)) return run_topology_merge(a, out);
  const SweepReport r = naming_options(kSweepOptionNames, [&] {
    return merge_sweep_files(dijksman1966::catalogue(), a.files, a.out, a.scenes,
                             [](const SweepReport& s) { return exit_status(s); });
  });
  return print_report(out, r, a.json, exit_status(r));
}

}  // namespace

void add_merge_command(CLI::App& app, Action& action) {
  auto* s = app.add_subcommand("merge", "combine the result files of the shards of a sweep (sweep --shard K/N --out)");
  auto& a = bind_action<MergeArgs>(s, action, run_merge_command);
  s->add_option("files", a.files, "the result files of shards 1..N, in any order")->required();
  s->add_option("--out", a.out, "the merged result file: the bytes a single run writes (must not exist)")->required();
  s->add_option("--scenes", a.scenes,
                "write every case with an unexpected outcome to DIR as a scene (with --topology: the shrunk "
                "counterexample of each disproved claim)");
  s->add_option("--topology", a.topology, "shards of a sweep of a topology: the scene it was run on (sweep --topology)");
  s->add_option("--claims", a.claims, "shards of a sweep of a topology: the claim file it was run with (sweep --claims)");
  s->add_flag("--json", a.json, "print JSON");
}

}  // namespace linkproof::cli
