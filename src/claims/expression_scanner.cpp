#include "claims/expression_scanner.h"

#include <fmt/format.h>

#include <cctype>

namespace linkproof {

namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool starts_name(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool continues_name(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The end of a decimal number written from `start` (0.5, 1e-3, 2.5E+4), for the message.
std::size_t decimal_end(const std::string& t, std::size_t i) {
  std::size_t end = i + 1;
  while (end < t.size() && (is_digit(t[end]) || t[end] == '.' || t[end] == 'e' || t[end] == 'E' ||
                            ((t[end] == '-' || t[end] == '+') && (t[end - 1] == 'e' || t[end - 1] == 'E'))))
    ++end;
  return end;
}

}  // namespace

std::vector<ExpressionToken> scan_expression(const std::string& text, const ScanRules& rules) {
  const auto fail = [](std::size_t offset, std::string problem) { throw ScanError{offset, std::move(problem)}; };
  if (text.size() > kMaxClaimExpressionCharacters)
    fail(0, fmt::format("the expression has {} characters; the limit is {} (docs/limits.md)", text.size(),
                        kMaxClaimExpressionCharacters));
  std::vector<ExpressionToken> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    const char ch = text[i];
    if (is_space(ch)) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    if (starts_name(ch)) {
      while (i < text.size() && continues_name(text[i])) ++i;
      tokens.push_back({TokenKind::Name, text.substr(start, i - start), start});
    } else if (rules.quoted_names && (ch == '"' || ch == '\'')) {
      const std::size_t close = text.find(ch, i + 1);
      if (close == std::string::npos) fail(start, fmt::format("this {} is never closed", ch));
      if (close == i + 1) fail(start, "an empty quoted name");
      tokens.push_back({TokenKind::Quoted, text.substr(i + 1, close - i - 1), start});
      i = close + 1;
    } else if (is_digit(ch)) {
      while (i < text.size() && is_digit(text[i])) ++i;
      if (i < text.size() && (text[i] == '.' || text[i] == 'e' || text[i] == 'E'))
        fail(start, "'" + text.substr(start, decimal_end(text, i) - start) +
                        "' is a decimal number: claims are exact, write a fraction such as 1/2");
      if (rules.max_integer_digits && i - start > rules.max_integer_digits)
        fail(start, fmt::format("an integer of {} digits; the limit is {} (docs/limits.md)", i - start,
                                rules.max_integer_digits));
      tokens.push_back({TokenKind::Number, text.substr(start, i - start), start});
    } else if (std::string("+-*/^").find(ch) != std::string::npos) {
      tokens.push_back({TokenKind::Op, std::string(1, ch), i++});
    } else if (ch == '(' || (rules.square_brackets && ch == '[')) {
      tokens.push_back({TokenKind::Open, std::string(1, ch), i++});
    } else if (ch == ')' || (rules.square_brackets && ch == ']')) {
      tokens.push_back({TokenKind::Close, std::string(1, ch), i++});
    } else if (ch == ',') {
      tokens.push_back({TokenKind::Comma, ",", i++});
    } else {
      const auto byte = static_cast<unsigned char>(ch);
      fail(i, byte < 0x20 || byte >= 0x7f ? fmt::format("unexpected byte 0x{:02x}", byte)
                                          : std::string("unexpected character '") + ch + "'");
    }
  }
  tokens.push_back({TokenKind::End, "end of expression", text.size()});
  return tokens;
}

}  // namespace linkproof
