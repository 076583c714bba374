#include "claims/mechanism_expression.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "claims/expression_scanner.h"
#include "linkproof/core/error.h"

namespace linkproof {

namespace {

// The limits of the mechanism language, as of the polygon one (docs/limits.md).
constexpr int kMaxNesting = 100;
constexpr int kMaxExponent = 64;
constexpr std::size_t kMaxIntegerDigits = 200;
constexpr std::size_t kMaxExpressionDegree = 1024;  // as a polygon claim's term (claim_expression.cpp)

using Tok = TokenKind;
using Token = ExpressionToken;

bool is_value(ClaimKind k) { return k == ClaimKind::Number || k == ClaimKind::Vector; }

class Parser {
 public:
  Parser(const std::string& text, const ExpressionContext& c, const PositionMap& pos)
      : text_(text), context_(c), positions_(pos) {}

  MechanismNode run() {
    tokenize();
    MechanismNode root = expression(0);
    if (tokens_[i_].kind != Tok::End)
      fail(tokens_[i_].offset, tokens_[i_].kind == Tok::Close ? "'" + tokens_[i_].text + "' closes no bracket"
                                                               : "unexpected '" + tokens_[i_].text + "'");
    (void)degree_bound(root);
    return root;
  }

 private:
  std::string where(size_t offset) const {
    const auto [line, column] = positions_(offset);
    return context_.file + ":" + std::to_string(line) + ":" + std::to_string(column);
  }

  [[noreturn]] void fail(size_t offset, const std::string& problem) const {
    throw InputError(where(offset), context_.field, problem);
  }

  std::string slice(size_t from, size_t to) const {
    std::string t = text_.substr(from, to - from);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
    return t;
  }

  void tokenize() {
    try {
      tokens_ = scan_expression(text_, ScanRules{.quoted_names = true, .max_integer_digits = kMaxIntegerDigits});
    } catch (const ScanError& e) {
      fail(e.offset, e.problem);
    }
  }

  // A bound on the degree of a node, a number counting its digits (as the polygon language
  // bounds a term): a product adds, a power multiplies. Past kMaxExpressionDegree the claim is
  // refused before any work: ((N^64)^64)^64 of a 200-digit N is a 52-million-digit number that
  // exact arithmetic would form and print for as long as the run's budget allows.
  std::size_t degree_bound(const MechanismNode& n) const {
    using Op = MechanismNode::Op;
    std::size_t d = 0;
    switch (n.op) {
      case Op::Constant: d = n.text.size(); break;
      case Op::Name: d = 0; break;
      case Op::Negate: d = degree_bound(n.children[0]); break;
      case Op::Add:
      case Op::Subtract: d = std::max(degree_bound(n.children[0]), degree_bound(n.children[1])); break;
      case Op::Multiply:
      case Op::Divide: d = degree_bound(n.children[0]) + degree_bound(n.children[1]); break;
      case Op::Power: d = degree_bound(n.children[0]) * static_cast<std::size_t>(std::abs(n.exponent)); break;
      case Op::Call:
        d = 1;
        for (const MechanismNode& c : n.children) d += degree_bound(c);
        break;
    }
    if (d > kMaxExpressionDegree)
      throw InputError(n.where, context_.field,
                       fmt::format("{} has degree (digits of numbers included) above {}: it would expand beyond the "
                                   "budget (docs/limits.md)",
                                   n.text.size() > 60 ? n.text.substr(0, 60) + "..." : n.text, kMaxExpressionDegree));
    return d;
  }

  bool at_op(const char* op) const { return tokens_[i_].kind == Tok::Op && tokens_[i_].text == op; }

  MechanismNode binary(MechanismNode::Op op, MechanismNode a, MechanismNode b, size_t from, size_t op_offset) {
    using K = ClaimKind;
    MechanismNode n;
    n.op = op;
    n.where = a.where;
    n.text = slice(from, tokens_[i_].offset);
    switch (op) {
      case MechanismNode::Op::Add:
      case MechanismNode::Op::Subtract:
        if (a.kind != b.kind)
          fail(op_offset, fmt::format("'{}' between {} and {}: both sides of + and - must be numbers or both vectors",
                                      op == MechanismNode::Op::Add ? "+" : "-", describe(a.kind), describe(b.kind)));
        n.kind = a.kind;
        break;
      case MechanismNode::Op::Multiply:
        if (a.kind == K::Vector && b.kind == K::Vector)
          fail(op_offset, "a product of two vectors: write dot(a, b) or cross(a, b)");
        n.kind = a.kind == K::Vector || b.kind == K::Vector ? K::Vector : K::Number;
        break;
      case MechanismNode::Op::Divide:
        if (b.kind == K::Vector) fail(op_offset, "a division by a vector: a vector where a number is expected");
        n.kind = a.kind;
        break;
      default: break;
    }
    n.children.push_back(std::move(a));
    n.children.push_back(std::move(b));
    return n;
  }

  MechanismNode expression(int depth) {
    if (depth > kMaxNesting)
      fail(tokens_[i_].offset, fmt::format("brackets and calls are nested more than {} levels deep (docs/limits.md)",
                                           kMaxNesting));
    const size_t from = tokens_[i_].offset;
    MechanismNode left = term(depth);
    while (at_op("+") || at_op("-")) {
      const Token& op = tokens_[i_++];
      MechanismNode right = term(depth);
      left = binary(op.text == "+" ? MechanismNode::Op::Add : MechanismNode::Op::Subtract, std::move(left),
                    std::move(right), from, op.offset);
    }
    return left;
  }

  MechanismNode term(int depth) {
    const size_t from = tokens_[i_].offset;
    MechanismNode left = factor(depth, 0);
    while (at_op("*") || at_op("/")) {
      const Token& op = tokens_[i_++];
      MechanismNode right = factor(depth, 0);
      left = binary(op.text == "*" ? MechanismNode::Op::Multiply : MechanismNode::Op::Divide, std::move(left),
                    std::move(right), from, op.offset);
    }
    return left;
  }

  MechanismNode factor(int depth, int signs) {
    const Token& t = tokens_[i_];
    if (t.kind == Tok::Op && (t.text == "-" || t.text == "+")) {
      if (signs >= 8) fail(t.offset, "more than 8 signs in a row (docs/limits.md)");
      ++i_;
      MechanismNode inner = factor(depth, signs + 1);
      if (t.text == "+") return inner;
      MechanismNode n;
      n.op = MechanismNode::Op::Negate;
      n.kind = inner.kind;
      n.where = where(t.offset);
      n.text = slice(t.offset, tokens_[i_].offset);
      n.children.push_back(std::move(inner));
      return n;
    }
    MechanismNode base = atom(depth);
    if (!at_op("^")) return base;
    const size_t caret = tokens_[i_++].offset;
    if (base.kind != ClaimKind::Number) fail(caret, "a power of a vector: a vector where a number is expected");
    const int e = exponent(caret);
    MechanismNode n;
    n.op = MechanismNode::Op::Power;
    n.exponent = e;
    n.where = base.where;
    n.text = slice(t.offset, tokens_[i_].offset);
    n.children.push_back(std::move(base));
    if (at_op("^")) fail(tokens_[i_].offset, "a power of a power needs brackets: write (a^b)^c");
    return n;
  }

  int exponent(size_t caret) {
    const auto refuse = [&] {
      fail(caret, fmt::format("the exponent of '^' must be an integer from -{0} to {0} written as a number, as in "
                              "x^2 or x^(-1) (docs/limits.md)",
                              kMaxExponent));
    };
    const bool bracket = tokens_[i_].kind == Tok::Open;
    if (bracket) ++i_;
    bool negative = false;
    if (bracket && (at_op("-") || at_op("+"))) negative = tokens_[i_++].text == "-";
    if (tokens_[i_].kind != Tok::Number || tokens_[i_].text.size() > 3) refuse();
    const int e = std::stoi(tokens_[i_++].text);
    if (e > kMaxExponent) refuse();
    if (bracket) {
      if (tokens_[i_].kind != Tok::Close) refuse();
      ++i_;
    }
    return negative ? -e : e;
  }

  void operator_missing_check() {
    const Token& t = tokens_[i_];
    if (t.kind == Tok::Number || t.kind == Tok::Name || t.kind == Tok::Quoted || t.kind == Tok::Open)
      fail(t.offset, "an operator is missing before '" + t.text + "' (write * for a product)");
  }

  MechanismNode atom(int depth) {
    const Token& t = tokens_[i_];
    MechanismNode n;
    n.where = where(t.offset);
    switch (t.kind) {
      case Tok::Number:
        ++i_;
        n.op = MechanismNode::Op::Constant;
        n.constant = parse_rational(t.text);
        n.text = t.text;
        break;
      case Tok::Open: {
        ++i_;
        n = expression(depth + 1);
        if (tokens_[i_].kind != Tok::Close)
          fail(tokens_[i_].kind == Tok::End ? t.offset : tokens_[i_].offset,
               tokens_[i_].kind == Tok::End ? "this '(' is never closed" : "expected ')', got '" + tokens_[i_].text + "'");
        ++i_;
        n.text = slice(t.offset, tokens_[i_].offset);
        break;
      }
      case Tok::Name: n = call(depth); break;
      case Tok::Quoted:
        fail(t.offset, "the quoted name \"" + t.text + "\" where a number or vector is expected: names are arguments "
                       "of words such as omega(\"" + t.text + "\")");
      default:
        fail(t.offset, t.kind == Tok::End ? "the expression ends where an operand is expected"
                                          : "'" + t.text + "' where an operand is expected");
    }
    operator_missing_check();
    return n;
  }

  // A word's argument: a name (bare or quoted) followed by ',' or ')', or an expression.
  MechanismNode argument(int depth) {
    const Token& t = tokens_[i_];
    const Tok next = tokens_[i_ + 1 < tokens_.size() ? i_ + 1 : i_].kind;
    if ((t.kind == Tok::Quoted || (t.kind == Tok::Name && next != Tok::Open)) &&
        (next == Tok::Comma || next == Tok::Close)) {
      ++i_;
      MechanismNode n;
      n.op = MechanismNode::Op::Name;
      n.kind = ClaimKind::Link;  // set from the word's table entry by the caller
      n.name = t.text;
      n.text = t.kind == Tok::Quoted ? "\"" + t.text + "\"" : t.text;
      n.where = where(t.offset);
      return n;
    }
    return expression(depth + 1);
  }

  MechanismNode call(int depth) {
    const Token& t = tokens_[i_++];
    const std::string signatures = word_signatures(Language::Mechanism, t.text);
    if (signatures.empty())
      fail(t.offset, "unknown word '" + t.text +
                         "' (see `linkproof check-claim --vocabulary`; a link, joint or point name is an argument, "
                         "as in omega(" + t.text + ") or pos(" + t.text + "))");
    if (tokens_[i_].kind != Tok::Open) fail(t.offset, "'" + t.text + "' needs its arguments: " + signatures);
    const size_t open = tokens_[i_++].offset;
    std::vector<MechanismNode> args;
    if (tokens_[i_].kind == Tok::Close) fail(tokens_[i_].offset, "'" + t.text + "' needs arguments: " + signatures);
    for (;;) {
      args.push_back(argument(depth));
      if (tokens_[i_].kind == Tok::Comma) {
        ++i_;
        continue;
      }
      if (tokens_[i_].kind == Tok::Close) break;
      fail(tokens_[i_].kind == Tok::End ? open : tokens_[i_].offset,
           tokens_[i_].kind == Tok::End ? "this '(' is never closed"
                                        : "expected ',' or ')', got '" + tokens_[i_].text + "'");
    }
    ++i_;
    const Word* w = find_word(Language::Mechanism, t.text, static_cast<int>(args.size()));
    if (!w)
      fail(t.offset, fmt::format("'{}' with {} argument{}: it takes {}", t.text, args.size(),
                                 args.size() == 1 ? "" : "s", signatures));
    for (size_t k = 0; k < args.size(); ++k) {
      MechanismNode& a = args[k];
      const ClaimKind want = w->arguments[k];
      const bool is_name = a.op == MechanismNode::Op::Name;
      if (is_value(want) && is_name)
        fail(a.where, a.text, fmt::format("argument {} of {} is {}, but '{}' is a name (names are arguments of words "
                                          "such as pos({}) or omega({}))",
                                          k + 1, w->signature, describe(want), a.name, a.text, a.text));
      if (!is_value(want) && !is_name)
        fail(a.where, a.text, fmt::format("argument {} of {} is {}, written bare or in quotes; got an expression",
                                          k + 1, w->signature, describe(want)));
      if (is_value(want) && a.kind != want)
        fail(a.where, a.text, fmt::format("argument {} of {} is {}; got {}{}", k + 1, w->signature, describe(want),
                                          describe(a.kind),
                                          want == ClaimKind::Number ? ": a vector where a number is expected"
                                                                        : ": a number where a vector is expected"));
      if (is_name) a.kind = want;
    }
    MechanismNode n;
    n.op = MechanismNode::Op::Call;
    n.word = w;
    n.kind = w->result;
    n.where = where(t.offset);
    n.text = slice(t.offset, tokens_[i_].offset);
    n.children = std::move(args);
    return n;
  }

  // An argument's error at its recorded place ("FILE:L:C" already).
  [[noreturn]] void fail(const std::string& at, const std::string&, const std::string& problem) const {
    throw InputError(at, context_.field, problem);
  }

  const std::string& text_;
  const ExpressionContext& context_;
  const PositionMap& positions_;
  std::vector<Token> tokens_;
  size_t i_ = 0;
};

}  // namespace

MechanismExpression MechanismExpression::parse(const std::string& text, const ExpressionContext& context,
                                               const PositionMap& positions) {
  MechanismExpression e;
  e.text_ = text;
  e.field_ = context.field;
  e.root_ = Parser(text, context, positions).run();
  return e;
}

}  // namespace linkproof
