// libFuzzer target: report output safety (report/escape.h). The input, cut at NUL bytes, gives
// the strings a user controls: a scene's name and description, link, joint and point names,
// a claim's id, source, statement and note, a term label, a table title, a command line. They
// go into a mechanism report (the four-bar of the acceleration-polygon course notes, built in
// memory with a hand-made check: no solver runs) and a document with a string in every slot; both are rendered as LaTeX,
// Markdown and HTML. Each rendering is compared with that of its twin, the same document with
// every string replaced by a harmless one of the same shape: the structure must be the same.
// Aborts (a libFuzzer crash) when
//   LaTeX     a listing does not end where the renderer ends it, braces do not balance outside
//             listings, a group holds a blank line, a % or ^^ appears, a byte is not printable
//             ASCII, or the commands differ from the twin's (a command of the input is active);
//   Markdown  the fences, headings or table cells differ from the twin's, a fence is left open,
//             or a < outside code is raw HTML; a figure file name is a path or hidden;
//   HTML      the elements (in order) or the number of quote characters differ from the twin's;
//   names     file_stem gives a path, a hidden, empty, over-long or non-deterministic name.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "../report/report_checks.h"
#include "report/document.h"
#include "report/escape.h"
#include "report/mechanism_document.h"
#include "report/render.h"
#include "report/statement_tex.h"

namespace {

using namespace linkproof;
using namespace linkproof::report;

[[noreturn]] void violated(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_report: %s\n%s\n", what, detail.substr(0, 4000).c_str());
  std::abort();
}

void require(bool ok, const char* what, const std::string& detail = "") {
  if (!ok) violated(what, detail);
}

// The strings of one run: the input cut at NUL bytes, missing ones empty.
struct Strings {
  std::vector<std::string> s;
  const std::string& operator[](std::size_t k) const {
    static const std::string empty;
    return k < s.size() ? s[k] : empty;
  }
};

// A harmless string of the same shape: empty stays empty; a label with an '_' keeps it, and
// something after it when it had something, so that figures draw the same elements (names get
// an index appended, which turns a trailing '_' into a subscript).
std::string twin(const std::string& s) {
  if (s.empty()) return "";
  const auto u = s.find('_');
  if (u == std::string::npos) return "x";
  return u + 1 < s.size() ? "x_x" : "x_";
}

// A claim's statement is typeset when it is made of formula characters alone
// (report/statement_tex.h): then it is harmless by construction and is its own twin (its math
// spans are the structure it must have); otherwise it is plain text, twinned by a plain word.
std::string statement_twin(const std::string& s) {
  if (s.empty()) return "";
  for (const Span& span : statement_rich(s))
    if (span.math) return s;
  return "xx";
}

// A term label of the engine's form ("omega[1]*omega[2]") is typeset likewise: its own twin.
std::string term_label_twin(const std::string& s) {
  const Rich r = term_label_rich(s);
  return r.size() == 1 && r[0].math ? s : twin(s);
}

Strings twin_of(const Strings& in) {
  Strings out;
  for (std::size_t k = 0; k < in.s.size(); ++k)
    out.s.push_back(k == 13 ? statement_twin(in.s[k]) : k == 15 ? term_label_twin(in.s[k]) : twin(in.s[k]));
  return out;
}

Vec2<Rational> at(int x, int y) { return {Rational(x), Rational(y)}; }

// Slots: 0 name, 1 description, 2-5 links, 6-9 joints, 10 point, 11 claim id, 12 source,
// 13 statement, 14 note, 15 term label, 16 table title, 17 command line.
std::pair<MechanismScene, MechanismCheck> fourbar(const Strings& f) {
  // Names get their index appended: distinct, as a scene's must be, whatever the input.
  std::vector<std::string> links;
  for (int k = 0; k < 4; ++k) links.push_back(f[2 + static_cast<std::size_t>(k)] + std::to_string(k));
  std::vector<LinkageJoint> joints(4);
  const Vec2<Rational> where[] = {at(0, 0), at(3, 4), at(11, 10), at(11, 0)};
  for (int k = 0; k < 4; ++k) {
    joints[static_cast<std::size_t>(k)].name = f[6 + static_cast<std::size_t>(k)] + std::to_string(k);
    joints[static_cast<std::size_t>(k)].links[0] = k;
    joints[static_cast<std::size_t>(k)].links[1] = (k + 1) % 4;
    joints[static_cast<std::size_t>(k)].at = where[k];
  }
  MechanismScene scene;
  scene.name = f[0];
  scene.source = "fuzz.yaml";
  scene.linkage = Linkage(links, 0, joints);
  scene.inputs.push_back({MechanismInput::Kind::Link, 1, Rational(2), Rational(5)});
  scene.points.push_back({f[10], 2, at(9, 14)});

  MechanismCheck check;
  check.scene = f[0];
  check.mobility = check.grubler = check.rank = check.loops = 1;
  check.link_names = links;
  const auto q = [](const char* text) { return ResultNumber(parse_rational(text)); };
  check.omega = {q("0"), q("2"), q("-3/4"), q("7/20")};
  check.omega_dot = {q("0"), q("5"), q("63/160"), q("3109/800")};
  for (const auto& j : joints) check.joints.push_back({j.name, {q("1"), q("2")}, {q("3"), q("-4")}, {}, {}});
  check.points.push_back({f[10], {q("1/2"), q("1")}, {q("-629/16"), q("-341/80")}, {}, {}});
  ClaimOutcome c;
  c.info.id = f[11];
  c.info.source = f[12];
  c.info.statement = f[13];
  c.info.note = f[14];
  c.info.expected = Expectation::Fails;  // an erratum that fails here: the scene text is shown
  c.verdict = Verdict::Fails;
  c.headline.label = f[15];
  c.headline.verdict = Verdict::Fails;
  c.headline.lhs = Rational(1), c.headline.rhs = Rational(2), c.headline.residual = Rational(-1);
  c.terms.push_back(c.headline);
  check.claims.push_back(c);
  check.tables.push_back({f[16], {{f[15], "1/2"}}});
  return {std::move(scene), std::move(check)};
}

// Every slot of a document holds an input string (math spans hold the program's TeX).
Document every_slot(const Strings& f) {
  Document d;
  d.title = f[0];
  d.subtitle = f[1];
  Section s{f[11], f[12], {}, {}};
  s.blocks.push_back(paragraph({text(f[13]), math("\\omega_{1}"), text(f[14])}));
  s.blocks.push_back(table_block({{plain(f[2]), tex("\\dot\\omega")}, {{plain(f[3]), plain(f[4])}, {plain(f[5])}}}));
  s.blocks.push_back(list_block({plain(f[6]), plain(f[7])}));
  s.blocks.push_back(code_block(f[1]));
  Drawing dr;
  dr.segments.push_back(Segment{{0, 0}, {1, 1}, f[15], Stroke::Solid, true, f[8]});
  dr.markers.push_back({{0, 0}, f[9], "#222222", true, false});
  dr.markers.push_back({{1e9, 0}, f[10], "#aa0000", false, true});  // off the view: named in the caption
  dr.angles.push_back({{0, 0}, {1, 0}, {0, 1}, f[16], "#aa3300"});
  s.blocks.push_back(figure_block({f[17], f[16], dr}));
  Section sub{f[2], f[3], {paragraph(plain(f[4]))}, {}};
  s.subsections.push_back(sub);
  d.sections.push_back(s);
  d.reproduce = {f[17], f[0], "0", "x"};
  add_reproduce_section(d);
  return d;
}

Document mechanism_report(const Strings& f) {
  const auto [scene, check] = fourbar(f);
  Document d = build_mechanism_document(scene, check, {true, f[1]});
  d.reproduce = {f[17], "none", "0", "x"};
  add_reproduce_section(d);
  return d;
}

// ------------------------------------------------------------------ checks per language

void check_latex(const std::string& tex, const std::string& twin_tex, std::size_t code_blocks) {
  require(linkproof::test::count(tex, "\\begin{verbatim}") == code_blocks &&
              linkproof::test::count(tex, "\\end{verbatim}") == code_blocks,
          "LaTeX: a listing was closed from inside", tex);
  const std::string outside = linkproof::test::latex_outside_verbatim(tex);
  const std::string problem = linkproof::test::latex_brace_depth_problem(outside);
  require(problem.empty(), "LaTeX: braces", problem + "\n" + outside);
  require(outside.find("^^") == std::string::npos, "LaTeX: ^^ notation", outside);
  for (char c : tex)
    require(c == '\n' || c == '\t' || (c >= 0x20 && c < 0x7f), "LaTeX: a byte that is not printable ASCII", tex);
  require(linkproof::test::latex_structure(outside) ==
              linkproof::test::latex_structure(linkproof::test::latex_outside_verbatim(twin_tex)),
          "LaTeX: a command of the input is active", tex);
}

void check_markdown(const std::string& md, const std::string& twin_md, const std::map<std::string, std::string>& files) {
  const auto o = linkproof::test::markdown_outline(md), t = linkproof::test::markdown_outline(twin_md);
  require(!o.unclosed_fence && o.fences == t.fences, "Markdown: a fence was closed or opened by the input", md);
  require(o.headings.size() == t.headings.size(), "Markdown: a heading of the input", md);
  require(o.raw_html_other_than_anchors.empty(), "Markdown: raw HTML of the input", o.raw_html_other_than_anchors);
  require(o.bad_table_rows.empty(), "Markdown: a table cell was split", md);
  for (const auto& [name, svg] : files) {
    require(name.find('/') == std::string::npos && name[0] != '.' && name.size() <= 255, "Markdown: figure file name",
            name);
    require(svg.rfind("<svg", 0) == 0, "SVG: not an SVG document", svg);
  }
}

// The text around the k-th '<' of an HTML text, for a finding's message.
std::string around_element(const std::string& html, std::size_t k) {
  std::size_t at = html.find('<');
  for (std::size_t i = 0; i < k && at != std::string::npos; ++i) at = html.find('<', at + 1);
  if (at == std::string::npos) return "(end)";
  const std::size_t from = at > 300 ? at - 300 : 0;
  return html.substr(from, 600);
}

void check_html(const std::string& html, const std::string& twin_html) {
  const auto e = linkproof::test::html_elements(html), t = linkproof::test::html_elements(twin_html);
  if (e != t) {
    std::size_t k = 0;
    while (k < e.size() && k < t.size() && e[k] == t[k]) ++k;
    const std::string got = k < e.size() ? e[k] : "(end)", want = k < t.size() ? t[k] : "(end)";
    violated("HTML: an element of the input", "element " + std::to_string(k) + ": " + got + " where the twin has " +
                                                   want + "\n" + around_element(html, k) + "\ntwin:\n" +
                                                   around_element(twin_html, k));
  }
  require(linkproof::test::count(html, "\"") == linkproof::test::count(twin_html, "\""),
          "HTML: a quote of the input closed an attribute", html);
}

void check_names(const Strings& f) {
  for (const auto& s : f.s) {
    const std::string stem = file_stem(s);
    require(!stem.empty() && stem.size() <= kMaxFileStemBytes && stem[0] != '.' && stem[0] != '-' &&
                stem.find('/') == std::string::npos && stem.find('\\') == std::string::npos && stem == file_stem(s),
            "file_stem", stem);
    const std::string id = anchor_id(s);
    for (char c : id)
      require(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == ':' || c == '-', "anchor_id",
              id);
  }
}

void check_document(const Document& d, const Document& twin_d, std::size_t code_blocks) {
  check_latex(render_latex(d), render_latex(twin_d), code_blocks);
  std::map<std::string, std::string> files, twin_files;
  const std::string md = render_markdown(d, files);
  check_markdown(md, render_markdown(twin_d, twin_files), files);
  require(files.size() == twin_files.size(), "Markdown: two figures were written to one file");
  check_html(render_html(d, std::nullopt), render_html(twin_d, std::nullopt));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Strings f;
  std::string cur;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      f.s.push_back(cur);
      cur.clear();
    } else {
      cur += static_cast<char>(data[i]);
    }
  }
  f.s.push_back(cur);
  if (f.s.size() > 18) f.s.resize(18);
  while (f.s.size() < 18) f.s.push_back("");  // every slot has a string (its twin may be "")
  const Strings t = twin_of(f);
  check_names(f);
  check_document(every_slot(f), every_slot(t), 2);
  // The scene text is shown (a second listing) only when there is one.
  check_document(mechanism_report(f), mechanism_report(t), f[1].empty() ? 1 : 2);
  return 0;
}
