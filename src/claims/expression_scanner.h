// The tokens of a claim expression: one scanner for both claim languages, the polygon one
// (claims/claim_expression.cpp, checked before GiNaC parses it) and the mechanism one
// (claims/mechanism_expression.cpp). What differs between them is a rule, not a copy: whether a
// name may be quoted ("3", a mechanism's link), whether [ ] are brackets (a polygon's index r[k]),
// and the limits (docs/limits.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace linkproof {

enum class TokenKind { Name, Quoted, Number, Op, Open, Close, Comma, End };

struct ExpressionToken {
  TokenKind kind;
  std::string text;  ///< as written (a quoted name without its quotes)
  std::size_t offset;
};

struct ScanRules {
  bool quoted_names = false;         ///< "name" and 'name' are Quoted tokens
  bool square_brackets = false;      ///< [ and ] are Open and Close tokens
  std::size_t max_integer_digits = 0;  ///< 0: no limit here (the caller bounds the degree)
};

/// The expression's length limit, for both languages (docs/limits.md).
constexpr std::size_t kMaxClaimExpressionCharacters = 20000;

/// What the scanner refuses, at a byte offset of the expression (the caller names the file,
/// line and column).
struct ScanError {
  std::size_t offset;
  std::string problem;
};

/// The tokens of `text`, ending with an End token at text.size(); throws ScanError: too long, a
/// decimal number (claims are exact), an integer over the digit limit, a quote never closed or
/// empty, an unexpected character or byte.
std::vector<ExpressionToken> scan_expression(const std::string& text, const ScanRules& rules);

}  // namespace linkproof
