#include "report/text_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "io/sweep_scene.h"
#include "report/comparison_text.h"
#include "report/json_report.h"
#include "report/number_text.h"

namespace linkproof {

namespace {

/// A floating-point decimal of the mp arithmetics can have ~1000 digits: tables show its first
/// 22 characters, "...", and the exponent. Exact "p/q" (no '.') and the JSON are never cut.
std::string readable(const std::string& s) {
  if (s.find('.') == std::string::npos) return s;
  const size_t e = s.find_first_of("eE");
  const size_t mantissa = e == std::string::npos ? s.size() : e;
  if (mantissa <= 26) return s;
  return s.substr(0, 22) + "..." + s.substr(mantissa);
}

/// An exact value with its decimal beside it (report/number_text.h); a float as `readable` shows it.
std::string value_text(const ResultNumber& v, int digits) {
  return is_exact(v) ? readable_number(v, digits) : readable(number_text(v));
}

std::string value_or_undefined(const std::optional<ResultNumber>& v, int digits) {
  return v ? value_text(*v, digits) : "undefined";
}

std::string optional_text(const std::optional<ResultNumber>& v) { return v ? number_text(*v) : ""; }

std::string member_text(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : "";
}

// A comparison's evidence on one line, from its JSON form (to_json), so that evidence read back
// from a result file prints as a fresh one does.
std::string evidence(const nlohmann::json& j) {
  const std::string verdict = member_text(j, "verdict"), reason = member_text(j, "reason");
  if (verdict == to_string(Verdict::Undefined)) return member_text(j, "undefined_quantity") + " undefined: " + reason;
  if (verdict == to_string(Verdict::Error)) return reason;
  const std::string label = member_text(j, "label"), tolerance = member_text(j, "tolerance");
  std::string s = fmt::format("{} = {}  vs  {}", label.empty() ? "value" : label, readable(member_text(j, "lhs")),
                              readable(member_text(j, "rhs")));
  if (verdict == to_string(Verdict::Fails) || !tolerance.empty()) s += "  residual " + readable(member_text(j, "residual"));
  if (!tolerance.empty()) s += "  tol " + tolerance;
  if (!reason.empty()) s += "  (" + reason + ")";
  if (const std::string t = member_text(j, "trust_route"); !t.empty()) s += "  trust: " + t;
  return s;
}

std::string evidence(const ComparisonOutcome& c) { return evidence(to_json(c)); }

}  // namespace

void write_text(std::ostream& out, const PolygonCheck& c, const ClaimsStatus& status, bool show_terms, int digits) {
  LINKPROOF_ASSERT(status.as_expected.size() == c.claims.size(), "one status per claim");
  fmt::print(out, "linkproof check: {} (n = {}, {} arithmetic)\n", c.scene, c.n, to_string(c.arithmetic));
  if (c.dead_centre) {
    fmt::print(out, "DEAD CENTRE: D = r_{} x r_{} = 0: {}\n", c.n - 2, c.n - 1, c.dead_centre_reason);
    fmt::print(out, "The ground truth does not exist here; every claim is undefined.\n");
  }
  if (c.ask) {
    fmt::print(out, "asked (the scene's `ask`; nothing else computed): {}\n", fmt::join(c.ask->describe(), "; "));
    if (!c.ask->rates.empty()) fmt::print(out, "asked rates (loop closure, solved exactly), relative to side {}:\n", c.n);
    for (const AskedRate& r : c.ask->rates) {
      const size_t j = static_cast<size_t>(std::stoi(r.subject.name) - 1);
      fmt::print(out, "  {:<16} = {}\n", r.text(), value_or_undefined((r.dot ? c.omega_dot : c.omega)[j], digits));
    }
  } else {
    fmt::print(out, "ground truth (loop closure, solved exactly), relative to side {}:\n", c.n);
    for (int j = 0; j < c.n; ++j)
      fmt::print(out, "  side {:>2}: omega = {:<24} omega-dot = {}\n", j + 1, value_or_undefined(c.omega[j], digits),
                 value_or_undefined(c.omega_dot[j], digits));
  }
  fmt::print(out, "D = r_{} x r_{} = {}\n\n", c.n - 2, c.n - 1, value_text(c.determinant, digits));

  if (!c.claims.empty() || !c.ask) fmt::print(out, "{:<34} {:<9} {:<13} {}\n", "claim", "expected", "verdict", "evidence");
  int unexpected = 0, not_as_expected = 0, erratum_failed = 0, erratum_total = 0, true_held = 0, true_total = 0;
  for (size_t k = 0; k < c.claims.size(); ++k) {
    const ClaimOutcome& cl = c.claims[k];
    std::string mark = status.as_expected[k] ? "" : "  <-- UNEXPECTED";
    not_as_expected += !status.as_expected[k];
    if (cl.info.expected == Expectation::Fails && cl.verdict == Verdict::Holds)
      mark = "  (this misreading coincides with the truth on this configuration)";
    fmt::print(out, "{:<34} {:<9} {:<13} {}{}\n", cl.info.id, to_string(cl.info.expected), to_string(cl.verdict),
               cl.error.empty() ? evidence(cl.headline) : cl.error, mark);
    if (cl.is_unexpected_failure()) ++unexpected;
    if (cl.info.expected == Expectation::Holds) {
      ++true_total;
      true_held += cl.verdict == Verdict::Holds;
    } else {
      ++erratum_total;
      erratum_failed += cl.verdict == Verdict::Fails;
    }
  }
  if (show_terms) {
    for (const auto& cl : c.claims) {
      if (cl.terms.empty() || cl.info.expected != Expectation::Holds) continue;
      fmt::print(out, "\nterm by term, {} (engine's exact coefficient vs the formula's):\n", cl.info.id);
      for (const auto& t : cl.terms) {
        if (t.verdict == Verdict::Undefined)
          fmt::print(out, "  {:<22} {:<13} {} undefined: {}\n", t.label, to_string(t.verdict), t.undefined_quantity,
                     t.reason);
        else
          fmt::print(out, "  {:<22} {:<13} {:<24} {}\n", t.label, to_string(t.verdict), readable(optional_text(t.lhs)), readable(optional_text(t.rhs)));
      }
    }
  }
  if (!c.not_applicable.empty()) {
    fmt::print(out, "\nnot applicable at n = {}:", c.n);
    for (const auto& id : c.not_applicable) fmt::print(out, " {}", id);
    fmt::print(out, "\n");
  }
  fmt::print(out, "\nverdict rule: {}\n", tolerance_rule(c.arithmetic));
  fmt::print(out, "summary: {}/{} true claims hold, {}/{} erratum readings fail here, {} unexpected failure(s), {} not as "
             "expected{}\n",
             true_held, true_total, erratum_failed, erratum_total, unexpected, not_as_expected,
             status.strict ? " (strict: undefined or inconclusive on a true claim counts)" : "");
}

void write_text(std::ostream& out, const SweepReport& s) {
  const auto& o = s.options;
  fmt::print(out, "linkproof sweep: n = {}..{}, {} per n, seed {}, {} arithmetic: {} polygons in {:.2f} s\n",
             o.n_min, o.n_max, o.only_index ? 1 : o.count, o.seed, to_string(o.arithmetic), s.cases, s.seconds);
  fmt::print(out, "{:<34} {:<9} {:>7} {:>7} {:>9} {:>12} {:>6} {:>6}\n", "claim", "expected", "holds", "fails",
             "undefined", "inconclusive", "error", "n/a");
  for (const auto& t : s.tallies)
    fmt::print(out, "{:<34} {:<9} {:>7} {:>7} {:>9} {:>12} {:>6} {:>6}\n", t.id, to_string(t.expected), t.holds,
               t.fails, t.undefined, t.inconclusive, t.error, t.not_applicable);
  for (const auto& t : s.tallies)
    if (t.expected == Expectation::Fails && t.fails == 0 && t.total() > 0)
      fmt::print(out, "note: erratum reading {} never failed in this sweep\n", t.id);
  if (s.unexpected.empty()) {
    fmt::print(out, "\nevery claim expected to hold held or was undefined/inconclusive\n");
  } else {
    fmt::print(out, "\nUNEXPECTED: {} case(s) where a claim expected to hold did not:\n", s.unexpected.size());
    for (const auto& e : s.unexpected) {
      fmt::print(out, "- {} {} on n = {}, index {} ({}): {}\n", e.claim_id, to_string(e.verdict), e.polygon.n,
                 e.polygon.index, e.polygon.family, e.error.empty() ? evidence(evidence_json(e)) : e.error);
      fmt::print(out, "  replay: linkproof sweep --n {} --seed {} --index {}\n", e.polygon.n, o.seed, e.polygon.index);
      fmt::print(out, "  scene (exact):\n{}", sweep_scene_yaml(e.polygon));
    }
  }
  fmt::print(out, "\nverdict rule: {}\n", tolerance_rule(o.arithmetic));
}

}  // namespace linkproof
