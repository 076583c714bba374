// linkproof count --n N|A..B [--seed S] [--json]
// linkproof count --eightbar [--polygons "1-2-3-4-0,1-5-7-4-0,1-5-6-3-2"] [--json]
#include <fmt/format.h>

#include "command.h"
#include "core/time_budget.h"
#include "dijksman1966_counting.h"
#include "linkproof/core/error.h"
#include "report/count_report.h"

namespace linkproof::cli {

namespace {

struct CountArgs {
  std::string n_range;
  bool eightbar = false;
  std::string polygons;
  std::uint64_t seed = 1;
  bool json = false;
  bool strict = false;
};

int run_count(const CountArgs& a, std::ostream& out, std::ostream&) {
  if (a.n_range.empty() == !a.eightbar)
    throw InputError("<command line>", "--n/--eightbar", "give exactly one of --n N (or A..B) and --eightbar");
  if (!a.polygons.empty() && !a.eightbar)
    throw InputError("<command line>", "--polygons", "only applies to --eightbar");
  CountReport r;
  if (a.eightbar) {
    const std::string loops_text = a.polygons.empty() ? dijksman1966::kFig5Polygons : a.polygons;
    const auto loops = parse_polygon_list(loops_text, "<command line>", "--polygons");
    const CompoundMechanism m = dijksman1966::fig5_eightbar();
    r.subject = fmt::format("{}, loops {} (last link of each loop taken as fixed)", m.name, loops_text);
    r.claims = dijksman1966::eightbar_claims(m, loops, r.notes);
  } else {
    const auto [lo, hi] = parse_n_range(a.n_range, "--n", 3, 200);
    r.subject = lo == hi ? fmt::format("n = {}", lo) : fmt::format("n = {}..{}", lo, hi);
    for (int n = lo; n <= hi; ++n) {
      TimeBudget::check("the count at n = " + std::to_string(n));
      for (auto& c : dijksman1966::count_claims_for_n(n, a.seed)) r.claims.push_back(std::move(c));
    }
  }
  const ClaimsStatus status = count_status(r, a.strict);
  if (a.json)
    out << json_text(to_json(r, status)) << "\n";
  else
    write_text(out, r, status);
  return status.exit_status;
}

}  // namespace

void add_count_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("count", "count relations between relative angular rates by exact rank (docs/conventions.md §A7)");
  auto& a = bind_action<CountArgs>(c, action, run_count);
  c->add_option("--n", a.n_range, "number of bodies / polygon sides, N or A..B with 3 <= A <= B <= 200");
  c->add_flag("--eightbar", a.eightbar, "the eight-bar of Fig. 5 (geometry and input of docs/conventions.md §A8)");
  c->add_option("--polygons", a.polygons,
                "loops of links for --eightbar, last link fixed (default 1-2-3-4-0,1-5-7-4-0,1-5-6-3-2)");
  c->add_option("--seed", a.seed, "seed of the random polygons of the rank-2 claims (default 1)")
      ->check(seed_validator());
  c->add_flag("--json", a.json, "print JSON (docs/count.md)");
  c->add_flag("--strict", a.strict, "a rank that holds only on sample polygons is not as expected (exit 1): for CI");
}

}  // namespace linkproof::cli
