// How a subcommand plugs into the linkproof program.
//
// Each subcommand lives in its own file (check_command.cpp, sweep_command.cpp, ...) and
// exposes one `add_<name>_command` function. It declares its options on `app` and, when CLI11
// has parsed it, stores the action to run in `action`. Parsing and running are separate so that
// errors of the run (bad scene files, ...) are reported with the run's exit codes, not CLI11's.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "linkproof/check/arithmetic.h"
#include "linkproof/check/ask.h"
#include "exit_status.h"
#include "report/json_report.h"
#include "io/claim_file.h"

namespace linkproof {
struct ProveOptions;
}

namespace linkproof::cli {

/// The work of one parsed subcommand; returns the exit code.
using Action = std::function<int(std::ostream& out, std::ostream& err)>;

/// Registers `run(args, out, err)` as the action of `sub` once it is parsed. `args` is owned by
/// the returned callback, so the options can bind to its fields.
template <class Args, class Run>
Args& bind_action(CLI::App* sub, Action& action, Run run) {
  auto args = std::make_shared<Args>();
  sub->callback([&action, args, run] {
    action = [args, run](std::ostream& out, std::ostream& err) { return run(*args, out, err); };
  });
  return *args;
}

/// Prints `report` as JSON (its to_json, which records `status`) or as text (its write_text) and
/// returns `status`, the exit code (exit_status.h): how every subcommand ends.
template <class Report>
int print_report(std::ostream& out, const Report& report, bool json, int status) {
  if (json)
    out << json_text(to_json(report, status)) << "\n";
  else
    write_text(out, report);
  return status;
}

/// Library errors name the quantity they are about (the field "result file", "only_n", ...); the
/// command line names the option that gave it. Pairs {library field, option}.
using OptionNames = std::vector<std::pair<std::string, std::string>>;
/// To be called in a handler of `e`: rethrows it with the option as its field when `names` maps
/// its field (a source "<api>" becoming "<command line>"), or else rethrows `e` itself.
[[noreturn]] void rethrow_naming_option(const InputError& e, const OptionNames& names);
/// Runs `work()`; an InputError it throws goes through rethrow_naming_option.
template <class Work>
decltype(auto) naming_options(const OptionNames& names, Work&& work) {
  try {
    return work();
  } catch (const InputError& e) {
    rethrow_naming_option(e, names);
  }
}

/// "--arith" parsed, or an InputError naming the option.
Arithmetic arithmetic_or_throw(const std::string& s);
/// The arithmetic of a scene's check: --arith when given (it takes precedence), else the
/// scene's `ask: [arithmetic: ...]`, else exact.
Arithmetic chosen_arithmetic(const std::optional<std::string>& option, const std::optional<SceneAsk>& ask);

/// "N" or "A..B" with lo <= A <= B <= hi, or an InputError naming `option`.
std::pair<int, int> parse_n_range(const std::string& s, const std::string& option, int lo, int hi);

/// CLI11 check for a seed: an unsigned 64-bit integer in decimal digits. "-1" or a value above
/// 2^64 - 1 is refused (CLI11 alone wraps or clamps them, which breaks replay).
CLI::Validator seed_validator();
/// The largest time budgets: a per-claim proof ladder (--ladder-seconds) and a whole run
/// (--max-seconds).
inline constexpr double kMaxClaimLadderSeconds = 3600;
inline constexpr double kMaxRunSeconds = 604800;  // a week
/// CLI11 check for a time budget: a finite number of seconds from 0 to max_seconds (NaN, inf
/// refused). Every seconds option uses it.
CLI::Validator seconds_validator(double max_seconds = kMaxClaimLadderSeconds);
/// CLI11 check for an integer option from lo to hi.
CLI::Validator int_range_validator(int lo, int hi);
/// The claims of `file` named by `ids` (the full id or its last part, e.g. "eq22"), in that
/// order; every claim when `ids` is empty. InputError naming --claim for an unknown id.
std::vector<const DataClaim*> choose_claims(const ClaimFile& file, const std::vector<std::string>& ids);

/// --n within 4..kMaxClaimSides and --ladder-seconds within 0..3600, or an InputError naming it.
void check_prove_limits(const std::optional<int>& n, double ladder_seconds);

/// The per-n ladder as the command line sets it: --ladder-seconds if given, and re-checks of
/// claims already proved for every n only when the ladder is asked for (--ladder-seconds, or
/// `range_asked`: a range of n), where they add nothing but time otherwise.
void set_ladder(ProveOptions& o, const std::optional<double>& ladder_seconds, bool range_asked);

/// The claim file `file` read for a mechanism scene and bound to its names (a polygon claim file
/// is refused as such).
std::vector<MechanismDataClaim> mechanism_claims_for(const std::string& file, const MechanismScene& scene,
                                                     const std::string& scene_path);
/// Proves the claims over every configuration of the scene's topology; prints; the exit status.
int run_topology_proof(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                       const TopologyProofOptions& options, bool json, bool strict, std::ostream& out);

void add_check_command(CLI::App& app, Action& action);
void add_sweep_command(CLI::App& app, Action& action);
void add_prove_command(CLI::App& app, Action& action);
void add_check_claim_command(CLI::App& app, Action& action);
void add_count_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);
void add_curvature_command(CLI::App& app, Action& action);
void add_merge_command(CLI::App& app, Action& action);
void add_report_command(CLI::App& app, Action& action);

}  // namespace linkproof::cli
