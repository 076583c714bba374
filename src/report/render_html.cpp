#include <fmt/format.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "report/render.h"

namespace linkproof::report {

namespace {

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += table[v >> 18 & 63], out += table[v >> 12 & 63], out += table[v >> 6 & 63], out += table[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += table[v >> 18 & 63], out += table[v >> 12 & 63];
    out += i + 1 < bytes.size() ? table[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::string span_html(const Span& s) {
  return s.math ? "<span class=\"lp-math\" data-tex=\"" + html_escape(s.text) + "\">" + html_escape(s.text) + "</span>"
                : html_escape(s.text);
}

std::string rich_html(const Rich& r) {
  std::string out;
  for (const auto& s : r)
    out += s.fold.empty() ? span_html(s)
                          : "<details class=\"lp-fold\"><summary>" + html_escape(s.fold) +
                                "</summary><div class=\"lp-folded\">" + span_html(s) + "</div></details>";
  return out;
}

void block_html(const Block& b, std::string& out) {
  switch (b.kind) {
    case Block::Kind::Paragraph: out += "<p>" + rich_html(b.paragraph) + "</p>\n"; break;
    case Block::Kind::DisplayMath: {
      const std::string div = "<div class=\"lp-math lp-display\" data-tex=\"" + html_escape(b.display) + "\">" +
                              html_escape(b.display) + "</div>";
      out += b.fold.empty() ? div + "\n"
                            : "<details class=\"lp-fold lp-fold-display\"><summary>" + rich_html(b.fold) + "</summary>" + div +
                                  "</details>\n";
      break;
    }
    case Block::Kind::Headline:
      out += "<ul class=\"lp-headline\">\n";
      for (const auto& i : b.items) out += "<li>" + rich_html(i) + "</li>\n";
      out += "</ul>\n";
      break;
    case Block::Kind::Code: out += "<pre><code>" + html_escape(b.code) + "</code></pre>\n"; break;
    case Block::Kind::List:
      out += "<ul>\n";
      for (const auto& i : b.items) out += "<li>" + rich_html(i) + "</li>\n";
      out += "</ul>\n";
      break;
    case Block::Kind::Table:
      out += "<div class=\"lp-table\"><table>\n<thead><tr>";
      for (const auto& h : b.table.header) out += "<th>" + rich_html(h) + "</th>";
      out += "</tr></thead>\n<tbody>\n";
      for (const auto& row : b.table.rows) {
        out += "<tr>";
        for (const auto& c : row) out += "<td>" + rich_html(c) + "</td>";
        out += "</tr>\n";
      }
      out += "</tbody></table></div>\n";
      break;
    case Block::Kind::Figure: {
      const View v = compute_view(b.figure.drawing);
      out += "<figure id=\"fig-" + anchor_id(b.figure.id) + "\">\n" + render_svg(b.figure.drawing) +
             "<figcaption>" + (b.figure.rich_caption.empty() ? html_escape(b.figure.caption) : rich_html(b.figure.rich_caption));
      if (!v.off_view.empty()) {
        out += " Outside the view:";
        for (const auto& o : v.off_view) out += " " + html_escape(o) + ";";
      }
      out += "</figcaption>\n</figure>\n";
      break;
    }
  }
}

void section_html(const Section& s, int level, std::string& out) {
  out += fmt::format("<section id=\"{}\">\n<h{}>{}</h{}>\n", anchor_id(s.id), level, html_escape(s.title), level);
  for (size_t k = 0; k < s.blocks.size(); ++k) {
    // A figure followed by a headline: side by side, the first thing a reader sees.
    if (s.blocks[k].kind == Block::Kind::Figure && k + 1 < s.blocks.size() &&
        s.blocks[k + 1].kind == Block::Kind::Headline) {
      out += "<div class=\"lp-hero\">\n";
      block_html(s.blocks[k], out);
      block_html(s.blocks[k + 1], out);
      out += "</div>\n";
      ++k;
      continue;
    }
    block_html(s.blocks[k], out);
  }
  for (const auto& sub : s.subsections) section_html(sub, level + 1, out);
  out += "</section>\n";
}

// The page fits a 1200 px window (no table or formula wider: long ones are folded, cells wrap),
// opens with the hero (the figure beside the headline), and prints without the navigation.
constexpr const char* kStyle = R"(
body { font-family: Georgia, serif; max-width: 72rem; margin: 1.2rem auto; padding: 0 1rem; color: #222; line-height: 1.4; }
h1, h2, h3, h4 { font-family: sans-serif; }
h1 { font-size: 1.6rem; margin: 0 0 0.2rem; }
h2 { font-size: 1.3rem; margin: 1.4rem 0 0.5rem; border-bottom: 1px solid #ddd; }
.lp-subtitle { margin: 0 0 0.3rem; color: #555; }
nav ul { display: flex; flex-wrap: wrap; gap: 0.2rem 1.2rem; list-style: none; padding: 0; margin: 0.2rem 0 0.6rem;
         font-family: sans-serif; font-size: 0.9rem; }
#summary > h2 { margin-top: 0.4rem; }
.lp-hero { display: flex; flex-wrap: wrap; gap: 0.8rem 2rem; align-items: flex-start; }
.lp-hero figure { flex: 3 1 540px; margin: 0; min-width: 0; }
.lp-hero svg { width: 100%; height: auto; max-height: 560px; }
.lp-headline { flex: 2 1 280px; list-style: none; padding: 0; margin: 0; font-family: sans-serif; }
.lp-headline li { font-size: 1.05rem; border-left: 5px solid #2a8a5a; background: #f2f9f5; padding: 0.45rem 0.8rem;
                  margin: 0 0 0.5rem; }
table { border-collapse: collapse; margin: 0.5rem 0; max-width: 100%; }
th, td { border: 1px solid #bbb; padding: 0.2rem 0.5rem; text-align: left; vertical-align: top; overflow-wrap: break-word; }
th { background: #f0f0f0; }
.lp-table { overflow-x: auto; max-width: 100%; }
.lp-display { overflow-x: auto; margin: 0.6rem 0; }
details.lp-fold { display: inline-block; max-width: 100%; vertical-align: top; }
details.lp-fold > summary { cursor: pointer; color: #333; }
details.lp-fold-display { display: block; margin: 0.5rem 0; }
details.lp-fold-display > summary { color: #222; }
.lp-folded { max-width: 100%; overflow-x: auto; overflow-wrap: anywhere; word-break: break-all; }
pre { background: #f6f6f6; padding: 0.5rem; overflow-x: auto; white-space: pre-wrap; overflow-wrap: anywhere; }
figure { margin: 1rem 0; } figcaption { font-size: 0.9rem; color: #444; }
svg { max-width: 100%; height: auto; border: 1px solid #ddd; box-sizing: border-box; }
.lp-nokatex { color: #a00; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 10pt; }
  nav, .lp-nokatex { display: none; }
  .lp-hero { display: block; }
  .lp-hero svg { max-height: 12cm; }
  figure, tr, .lp-headline li, .lp-display { break-inside: avoid; }
  h2, h3, h4 { break-after: avoid; }
  .lp-table, .lp-display, pre { overflow: visible; }
  a { color: inherit; text-decoration: none; }
}
)";

// Renders every .lp-math element with KaTeX; errors stay in the page as .katex-error.
constexpr const char* kRenderScript = R"(
(function () {
  var n = 0;
  document.querySelectorAll('.lp-math').forEach(function (e) {
    katex.render(e.getAttribute('data-tex'), e,
                 {displayMode: e.classList.contains('lp-display'), throwOnError: false});
    n++;
  });
  document.body.setAttribute('data-math-rendered', String(n));
})();
)";

}  // namespace

std::optional<KatexAssets> load_katex_assets(const std::string& dir) {
  const auto script = read_file(dir + "/katex.min.js");
  const auto css = read_file(dir + "/katex.min.css");
  if (!script || !css) return std::nullopt;
  // Fonts: woff2 as data: URLs; the woff/ttf fallbacks are dropped (every browser that runs
  // KaTeX reads woff2), so the page refers to no file and no network.
  std::string style = std::regex_replace(*css, std::regex(R"(,\s*url\(fonts/[^)]*\.(woff|ttf)\) format\("[a-z]+"\))"), "");
  std::string out;
  const std::regex font(R"(url\(fonts/([A-Za-z0-9_-]+\.woff2)\))");
  auto it = std::sregex_iterator(style.begin(), style.end(), font);
  size_t last = 0;
  for (; it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    out += style.substr(last, static_cast<size_t>(m.position(0)) - last);
    const auto bytes = read_file(dir + "/fonts/" + m[1].str());
    out += bytes ? "url(data:font/woff2;base64," + base64(*bytes) + ")" : m[0].str();
    last = static_cast<size_t>(m.position(0) + m.length(0));
  }
  out += style.substr(last);
  return KatexAssets{*script, out, dir};
}

std::string render_html(const Document& d, const std::optional<KatexAssets>& katex) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                    html_escape(d.title) + "</title>\n<style>" + kStyle + "</style>\n";
  if (katex) out += "<style>\n" + katex->stylesheet + "\n</style>\n";
  out += "</head>\n<body>\n<h1>" + html_escape(d.title) + "</h1>\n";
  if (!d.subtitle.empty()) out += "<p class=\"lp-subtitle\"><em>" + html_escape(d.subtitle) + "</em></p>\n";
  if (!katex)
    out += "<p class=\"lp-nokatex\">KaTeX was not found (Debian package libjs-katex): formulas are shown as TeX "
           "source.</p>\n";
  out += "<nav><ul>\n";
  for (const auto& s : d.sections)
    out += "<li><a href=\"#" + anchor_id(s.id) + "\">" + html_escape(s.title) + "</a></li>\n";
  out += "</ul></nav>\n";
  for (const auto& s : d.sections) section_html(s, 2, out);
  if (katex) {
    // "</script" inside the script would end it early; KaTeX's minified source has none, but
    // escape it anyway.
    std::string script = katex->script;
    for (size_t at = script.find("</script"); at != std::string::npos; at = script.find("</script", at + 2))
      script.replace(at, 2, "<\\/");
    out += "<script>\n" + script + "\n</script>\n<script>" + kRenderScript + "</script>\n";
  }
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace linkproof::report
