// The report data model: what a derivation report says, independent of how it is rendered.
//
// A report is built once (report/polygon_document.h, mechanism_document.h, proof_document.h)
// and rendered three ways (report/render.h): one self-contained HTML file (KaTeX, inline SVG),
// Markdown with $...$ math and SVG files beside it, and LaTeX that pdflatex compiles.
//
// Text is a list of spans, each plain text or inline TeX math; renderers escape plain text for
// their format (report/escape.h) and pass math through (KaTeX and LaTeX read the same TeX). A
// user's string (a name, a description, a claim's text) goes into plain text, never into math. Figures are drawings
// (report/drawing.h) in world coordinates, rendered to SVG or to a LaTeX picture.
//
// Section ids are stable (the browser test and readers' links rely on them):
//   summary, derivation, construction, drawing, mechanism, terms, errata, proof, numerics,
//   reproduce. A report leaves out the sections that do not apply.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "report/drawing.h"

namespace linkproof::report {

/// Plain text (escaped by the renderer) or inline TeX math.
///
/// A span with a `fold` line is long (a symbolic coefficient of hundreds of characters, an exact
/// fraction of hundreds of digits): HTML shows the fold line, plain text, and opens to the span
/// in a <details> element, so that no table is wider than the page; Markdown and LaTeX show a
/// math span in full (LaTeX scales it) and a plain one by its fold line alone.
struct Span {
  bool math = false;
  std::string text;
  std::string fold{};
};

/// A run of spans: a sentence, a table cell.
using Rich = std::vector<Span>;

inline Span text(std::string s) { return {false, std::move(s)}; }
inline Span math(std::string tex) { return {true, std::move(tex)}; }
/// A rich text of one plain span.
inline Rich plain(std::string s) { return {text(std::move(s))}; }
/// A rich text of one math span.
inline Rich tex(std::string s) { return {math(std::move(s))}; }
/// A folded span (see Span): `fold` is the plain line shown in its place.
inline Span folded(Span s, std::string fold) { s.fold = std::move(fold); return s; }

/// TeX longer than this many characters is folded in HTML (wider than a 1200 px page).
inline constexpr size_t kFoldTexChars = 320;

struct Table {
  std::vector<Rich> header;
  std::vector<std::vector<Rich>> rows;
};

struct Figure {
  std::string id;       ///< any text (it starts with the scene's name): renderers make it an anchor
                        ///< and a file stem (report/escape.h) for figures written beside the report
  std::string caption;  ///< plain text (an image's alternative text, LaTeX's list of figures)
  Drawing drawing;
  Rich rich_caption{};  ///< the caption as shown, with its formulas as math; empty: `caption`
};

/// One block of a section, in order. Exactly one of the members is used, by `kind`.
///   Headline  the results a reader came for, first on the page (the claims at a glance, the
///             asked values): `items`, shown as large badges in HTML and as a list elsewhere.
struct Block {
  enum class Kind { Paragraph, DisplayMath, Table, Figure, List, Code, Headline } kind = Kind::Paragraph;
  Rich paragraph;                 ///< Paragraph
  std::string display;            ///< DisplayMath: TeX of one displayed equation
  Rich fold;                      ///< DisplayMath: if not empty, HTML shows this line and opens to the equation
  Table table;                    ///< Table
  Figure figure;                  ///< Figure
  std::vector<Rich> items;        ///< List, Headline (each item a rich text)
  std::string code;               ///< Code: verbatim text (a command line, a scene file)
};

inline Block paragraph(Rich r) { Block b; b.kind = Block::Kind::Paragraph; b.paragraph = std::move(r); return b; }
inline Block display_math(std::string t) { Block b; b.kind = Block::Kind::DisplayMath; b.display = std::move(t); return b; }
inline Block table_block(Table t) { Block b; b.kind = Block::Kind::Table; b.table = std::move(t); return b; }
inline Block figure_block(Figure f) { Block b; b.kind = Block::Kind::Figure; b.figure = std::move(f); return b; }
inline Block list_block(std::vector<Rich> items) { Block b; b.kind = Block::Kind::List; b.items = std::move(items); return b; }
inline Block code_block(std::string c) { Block b; b.kind = Block::Kind::Code; b.code = std::move(c); return b; }
inline Block headline_block(std::vector<Rich> items) { Block b; b.kind = Block::Kind::Headline; b.items = std::move(items); return b; }
/// A displayed equation `lhs = rhs`, folded in HTML behind "lhs = … (N characters of TeX)" when the
/// TeX is longer than kFoldTexChars.
Block display_equation(const std::string& lhs_tex, const std::string& rhs_tex);
/// A displayed equation folded in HTML behind `what` and its size when its TeX is longer than
/// kFoldTexChars ("the second time derivative, x component (a long expression, ...)").
Block display_folded(const std::string& tex, const std::string& what);

struct Section {
  std::string id;     ///< stable anchor, e.g. "summary"
  std::string title;
  std::vector<Block> blocks;
  /// Sub-sections (one per claim of a proof, ...), rendered one heading level lower.
  std::vector<Section> subsections;
};

/// How to reproduce the report: the command line and what it depends on.
struct Reproduce {
  std::string command;  ///< e.g. "linkproof report verify/scenes/pentagon.yaml --format html"
  std::string seed;     ///< the random seed, or "none"
  std::string version;  ///< program version
  std::string commit;   ///< git commit of the build, or "unknown"
};

struct Document {
  std::string title;
  std::string subtitle;
  std::vector<Section> sections;
  Reproduce reproduce;
};

/// Appends the "reproduce" section (command, seed, version, commit) built from d.reproduce.
void add_reproduce_section(Document& d);

/// Every figure of the document, in order (sections, then their subsections).
std::vector<const Figure*> figures_of(const Document& d);

}  // namespace linkproof::report
