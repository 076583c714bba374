// linkproof_mpi: a sweep distributed over MPI ranks (the optional MPI component).
//
//   mpirun -np 64 build/linkproof_mpi --n 4..12 --count 10000 --seed 7 --out sweep.jsonl
//   mpirun -np 64 build/linkproof_mpi --topology SCENE --claims CLAIMS --count 100000 --out sweep.jsonl
//
// Rank r computes shard r+1 of N = size (the cases k with k mod N = r, as `sweep --shard`),
// trimmed to the examples its report keeps; rank 0 gathers every shard's lines and merges them
// (batch/merge.h). The result file and the report are the bytes `linkproof sweep` gives with the
// same options. Options: those of `sweep` that describe the cases and the output (see
// sweep_args.h), for polygons or (--topology --claims) a mechanism topology; exit codes as
// `sweep` (0, 1 a claim not as expected, 2 bad input, 3 internal error).
#include <mpi.h>

#include <chrono>
#include <climits>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "dijksman1966.h"
#include "batch/batch_sweep.h"
#include "batch/merge.h"
#include "batch/scene_directory.h"
#include "batch/topology_sweep_job.h"
#include "check/sweep_tally.h"
#include "core/large_blocks.h"
#include "exit_status.h"
#include "report/json_report.h"
#include "report/text_report.h"
#include "sweep_args.h"

namespace linkproof::cli {
namespace {

/// This rank's shard as result-file lines (cases, then the shard's summary).
std::string shard_lines(const std::vector<Claim>& catalogue, const SweepOptions& o, const Shard& shard) {
  GroundTruthEngine engine;
  SweepTally tally(catalogue, o);
  std::string lines;
  for (long k : shard_cases(o, shard)) {
    SweepCase c = run_sweep_case(engine, catalogue, o, k);
    tally.add(c);
    lines += sweep_case_line(c, o.arithmetic) + "\n";
  }
  return lines + sweep_summary_line(tally.report(), shard, exit_status(tally.report())) + "\n";
}

/// This rank's shard of a sweep of a topology as result-file lines: the bytes of
/// `sweep --topology ... --shard K/N --out` (cases, then the shard's summary).
std::string topology_shard_lines(TopologySweepJob& job, long count, const Shard& shard) {
  std::string lines;
  long i = 0;
  for (long k : shard_case_numbers(count, shard)) {
    const std::string line = job.case_line(k);
    job.take_worker_line(line, k, ++i);  // counted for the summary line
    lines += line + "\n";
  }
  return lines + job.summary_line(shard) + "\n";
}

/// Gathers every rank's text on rank 0 (empty elsewhere), one string per rank.
std::vector<std::string> gather(const std::string& mine, int rank, int size) {
  if (mine.size() > static_cast<size_t>(INT_MAX))
    throw InternalError("a rank's result exceeds 2 GiB: use more ranks, or `sweep --shard` and `merge`");
  int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<size_t>(size)), offsets(static_cast<size_t>(size));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  long total = 0;
  for (int r = 0; r < size; ++r) {
    offsets[static_cast<size_t>(r)] = static_cast<int>(total);
    total += lengths[static_cast<size_t>(r)];
  }
  if (rank == 0 && total > INT_MAX) throw InternalError("the gathered result exceeds 2 GiB: use `sweep --shard` and `merge`");
  std::string all(rank == 0 ? static_cast<size_t>(total) : 0, '\0');
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::string> parts;
  if (rank == 0)
    for (int r = 0; r < size; ++r)
      parts.push_back(all.substr(static_cast<size_t>(offsets[static_cast<size_t>(r)]),
                                 static_cast<size_t>(lengths[static_cast<size_t>(r)])));
  return parts;
}

/// Rank 0's reader of the gathered parts: the next line of rank s's part (nullopt at its end).
class GatheredLines {
 public:
  explicit GatheredLines(const std::vector<std::string>& parts) {
    for (const auto& p : parts) in_.emplace_back(p);
  }
  std::optional<std::string> next(int s) {
    std::string line;
    if (std::getline(in_[static_cast<size_t>(s)], line)) return line;
    return std::nullopt;
  }
  static std::string source(int s) { return fmt::format("<rank {}>", s); }

 private:
  std::vector<std::istringstream> in_;
};

/// `sweep --topology SCENE --claims CLAIMS` over the ranks; every rank reads both files.
int run_topology(const SweepCommandArgs& a, int rank, int size) {
  TopologySweepInput in;
  try {
    check_topology_options(a);  // the same on every rank: all fail or none does
    const Arithmetic arithmetic = arithmetic_or_throw(a.arith);
    in = load_topology_sweep(a.topology, a.claims);
    in.id.seed = a.seed;
    in.id.count = a.count;
    in.id.arithmetic = arithmetic;
  } catch (const InputError& e) {
    if (rank == 0) fmt::print(std::cerr, "linkproof_mpi: bad input: {}\n", e.what());
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const TopologySweepStatus status = topology_sweep_status;
  TopologySweepJob shard_job(in.scene, in.claims, in.id, status);
  const std::vector<std::string> parts =
      gather(topology_shard_lines(shard_job, in.id.count, Shard{rank + 1, size}), rank, size);
  if (rank != 0) return 0;
  GatheredLines lines(parts);
  try {
    TopologySweepJob job(in.scene, in.claims, in.id, status);
    naming_options(kSweepOptionNames, [&] {
      merge_batch_lines(job, in.id.count, size, [&](int s) { return lines.next(s); }, GatheredLines::source, a.out);
      if (!a.scenes.empty()) write_counterexample_scenes(a.scenes, job.report());
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return print_topology_sweep_report(std::cout, job.report(), in.id, Shard{}, seconds, a.json);
  } catch (const InputError& e) {
    fmt::print(std::cerr, "linkproof_mpi: bad input: {}\n", e.what());
    return 2;
  }
}

int run(int argc, char** argv, int rank, int size) {
  CLI::App app{"linkproof_mpi: `linkproof sweep` distributed over MPI ranks"};
  SweepCommandArgs a;
  add_sweep_options(&app, a);
  add_topology_options(&app, a);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (rank == 0) return app.exit(e) == 0 ? 0 : 2;
    return e.get_exit_code() == 0 ? 0 : 2;
  }
  if (!a.topology.empty() || !a.claims.empty()) return run_topology(a, rank, size);
  SweepOptions o;
  try {
    o = sweep_options_or_throw(a);  // the same on every rank: all fail or none does
  } catch (const InputError& e) {
    if (rank == 0) fmt::print(std::cerr, "linkproof_mpi: bad input: {}\n", e.what());
    return 2;
  }
  const auto catalogue = dijksman1966::catalogue();
  const std::vector<std::string> parts = gather(shard_lines(catalogue, o, Shard{rank + 1, size}), rank, size);
  if (rank != 0) return 0;
  GatheredLines lines(parts);
  try {
    const SweepReport r = naming_options(kSweepOptionNames, [&] {
      return merge_shard_lines(
          catalogue, o, size, [&](int s) { return lines.next(s); }, GatheredLines::source, a.out, a.scenes,
          [](const SweepReport& s) { return exit_status(s); });
    });
    return print_report(std::cout, r, a.json, exit_status(r));
  } catch (const InputError& e) {
    fmt::print(std::cerr, "linkproof_mpi: bad input: {}\n", e.what());
    return 2;
  }
}

}  // namespace
}  // namespace linkproof::cli

int main(int argc, char** argv) {
  linkproof::keep_large_blocks_for_reuse();  // as the CLI (core/large_blocks.h)
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int code = 3;
  try {
    code = linkproof::cli::run(argc, argv, rank, size);
  } catch (const std::exception& e) {
    fmt::print(std::cerr, "linkproof_mpi: internal error on rank {}: {}\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  MPI_Finalize();
  return code;
}
