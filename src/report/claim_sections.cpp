// The sections every claim-checking report shares: summary table, term-by-term tables, errata.
#include <fmt/format.h>

#include <map>

#include "report/comparison_text.h"
#include "report/number_rich.h"
#include "report/statement_tex.h"
#include "report/polygon_document.h"

namespace linkproof::report {

namespace {
std::string s(std::string_view v) { return std::string(v); }

// A comparison's value as a report shows it (report/number_rich.h); empty where there is none.
Rich value_cell(const std::optional<ResultNumber>& x) { return x ? number_rich(*x) : plain(""); }

// "lhs  vs  rhs" of a comparison, each value with its decimal.
Rich versus(const ComparisonOutcome& c) {
  Rich r = value_cell(c.lhs);
  r.push_back(text("  vs  "));
  for (const Span& x : value_cell(c.rhs)) r.push_back(x);
  return r;
}
}  // namespace

std::string verdict_basis(const ClaimOutcome& c, Arithmetic a) {
  const ComparisonOutcome& h = c.headline;
  switch (c.verdict) {
    case Verdict::Undefined:
      return "undefined: " + h.undefined_quantity + (h.reason.empty() ? "" : " (" + h.reason + ")");
    case Verdict::Error: return "error: " + (c.error.empty() ? h.reason : c.error);
    default: break;
  }
  const std::string where = h.label.empty() ? "" : " at " + h.label;
  const size_t compared = c.instances.size() + c.terms.size();
  if (a == Arithmetic::Exact)
    return fmt::format("exact instance (rational arithmetic): residual {}{} ({} comparison{})",
                       residual_text(h, NumberStyle::Readable), where,
                       compared, compared == 1 ? "" : "s");
  std::string basis = fmt::format("floating point ({}): |residual| {} against the derived bound {}{}", s(to_string(a)),
                                  residual_text(h), tolerance_text(h), where);
  if (const std::string r = reason_text(h); !r.empty()) basis += "; " + r;
  return basis;
}

std::vector<Rich> claims_at_a_glance(const std::vector<ClaimOutcome>& claims) {
  int true_total = 0, true_held = 0, errata = 0, errata_failed = 0, errata_coincide = 0;
  std::vector<std::string> not_as_expected;
  for (const auto& c : claims) {
    if (c.info.expected == Expectation::Holds) {
      ++true_total;
      true_held += c.verdict == Verdict::Holds;
    } else {
      ++errata;
      errata_failed += c.verdict == Verdict::Fails;
      errata_coincide += c.verdict == Verdict::Holds;
    }
    if (!c.is_as_expected()) not_as_expected.push_back(c.info.id);
  }
  std::vector<Rich> items;
  if (claims.empty()) return items;
  if (true_total > 0)
    items.push_back(plain(fmt::format("{} of {} true claim{} hold{}", true_held, true_total, true_total == 1 ? "" : "s",
                                      true_held == 1 && true_total == 1 ? "s" : "")));
  if (errata > 0)
    items.push_back(plain(fmt::format("{} of {} erratum reading{} fail, as expected{}", errata_failed, errata,
                                      errata == 1 ? "" : "s",
                                      errata_coincide == 0 ? ""
                                                           : fmt::format(" ({} coincide{} with the truth on this scene)",
                                                                         errata_coincide, errata_coincide == 1 ? "s" : ""))));
  if (not_as_expected.empty()) {
    items.push_back(plain(fmt::format("all {} claim{} as expected", claims.size(), claims.size() == 1 ? "" : "s")));
  } else {
    std::string ids;
    for (const auto& id : not_as_expected) ids += (ids.empty() ? "" : ", ") + id;
    items.push_back(plain(fmt::format("{} NOT as expected: {}", not_as_expected.size(), ids)));
  }
  return items;
}

Table claim_summary_table(const std::vector<ClaimOutcome>& claims, Arithmetic a) {
  Table t{{plain("claim"), plain("source"), plain("expected"), plain("verdict"), plain("rests on")}, {}};
  for (const auto& c : claims)
    t.rows.push_back({plain(c.info.id), plain(c.info.source), plain(s(to_string(c.info.expected))),
                      plain(s(to_string(c.verdict)) + (c.is_as_expected() ? "" : " (NOT as expected)")),
                      plain(verdict_basis(c, a))});
  return t;
}

Section terms_section(const std::vector<ClaimOutcome>& claims) {
  Section sec{"terms", "Term by term", {}, {}};
  sec.blocks.push_back(paragraph(
      plain("Each identity that is a polynomial in the input rates is compared coefficient by coefficient: the "
            "engine's exact coefficient (from the differentiated loop closure) against the formula's. A wrong term "
            "is named, not only a wrong total.")));
  for (const auto& c : claims) {
    if (c.terms.empty()) continue;
    Table t{{plain("monomial"), plain("engine (exact)"), plain("formula"), plain("residual"), plain("verdict")}, {}};
    for (const auto& term : c.terms)
      t.rows.push_back({term_label_rich(term.label), value_cell(term.lhs), value_cell(term.rhs), value_cell(term.residual),
                        plain(s(to_string(term.verdict)))});
    Section sub{"terms-" + c.info.id, c.info.id + ": " + c.info.source, {}, {}};
    sub.blocks.push_back(paragraph(statement_rich(c.info.statement)));
    sub.blocks.push_back(table_block(std::move(t)));
    sec.subsections.push_back(std::move(sub));
  }
  return sec;
}

Section errata_section(const std::vector<ClaimOutcome>& claims, const std::string& scene_text) {
  Section sec{"errata", "Errata", {}, {}};
  std::map<std::string, const ClaimOutcome*> by_id;
  for (const auto& c : claims) by_id[c.info.id] = &c;
  bool any_fails_here = false;
  for (const auto& c : claims) {
    if (c.info.expected != Expectation::Fails) continue;
    // The corrected form: the claim named by the erratum's id without its last ".reading", else
    // the first claim expected to hold under that same prefix (koshel.eq15.superposition
    // beside koshel.eq15.rescaling).
    const auto dot = c.info.id.rfind('.');
    const ClaimOutcome* ok = nullptr;
    if (dot != std::string::npos) {
      const std::string prefix = c.info.id.substr(0, dot);
      if (const auto it = by_id.find(prefix); it != by_id.end()) ok = it->second;
      for (const auto& other : claims)
        if (!ok && other.info.expected == Expectation::Holds && other.info.id.rfind(prefix + ".", 0) == 0) ok = &other;
    }
    Table t{{plain(""), plain("as printed / misread"), plain("corrected")}, {}};
    t.rows.push_back({plain("claim"), plain(c.info.id), plain(ok ? ok->info.id : "(no corrected claim)")});
    t.rows.push_back({plain("statement"), statement_rich(c.info.statement), ok ? statement_rich(ok->info.statement) : plain("")});
    t.rows.push_back({plain("verdict here"), plain(s(to_string(c.verdict))), plain(ok ? s(to_string(ok->verdict)) : "")});
    t.rows.push_back({plain("lhs vs rhs"), versus(c.headline), ok ? versus(ok->headline) : plain("")});
    Section sub{"erratum-" + c.info.id, c.info.id, {}, {}};
    if (!c.info.note.empty()) sub.blocks.push_back(paragraph(plain(c.info.note)));
    sub.blocks.push_back(table_block(std::move(t)));
    if (c.verdict == Verdict::Fails) {
      any_fails_here = true;
      sub.blocks.push_back(paragraph(plain("This scene is a counterexample: the reading fails here (residual " +
                                           residual_text(c.headline, NumberStyle::Readable) + " at " +
                                           c.headline.label + ").")));
    } else {
      sub.blocks.push_back(paragraph(plain("On this scene the reading does not fail (" + s(to_string(c.verdict)) +
                                           "): it coincides with the truth here, which says nothing for it in general.")));
    }
    sec.subsections.push_back(std::move(sub));
  }
  if (sec.subsections.empty()) return sec;
  sec.blocks.push_back(paragraph(plain(
      "Each erratum reading (the paper's printed form or a tempting misreading, docs/conventions.md §A5) is shown beside the corrected "
      "claim, evaluated on the same scene.")));
  if (any_fails_here && !scene_text.empty()) {
    sec.blocks.push_back(paragraph(plain("The counterexample scene (run `linkproof check` on it):")));
    sec.blocks.push_back(code_block(scene_text));
  }
  return sec;
}

}  // namespace linkproof::report
