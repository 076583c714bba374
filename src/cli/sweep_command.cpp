// linkproof sweep --n 4..12 --count N --seed S [--arith ...] [--index I] [--json]
//                 [--jobs N] [--out FILE [--resume]] [--shard K/N] [--scenes DIR]
// linkproof sweep --topology SCENE --claims CLAIMS --count K [--seed S] [--arith A] [--json]
//                 [--jobs N] [--out FILE [--resume]] [--shard K/N] [--scenes DIR]   (topology_sweep_command.cpp)
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "dijksman1966.h"
#include "batch/batch_sweep.h"
#include "batch/result_file.h"
#include "batch/worker_pool.h"
#include "report/json_report.h"
#include "report/text_report.h"
#include "sweep_args.h"

namespace linkproof::cli {

SweepOptions sweep_options_or_throw(const SweepArgs& a) {
  SweepOptions o;
  std::tie(o.n_min, o.n_max) = parse_n_range(a.n_range, "--n", 4, 200);
  if (a.count < 1 || a.count > 1000000) throw InputError("<command line>", "--count", "must be between 1 and 1000000");
  if (a.index && *a.index < 0) throw InputError("<command line>", "--index", "must be >= 0");
  o.count = a.count;
  o.seed = a.seed;
  o.arithmetic = arithmetic_or_throw(a.arith);
  o.only_index = a.index;
  return o;
}

void add_sweep_options(CLI::App* s, SweepArgs& a) {
  s->add_option("--n", a.n_range, "number of sides, N or A..B (default 4..12)");
  s->add_option("--count", a.count, "cases per n (default 100); with --topology: the configurations drawn");
  s->add_option("--seed", a.seed, "seed; any case replays from seed, n and index (default 1)")->check(seed_validator());
  s->add_option("--arith", a.arith,
                "arithmetic: exact (default), double, long-double, mp30, mp50, mp100, mp1000 (see check --help)");
  s->add_option("--out", a.out, "stream every case to FILE (JSON Lines: one case per line, then a summary line)");
  s->add_option("--scenes", a.scenes,
                "write every case with an unexpected outcome to DIR as a scene `check` reads; with --topology: the "
                "shrunk counterexample of each disproved claim, a scene `check-claim CLAIMS --scene` re-fails");
  s->add_flag("--json", a.json, "print JSON");
}

void add_topology_options(CLI::App* s, SweepCommandArgs& a) {
  s->get_option("--n")->each([&a](const std::string&) { a.n_given = true; });
  s->add_option("--topology", a.topology,
                "sweep the configurations 0..K-1 (--count K) of this mechanism scene's topology instead of polygons; "
                "with --claims");
  s->add_option("--claims", a.claims, "with --topology: the mechanism claim file judged on every configuration");
}

Shard parse_shard(const std::string& s) {
  Shard shard;
  char tail = 0;
  if (std::sscanf(s.c_str(), "%d/%d%c", &shard.k, &shard.n, &tail) != 2 || shard.n < 1 || shard.k < 1 ||
      shard.k > shard.n)
    throw InputError("<command line>", "--shard", "'" + s + "' is not K/N with 1 <= K <= N");
  return shard;
}

int report_stopped_sweep(const BatchRun& r, const std::string& out, std::ostream& err, int code) {
  // How to continue: the options are this command's, so the hint is written here.
  const std::string hint = out.empty() ? "; nothing was saved (--out FILE keeps every completed case)"
                                       : fmt::format("; {} holds every completed case: rerun the same command "
                                                     "with --resume to continue",
                                                     out);
  if (r.status == BatchRun::Status::OutOfTime) throw InputError("<command line>", "--max-seconds", r.message + hint);
  fmt::print(err, "linkproof sweep: {}{}\n", r.message, hint);
  return code;
}

BatchRunOptions batch_run_options_or_throw(const SweepCommandArgs& a, std::ostream& err) {
  BatchRunOptions o;
  o.jobs = a.jobs.value_or(default_jobs());
  if (o.jobs < 1 || o.jobs > 1024) throw InputError("<command line>", "--jobs", "must be between 1 and 1024");
  if (!a.shard.empty()) o.shard = parse_shard(a.shard);
  o.out = a.out;
  o.resume = a.resume;
  // The bar only on the real stderr, and only when it is a terminal.
  if (&err == &std::cerr && ::isatty(STDERR_FILENO)) o.progress = &err;
  return o;
}

namespace {

int run_sweep_command(const SweepCommandArgs& a, std::ostream& out, std::ostream& err) {
  if (!a.topology.empty() || !a.claims.empty()) return run_topology_sweep_command(a, out, err);
  BatchSweepOptions b;
  b.sweep = sweep_options_or_throw(a);
  static_cast<BatchRunOptions&>(b) = batch_run_options_or_throw(a, err);
  b.scenes_dir = a.scenes;
  b.exit_status = [](const SweepReport& s) { return exit_status(s); };
  if (a.resume && a.out.empty()) throw InputError("<command line>", "--resume", "needs --out FILE (the file to continue)");
  if (a.index && (!a.out.empty() || !a.shard.empty()))
    throw InputError("<command line>", "--index", "replays one case; it cannot be combined with --out or --shard");
  const BatchSweepResult r = naming_sweep_options([&] { return run_batch_sweep(dijksman1966::catalogue(), b); });
  if (r.status != BatchSweepResult::Status::Complete) return report_stopped_sweep(r, a.out, err, exit_status(r));
  return print_report(out, r.report, a.json, exit_status(r));
}

}  // namespace

void add_sweep_command(CLI::App& app, Action& action) {
  auto* s = app.add_subcommand("sweep",
                               "check every claim on random exact polygons, or (--topology --claims) mechanism claims on "
                               "random configurations of a topology");
  auto& a = bind_action<SweepCommandArgs>(s, action, run_sweep_command);
  add_sweep_options(s, a);
  add_topology_options(s, a);
  s->add_option("--index", a.index, "replay only this case index");
  s->add_option("--jobs", a.jobs, "worker processes (default: every core); the output does not depend on it");
  s->add_flag("--resume", a.resume, "continue --out FILE from its last complete case (after a kill or a crash)");
  s->add_option("--shard", a.shard, "run only shard K of N (cases k with k mod N = K-1); combine with `merge`");
}

}  // namespace linkproof::cli
