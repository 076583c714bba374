// linkproof sweep --n 4..12 --count N --seed S [--arith ...] [--index I] [--json]
#include <optional>

#include "command.h"
#include "dijksman1966.h"
#include "linkproof/check/sweep.h"
#include "linkproof/report/json_report.h"
#include "linkproof/report/text_report.h"

namespace linkproof::cli {

namespace {

struct SweepArgs {
  std::string n_range = "4..12";
  int count = 100;
  std::uint64_t seed = 1;
  std::string arith = "exact";
  std::optional<int> index;
  bool json = false;
};

int run_sweep_command(const SweepArgs& a, std::ostream& out, std::ostream&) {
  SweepOptions o;
  std::tie(o.n_min, o.n_max) = parse_n_range(a.n_range, "--n", 4, 200);
  if (a.count < 1 || a.count > 1000000) throw InputError("<command line>", "--count", "must be between 1 and 1000000");
  if (a.index && *a.index < 0) throw InputError("<command line>", "--index", "must be >= 0");
  o.count = a.count;
  o.seed = a.seed;
  o.arithmetic = arithmetic_or_throw(a.arith);
  o.only_index = a.index;
  GroundTruthEngine engine;
  const SweepReport r = run_sweep(engine, dijksman1966::catalogue(), o);
  return print_report(out, r, a.json, r.exit_status());
}

}  // namespace

void add_sweep_command(CLI::App& app, Action& action) {
  auto* s = app.add_subcommand("sweep", "check every claim on random exact polygons");
  auto& a = bind_action<SweepArgs>(s, action, run_sweep_command);
  s->add_option("--n", a.n_range, "number of sides, N or A..B (default 4..12)");
  s->add_option("--count", a.count, "cases per n (default 100)");
  s->add_option("--seed", a.seed, "seed; any case replays from seed, n and index (default 1)")
      ->check(seed_validator());
  s->add_option("--arith", a.arith,
                "arithmetic: exact (default), double, long-double, mp30, mp50, mp100, mp1000 (see check --help)");
  s->add_option("--index", a.index, "replay only this case index");
  s->add_flag("--json", a.json, "print JSON");
}

}  // namespace linkproof::cli
