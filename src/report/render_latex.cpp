#include "report/render.h"

namespace linkproof::report {

namespace {

std::string rich_tex(const Rich& r) {
  std::string out;
  // A folded span: math in full, plain text by its fold line (document.h).
  for (const auto& s : r) out += s.math ? "$" + s.text + "$" : latex_escape(s.fold.empty() ? s.text : s.fold);
  return out;
}

// After \\ (a table row's end) and \item, LaTeX looks for an optional [..] or *: a cell or
// item whose text starts with one is shielded by {} so that the text is shown, not read.
std::string shielded(std::string tex) {
  const auto first = tex.find_first_not_of(" \n");
  if (first != std::string::npos && (tex[first] == '[' || tex[first] == '*')) tex.insert(0, "{}");
  return tex;
}

void block_tex(const Block& b, std::string& out) {
  switch (b.kind) {
    case Block::Kind::Paragraph: out += rich_tex(b.paragraph) + "\n\n"; break;
    case Block::Kind::DisplayMath:
      // Long derived expressions are scaled down to the line width rather than overflowing it.
      if (b.display.size() > 220)
        out += "\\begin{center}\\resizebox{\\linewidth}{!}{$\\displaystyle " + b.display + "$}\\end{center}\n\n";
      else
        out += "\\[ " + b.display + " \\]\n\n";
      break;
    case Block::Kind::Code: out += latex_verbatim(b.code) + "\n"; break;
    case Block::Kind::List:
    case Block::Kind::Headline:
      out += "\\begin{itemize}\n";
      for (const auto& i : b.items) out += "\\item " + shielded(rich_tex(i)) + "\n";
      out += "\\end{itemize}\n\n";
      break;
    case Block::Kind::Table: {
      const size_t cols = b.table.header.size();
      const double w = 0.95 / static_cast<double>(std::max<size_t>(cols, 1));
      out += "{\\footnotesize\\begin{longtable}{";
      for (size_t k = 0; k < cols; ++k) out += "p{" + std::to_string(w) + "\\linewidth}";
      out += "}\n\\hline\n";
      for (size_t k = 0; k < cols; ++k) out += (k ? " & " : "") + ("\\textbf{" + rich_tex(b.table.header[k]) + "}");
      out += " \\\\\n\\hline\n\\endhead\n";
      for (const auto& row : b.table.rows) {
        for (size_t k = 0; k < cols; ++k) {
          const std::string cell = k < row.size() ? rich_tex(row[k]) : std::string();
          out += (k ? " & " + cell : shielded(cell));
        }
        out += " \\\\\n";
      }
      out += "\\hline\n\\end{longtable}}\n\n";
      break;
    }
    case Block::Kind::Figure: {
      // The plain caption for the list of figures (braced: a ']' in it cannot end the option);
      // the shown one with its formulas.
      out += "\\begin{figure}[htbp]\\centering\n" + render_latex_picture(b.figure.drawing) + "\\caption[{" +
             latex_escape(b.figure.caption) + "}]{" +
             (b.figure.rich_caption.empty() ? latex_escape(b.figure.caption) : rich_tex(b.figure.rich_caption));
      const View v = compute_view(b.figure.drawing);
      if (!v.off_view.empty()) {
        out += " Outside the view:";
        for (const auto& o : v.off_view) out += " " + latex_escape(o) + ";";
      }
      out += "}\n\\end{figure}\n\n";
      break;
    }
  }
}

void section_tex(const Section& s, int level, std::string& out) {
  static const char* commands[] = {"section", "subsection", "subsubsection", "paragraph"};
  out += std::string("\\") + commands[std::min(level, 3)] + "{" + latex_escape(s.title) + "}\\label{" +
         anchor_id(s.id) + "}\n\n";
  for (const auto& b : s.blocks) block_tex(b, out);
  for (const auto& sub : s.subsections) section_tex(sub, level + 1, out);
}

}  // namespace

std::string render_latex(const Document& d) {
  std::string out =
      "\\documentclass[a4paper,10pt]{article}\n"
      "\\usepackage[utf8]{inputenc}\n"
      "\\usepackage{amsmath,amssymb,longtable,graphicx}\n"
      "\\providecommand{\\lt}{<}\\providecommand{\\gt}{>}\n"
      "\\setlength{\\textwidth}{16cm}\\setlength{\\oddsidemargin}{0cm}\\setlength{\\evensidemargin}{0cm}\n"
      "\\setlength{\\textheight}{24cm}\\setlength{\\topmargin}{-1.5cm}\n"
      "\\setlength{\\parindent}{0pt}\\setlength{\\parskip}{0.5ex}\n"
      "\\sloppy\n"
      "\\title{" + latex_escape(d.title) + "}\n\\author{" + latex_escape(d.subtitle) + "}\n\\date{}\n"
      "\\begin{document}\n\\maketitle\n\n";
  for (const auto& s : d.sections) section_tex(s, 0, out);
  out += "\\end{document}\n";
  return out;
}

}  // namespace linkproof::report
