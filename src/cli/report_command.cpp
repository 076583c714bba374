// linkproof report SCENE|CLAIMS [--format html|md|tex|all] [--out DIR] [--claim ID]... [--n N]
//                  [--ladder-seconds S] [--arith A] [--numerics] [--plans] [--katex DIR]
// A derivation report (report/document.h) of a polygon scene, a mechanism scene, or a claim
// file (the claims proved, report/proof_document.h), written to DIR as <stem>.html (one
// self-contained file), <stem>.md (+ SVG figures beside it) or <stem>.tex.
// Exit code: that of check / prove on the same input (0 as expected, 1 a claim failed, 3 error),
// 2 for bad input.
#include <fmt/format.h>
#include <fmt/ostream.h>

#include <filesystem>
#include <optional>
#include <regex>

#include "build_info.h"
#include "command.h"
#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "report/dimensioned_bound_report.h"
#include "report/scene_placement_report.h"
#include "linkproof/io/scene.h"
#include "report/atomic_file.h"
#include "report/mechanism_document.h"
#include "report/polygon_document.h"
#include "report/proof_document.h"
#include "report/prove_report.h"
#include "report/render.h"
#include "mechanism_catalogues.h"

namespace linkproof::cli {

namespace {

struct ReportArgs {
  std::string input;
  std::string format = "html";
  std::string out = ".";
  std::vector<std::string> claims;
  std::optional<int> n;
  std::optional<double> ladder_seconds;  // given: per-n proofs also re-check claims proved for every n
  std::optional<std::string> arith;  // polygon scenes; default: the scene's ask, else exact
  bool numerics = false;
  bool plans = false;
  std::string katex = "/usr/share/javascript/katex";
};

// The command line that reproduces the report (options at their defaults are left out).
std::string command_line(const ReportArgs& a) {
  std::string c = "linkproof report " + a.input + " --format " + a.format;
  if (a.out != ".") c += " --out " + a.out;
  for (const auto& id : a.claims) c += " --claim " + id;
  if (a.n) c += " --n " + std::to_string(*a.n);
  if (a.ladder_seconds) c += fmt::format(" --ladder-seconds {}", *a.ladder_seconds);
  if (a.arith) c += " --arith " + *a.arith;
  if (a.numerics) c += " --numerics";
  if (a.plans) c += " --plans";
  return c;
}

// Renders every asked format in memory, then writes all the files or none
// (write_files_atomically): a failure leaves no half of a report behind. Every file name is a
// file_stem (report/escape.h): inside `--out`, whatever the input's or the scene's name holds.
void write_document(const ReportArgs& a, const report::Document& d, std::ostream& out, std::ostream& err) {
  namespace fs = std::filesystem;
  const fs::path dir(a.out);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(a.out, "--out", "cannot create the directory: " + ec.message());
  const std::string stem = report::file_stem(fs::path(a.input).stem().string());
  const bool all = a.format == "all";
  std::vector<OutputFile> files;
  if (all || a.format == "html") {
    const auto katex = report::load_katex_assets(a.katex);
    if (!katex)
      fmt::print(err,
                 "linkproof: warning: KaTeX not found in {} (Debian package libjs-katex); the HTML shows TeX source\n",
                 a.katex);
    files.push_back({dir / (stem + ".html"), report::render_html(d, katex)});
  }
  if (all || a.format == "md") {
    std::map<std::string, std::string> figures;
    files.push_back({dir / (stem + ".md"), report::render_markdown(d, figures)});
    for (auto& [name, svg] : figures) files.push_back({dir / name, std::move(svg)});
  }
  if (all || a.format == "tex") files.push_back({dir / (stem + ".tex"), report::render_latex(d)});
  write_files_atomically(files, "--out");
  for (const auto& f : files) fmt::print(out, "wrote {}\n", f.path.string());
}

report::Reproduce reproduce_of(const ReportArgs& a, std::string seed) {
  return {command_line(a), std::move(seed), LINKPROOF_VERSION, LINKPROOF_GIT_COMMIT};
}

int report_claim_file(const ReportArgs& a, const std::string& text, std::ostream& out, std::ostream& err) {
  const ClaimFile file = parse_user_claim_file(text, a.input);
  ProveOptions o;
  check_prove_limits(a.n, a.ladder_seconds.value_or(o.ladder_seconds));
  const std::vector<const DataClaim*> chosen = choose_claims(file, a.claims);
  o.only_n = a.n;
  set_ladder(o, a.ladder_seconds, false);
  GroundTruthEngine engine;
  std::vector<ProofResult> results;
  for (const DataClaim* c : chosen)
    if (!a.n || c->info.applies_to(*a.n)) results.push_back(prove_claim(engine, *c, o));
  if (results.empty()) throw InputError("<command line>", "--n", "no chosen claim applies to n = " + std::to_string(*a.n));
  report::Document d = report::build_proof_document(file, results);
  d.reproduce = reproduce_of(a, std::to_string(o.search.seed) + " (counterexample search)");
  report::add_reproduce_section(d);
  write_document(a, d, out, err);
  return exit_status(results);
}

int report_mechanism(const ReportArgs& a, const std::string& text, std::ostream& out, std::ostream& err) {
  const MechanismScene scene = parse_mechanism_scene(text, a.input);
  // A scene given by dimensions runs on rationalised positions: said, never silent.
  if (const std::string note = rationalised_statement(scene); !note.empty())
    err << "linkproof: note: " << a.input << ": " << note << " (docs/mechanisms.md)\n";
  const MechanismCheck check = check_mechanism(scene, catalogues::mechanism_catalogues(scene), Arithmetic::Exact);
  if (check.dimensioned) err << "linkproof: note: " << a.input << ": " << dimensioned_bound_summary(*check.dimensioned) << "\n";
  report::Document d = report::build_mechanism_document(scene, check, {a.plans, text});
  d.reproduce = reproduce_of(a, "none (deterministic)");
  report::add_reproduce_section(d);
  write_document(a, d, out, err);
  return exit_status(check.claims);
}

int report_polygon(const ReportArgs& a, const std::string& text, std::ostream& out, std::ostream& err) {
  if (a.arith) arithmetic_or_throw(*a.arith);
  const PolygonScene scene = parse_polygon_scene(text, a.input);
  GroundTruthEngine engine;
  const std::vector<Claim> catalogue = asked_claims(dijksman1966::catalogue(), scene.ask, a.input);
  const PolygonCheck check = check_polygon(engine, catalogue, scene.name, scene.polygon, scene.rates,
                                           chosen_arithmetic(a.arith, scene.ask), Evidence::All, scene.ask);
  report::Document d = report::build_polygon_document(engine, catalogue, scene, check, {a.numerics, text});
  d.reproduce = reproduce_of(a, "none (deterministic)");
  report::add_reproduce_section(d);
  write_document(a, d, out, err);
  return exit_status(check.claims);
}

bool is_claim_file_text(const std::string& text) {
  static const std::regex top_level_claims(R"((^|\n)claims\s*:)");
  return std::regex_search(text, top_level_claims);
}

int run_report(const ReportArgs& a, std::ostream& out, std::ostream& err) {
  if (a.format != "html" && a.format != "md" && a.format != "tex" && a.format != "all")
    throw InputError("<command line>", "--format", "must be html, md, tex or all, not '" + a.format + "'");
  const std::string text = read_scene_text(a.input);
  if (is_mechanism_scene_text(text)) return report_mechanism(a, text, out, err);
  if (is_claim_file_text(text)) return report_claim_file(a, text, out, err);
  return report_polygon(a, text, out, err);
}

}  // namespace

void add_report_command(CLI::App& app, Action& action) {
  auto* r = app.add_subcommand("report", "write a derivation report (HTML, Markdown or LaTeX) of a scene or a claim file");
  auto& a = bind_action<ReportArgs>(r, action, run_report);
  r->add_option("input", a.input, "polygon scene, mechanism scene, or claim file (proved), e.g. verify/scenes/pentagon.yaml")
      ->required();
  r->add_option("--format", a.format, "html (default: one self-contained file), md (+ SVG files), tex, or all");
  r->add_option("--out", a.out, "directory to write into (created; default .)");
  r->add_option("--claim", a.claims, "claim files: the claim to prove (repeatable; default every claim), e.g. eq22");
  r->add_option("--n", a.n, "claim files: prove for this number of sides only");
  r->add_option("--ladder-seconds", a.ladder_seconds,
                "claim files: time for per-n proofs per claim (default 1, where a proof leaves part of the range "
                "uncovered; given, they also re-check claims proved for every n)")
      ->check(seconds_validator());
  r->add_option("--arith", a.arith,
                "polygon scenes: the arithmetic of the check (default: the scene's `ask: [arithmetic: ...]`, else exact)");
  r->add_flag("--numerics", a.numerics, "polygon scenes: add the numerics section (every floating-point arithmetic)");
  r->add_flag("--plans", a.plans, "mechanism scenes: add the velocity and acceleration plans");
  r->add_option("--katex", a.katex, "directory of KaTeX (default Debian's /usr/share/javascript/katex)");
}

}  // namespace linkproof::cli
