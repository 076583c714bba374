#include "report/sweep_lines.h"

#include <algorithm>
#include <cstdint>
#include <iterator>

#include <fmt/format.h>

#include "linkproof/core/error.h"
#include "report/json_line_fields.h"
#include "report/json_report.h"

namespace linkproof {

using nlohmann::json;

namespace {

std::string text(const json& j, const char* key, const std::string& file, const std::string& where) {
  return line_member(j, key, json::value_t::string, file, where).get<std::string>();
}

std::string optional_text(const json& j, const char* key, const std::string& file, const std::string& where) {
  return j.contains(key) ? text(j, key, file, where) : std::string();
}

}  // namespace

std::string sweep_line_digest(const std::string& canonical_line) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a, 64 bits
  for (unsigned char c : canonical_line) h = (h ^ c) * 0x100000001b3ULL;
  return fmt::format("{:016x}", h);
}

std::string sweep_case_line(const SweepCase& c, Arithmetic arithmetic) {
  json verdicts = json::object();
  for (const auto& [id, v] : c.verdicts) verdicts[id] = std::string(to_string(v));
  json examples = json::array();
  for (const auto& e : c.examples) {
    json x{{"claim", e.claim_id}, {"verdict", std::string(to_string(e.verdict))}, {"evidence", evidence_json(e)}};
    if (!e.error.empty()) x["error"] = e.error;
    examples.push_back(std::move(x));
  }
  const RandomPolygonCase& p = c.polygon;
  json line{{"case", c.k},          {"seed", p.seed},       {"n", p.n},
            {"index", p.index},     {"family", p.family},   {"arithmetic", std::string(to_string(arithmetic))},
            {"verdicts", verdicts}, {"examples", examples}, {"not_applicable", c.not_applicable}};
  line["digest"] = sweep_line_digest(line.dump());
  return line.dump();
}

std::string sweep_summary_line(const SweepReport& report, const Shard& shard, int exit_status) {
  json s = to_json(report, exit_status);
  s.erase("seconds");  // the only field that differs between equal runs
  if (!shard.whole()) s["shard"] = fmt::format("{}/{}", shard.k, shard.n);
  return json{{"summary", s}}.dump();
}

void check_evidence_json(const json& j, const std::string& file, const std::string& field) {
  if (!j.is_object()) throw InputError(file, field, "must be an object");
  text(j, "label", file, field);
  const Verdict v = line_verdict(line_member(j, "verdict", json::value_t::string, file, field), file, field + ".verdict");
  for (const char* key : {"undefined_quantity", "reason", "tolerance_derivation", "trust_route", "inconclusive_side",
                          "inconclusive_quantity"})
    optional_text(j, key, file, field);
  if (v == Verdict::Undefined || v == Verdict::Error) return;
  for (const char* key : {"lhs", "rhs", "residual"}) text(j, key, file, field);
  if (!optional_text(j, "tolerance", file, field).empty()) {
    const auto& b = j.find("relative_error_bound");
    if (b == j.end() || !b->is_number()) throw InputError(file, field + ".relative_error_bound", "missing or not a number");
  }
}

SweepLine parse_sweep_line(const std::string& line, const std::string& file, long line_number) {
  const std::string where = fmt::format("line {}", line_number);
  json j = parse_line_object(line, file, where);
  SweepLine out;
  if (j.contains("summary")) {
    out.summary = line_member(j, "summary", json::value_t::object, file, where);
    return out;
  }
  // The digest first: an edited line is reported as edited, whatever else it breaks.
  check_line_digest(j, line, file, where);
  static const char* const kCaseKeys[] = {"arithmetic", "case",    "digest", "examples",       "family",
                                          "index",      "n",       "seed",   "not_applicable", "verdicts"};
  for (const auto& [key, value] : j.items())
    if (std::find(std::begin(kCaseKeys), std::end(kCaseKeys), key) == std::end(kCaseKeys))
      throw InputError(file, where + "." + key, "is not a field of a case line");
  const json& seed = j.find("seed") != j.end() && j["seed"].is_number_unsigned() ? j["seed"] : json();
  if (seed.is_null()) throw InputError(file, where + ".seed", "missing or not an unsigned integer");
  const long k = line_member(j, "case", json::value_t::number_integer, file, where).get<long>();
  const int n = line_member(j, "n", json::value_t::number_integer, file, where).get<int>();
  const int index = line_member(j, "index", json::value_t::number_integer, file, where).get<int>();
  if (k < 0 || n < 4 || n > 200 || index < 0) throw InputError(file, where, "case, n or index out of range");
  const auto arithmetic = parse_arithmetic(text(j, "arithmetic", file, where));
  if (!arithmetic) throw InputError(file, where + ".arithmetic", "unknown arithmetic " + j["arithmetic"].dump());
  out.arithmetic = *arithmetic;
  SweepCase c;
  c.k = k;
  c.polygon = generate_random_polygon(seed.get<std::uint64_t>(), n, index);
  if (text(j, "family", file, where) != c.polygon.family)
    throw InputError(file, where + ".family", "does not match the polygon generated from seed, n and index");
  for (const auto& [id, v] : line_member(j, "verdicts", json::value_t::object, file, where).items())
    c.verdicts[id] = line_verdict(v, file, where + ".verdicts." + id);
  for (const auto& id : line_member(j, "not_applicable", json::value_t::array, file, where)) {
    if (!id.is_string()) throw InputError(file, where + ".not_applicable", "must hold claim ids");
    c.not_applicable.push_back(id.get<std::string>());
  }
  const json& examples = line_member(j, "examples", json::value_t::array, file, where);
  for (size_t i = 0; i < examples.size(); ++i) {
    const std::string at = fmt::format("{}.examples[{}]", where, i);
    const json& x = examples[i];
    if (!x.is_object()) throw InputError(file, at, "must be an object");
    SweepExample e;
    e.claim_id = text(x, "claim", file, at);
    e.verdict = line_verdict(line_member(x, "verdict", json::value_t::string, file, at), file, at + ".verdict");
    e.polygon = c.polygon;
    const json& evidence = line_member(x, "evidence", json::value_t::object, file, at);
    check_evidence_json(evidence, file, at + ".evidence");
    e.recorded_evidence = evidence.dump();
    e.error = optional_text(x, "error", file, at);
    const auto v = c.verdicts.find(e.claim_id);
    if (v == c.verdicts.end() || v->second != e.verdict)
      throw InputError(file, at, "the example's verdict is not the case's verdict of " + e.claim_id);
    c.examples.push_back(std::move(e));
  }
  out.sweep_case = std::move(c);
  return out;
}

}  // namespace linkproof
