#include "batch/merge.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "batch/batch_sweep.h"
#include "batch/case_sink.h"

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
  Shard shard;
  if (s.contains("shard")) {
    const std::string k = text_field(s, "shard", file);
    if (std::sscanf(k.c_str(), "%d/%d", &shard.k, &shard.n) != 2 || shard.n < 1 || shard.k < 1 || shard.k > shard.n)
      throw InputError(file, "summary.shard", "must be \"K/N\" with 1 <= K <= N, not " + k);
  }
  return {o, shard};
}

SweepReport merge_shard_lines(const std::vector<Claim>& catalogue, const SweepOptions& o, int shards,
                              const std::function<std::optional<std::string>(int)>& next_line,
                              const std::function<std::string(int)>& source, const std::string& out,
                              const std::string& scenes_dir, const SweepExitStatus& exit_status) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<ResultFile> file;
  if (!out.empty()) file = std::make_unique<ResultFile>(out, false, [](const std::string&, long) {});
  CaseSink sink(catalogue, o, file.get(), scenes_dir);
  std::vector<long> line_numbers(static_cast<size_t>(shards), 0);
  auto read = [&](int s) -> std::optional<SweepLine> {
    const auto text = next_line(s);
    if (!text) return std::nullopt;
    return parse_sweep_line(*text, source(s), ++line_numbers[static_cast<size_t>(s)]);
  };
  const long size = SweepPlan(o).size();
  for (long k = 0; k < size; ++k) {
    const int s = static_cast<int>(k % shards);
    const std::string where = fmt::format("line {}", line_numbers[static_cast<size_t>(s)] + 1);
    auto line = read(s);
    if (!line || !line->sweep_case)
      throw InputError(source(s), where, fmt::format("case {} expected: shard {}/{} is incomplete", k, s + 1, shards));
    check_case_identity(*line, k, o, catalogue, source(s), where);
    sink.add(*line->sweep_case, true, source(s), where);
  }
  for (int s = 0; s < shards; ++s) {
    auto line = read(s);
    if (!line || !line->summary)
      throw InputError(source(s), fmt::format("line {}", line_numbers[static_cast<size_t>(s)]),
                       "the shard's summary line expected after its last case");
    if (read(s)) throw InputError(source(s), "<end>", "lines after the summary line");
  }
  if (file) file->append(sweep_summary_line(sink.tally().report(), Shard{}, exit_status(sink.tally().report())));
  SweepReport r = sink.tally().report();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

SweepReport merge_sweep_files(const std::vector<Claim>& catalogue, const std::vector<std::string>& files,
                              const std::string& out, const std::string& scenes_dir, const SweepExitStatus& exit_status) {
  if (files.empty()) throw InputError("<command line>", "FILES", "no shard files given");
  std::optional<SweepOptions> sweep;
  std::map<int, std::string> by_shard;  // K - 1 -> file
  int shards = 0;
  for (const auto& f : files) {
    const std::string last = last_line(f);
    SweepLine line = last.empty() ? SweepLine{} : parse_sweep_line(last, f, 0);
    if (!line.summary) throw InputError(f, "<last line>", "no summary line: the shard is incomplete (its sweep stopped before the end: resume that sweep "
                                                     "to complete the file)");
    auto [o, shard] = sweep_of_summary(*line.summary, f);
    if (sweep && (o.seed != sweep->seed || o.n_min != sweep->n_min || o.n_max != sweep->n_max ||
                  o.count != sweep->count || o.arithmetic != sweep->arithmetic || shard.n != shards))
      throw InputError(f, "summary", fmt::format("is a shard of another sweep than {}", files.front()));
    if (by_shard.count(shard.k - 1)) throw InputError(f, "summary.shard", "shard given twice (also " + by_shard[shard.k - 1] + ")");
    sweep = o;
    shards = shard.n;
    by_shard[shard.k - 1] = f;
  }
  if (static_cast<int>(by_shard.size()) != shards)
    throw InputError(files.front(), "summary.shard",
                     fmt::format("{} of {} shards given; every shard 1..{} is needed", by_shard.size(), shards, shards));
  std::vector<std::unique_ptr<std::ifstream>> in;
  for (int s = 0; s < shards; ++s) in.push_back(std::make_unique<std::ifstream>(by_shard[s], std::ios::binary));
  return merge_shard_lines(
      catalogue, *sweep, shards,
      [&](int s) -> std::optional<std::string> {
        std::string line;
        if (std::getline(*in[static_cast<size_t>(s)], line)) return line;
        return std::nullopt;
      },
      [&](int s) { return by_shard[s]; }, out, scenes_dir, exit_status);
}

}  // namespace linkproof
