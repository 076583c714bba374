// linkproof bench [--families a,b,...] [--out DIR] [--json] [--full] [--cases N] [--n N] [--seed S]
// The stability study (numerics/bench_study.h): error against run time for every route x arithmetic,
// error against the parameter of each extreme family, adaptive-mode statistics. The default is
// quick (a few seconds); --full runs the long lists (with a progress bar on stderr).
#include <fmt/format.h>
#include <fmt/ostream.h>

#include <sstream>

#include "cli.h"
#include "command.h"
#include "linkproof/core/error.h"
#include "numerics/bench_study.h"
#include "report/bench_report.h"
#include "report/json_report.h"

namespace linkproof::cli {

namespace {

struct BenchArgs {
  std::string families;
  std::string out_dir;
  bool json = false;
  bool full = false;
  bool quiet = false;
  std::optional<int> cases;
  int n = 5;
  std::uint64_t seed = 1966;
  std::optional<double> time_budget_ms;
  std::optional<int> adaptive_cases;
};

std::set<std::string> split_names(const std::string& s) {
  std::set<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.insert(item);
  return out;
}

int run_bench_command(const BenchArgs& a, std::ostream& out, std::ostream& err) {
  BenchOptions o;
  o.full = a.full;
  o.families = split_names(a.families);
  o.seed = a.seed;
  if (a.n < 4 || a.n > 200) throw InputError("<command line>", "--n", "must be between 4 and 200");
  o.n = a.n;
  o.random_cases = a.cases.value_or(a.full ? 16 : 3);
  if (o.random_cases < 1 || o.random_cases > 10000) throw InputError("<command line>", "--cases", "must be between 1 and 10000");
  const double budget_ms = a.time_budget_ms.value_or(a.full ? 20.0 : 1.0);
  if (!(budget_ms >= 0 && budget_ms <= 10000)) throw InputError("<command line>", "--time-budget-ms", "must be between 0 and 10000");
  o.time_budget_seconds = budget_ms * 1e-3;
  o.adaptive_cases = a.adaptive_cases.value_or(a.full ? 10000 : 200);
  if (o.adaptive_cases < 0 || o.adaptive_cases > 1000000)
    throw InputError("<command line>", "--adaptive-cases", "must be between 0 and 1000000");
  if (a.full && !a.quiet) {
    o.progress = [&err](int done, int total) {
      const int width = 40, filled = total ? done * width / total : width;
      fmt::print(err, "\r[{}{}] {}/{}", std::string(static_cast<size_t>(filled), '#'),
                 std::string(static_cast<size_t>(width - filled), ' '), done, total);
      if (done == total) err << "\n";
      err.flush();
    };
  }
  const BenchResult r = naming_options({{"families", "--families"}}, [&] { return run_bench(o); });
  if (!a.out_dir.empty()) {
    const auto written = naming_options({{"output directory", "--out"}}, [&] { return write_bench_files(r, a.out_dir); });
    for (const auto& p : written)
      if (!a.json) fmt::print(out, "wrote {}\n", p.string());
  }
  if (a.json)
    out << json_text(to_json(r)) << "\n";
  else if (a.out_dir.empty())
    out << to_markdown(r);
  return kAsExpected;
}

}  // namespace

void add_bench_command(CLI::App& app, Action& action) {
  auto* s = app.add_subcommand("bench", "error against run time per route and arithmetic; extreme families; adaptive mode");
  auto& a = bind_action<BenchArgs>(s, action, run_bench_command);
  s->add_option("--families", a.families,
                "comma-separated extreme families (default all): dead_centre, q_infinity, beta_zero, p_infinity, "
                "q_at_k, kprime_at_kn, length_ratio, omega_scale, large_n");
  s->add_option("--out", a.out_dir, "write bench.md, bench.json, pareto.svg, family_<name>.svg into this directory");
  s->add_flag("--json", a.json, "print JSON instead of Markdown");
  s->add_flag("--full", a.full, "the full study: long parameter lists, n up to 1000, more cases, longer timing");
  s->add_flag("--quiet", a.quiet, "no progress bar");
  s->add_option("--cases", a.cases, "random polygons for the error-vs-time table (default 3, full 16)");
  s->add_option("--n", a.n, "sides of those polygons (default 5)");
  s->add_option("--seed", a.seed, "seed of the random polygons (default 1966)")->check(seed_validator());
  s->add_option("--time-budget-ms", a.time_budget_ms, "timing per route x arithmetic x case, ms (default 1, full 20)");
  s->add_option("--adaptive-cases", a.adaptive_cases, "random pentagons for the adaptive statistics (default 200, full 10000)");
}

}  // namespace linkproof::cli
