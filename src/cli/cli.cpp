#include "cli.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "command.h"
#include "linkproof/core/error.h"

namespace linkproof::cli {

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"linkproof: checks published kinematics formulas of planar linkages against the exact truth"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "linkproof 0.1.0");

  // One line per subcommand; each lives in its own <name>_command.cpp.
  Action action;
  add_check_command(app, action);
  add_sweep_command(app, action);
  add_prove_command(app, action);
  add_check_claim_command(app, action);
  add_count_command(app, action);
  add_bench_command(app, action);
  add_report_command(app, action);

  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them reversed
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return kAsExpected;
  } catch (const CLI::CallForVersion&) {
    out << "linkproof 0.1.0\n";
    return kAsExpected;
  } catch (const CLI::ParseError& e) {
    fmt::print(err, "linkproof: {}\n{}", e.what(), app.help());
    return kBadInput;
  }
  if (!action) return kInternalError;

  try {
    return action(out, err);
  } catch (const InputError& e) {
    fmt::print(err, "linkproof: bad input: {}\n", e.what());
    return kBadInput;
  } catch (const InternalError& e) {
    fmt::print(err, "linkproof: internal error: {}\n", e.what());
    return kInternalError;
  } catch (const std::exception& e) {
    fmt::print(err, "linkproof: internal error: {}\n", e.what());
    return kInternalError;
  }
}

}  // namespace linkproof::cli
