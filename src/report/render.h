// Renderers of a report document (report/document.h): HTML, Markdown and LaTeX.
//
//   HTML      one self-contained file: inline CSS, inline SVG figures, and KaTeX (Debian's
//             libjs-katex: script, stylesheet and fonts as data: URLs) inlined, so the page
//             needs no network. Math spans are <span class="lp-math" data-tex="...">, rendered
//             by KaTeX when the page loads (errors show as .katex-error, which the browser test
//             looks for); <body data-math-rendered="N"> says how many were rendered.
//             Without KaTeX assets the TeX source is shown and the page says so.
//   Markdown  $...$ inline and $$...$$ display math (GitHub, pandoc); figures are written as
//             SVG files beside the .md, referenced by relative path.
//   LaTeX     an article that pdflatex compiles with texlive-latex-base alone (amsmath,
//             longtable, graphicx); figures are picture environments drawn by \pdfliteral.
// Every plain string is escaped for its format by report/escape.h (user strings included:
// names, descriptions, claim texts, paths); section and figure ids become anchors by anchor_id.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "report/document.h"
#include "report/escape.h"

namespace linkproof::report {

/// KaTeX's script and stylesheet, the stylesheet's font URLs already replaced by data: URLs.
struct KatexAssets {
  std::string script;
  std::string stylesheet;
  std::string source_dir;  ///< where they were read from, for the page's colophon
};

/// Reads KaTeX from `dir` (katex.min.js, katex.min.css, fonts/*.woff2). nullopt if the
/// script or stylesheet is missing. The default directory is Debian's libjs-katex.
std::optional<KatexAssets> load_katex_assets(const std::string& dir = "/usr/share/javascript/katex");

std::string render_html(const Document& d, const std::optional<KatexAssets>& katex);

/// The Markdown text; `figure_files` receives file name -> SVG text for every figure, to be
/// written beside the .md. Names are file_stem(figure id) + ".svg" (report/escape.h), with
/// "-2", "-3", ... before ".svg" when two ids give the same stem: a plain file name, never a
/// path, whatever the id holds.
std::string render_markdown(const Document& d, std::map<std::string, std::string>& figure_files);

std::string render_latex(const Document& d);

}  // namespace linkproof::report
