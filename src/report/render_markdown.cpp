#include "linkproof/report/render.h"

namespace linkproof::report {

namespace {

// Markdown text: characters that would start markup inside a table or a line are escaped.
std::string md_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|' || c == '*' || c == '_' || c == '`' || c == '<' || c == '$') out += '\\';
    out += c;
  }
  return out;
}

std::string rich_md(const Rich& r) {
  std::string out;
  for (const auto& s : r) out += s.math ? "$" + s.text + "$" : md_escape(s.text);
  return out;
}

void block_md(const Block& b, std::string& out, std::map<std::string, std::string>& files) {
  switch (b.kind) {
    case Block::Kind::Paragraph: out += rich_md(b.paragraph) + "\n\n"; break;
    case Block::Kind::DisplayMath: out += "$$\n" + b.display + "\n$$\n\n"; break;
    case Block::Kind::Code: out += "```\n" + b.code + "\n```\n\n"; break;
    case Block::Kind::List:
      for (const auto& i : b.items) out += "- " + rich_md(i) + "\n";
      out += "\n";
      break;
    case Block::Kind::Table: {
      out += "|";
      for (const auto& h : b.table.header) out += " " + rich_md(h) + " |";
      out += "\n|";
      for (size_t k = 0; k < b.table.header.size(); ++k) out += "---|";
      out += "\n";
      for (const auto& row : b.table.rows) {
        out += "|";
        for (const auto& c : row) out += " " + rich_md(c) + " |";
        out += "\n";
      }
      out += "\n";
      break;
    }
    case Block::Kind::Figure: {
      const std::string name = b.figure.id + ".svg";
      files[name] = render_svg(b.figure.drawing);
      out += "![" + md_escape(b.figure.caption) + "](" + name + ")\n\n*" + md_escape(b.figure.caption);
      const View v = compute_view(b.figure.drawing);
      if (!v.off_view.empty()) {
        out += " Outside the view:";
        for (const auto& o : v.off_view) out += " " + md_escape(o) + ";";
      }
      out += "*\n\n";
      break;
    }
  }
}

void section_md(const Section& s, int level, std::string& out, std::map<std::string, std::string>& files) {
  // An HTML anchor (GitHub and pandoc keep it), so that links to a section id work.
  out += "<a id=\"" + s.id + "\"></a>\n\n" + std::string(static_cast<size_t>(level), '#') + " " + s.title + "\n\n";
  for (const auto& b : s.blocks) block_md(b, out, files);
  for (const auto& sub : s.subsections) section_md(sub, level + 1, out, files);
}

}  // namespace

std::string render_markdown(const Document& d, std::map<std::string, std::string>& figure_files) {
  std::string out = "# " + d.title + "\n\n";
  if (!d.subtitle.empty()) out += "*" + md_escape(d.subtitle) + "*\n\n";
  for (const auto& s : d.sections) section_md(s, 2, out, figure_files);
  return out;
}

}  // namespace linkproof::report
