#include "cli.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <new>

#include "budget_watchdog.h"
#include "build_info.h"
#include "command.h"
#include "error_report.h"
#include "linkproof/core/error.h"
#include "core/time_budget.h"

namespace linkproof::cli {

void add_check_data_command(CLI::App& app, Action& action);  // check_data_command.cpp

namespace {

// "check, sweep, ..." for messages.
std::string subcommand_names(CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

// A report that did not reach its reader (stdout on a full disk, a closed pipe) is a failed
// run: exit 2 with a message, never 0.
int checked_output(std::ostream& out, std::ostream& err, int status) {
  out.flush();
  if (out) return status;
  print_error(out, err,
              command_line_error_report("(standard output)", "cannot write the report (disk full, or the output closed)"),
              /*json=*/false);
  return kBadInput;
}

// Parses `args` into `action` and `resources`; returns the exit code when the command line ends
// here.
std::optional<int> parse(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, Action& action,
                         Resources& resources, bool json) {
  CLI::App app{"linkproof: checks published kinematics formulas of planar linkages against the exact truth"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "linkproof " LINKPROOF_VERSION);
  // The resource options belong to every subcommand: declared once here, and found after the
  // subcommand's name too (fallthrough, inherited by the subcommands declared below).
  app.fallthrough();
  std::optional<double> max_seconds;
  app.add_option("--max-seconds", max_seconds,
                 "wall-clock budget of the run in seconds (default 3600; sweep: none; 0: none); past it the run "
                 "stops with exit 2 (docs/limits.md)")
      ->check(seconds_validator(kMaxRunSeconds));
  app.add_option("--max-memory-mb", resources.max_memory_mb,
                 "address-space budget in MiB (default 8192; 0: none); past it the run stops with exit 2")
      ->check(int_range_validator(0, 1 << 24));

  // One line per subcommand; each lives in its own <name>_command.cpp.
  add_check_command(app, action);
  add_sweep_command(app, action);
  add_prove_command(app, action);
  add_check_claim_command(app, action);
  add_count_command(app, action);
  add_bench_command(app, action);
  add_curvature_command(app, action);
  add_merge_command(app, action);
  add_check_data_command(app, action);
  add_report_command(app, action);

  if (!args.empty() && !args.front().empty() && args.front().front() != '-' &&
      app.get_subcommands([&](CLI::App* sub) { return sub->check_name(args.front()); }).empty())
    return print_error(out, err,
                       command_line_error_report("SUBCOMMAND", "unknown subcommand '" + args.front() +
                                                                   "'; expected one of: " + subcommand_names(app)),
                       json);

  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them reversed
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return checked_output(out, err, kAsExpected);
  } catch (const CLI::CallForVersion&) {
    out << "linkproof " LINKPROOF_VERSION "\n";  // the project version (CMakeLists.txt)
    return checked_output(out, err, kAsExpected);
  } catch (const CLI::ParseError& e) {
    const int status = print_error(out, err, command_line_error_report("", e.what()), json);
    if (!json) err << app.help();
    return status;
  }
  if (!action) return print_error(out, err, internal_error_report("no subcommand action was set"), json);
  const bool is_sweep = !app.get_subcommands().empty() && app.get_subcommands().front()->get_name() == "sweep";
  resources.max_seconds = max_seconds.value_or(is_sweep ? 0.0 : kDefaultMaxSeconds);
  return std::nullopt;
}

bool wants_json(const std::vector<std::string>& args) {
  return std::find(args.begin(), args.end(), "--json") != args.end();
}

}  // namespace

std::optional<int> parse_only(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  Action action;
  Resources resources;
  return parse(args, out, err, action, resources, wants_json(args));
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, RunMode mode) {
  const bool json = wants_json(args);
  Action action;
  Resources resources;
  if (const auto finished = parse(args, out, err, action, resources, json)) return *finished;
  // The budget is cooperative in-process (TimeBudget::check at each unit of work); the program
  // adds a watchdog for units that never reach a check point, and the memory limit.
  BudgetScope budget(resources, mode == RunMode::Program, json);
  try {
    return checked_output(out, err, action(out, err));
  } catch (const InputError& e) {
    return print_error(out, err, input_error_report(e), json);
  } catch (const BudgetExceeded& e) {
    return print_error(out, err, command_line_error_report("--max-seconds", e.what()), json);
  } catch (const std::bad_alloc&) {
    lift_memory_limit();
    return print_error(out, err, memory_error_report(resources), json);
  } catch (const std::exception& e) {
    return print_error(out, err, internal_error_report(e.what()), json);
  }
}

}  // namespace linkproof::cli
