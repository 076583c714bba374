// Markdown escaping (report/escape.h): inline text and fenced code blocks.
#include <algorithm>
#include <cctype>
#include <string_view>

#include "report/escape.h"

namespace linkproof::report {

std::string markdown_escape(const std::string& s, bool block_start) {
  std::string out;
  out.reserve(s.size());
  std::size_t i = 0;
  if (block_start) {
    // Up to three leading spaces are dropped by Markdown anyway; four make a code block.
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
    std::size_t digits = i;
    while (digits < s.size() && digits - i < 10 && std::isdigit(static_cast<unsigned char>(s[digits]))) ++digits;
    if (i < s.size() && std::string_view("[-+=>").find(s[i]) != std::string_view::npos) {
      out += '\\';  // a link definition, a list item, a setext underline, a block quote
    } else if (digits > i && digits < s.size() && (s[digits] == '.' || s[digits] == ')')) {
      out.append(s, i, digits - i);  // "1." would start an ordered list
      out += '\\';
      i = digits;
    }
  }
  for (; i < s.size(); ++i) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '\\': case '`': case '*': case '_': case '<': case '|': case '$': case '&': case '#': case '~':
        out += '\\';
        out += c;
        break;
      case ']':
        if (i + 1 < s.size() && (s[i + 1] == '(' || s[i + 1] == '[')) out += '\\';  // no [text](url), [text][ref]
        out += c;
        break;
      case '\t': case '\n': case '\r': out += ' '; break;  // a line break could start a block
      default: out += u < 0x20 || u == 0x7f ? '?' : c;
    }
  }
  return out;
}

std::string markdown_code_block(const std::string& code) {
  std::size_t longest = 0, run = 0;
  for (char c : code) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  // A closing fence must be at least as long as the opening one: a longer fence than any
  // backtick run inside cannot be closed from inside.
  const std::string fence(std::max<std::size_t>(3, longest + 1), '`');
  return fence + "\n" + code + "\n" + fence + "\n";
}

}  // namespace linkproof::report
