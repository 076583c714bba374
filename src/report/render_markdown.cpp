#include "report/render.h"

namespace linkproof::report {

namespace {

// A rich text; at the start of a block (a paragraph, a list item) its first span is escaped as
// such (markdown_escape's block_start).
std::string rich_md(const Rich& r, bool block_start = false) {
  std::string out;
  // A folded span: math in full, plain text by its fold line (document.h).
  for (const auto& s : r)
    out += s.math ? "$" + s.text + "$" : markdown_escape(s.fold.empty() ? s.text : s.fold, block_start && out.empty());
  return out;
}

// A figure's file: its id as a file stem (never a path), made unique among the report's figures.
std::string figure_file_name(const std::string& id, const std::map<std::string, std::string>& files) {
  const std::string stem = file_stem(id);
  std::string name = stem + ".svg";
  for (int k = 2; files.count(name); ++k) name = stem + "-" + std::to_string(k) + ".svg";
  return name;
}

void block_md(const Block& b, std::string& out, std::map<std::string, std::string>& files) {
  switch (b.kind) {
    case Block::Kind::Paragraph: out += rich_md(b.paragraph, true) + "\n\n"; break;
    case Block::Kind::DisplayMath: out += "$$\n" + b.display + "\n$$\n\n"; break;
    case Block::Kind::Code: out += markdown_code_block(b.code) + "\n"; break;
    case Block::Kind::List:
    case Block::Kind::Headline:
      for (const auto& i : b.items) out += "- " + rich_md(i, true) + "\n";
      out += "\n";
      break;
    case Block::Kind::Table: {
      out += "|";
      for (const auto& h : b.table.header) out += " " + rich_md(h) + " |";
      out += "\n|";
      for (size_t k = 0; k < b.table.header.size(); ++k) out += "---|";
      out += "\n";
      // Every row has the header's cells, as in LaTeX: a shorter row is padded, so no row of
      // the table reads as another table's (found by fuzz_report).
      for (const auto& row : b.table.rows) {
        out += "|";
        for (size_t k = 0; k < b.table.header.size(); ++k) out += " " + (k < row.size() ? rich_md(row[k]) : "") + " |";
        out += "\n";
      }
      out += "\n";
      break;
    }
    case Block::Kind::Figure: {
      const std::string name = figure_file_name(b.figure.id, files);
      files[name] = render_svg(b.figure.drawing);
      out += "![" + markdown_escape(b.figure.caption) + "](" + name + ")\n\n*" +
             (b.figure.rich_caption.empty() ? markdown_escape(b.figure.caption) : rich_md(b.figure.rich_caption));
      const View v = compute_view(b.figure.drawing);
      if (!v.off_view.empty()) {
        out += " Outside the view:";
        for (const auto& o : v.off_view) out += " " + markdown_escape(o) + ";";
      }
      out += "*\n\n";
      break;
    }
  }
}

void section_md(const Section& s, int level, std::string& out, std::map<std::string, std::string>& files) {
  // An HTML anchor (GitHub and pandoc keep it), so that links to a section id work.
  out += "<a id=\"" + anchor_id(s.id) + "\"></a>\n\n" + std::string(static_cast<size_t>(level), '#') + " " +
         markdown_escape(s.title) + "\n\n";
  for (const auto& b : s.blocks) block_md(b, out, files);
  for (const auto& sub : s.subsections) section_md(sub, level + 1, out, files);
}

}  // namespace

std::string render_markdown(const Document& d, std::map<std::string, std::string>& figure_files) {
  std::string out = "# " + markdown_escape(d.title) + "\n\n";
  if (!d.subtitle.empty()) out += "*" + markdown_escape(d.subtitle) + "*\n\n";
  for (const auto& s : d.sections) section_md(s, 2, out, figure_files);
  return out;
}

}  // namespace linkproof::report
