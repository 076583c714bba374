#include "report/proof_document.h"

#include <fmt/format.h>

#include <map>

#include "report/number_rich.h"
#include "report/polygon_document.h"
#include "report/statement_tex.h"
#include "report/prove_report.h"

namespace linkproof::report {

namespace {

using nlohmann::json;

std::string str(const json& j, const char* key) {
  if (!j.contains(key)) return "";
  const json& v = j.at(key);
  return v.is_string() ? v.get<std::string>() : v.dump();
}

// What the verdict rests on, from the result's evidence.
std::string proof_basis(const json& r) {
  const std::string verdict = str(r, "verdict");
  std::string basis;
  if (r.contains("counterexample"))
    basis = fmt::format("an exact counterexample at n = {} (found among {} candidates, shrunk in {} steps)",
                        r["counterexample"].value("n", 0), r["counterexample"].value("candidates_tried", 0),
                        r["counterexample"].value("shrink_steps", 0));
  else if (r.contains("samples"))
    basis = fmt::format("{} exact random instances (no symbolic proof)", r.value("samples", 0));
  else if (!str(r, "scope").empty())
    basis = "symbolic proof for " + str(r, "scope");
  if (r.contains("except") && !r["except"].empty())
    basis += fmt::format(", generic: except where {} factor{} vanish", r["except"].size(),
                         r["except"].size() == 1 ? "" : "s");
  if (r.contains("error")) basis += (basis.empty() ? "" : "; ") + ("error: " + str(r, "error"));
  return basis.empty() ? verdict : basis;
}

Section claim_subsection(const json& r, const DataClaim* claim) {
  const std::string id = str(r, "id");
  Section s{"proof-" + id, id, {}, {}};
  if (claim) {
    Rich statement = plain(claim->info.source + ": ");
    for (Span& x : statement_rich(claim->info.statement)) statement.push_back(std::move(x));
    s.blocks.push_back(paragraph(std::move(statement)));
    if (!claim->info.note.empty()) s.blocks.push_back(paragraph(plain("Note: " + claim->info.note)));
  }
  s.blocks.push_back(paragraph(plain(fmt::format("Verdict: {} (expected: {}{}); rests on {}.", str(r, "verdict"),
                                                 str(r, "expected"), r.value("as_expected", false) ? ", as expected" : ", NOT as expected",
                                                 proof_basis(r)))));
  if (r.contains("argument") && !r["argument"].empty()) {
    std::vector<Rich> steps;
    for (const auto& a : r["argument"]) steps.push_back(plain(a.get<std::string>()));
    s.blocks.push_back(paragraph(plain("The argument, step by step:")));
    s.blocks.push_back(list_block(std::move(steps)));
  }
  if (r.contains("not_local") && !r["not_local"].empty()) {
    std::vector<Rich> why;
    for (const auto& a : r["not_local"]) why.push_back(plain(a.get<std::string>()));
    s.blocks.push_back(paragraph(plain("No proof for every n, because:")));
    s.blocks.push_back(list_block(std::move(why)));
  }
  if (r.contains("except") && !r["except"].empty()) {
    Table t{{plain("factor of a denominator"), plain("meaning")}, {}};
    for (const auto& e : r["except"]) t.rows.push_back({plain(str(e, "polynomial") + " = 0"), plain(str(e, "meaning"))});
    s.blocks.push_back(paragraph(plain(std::string("Exceptional set: the proof divides by these factors; the claim holds "
                                                   "generically, except where one vanishes (coordinates: ") +
                                       kProofCoordinates + ").")));
    s.blocks.push_back(table_block(std::move(t)));
  }
  if (r.contains("per_n") && !r["per_n"].empty()) {
    Table t{{plain("n"), plain("proved"), plain("monomials"), plain("tree size"), plain("DAG size"), plain("seconds"),
             plain("first non-zero")},
            {}};
    for (const auto& p : r["per_n"])
      t.rows.push_back({plain(str(p, "n")), plain(str(p, "proved")), plain(str(p, "monomials")), plain(str(p, "tree_size")),
                        plain(str(p, "dag_size")), plain(fmt::format("{:.3f}", p.value("seconds", 0.0))),
                        plain(str(p, "first_nonzero"))});
    s.blocks.push_back(paragraph(plain("Per-n proofs (symbolic coordinates, every coefficient of lhs − rhs):")));
    s.blocks.push_back(table_block(std::move(t)));
  }
  return s;
}

}  // namespace

Document build_proof_document(const ClaimFile& file, const std::vector<ProofResult>& results) {
  Document d;
  d.title = "Proof report: " + file.source;
  d.subtitle = "claims proved in symbolic coordinates or disproved by exact counterexamples; linkproof";
  std::map<std::string, const DataClaim*> claims;
  for (const auto& c : file.claims) claims[c.info.id] = &c;

  Section summary{"summary", "Summary", {}, {}};
  Table t{{plain("claim"), plain("expected"), plain("verdict"), plain("rests on")}, {}};
  int as_expected = 0;
  for (const auto& r : results) {
    const json j = to_json(r, r.is_as_expected());
    as_expected += j.value("as_expected", false) ? 1 : 0;
    t.rows.push_back({plain(str(j, "id")), plain(str(j, "expected")),
                      plain(str(j, "verdict") + (j.value("as_expected", false) ? "" : " (NOT as expected)")),
                      plain(proof_basis(j))});
  }
  summary.blocks.push_back(paragraph(plain(fmt::format("{} of {} claims as expected. Coordinates of the proofs: {}.",
                                                       as_expected, results.size(), kProofCoordinates))));
  summary.blocks.push_back(table_block(std::move(t)));
  d.sections.push_back(std::move(summary));

  Section proof{"proof", "Proofs", {}, {}};
  Section counter{"counterexamples", "Counterexamples", {}, {}};
  for (size_t k = 0; k < results.size(); ++k) {
    const json j = to_json(results[k], results[k].is_as_expected());
    const auto it = claims.find(results[k].id);
    proof.subsections.push_back(claim_subsection(j, it == claims.end() ? nullptr : it->second));
    if (!results[k].counterexample) continue;
    const Counterexample& c = *results[k].counterexample;
    Section sub{"counterexample-" + results[k].id, results[k].id, {}, {}};
    Table diff{{plain("comparison"), plain("lhs"), plain("rhs"), plain("residual")}, {}};
    for (const auto& e : j["counterexample"]["differing"])
      diff.rows.push_back({plain(str(e, "label")), value_rich(str(e, "lhs")), value_rich(str(e, "rhs")),
                           value_rich(str(e, "residual"))});
    sub.blocks.push_back(paragraph(plain("Where the claim fails on this exact configuration:")));
    sub.blocks.push_back(table_block(std::move(diff)));
    sub.blocks.push_back(figure_block({"counterexample-" + results[k].id,
                                       "The counterexample polygon to scale with its construction (K'_j, Q_j, P'_j, "
                                       "beta_j).",
                                       polygon_construction_drawing(c.polygon),
                                       {text("The counterexample polygon to scale with its construction ("),
                                        math("K'_j, Q_j, P'_j, \\beta_j"), text(").")}}));
    sub.blocks.push_back(paragraph(plain("The scene (`linkproof check` or `linkproof report` reads it):")));
    sub.blocks.push_back(code_block(c.scene_yaml));
    counter.subsections.push_back(std::move(sub));
  }
  d.sections.push_back(std::move(proof));
  if (!counter.subsections.empty()) d.sections.push_back(std::move(counter));
  return d;
}

}  // namespace linkproof::report
