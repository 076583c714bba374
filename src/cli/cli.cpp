#include "cli.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>

#include "command.h"
#include "error_report.h"
#include "linkproof/core/error.h"

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

// Parses `args` into `action`; returns the exit code when the command line ends here.
std::optional<int> parse(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, Action& action,
                         bool json) {
  CLI::App app{"linkproof: checks published kinematics formulas of planar linkages against the exact truth"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "linkproof 0.1.0");

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
    out << "linkproof 0.1.0\n";
    return checked_output(out, err, kAsExpected);
  } catch (const CLI::ParseError& e) {
    const int status = print_error(out, err, command_line_error_report("", e.what()), json);
    if (!json) err << app.help();
    return status;
  }
  if (!action) return print_error(out, err, internal_error_report("no subcommand action was set"), json);
  return std::nullopt;
}

bool wants_json(const std::vector<std::string>& args) {
  return std::find(args.begin(), args.end(), "--json") != args.end();
}

}  // namespace

std::optional<int> parse_only(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  Action action;
  return parse(args, out, err, action, wants_json(args));
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const bool json = wants_json(args);
  Action action;
  if (const auto finished = parse(args, out, err, action, json)) return *finished;
  try {
    return checked_output(out, err, action(out, err));
  } catch (const InputError& e) {
    return print_error(out, err, input_error_report(e), json);
  } catch (const std::exception& e) {
    return print_error(out, err, internal_error_report(e.what()), json);
  }
}

}  // namespace linkproof::cli
