#include "batch/topology_sweep_job.h"

#include <chrono>

#include <fmt/format.h>

#include "batch/merge.h"
#include "batch/scene_directory.h"
#include "report/topology_sweep_report.h"

namespace linkproof {

namespace {

TopologySampling sampling_of(const TopologySweepIdentity& id) {
  TopologySampling o;
  o.count = static_cast<int>(id.count);
  o.seed = id.seed;
  o.arithmetic = id.arithmetic;
  return o;
}

}  // namespace

TopologySweepJob::TopologySweepJob(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                   const TopologySweepIdentity& id, const TopologySweepStatus& status)
    : id_(id),
      status_(status),
      configurations_(scene, claims, sampling_of(id)),
      tally_(scene, claims, sampling_of(id)) {
  for (const MechanismDataClaim& c : claims) claim_ids_.push_back(c.info.id);
}

void TopologySweepJob::take(const TopologySweepCase& c, bool write) {
  tally_.add(c);
  report_.reset();
  if (write && file_ != nullptr) file_->append(topology_case_line(c, id_, claim_ids_));
}

void TopologySweepJob::run_case(long k) { take(run_topology_sweep_case(configurations_, k), true); }

std::string TopologySweepJob::case_line(long k) {
  return topology_case_line(run_topology_sweep_case(configurations_, k), id_, claim_ids_);
}

void TopologySweepJob::take_worker_line(const std::string& line, long k, long i) {
  const TopologySweepLine parsed = parse_topology_line(line, "<worker>", i, claim_ids_);
  check_topology_case_identity(parsed, k, id_, "<worker>", fmt::format("line {}", i));
  take(*parsed.sweep_case, true);
}

bool TopologySweepJob::read(const std::string& line, const std::string& file, long number) {
  pending_ = parse_topology_line(line, file, number, claim_ids_);
  return pending_.summary.has_value();
}

void TopologySweepJob::take_read_back(const std::string&, long k, const std::string& file, long number) {
  // parse_topology_line checked the digest and the canonical form: the line is the one this
  // sweep writes for its case once it is the case expected.
  check_topology_case_identity(pending_, k, id_, file, fmt::format("line {}", number));
  take(*pending_.sweep_case, false);
}

void TopologySweepJob::take_merged(long k, const std::string& file, const std::string& where) {
  check_topology_case_identity(pending_, k, id_, file, where);
  take(*pending_.sweep_case, true);
}

const TopologySweepReport& TopologySweepJob::report() const {
  if (!report_) report_ = finish_topology_sweep(configurations_, tally_);
  return *report_;
}

std::string TopologySweepJob::summary_line(const Shard& shard) const {
  return topology_summary_line(report(), id_, shard, status_(report()));
}

TopologyBatchResult run_topology_sweep(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                       const TopologyBatchOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  // Before the run: a directory that cannot be made fails now, not after the last case.
  if (!o.scenes_dir.empty()) create_scene_directory(o.scenes_dir);
  TopologySweepJob job(scene, claims, o.id, o.status);
  TopologyBatchResult result;
  static_cast<BatchRun&>(result) = run_batch(job, o, shard_case_numbers(o.id.count, o.shard));
  result.report = job.report();
  if (result.status == BatchRun::Status::Complete && !o.scenes_dir.empty())
    write_counterexample_scenes(o.scenes_dir, result.report);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

bool is_topology_summary_line(const std::string& line) {
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  return j.is_object() && j.contains("summary") && j["summary"].is_object() &&
         j["summary"].value("mode", "") == "topology_sweep";
}

TopologyBatchResult merge_topology_files(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                         TopologySweepIdentity& id, const std::vector<std::string>& files,
                                         const std::string& out, const std::string& scenes_dir,
                                         const TopologySweepStatus& status) {
  const auto start = std::chrono::steady_clock::now();
  if (!scenes_dir.empty()) create_scene_directory(scenes_dir);
  std::vector<std::string> claim_ids;
  for (const MechanismDataClaim& c : claims) claim_ids.push_back(c.info.id);
  bool first = true;
  const std::vector<std::string> ordered = shard_files_in_order(
      files,
      [&](const std::string& line, const std::string& f) { return parse_topology_line(line, f, 0, claim_ids).summary; },
      [&](const nlohmann::json& s, const std::string& f) {
        TopologySweepIdentity of;
        const auto text = [&](const char* key) {
          if (!s.contains(key) || !s[key].is_string())
            throw InputError(f, std::string("summary.") + key, "missing or not a string (not a topology sweep's file)");
          return s[key].get<std::string>();
        };
        of.topology = text("topology");
        of.scene_digest = text("scene_digest");
        of.claims_digest = text("claims_digest");
        if (of.scene_digest != id.scene_digest)
          throw InputError(f, "summary.scene_digest",
                           fmt::format("{} is not the digest {} of the scene file given (--topology): a sweep of "
                                       "another scene",
                                       of.scene_digest, id.scene_digest));
        if (of.claims_digest != id.claims_digest)
          throw InputError(f, "summary.claims_digest",
                           fmt::format("{} is not the digest {} of the claim file given (--claims): a sweep of "
                                       "other claims",
                                       of.claims_digest, id.claims_digest));
        if (!s.contains("seed") || !s["seed"].is_number_unsigned())
          throw InputError(f, "summary.seed", "missing or not an unsigned integer");
        of.seed = s["seed"].get<std::uint64_t>();
        if (!s.contains("count") || !s["count"].is_number_integer() || s["count"].get<long>() < 1)
          throw InputError(f, "summary.count", "missing or not a positive integer");
        of.count = s["count"].get<long>();
        const auto arithmetic = parse_arithmetic(text("arithmetic"));
        if (!arithmetic) throw InputError(f, "summary.arithmetic", "unknown arithmetic");
        of.arithmetic = *arithmetic;
        const Shard shard = shard_of_summary(s, f);
        if (first) id = of;
        first = false;
        return std::pair{describe(of), shard};
      });
  TopologySweepJob job(scene, claims, id, status);
  merge_batch_files(job, id.count, ordered, out);
  TopologyBatchResult result;
  result.report = job.report();
  if (!scenes_dir.empty()) write_counterexample_scenes(scenes_dir, result.report);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace linkproof
