#include "report/topology_sweep_lines.h"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>

#include "linkproof/core/error.h"
#include "report/json_line_fields.h"
#include "report/sweep_lines.h"

namespace linkproof {

using nlohmann::json;

namespace {

std::string string_field(const json& j, const char* key, const std::string& file, const std::string& where) {
  return line_member(j, key, json::value_t::string, file, where).get<std::string>();
}

bool flag(const json& j, const char* key, const std::string& file, const std::string& where) {
  return line_member(j, key, json::value_t::boolean, file, where).get<bool>();
}

}  // namespace

std::string describe(const TopologySweepIdentity& id) {
  return fmt::format("{} (scene digest {}, claims digest {}, seed {}, count {}, {})", id.topology, id.scene_digest,
                     id.claims_digest, id.seed, id.count, to_string(id.arithmetic));
}

json identity_json(const TopologySweepIdentity& id) {
  return {{"topology", id.topology},   {"scene_digest", id.scene_digest}, {"claims_digest", id.claims_digest},
          {"seed", id.seed},           {"count", id.count},               {"arithmetic", std::string(to_string(id.arithmetic))}};
}

std::string topology_case_line(const TopologySweepCase& c, const TopologySweepIdentity& id,
                               const std::vector<std::string>& claim_ids) {
  json verdicts = json::object();
  for (size_t k = 0; k < c.verdicts.size(); ++k) verdicts[claim_ids[k]] = std::string(to_string(c.verdicts[k]));
  json line = identity_json(id);  // an object's keys are written sorted, whatever the order here
  line["case"] = c.index;
  line["singular"] = c.singular;
  line["degenerate"] = c.degenerate;
  line["verdicts"] = verdicts;
  line["digest"] = sweep_line_digest(line.dump());
  return line.dump();
}

TopologySweepLine parse_topology_line(const std::string& line, const std::string& file, long line_number,
                                      const std::vector<std::string>& claim_ids) {
  const std::string where = fmt::format("line {}", line_number);
  json j = parse_line_object(line, file, where);
  TopologySweepLine out;
  if (j.contains("summary")) {
    out.summary = line_member(j, "summary", json::value_t::object, file, where);
    return out;
  }
  check_line_digest(j, line, file, where);
  static const char* const kCaseKeys[] = {"arithmetic", "case",   "claims_digest", "count",    "degenerate", "digest",
                                          "scene_digest", "seed", "singular",      "topology", "verdicts"};
  for (const auto& [key, value] : j.items())
    if (std::find(std::begin(kCaseKeys), std::end(kCaseKeys), key) == std::end(kCaseKeys))
      throw InputError(file, where + "." + key, "is not a field of a case line of a topology sweep");
  TopologySweepIdentity& id = out.identity;
  id.topology = string_field(j, "topology", file, where);
  id.scene_digest = string_field(j, "scene_digest", file, where);
  id.claims_digest = string_field(j, "claims_digest", file, where);
  if (!j.contains("seed") || !j["seed"].is_number_unsigned())
    throw InputError(file, where + ".seed", "missing or not an unsigned integer");
  id.seed = j["seed"].get<std::uint64_t>();
  id.count = line_member(j, "count", json::value_t::number_integer, file, where).get<long>();
  const auto arithmetic = parse_arithmetic(string_field(j, "arithmetic", file, where));
  if (!arithmetic) throw InputError(file, where + ".arithmetic", "unknown arithmetic " + j["arithmetic"].dump());
  id.arithmetic = *arithmetic;
  TopologySweepCase c;
  c.index = line_member(j, "case", json::value_t::number_integer, file, where).get<long>();
  if (c.index < 0 || id.count < 1 || c.index >= id.count) throw InputError(file, where, "case or count out of range");
  c.singular = flag(j, "singular", file, where);
  c.degenerate = flag(j, "degenerate", file, where);
  const json& verdicts = line_member(j, "verdicts", json::value_t::object, file, where);
  for (const auto& [claim, v] : verdicts.items())
    if (std::find(claim_ids.begin(), claim_ids.end(), claim) == claim_ids.end())
      throw InputError(file, where + ".verdicts." + claim, "a verdict of an unknown claim (not a claim of this sweep)");
  if (c.singular) {
    if (!verdicts.empty() || c.degenerate)
      throw InputError(file, where + ".verdicts", "a singular configuration has no verdicts and is not degenerate");
  } else {
    for (const std::string& claim : claim_ids) {
      const auto v = verdicts.find(claim);
      if (v == verdicts.end()) throw InputError(file, where + ".verdicts", "has no verdict of " + claim);
      c.verdicts.push_back(line_verdict(*v, file, where + ".verdicts." + claim));
      if (c.verdicts.back() == Verdict::Error)
        throw InputError(file, where + ".verdicts." + claim, "a topology sweep has no verdict error");
    }
    if (c.degenerate && std::find(c.verdicts.begin(), c.verdicts.end(), Verdict::Fails) == c.verdicts.end())
      throw InputError(file, where + ".degenerate", "only a configuration on which a claim fails is degenerate");
  }
  out.sweep_case = std::move(c);
  return out;
}

void check_topology_case_identity(const TopologySweepLine& line, long expected, const TopologySweepIdentity& id,
                                  const std::string& file, const std::string& where) {
  const TopologySweepIdentity& l = line.identity;
  const char* field = l.topology != id.topology             ? "topology"
                      : l.scene_digest != id.scene_digest   ? "scene_digest"
                      : l.claims_digest != id.claims_digest ? "claims_digest"
                      : l.seed != id.seed                   ? "seed"
                      : l.count != id.count                 ? "count"
                      : l.arithmetic != id.arithmetic       ? "arithmetic"
                      : line.sweep_case->index != expected  ? "case"
                                                            : nullptr;
  if (field == nullptr) return;
  throw InputError(file, where + "." + field,
                   fmt::format("case {} of the sweep of {} is not the next case of this sweep, which is case {} of "
                               "the sweep of {}: the file belongs to another sweep or shard",
                               line.sweep_case->index, describe(l), expected, describe(id)));
}

}  // namespace linkproof
