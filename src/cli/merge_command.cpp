// linkproof merge --out FILE SHARD_FILE... [--scenes DIR] [--json]
#include "command.h"
#include "dijksman1966.h"
#include "batch/merge.h"
#include "sweep_args.h"
#include "report/json_report.h"
#include "report/text_report.h"

namespace linkproof::cli {

namespace {

struct MergeArgs {
  std::vector<std::string> files;
  std::string out;
  std::string scenes;
  bool json = false;
};

int run_merge_command(const MergeArgs& a, std::ostream& out, std::ostream&) {
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
  s->add_option("--scenes", a.scenes, "write every case with an unexpected outcome to DIR as a scene");
  s->add_flag("--json", a.json, "print JSON");
}

}  // namespace linkproof::cli
