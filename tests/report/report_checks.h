// Structural checks of rendered reports, shared by the report tests and the fuzz target
// fuzz_report (header only, no GoogleTest): where a LaTeX listing ends, whether braces balance,
// which commands a LaTeX text holds, how a Markdown text is cut into fences, headings, tables
// and raw HTML as a CommonMark reader cuts it; and the hostile scenes the tests report on.
#pragma once

#include <cctype>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace linkproof::test {

inline std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

inline std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t nl = s.find('\n'); nl != std::string::npos; nl = s.find('\n', start)) {
    out.push_back(s.substr(start, nl - start));
    start = nl + 1;
  }
  if (start < s.size()) out.push_back(s.substr(start));
  return out;
}

inline std::vector<std::string> lines_starting_with(const std::string& s, const std::string& prefix) {
  std::vector<std::string> out;
  for (const auto& l : split_lines(s))
    if (l.rfind(prefix, 0) == 0) out.push_back(l);
  return out;
}

// ------------------------------------------------------------------ LaTeX

/// The LaTeX text with every verbatim listing (from \begin{verbatim} to the first
/// \end{verbatim} after it, as LaTeX reads it) left out.
inline std::string latex_outside_verbatim(const std::string& tex) {
  static const std::string begin = "\\begin{verbatim}", end = "\\end{verbatim}";
  std::string out;
  std::size_t at = 0;
  for (std::size_t b = tex.find(begin); b != std::string::npos; b = tex.find(begin, at)) {
    out += tex.substr(at, b - at);
    const std::size_t e = tex.find(end, b + begin.size());
    if (e == std::string::npos) return out;  // an unclosed listing swallows the rest
    at = e + end.size();
  }
  return out + tex.substr(at);
}

/// "" if the braces of a LaTeX text (outside listings) balance, no group holds a blank line
/// (a \par inside an argument), and no unescaped % starts a comment; else what is wrong.
inline std::string latex_brace_depth_problem(const std::string& tex) {
  long depth = 0;
  for (std::size_t i = 0; i < tex.size(); ++i) {
    const char c = tex[i];
    if (c == '\\') {
      ++i;  // a control symbol (\{, \\, \%) or the first letter of a control word
      continue;
    }
    if (c == '%') return "an unescaped % at byte " + std::to_string(i);
    if (c == '{') ++depth;
    if (c == '}' && --depth < 0) return "a } without { at byte " + std::to_string(i);
    if (c == '\n' && depth > 0 && i + 1 < tex.size() && tex[i + 1] == '\n')
      return "a blank line inside a group at byte " + std::to_string(i);
  }
  return depth == 0 ? "" : std::to_string(depth) + " unclosed {";
}

/// The control sequences of a LaTeX text in order ("\section", "\\", "\[") except those that
/// escaping itself produces (\textbackslash, \{, \$, the Unicode and label mappings): two
/// renderings of one document that differ only in its plain strings give the same list.
inline std::vector<std::string> latex_structure(const std::string& tex) {
  static const char* made_by_escaping[] = {
      "textbackslash", "textasciitilde", "textasciicircum", "backslash", "hat", "sim", "dots", "omega", "dot",
      "beta", "lambda", "varphi", "mu", "Sigma", "neq", "le", "ge", "times", "cdot", "to", "varepsilon",
      "approx", "infty", "alpha", "gamma", "phi", "S"};
  std::vector<std::string> out;
  for (std::size_t i = 0; i < tex.size(); ++i) {
    if (tex[i] != '\\' || i + 1 >= tex.size()) continue;
    std::size_t j = i + 1;
    while (j < tex.size() && std::isalpha(static_cast<unsigned char>(tex[j]))) ++j;
    if (j == i + 1) {  // a control symbol
      const char s = tex[i + 1];
      if (s == '\\' || s == '[' || s == ']') out.push_back(std::string("\\") + s);
      i = i + 1;
      continue;
    }
    const std::string word = tex.substr(i + 1, j - i - 1);
    bool escaping = false;
    for (const char* w : made_by_escaping) escaping = escaping || word == w;
    if (!escaping) out.push_back("\\" + word);
    i = j - 1;
  }
  return out;
}

// ------------------------------------------------------------------ Markdown

/// How a CommonMark reader cuts a Markdown text (enough of it for reports).
/// The element names of an HTML text in order ("<section", "</section", ...): two texts with
/// the same sequence have the same structure whatever their strings hold.
inline std::vector<std::string> html_elements(const std::string& html) {
  std::vector<std::string> out;
  for (std::size_t at = html.find('<'); at != std::string::npos; at = html.find('<', at + 1)) {
    std::size_t end = at + 1;
    while (end < html.size() && html[end] != ' ' && html[end] != '>' && html[end] != '\n') ++end;
    out.push_back(html.substr(at, end - at));
  }
  return out;
}

struct MarkdownOutline {
  std::size_t fences = 0;               ///< fenced code blocks
  bool unclosed_fence = false;          ///< a fence still open at the end
  std::vector<std::string> headings;    ///< ATX heading lines, outside code blocks
  std::string raw_html_other_than_anchors;  ///< the first line with a raw < that is not an <a id> anchor
  std::vector<std::string> bad_table_rows;  ///< rows whose cell count differs from their header's
};

namespace detail {
inline bool escaped_at(const std::string& s, std::size_t i) {
  std::size_t backslashes = 0;
  while (i > backslashes && s[i - backslashes - 1] == '\\') ++backslashes;
  return backslashes % 2 == 1;
}
inline std::size_t leading(const std::string& s, char c, std::size_t from) {
  std::size_t n = 0;
  while (from + n < s.size() && s[from + n] == c) ++n;
  return n;
}
}  // namespace detail

inline MarkdownOutline markdown_outline(const std::string& md) {
  MarkdownOutline o;
  std::size_t fence = 0;  // length of the open fence, 0 outside
  std::size_t header_pipes = 0;
  bool in_table = false;
  for (const std::string& line : split_lines(md)) {
    const std::size_t indent = detail::leading(line, ' ', 0);
    const std::size_t ticks = indent <= 3 ? detail::leading(line, '`', indent) : 0;
    if (fence > 0) {
      if (ticks >= fence && line.find_first_not_of(" \t", indent + ticks) == std::string::npos) fence = 0;
      continue;
    }
    if (ticks >= 3) {
      fence = ticks;
      ++o.fences;
      in_table = false;
      continue;
    }
    if (indent <= 3) {
      const std::size_t hashes = detail::leading(line, '#', indent);
      if (hashes >= 1 && hashes <= 6 && (indent + hashes == line.size() || line[indent + hashes] == ' '))
        o.headings.push_back(line);
    }
    const bool anchor = line.rfind("<a id=\"", 0) == 0 && line.find('"', 7) == line.size() - 6 &&
                        line.compare(line.size() - 6, 6, "\"></a>") == 0;
    for (std::size_t i = 0; i < line.size() && !anchor; ++i)
      if (line[i] == '<' && !detail::escaped_at(line, i) && o.raw_html_other_than_anchors.empty())
        o.raw_html_other_than_anchors = line;
    if (!line.empty() && line[0] == '|') {
      std::size_t pipes = 0;
      for (std::size_t i = 0; i < line.size(); ++i) pipes += line[i] == '|' && !detail::escaped_at(line, i);
      if (!in_table) header_pipes = pipes, in_table = true;
      else if (pipes != header_pipes) o.bad_table_rows.push_back(line);
    } else {
      in_table = false;
    }
  }
  o.unclosed_fence = fence > 0;
  return o;
}

// ------------------------------------------------------------------ hostile scenes

/// Strings a report must show without obeying: LaTeX commands (also through ^^5c), a verbatim
/// end, math delimiters, HTML elements, Markdown fences, links and headings.
inline std::string hostile_fourbar_scene() {
  return R"(name: "H}$\\input{/etc/passwd}$<script>alert(1)</script>```\n# Injected title"
description: |
  ```
  \end{verbatim}
  \input{/etc/passwd}
  <script>alert(2)</script>
  # Injected heading
  ~~~
mechanism:
  ground: "G"
  links: ["G", "C}$\\input{/etc/passwd}$", "\\end{verbatim}<b>x</b>", "R```|x|"]
  joints:
    - {name: "O^^5cinput{/etc/passwd}", type: revolute, links: ["G", "C}$\\input{/etc/passwd}$"], at: [0, 0]}
    - {name: "A_}$\\input{/etc/passwd}", type: revolute, links: ["C}$\\input{/etc/passwd}$", "\\end{verbatim}<b>x</b>"], at: [3, 4]}
    - {name: "<img src=x onerror=alert(3)>", type: revolute, links: ["\\end{verbatim}<b>x</b>", "R```|x|"], at: [11, 10]}
    - {name: "[x](javascript:alert(4))%", type: revolute, links: ["R```|x|", "G"], at: [11, 0]}
  inputs:
    - {link: "C}$\\input{/etc/passwd}$", omega: 2, omega_dot: 5}
  points:
    - {name: "P\\section{Injected}", link: "\\end{verbatim}<b>x</b>", at: [9, 14]}
  catalogue: [fourbar_polygon, dijksman1966_compound]
)";
}

/// hostile_fourbar_scene with every string made harmless (the same underscores, so the same
/// subscripts in figure labels): its report has the structure the hostile one must have.
inline std::string benign_fourbar_scene() {
  return R"(name: "H"
description: |
  a description
mechanism:
  ground: "G"
  links: ["G", "C", "L", "R"]
  joints:
    - {name: "O", type: revolute, links: ["G", "C"], at: [0, 0]}
    - {name: "A_x", type: revolute, links: ["C", "L"], at: [3, 4]}
    - {name: "I", type: revolute, links: ["L", "R"], at: [11, 10]}
    - {name: "X", type: revolute, links: ["R", "G"], at: [11, 0]}
  inputs:
    - {link: "C", omega: 2, omega_dot: 5}
  points:
    - {name: "P", link: "L", at: [9, 14]}
  catalogue: [fourbar_polygon, dijksman1966_compound]
)";
}

/// The bundled pentagon's polygon (joints and rates), to follow a `name:` line.
inline std::string pentagon_polygon_yaml() {
  return "polygon:\n  joints: [[0, 0], [1, 4], [5, 5], [7, 1], [3, -2]]\n  omega: [2, -1]\n  omega_dot: [1, 3]\n";
}

}  // namespace linkproof::test
