#include "report/statement_tex.h"

#include <cctype>
#include <regex>
#include <vector>

namespace linkproof::report {

namespace {

bool formula_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || std::string_view(" _^{}()[]+-*/=,.;:'|<>!").find(c) != std::string_view::npos;
}

// Names that are mathematics although they are words.
bool math_word(const std::string& w) {
  static const char* names[] = {"omega", "omega-dot", "lambda", "beta", "phi", "mu", "alpha", "gamma", "theta",
                                "Delta", "sum", "cot", "sin", "cos"};
  for (const char* n : names)
    if (w == n) return true;
  return false;
}

// A token of prose: a word of two or more lower-case letters (inner hyphens allowed, "'s" at the
// end), or a capitalised one of three or more, that is not a mathematical name; surrounding
// parentheses and trailing punctuation do not count.
bool prose_token(std::string t) {
  while (!t.empty() && (t.front() == '(')) t.erase(0, 1);
  while (!t.empty() && std::string_view("),;:").find(t.back()) != std::string_view::npos) t.pop_back();
  if (t == "eq." || t == "sec." || t == "e.g." || t == "i.e.") return true;
  if (t.size() > 2 && t.compare(t.size() - 2, 2, "'s") == 0) t.resize(t.size() - 2);
  if (t.size() < 2 || math_word(t)) return false;
  const bool capital = std::isupper(static_cast<unsigned char>(t[0])) != 0;
  if (capital && t.size() < 3) return false;
  for (size_t k = capital ? 1 : 0; k < t.size(); ++k)
    if (!std::islower(static_cast<unsigned char>(t[k])) && t[k] != '-') return false;
  return t.front() != '-' && t.back() != '-';
}

}  // namespace

std::string formula_tex(const std::string& formula) {
  int depth = 0;
  for (const char c : formula) {
    if (!formula_char(c)) return "";
    depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (depth < 0) return "";
  }
  if (depth != 0 || formula.find("^^") != std::string::npos) return "";
  if (!formula.empty() && std::string_view("_^").find(formula.back()) != std::string_view::npos) return "";
  static const std::regex double_script(R"(_(\w|\{[^{}]*\})_|\^(\w|\{[^{}]*\})\^)");
  if (std::regex_search(formula, double_script)) return "";
  // A script after a space starts a new (empty) atom: "sum_j _j omega-dot" has a left subscript
  // on its second term, not a double subscript.
  std::string t = std::regex_replace(formula, std::regex("(^| )([_^])"), "$1{}$2");
  // omega-dot holds "omega": kept aside while the names are replaced on word boundaries.
  t = std::regex_replace(t, std::regex(R"(\bomega-dot(?![A-Za-z]))"), "OMEGADOT");
  t = std::regex_replace(t, std::regex(R"(\b(omega|lambda|beta|phi|mu|alpha|gamma|theta|Delta|sum|cot|sin|cos)(?![A-Za-z]))"),
                         "\\$1 ");
  t = std::regex_replace(t, std::regex(R"(!=)"), "\\neq ");
  // A subscript of several lower-case letters is a name: omega_out -> \omega_{\mathrm{out}}.
  t = std::regex_replace(t, std::regex(R"(_([a-z]{2,})(?![A-Za-z']))"), "_{\\mathrm{$1}}");
  t = std::regex_replace(t, std::regex("OMEGADOT"), "\\dot\\omega ");
  // Characters that Markdown reads (a table's cell bar, raw HTML) as commands every reader knows
  // (KaTeX, MathJax; the LaTeX report defines \lt and \gt).
  t = std::regex_replace(t, std::regex("<"), "\\lt ");
  t = std::regex_replace(t, std::regex(">"), "\\gt ");
  t = std::regex_replace(t, std::regex("\\|"), "\\vert ");
  // "\omega _{j}": no space before a script or a prime.
  t = std::regex_replace(t, std::regex(R"( +([_^']))"), "$1");
  t = std::regex_replace(t, std::regex("  +"), " ");
  while (!t.empty() && t.back() == ' ') t.pop_back();
  return t;
}

Rich statement_rich(const std::string& statement) {
  for (const char c : statement)
    if (!formula_char(c)) return plain(statement);
  std::vector<std::string> tokens;
  for (size_t at = 0; at < statement.size();) {
    const size_t next = statement.find(' ', at);
    const size_t end = next == std::string::npos ? statement.size() : next;
    if (end > at) tokens.push_back(statement.substr(at, end - at));
    at = end + 1;
  }
  Rich out;
  std::string prose, formula;
  const auto flush_formula = [&]() -> bool {
    if (formula.empty()) return true;
    const std::string tex = formula_tex(formula);
    if (tex.empty()) return false;
    out.push_back(math(tex));
    formula.clear();
    return true;
  };
  const auto flush_prose = [&] {
    if (!prose.empty()) out.push_back(text(prose));
    prose.clear();
  };
  for (size_t k = 0; k < tokens.size(); ++k) {
    if (prose_token(tokens[k])) {
      if (!flush_formula()) return plain(statement);
      prose += (out.empty() && prose.empty() ? "" : " ") + tokens[k];
    } else {
      if (!prose.empty()) {
        prose += " ";
        flush_prose();
      } else if (!out.empty() && formula.empty()) {
        out.push_back(text(" "));
      }
      formula += (formula.empty() ? "" : " ") + tokens[k];
    }
  }
  if (!flush_formula()) return plain(statement);
  flush_prose();
  return out;
}

Rich term_label_rich(const std::string& label) {
  static const std::regex factor(R"((omega|omega_dot)\[([0-9]+)\](\^2)?)");
  static const std::regex monomial(R"((j=[0-9]+: )?(omega|omega_dot)\[[0-9]+\](\^2)?(\*(omega|omega_dot)\[[0-9]+\](\^2)?)*)");
  if (!std::regex_match(label, monomial)) return plain(label);
  std::string out;
  const size_t colon = label.find(": ");
  if (colon != std::string::npos) out = label.substr(0, colon) + ":\\ ";
  const std::string rest = colon == std::string::npos ? label : label.substr(colon + 2);
  for (auto it = std::sregex_iterator(rest.begin(), rest.end(), factor); it != std::sregex_iterator(); ++it)
    out += std::string((*it)[1] == "omega" ? "\\omega" : "\\dot\\omega") + "_{" + (*it)[2].str() + "}" + (*it)[3].str();
  return tex(out);
}

}  // namespace linkproof::report
