// The options a sweep shares between `linkproof sweep` and the MPI driver (linkproof_mpi).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "command.h"
#include "check/sweep.h"
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

/// Declares --n, --count, --seed, --arith, --out, --scenes and --json on `app`.
void add_sweep_options(CLI::App* app, SweepArgs& args);
/// The sweep the arguments describe, or an InputError naming the option.
SweepOptions sweep_options_or_throw(const SweepArgs& args);
/// "K/N" with 1 <= K <= N, or an InputError naming --shard.
Shard parse_shard(const std::string& s);

}  // namespace linkproof::cli
