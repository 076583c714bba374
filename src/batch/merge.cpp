#include "batch/merge.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "batch/polygon_sweep_job.h"

namespace linkproof {

using nlohmann::json;

namespace {

int int_field(const json& s, const char* key, const std::string& file) {
  const auto it = s.find(key);
  if (it == s.end() || !it->is_number_integer()) throw InputError(file, std::string("summary.") + key, "missing or not an integer");
  return it->get<int>();
}

std::string text_field(const json& s, const char* key, const std::string& file) {
  const auto it = s.find(key);
  if (it == s.end() || !it->is_string()) throw InputError(file, std::string("summary.") + key, "missing or not a string");
  return it->get<std::string>();
}

/// The last line of a file (its summary when complete), or "" if it has none.
std::string last_line(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "<file>", "cannot be read");
  std::string line, last;
  while (std::getline(in, line))
    if (!in.eof()) last = line;
  return last;
}

}  // namespace

std::pair<SweepOptions, Shard> sweep_of_summary(const json& s, const std::string& file) {
  SweepOptions o;
  const auto seed = s.find("seed");
  if (seed == s.end() || !seed->is_number_unsigned()) throw InputError(file, "summary.seed", "missing or not an unsigned integer");
  o.seed = seed->get<std::uint64_t>();
  const std::string n = text_field(s, "n", file);
  if (std::sscanf(n.c_str(), "%d..%d", &o.n_min, &o.n_max) != 2 || o.n_min < 4 || o.n_max < o.n_min || o.n_max > 200)
    throw InputError(file, "summary.n", "must be \"A..B\" with 4 <= A <= B <= 200, not " + n);
  o.count = int_field(s, "count_per_n", file);
  if (o.count < 1) throw InputError(file, "summary.count_per_n", "must be >= 1");
  const auto a = parse_arithmetic(text_field(s, "arithmetic", file));
  if (!a) throw InputError(file, "summary.arithmetic", "unknown arithmetic");
  o.arithmetic = *a;
  return {o, shard_of_summary(s, file)};
}

Shard shard_of_summary(const json& s, const std::string& file) {
  Shard shard;
  if (s.contains("shard")) {
    const std::string k = text_field(s, "shard", file);
    if (std::sscanf(k.c_str(), "%d/%d", &shard.k, &shard.n) != 2 || shard.n < 1 || shard.k < 1 || shard.k > shard.n)
      throw InputError(file, "summary.shard", "must be \"K/N\" with 1 <= K <= N, not " + k);
  }
  return shard;
}

void merge_batch_lines(BatchJob& job, long size, int shards,
                       const std::function<std::optional<std::string>(int)>& next_line,
                       const std::function<std::string(int)>& source, const std::string& out) {
  std::unique_ptr<ResultFile> file;
  if (!out.empty()) file = std::make_unique<ResultFile>(out, false, [](const std::string&, long) {});
  job.set_file(file.get());
  std::vector<long> line_numbers(static_cast<size_t>(shards), 0);
  // The next line of shard s: true if it is a case line (pending in the job), false at the end
  // of the shard or at its summary line.
  auto read = [&](int s) -> std::optional<bool> {
    const auto text = next_line(s);
    if (!text) return std::nullopt;
    return !job.read(*text, source(s), ++line_numbers[static_cast<size_t>(s)]);
  };
  for (long k = 0; k < size; ++k) {
    const int s = static_cast<int>(k % shards);
    const std::string where = fmt::format("line {}", line_numbers[static_cast<size_t>(s)] + 1);
    const auto is_case = read(s);
    if (!is_case || !*is_case)
      throw InputError(source(s), where, fmt::format("case {} expected: shard {}/{} is incomplete", k, s + 1, shards));
    job.take_merged(k, source(s), where);
  }
  for (int s = 0; s < shards; ++s) {
    const auto is_case = read(s);
    if (!is_case || *is_case)
      throw InputError(source(s), fmt::format("line {}", line_numbers[static_cast<size_t>(s)]),
                       "the shard's summary line expected after its last case");
    if (read(s)) throw InputError(source(s), "<end>", "lines after the summary line");
  }
  if (file) file->append(job.summary_line(Shard{}));
  job.set_file(nullptr);
}

namespace {

// The polygon sweep `o` merged by `merge` into a job of its cases: the report.
SweepReport merge_polygon_sweep(const std::vector<Claim>& catalogue, const SweepOptions& o, const std::string& scenes_dir,
                                const SweepExitStatus& exit_status, const std::function<void(BatchJob&)>& merge) {
  const auto start = std::chrono::steady_clock::now();
  BatchSweepOptions b;
  b.sweep = o;
  b.scenes_dir = scenes_dir;
  b.exit_status = exit_status;
  PolygonSweepJob job(catalogue, b);
  merge(job);
  SweepReport r = job.report();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

SweepReport merge_shard_lines(const std::vector<Claim>& catalogue, const SweepOptions& o, int shards,
                              const std::function<std::optional<std::string>(int)>& next_line,
                              const std::function<std::string(int)>& source, const std::string& out,
                              const std::string& scenes_dir, const SweepExitStatus& exit_status) {
  return merge_polygon_sweep(catalogue, o, scenes_dir, exit_status, [&](BatchJob& job) {
    merge_batch_lines(job, SweepPlan(o).size(), shards, next_line, source, out);
  });
}

std::vector<std::string> shard_files_in_order(const std::vector<std::string>& files, const SummaryOf& summary_of,
                                              const SweepOf& sweep_of) {
  if (files.empty()) throw InputError("<command line>", "FILES", "no shard files given");
  std::optional<std::string> sweep;
  std::map<int, std::string> by_shard;  // K - 1 -> file
  int shards = 0;
  for (const auto& f : files) {
    const std::string last = last_line(f);
    const std::optional<json> summary = last.empty() ? std::nullopt : summary_of(last, f);
    if (!summary) throw InputError(f, "<last line>", "no summary line: the shard is incomplete (its sweep stopped before the end: resume that sweep "
                                                     "to complete the file)");
    auto [key, shard] = sweep_of(*summary, f);
    if (sweep && (key != *sweep || shard.n != shards))
      throw InputError(f, "summary", fmt::format("is a shard of another sweep than {}", files.front()));
    if (by_shard.count(shard.k - 1)) throw InputError(f, "summary.shard", "shard given twice (also " + by_shard[shard.k - 1] + ")");
    sweep = key;
    shards = shard.n;
    by_shard[shard.k - 1] = f;
  }
  if (static_cast<int>(by_shard.size()) != shards)
    throw InputError(files.front(), "summary.shard",
                     fmt::format("{} of {} shards given; every shard 1..{} is needed", by_shard.size(), shards, shards));
  std::vector<std::string> ordered;
  for (int s = 0; s < shards; ++s) ordered.push_back(by_shard[s]);
  return ordered;
}

void merge_batch_files(BatchJob& job, long size, const std::vector<std::string>& shard_files, const std::string& out) {
  std::vector<std::unique_ptr<std::ifstream>> in;
  for (const std::string& f : shard_files) in.push_back(std::make_unique<std::ifstream>(f, std::ios::binary));
  merge_batch_lines(
      job, size, static_cast<int>(shard_files.size()),
      [&](int s) -> std::optional<std::string> {
        std::string line;
        if (std::getline(*in[static_cast<size_t>(s)], line)) return line;
        return std::nullopt;
      },
      [&](int s) { return shard_files[static_cast<size_t>(s)]; }, out);
}

SweepReport merge_sweep_files(const std::vector<Claim>& catalogue, const std::vector<std::string>& files,
                              const std::string& out, const std::string& scenes_dir, const SweepExitStatus& exit_status) {
  std::optional<SweepOptions> sweep;
  const std::vector<std::string> ordered = shard_files_in_order(
      files, [](const std::string& line, const std::string& f) { return parse_sweep_line(line, f, 0).summary; },
      [&](const json& summary, const std::string& f) {
        auto [o, shard] = sweep_of_summary(summary, f);
        if (!sweep) sweep = o;
        return std::pair{fmt::format("{} {} {} {} {}", o.seed, o.n_min, o.n_max, o.count, to_string(o.arithmetic)), shard};
      });
  return merge_polygon_sweep(catalogue, *sweep, scenes_dir, exit_status, [&](BatchJob& job) {
    merge_batch_files(job, SweepPlan(*sweep).size(), ordered, out);
  });
}

}  // namespace linkproof
