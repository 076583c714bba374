#include "report/document.h"

#include <fmt/format.h>

namespace linkproof::report {

Block display_equation(const std::string& lhs_tex, const std::string& rhs_tex) {
  Block b = display_math(lhs_tex + " = " + rhs_tex);
  if (b.display.size() > kFoldTexChars)
    b.fold = {math(lhs_tex + " = \\ldots"),
              text(fmt::format(" (a long expression, {} characters of TeX: open to show it)", rhs_tex.size()))};
  return b;
}

Block display_folded(const std::string& tex, const std::string& what) {
  Block b = display_math(tex);
  if (b.display.size() > kFoldTexChars)
    b.fold = {text(fmt::format("{} (a long expression, {} characters of TeX: open to show it)", what, tex.size()))};
  return b;
}

void add_reproduce_section(Document& d) {
  const Reproduce& r = d.reproduce;
  Section s{"reproduce", "Reproduce", {}, {}};
  s.blocks.push_back(paragraph(plain("This report is reproduced, byte for byte apart from timings, by:")));
  s.blocks.push_back(code_block(r.command));
  Table t{{plain("seed"), plain("program version"), plain("commit")},
          {{plain(r.seed), plain(r.version), plain(r.commit)}}};
  s.blocks.push_back(table_block(std::move(t)));
  d.sections.push_back(std::move(s));
}

namespace {
void collect(const Section& s, std::vector<const Figure*>& out) {
  for (const auto& b : s.blocks)
    if (b.kind == Block::Kind::Figure) out.push_back(&b.figure);
  for (const auto& sub : s.subsections) collect(sub, out);
}
}  // namespace

std::vector<const Figure*> figures_of(const Document& d) {
  std::vector<const Figure*> out;
  for (const auto& s : d.sections) collect(s, out);
  return out;
}

}  // namespace linkproof::report
