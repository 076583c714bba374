// The options a sweep shares between `linkproof sweep` and the MPI driver (linkproof_mpi).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "command.h"
#include "check/sweep.h"
#include "batch/batch_run.h"
#include "batch/result_file.h"
#include "batch/topology_sweep_job.h"
#include "linkproof/io/mechanism_scene.h"
#include "report/sweep_lines.h"

namespace linkproof::cli {

/// The options of sweep, merge and linkproof_mpi that give what the library's errors name.
inline const OptionNames kSweepOptionNames{{"result file", "--out"}, {"scene directory", "--scenes"}};

struct SweepArgs {
  std::string n_range = "4..12";
  int count = 100;
  std::uint64_t seed = 1;
  std::string arith = "exact";
  std::optional<int> index;
  bool json = false;
  std::string out;     ///< --out FILE
  std::string scenes;  ///< --scenes DIR
};

/// The options of `linkproof sweep` (polygons, or with --topology a mechanism topology).
struct SweepCommandArgs : SweepArgs {
  std::optional<int> jobs;
  bool resume = false;
  std::string shard;
  bool n_given = false;   ///< --n was on the command line
  std::string topology;   ///< --topology SCENE: a sweep of the scene's topology
  std::string claims;     ///< --claims CLAIMS: its mechanism claims
};

/// `linkproof sweep --topology SCENE --claims CLAIMS ...` (topology_sweep_command.cpp).
int run_topology_sweep_command(const SweepCommandArgs& args, std::ostream& out, std::ostream& err);

/// Declares --topology and --claims on `app` (with add_sweep_options: the options of a sweep of a
/// topology, for `sweep` and linkproof_mpi alike), and records whether --n was given.
void add_topology_options(CLI::App* app, SweepCommandArgs& args);
/// Refuses the options of a polygon sweep with --topology, and a half-given topology sweep,
/// naming the option (InputError).
void check_topology_options(const SweepCommandArgs& args);

/// What a sweep of a topology is run on: the scene, its claims, and the sweep's identity but for
/// seed, count and arithmetic (the scene's name, the digests of both files).
struct TopologySweepInput {
  MechanismScene scene;
  std::vector<MechanismDataClaim> claims;
  TopologySweepIdentity id;
};
/// Reads --topology SCENE and --claims CLAIMS; InputError naming the file or the option.
TopologySweepInput load_topology_sweep(const std::string& topology, const std::string& claims);

/// Prints the report of a sweep of a topology (JSON or text) and returns its exit status.
int print_topology_sweep_report(std::ostream& out, const TopologySweepReport& report, const TopologySweepIdentity& id,
                                const Shard& shard, double seconds, bool json);

/// The digest of a file's bytes (sweep_line_digest), naming `option` if it cannot be read.
std::string file_digest(const std::string& path, const std::string& option);

/// Runs `work()` (a sweep or merge writing --out) and names the command line's options in its
/// InputErrors: an existing --out (ResultFileExists) with the hint to pass --resume.
template <class Work>
decltype(auto) naming_sweep_options(Work&& work) {
  try {
    return work();
  } catch (const ResultFileExists& e) {
    throw InputError(e.source(), "--out", e.problem() + "; pass --resume to continue it, or remove it");
  } catch (const InputError& e) {
    rethrow_naming_option(e, kSweepOptionNames);
  }
}

/// A sweep that stopped before its end (interrupted, out of time, a worker failed): says how to
/// continue (with the result file `out`, if any) and returns `code`, its exit status; a stop by
/// the time budget is an InputError naming --max-seconds.
int report_stopped_sweep(const BatchRun& run, const std::string& out, std::ostream& err, int code);

/// Declares --n, --count, --seed, --arith, --out, --scenes and --json on `app`.
void add_sweep_options(CLI::App* app, SweepArgs& args);
/// The sweep the arguments describe, or an InputError naming the option.
SweepOptions sweep_options_or_throw(const SweepArgs& args);
/// --jobs, --shard, --out, --resume, and the progress bar on `err` when it is the terminal's
/// stderr; InputError naming a bad option.
BatchRunOptions batch_run_options_or_throw(const SweepCommandArgs& args, std::ostream& err);
/// "K/N" with 1 <= K <= N, or an InputError naming --shard.
Shard parse_shard(const std::string& s);

}  // namespace linkproof::cli
