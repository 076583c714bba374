#include "linkproof/report/render.h"

namespace linkproof::report {

std::string latex_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '\\': out += "\\textbackslash{}"; break;
      case '&': case '%': case '$': case '#': case '_': case '{': case '}': out += '\\'; out += c; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '<': out += "$<$"; break;
      case '>': out += "$>$"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

// Plain text may hold Unicode (omega-dot, Greek letters in titles): pdflatex with inputenc
// reads UTF-8 but has no glyphs for most of it, so the few characters reports use are mapped.
std::string latex_text(const std::string& s) {
  std::string e = latex_escape(s), out;
  static const std::pair<const char*, const char*> map[] = {
      {"ω̇", "$\\dot\\omega$"}, {"ω", "$\\omega$"}, {"β", "$\\beta$"}, {"λ", "$\\lambda$"}, {"φ", "$\\varphi$"},
      {"μ", "$\\mu$"},        {"Σ", "$\\Sigma$"}, {"≠", "$\\neq$"},  {"≤", "$\\le$"},     {"≥", "$\\ge$"},
      {"×", "$\\times$"},     {"·", "$\\cdot$"},  {"→", "$\\to$"},   {"−", "-"},          {"–", "--"},
      {"—", "---"},           {"′", "'"},         {"²", "$^2$"},     {"…", "\\dots{}"},   {"ε", "$\\varepsilon$"},
      {"≈", "$\\approx$"},    {"∞", "$\\infty$"}, {"α", "$\\alpha$"}, {"γ", "$\\gamma$"}};
  for (size_t i = 0; i < e.size();) {
    bool hit = false;
    for (const auto& [from, to] : map) {
      const std::string f = from;
      if (e.compare(i, f.size(), f) == 0) {
        out += to, i += f.size(), hit = true;
        break;
      }
    }
    if (!hit) {
      const unsigned char c = static_cast<unsigned char>(e[i]);
      if (c < 0x80)
        out += e[i++];
      else {  // any other non-ASCII character: dropped to '?', never an error
        out += '?';
        ++i;
        while (i < e.size() && (static_cast<unsigned char>(e[i]) & 0xC0) == 0x80) ++i;
      }
    }
  }
  return out;
}

std::string rich_tex(const Rich& r) {
  std::string out;
  for (const auto& s : r) out += s.math ? "$" + s.text + "$" : latex_text(s.text);
  return out;
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
    case Block::Kind::Code: {
      out += "\\begin{verbatim}\n";
      // verbatim lines are not broken: long ones are folded at 90 characters.
      std::string line;
      for (char c : b.code + "\n") {
        if (c == '\n' || line.size() >= 90) {
          out += line + "\n";
          line.clear();
          if (c == '\n') continue;
        }
        line += c;
      }
      out += "\\end{verbatim}\n\n";
      break;
    }
    case Block::Kind::List:
      out += "\\begin{itemize}\n";
      for (const auto& i : b.items) out += "\\item " + rich_tex(i) + "\n";
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
        for (size_t k = 0; k < cols; ++k) out += (k ? " & " : "") + (k < row.size() ? rich_tex(row[k]) : std::string());
        out += " \\\\\n";
      }
      out += "\\hline\n\\end{longtable}}\n\n";
      break;
    }
    case Block::Kind::Figure: {
      out += "\\begin{figure}[htbp]\\centering\n" + render_latex_picture(b.figure.drawing) + "\\caption{" +
             latex_text(b.figure.caption);
      const View v = compute_view(b.figure.drawing);
      if (!v.off_view.empty()) {
        out += " Outside the view:";
        for (const auto& o : v.off_view) out += " " + latex_text(o) + ";";
      }
      out += "}\n\\end{figure}\n\n";
      break;
    }
  }
}

void section_tex(const Section& s, int level, std::string& out) {
  static const char* commands[] = {"section", "subsection", "subsubsection", "paragraph"};
  out += std::string("\\") + commands[std::min(level, 3)] + "{" + latex_text(s.title) + "}\\label{" + s.id + "}\n\n";
  for (const auto& b : s.blocks) block_tex(b, out);
  for (const auto& sub : s.subsections) section_tex(sub, level + 1, out);
}

}  // namespace

std::string render_latex(const Document& d) {
  std::string out =
      "\\documentclass[a4paper,10pt]{article}\n"
      "\\usepackage[utf8]{inputenc}\n"
      "\\usepackage{amsmath,amssymb,longtable,graphicx}\n"
      "\\setlength{\\textwidth}{16cm}\\setlength{\\oddsidemargin}{0cm}\\setlength{\\evensidemargin}{0cm}\n"
      "\\setlength{\\textheight}{24cm}\\setlength{\\topmargin}{-1.5cm}\n"
      "\\setlength{\\parindent}{0pt}\\setlength{\\parskip}{0.5ex}\n"
      "\\sloppy\n"
      "\\title{" + latex_text(d.title) + "}\n\\author{" + latex_text(d.subtitle) + "}\n\\date{}\n"
      "\\begin{document}\n\\maketitle\n\n";
  for (const auto& s : d.sections) section_tex(s, 0, out);
  out += "\\end{document}\n";
  return out;
}

}  // namespace linkproof::report
