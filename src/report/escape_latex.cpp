// LaTeX escaping (report/escape.h): running text, math-mode labels and verbatim listings.
#include <cctype>
#include <string_view>
#include <utility>

#include "report/escape.h"

namespace linkproof::report {

namespace {

bool is_control(unsigned char c) { return c < 0x20 || c == 0x7f; }

// The bytes of the (possibly invalid) UTF-8 character starting at s[i]: its lead byte and
// the continuation bytes after it. A stray continuation byte counts as one character.
std::size_t non_ascii_length(const std::string& s, std::size_t i) {
  std::size_t n = 1;
  while (i + n < s.size() && (static_cast<unsigned char>(s[i + n]) & 0xC0) == 0x80) ++n;
  return n;
}

// pdflatex with inputenc reads UTF-8 but has glyphs for little of it: the characters reports
// use are mapped to TeX. The first entry (omega with a combining dot) must precede omega.
constexpr std::pair<const char*, const char*> kUnicodeTex[] = {
    {"ω̇", "$\\dot\\omega$"}, {"ω", "$\\omega$"}, {"β", "$\\beta$"}, {"λ", "$\\lambda$"}, {"φ", "$\\varphi$"},
    {"μ", "$\\mu$"},        {"Σ", "$\\Sigma$"}, {"≠", "$\\neq$"},  {"≤", "$\\le$"},     {"≥", "$\\ge$"},
    {"×", "$\\times$"},     {"·", "$\\cdot$"},  {"→", "$\\to$"},   {"−", "-"},          {"–", "--"},
    {"—", "---"},           {"′", "'"},         {"²", "$^2$"},     {"…", "\\dots{}"},   {"ε", "$\\varepsilon$"},
    {"≈", "$\\approx$"},    {"∞", "$\\infty$"}, {"α", "$\\alpha$"}, {"γ", "$\\gamma$"},
    {"§", "\\S{}"}};

}  // namespace

std::string latex_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {
      bool mapped = false;
      for (const auto& [from, to] : kUnicodeTex) {
        const std::string f = from;
        if (s.compare(i, f.size(), f) == 0) {
          out += to, i += f.size(), mapped = true;
          break;
        }
      }
      if (!mapped) out += '?', i += non_ascii_length(s, i);  // no glyph: shown, never an error
      continue;
    }
    switch (c) {
      case '\\': out += "\\textbackslash{}"; break;
      case '&': case '%': case '$': case '#': case '_': case '{': case '}': out += '\\'; out += c; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '<': out += "$<$"; break;
      case '>': out += "$>$"; break;
      // A blank line inside an argument (\section{...}) is an error: line ends are spaces.
      case '\t': case '\n': case '\r': out += ' '; break;
      default: out += is_control(u) ? '?' : c;  // ^^L is an \outer macro, DEL an invalid character
    }
    ++i;
  }
  return out;
}

std::string latex_math_escape(const std::string& s, bool superscript_ok) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {  // math fonts have no glyph for it and inputenc's text mapping fails in math
      out += '?';
      i += non_ascii_length(s, i);
      continue;
    }
    switch (c) {
      case '\\': out += "\\backslash{}"; break;
      case '{': case '}': case '$': case '&': case '%': case '#': case '_': out += '\\'; out += c; break;
      case '~': out += "\\sim{}"; break;
      case '^': {
        // The program's own labels end in a one-letter superscript ("A_BA^t"); any other ^
        // could start TeX's ^^5c notation (a backslash) or a double superscript.
        const bool last_superscript =
            superscript_ok && i + 2 == s.size() && std::isalnum(static_cast<unsigned char>(s[i + 1]));
        out += last_superscript ? "^" : "\\hat{}";
        break;
      }
      default:
        if (std::isalnum(u) || std::string_view(" '-+.,()/=:;!?*|[]<>@\"").find(c) != std::string_view::npos)
          out += c;
        else
          out += '?';  // control characters and the rest
    }
    ++i;
  }
  return out;
}

std::string latex_verbatim(const std::string& code) {
  static const std::string end_marker = "\\end{verbatim}";
  // verbatim prints every character as it is, but ends at the first \end{verbatim}, reads
  // control characters as TeX does (^^L is \outer) and non-ASCII through inputenc: the text is
  // first reduced to printable ASCII and line ends.
  std::string text;
  text.reserve(code.size() + 1);
  for (std::size_t i = 0; i < code.size();) {
    const auto u = static_cast<unsigned char>(code[i]);
    if (u >= 0x80) {
      // The section sign of the citations (docs/conventions.md §A3) is spelled out; the rest has
      // no ASCII form.
      const bool section = code.compare(i, 2, "§") == 0;
      text += section ? "sec. " : "?";
      i += section ? 2 : non_ascii_length(code, i);
      continue;
    }
    if (u == '\r') {
      text += '\n';
      i += i + 1 < code.size() && code[i + 1] == '\n' ? 2 : 1;
      continue;
    }
    text += u == '\n' || u == '\t' || !is_control(u) ? code[i] : '?';
    ++i;
  }
  std::string out = "\\begin{verbatim}\n";
  // verbatim lines are not broken: long ones are folded at 90 characters, and a line is also
  // broken before the character that would complete \end{verbatim}.
  std::string line;
  for (char c : text + "\n") {
    const bool closes = c == '}' && line.size() + 1 >= end_marker.size() &&
                        line.compare(line.size() + 1 - end_marker.size(), std::string::npos, end_marker, 0,
                                     end_marker.size() - 1) == 0;
    if (c == '\n' || line.size() >= 90 || closes) {
      out += line + "\n";
      line.clear();
      if (c == '\n') continue;
    }
    line += c;
  }
  out += end_marker + "\n";
  return out;
}

}  // namespace linkproof::report
