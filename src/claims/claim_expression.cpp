#include "claims/claim_expression.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <map>
#include <sstream>
#include <unordered_map>
#include <set>
#include <utility>
#include <vector>

#include "claims/claim_program.h"
#include "claims/expression_scanner.h"
#include "claims/vocabulary.h"
#include "linkproof/core/error.h"

namespace linkproof {
namespace {
// A word's call printed as the claim file writes it (r[1], dot(a, b)), so that messages about a
// claim quote the claim and not its internal form (lp_word1(32,1)).
void print_word(const GiNaC::ex& code, std::initializer_list<const GiNaC::ex*> args, const GiNaC::print_context& c) {
  const Word& w = word_of_code(GiNaC::ex_to<GiNaC::numeric>(code).to_int());
  const bool indexed = w.is_indexed();
  c.s << w.name << (indexed ? "[" : "(");
  const char* separator = "";
  for (const GiNaC::ex* a : args) {
    c.s << separator;
    a->print(c);
    separator = ", ";
  }
  c.s << (indexed ? "]" : ")");
}
void print_word1(const GiNaC::ex& code, const GiNaC::ex& a, const GiNaC::print_context& c) { print_word(code, {&a}, c); }
void print_word2(const GiNaC::ex& code, const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::print_context& c) {
  print_word(code, {&a, &b}, c);
}
}  // namespace
}  // namespace linkproof

namespace GiNaC {
// A call of a vocabulary word: lp_word1(code, a) and lp_word2(code, a, b). GiNaC leaves them
// unevaluated (no eval method), so they are plain tree nodes for the claim evaluator.
DECLARE_FUNCTION_2P(lp_word1)
DECLARE_FUNCTION_3P(lp_word2)
REGISTER_FUNCTION(lp_word1, print_func<print_dflt>(linkproof::print_word1))
REGISTER_FUNCTION(lp_word2, print_func<print_dflt>(linkproof::print_word2))
}  // namespace GiNaC

namespace linkproof {

namespace {

// Limits stated in docs/limits.md; each refusal names file:line:column.
constexpr int kMaxExpressionNesting = 100;  // GiNaC's parser recurses per bracket and per sign
constexpr int kMaxUnarySigns = 8;
constexpr int kMaxExponent = 64;
constexpr std::size_t kMaxExpressionDegree = 1024;

// --- The atom table ---------------------------------------------------------------------------

struct AtomTable {
  std::map<int, GiNaC::symbol> symbols;
  GiNaC::symtab symtab;
  GiNaC::prototype_table prototypes;
};

template <int Code>
GiNaC::ex read_call1(const GiNaC::exvector& a) { return GiNaC::lp_word1(Code, a[0]); }
template <int Code>
GiNaC::ex read_call2(const GiNaC::exvector& a) { return GiNaC::lp_word2(Code, a[0], a[1]); }

constexpr int kMaxWords = 64;

// The readers of the calls of every polygon word, by code (a GiNaC reader is a plain function,
// so the code is a template argument).
template <int... Codes>
void register_readers(AtomTable& t, std::integer_sequence<int, Codes...>) {
  static const GiNaC::reader_func one[] = {&read_call1<Codes>...}, two[] = {&read_call2<Codes>...};
  for (const Word& w : vocabulary()) {
    if (!w.belongs_to(Language::Polygon) || w.arity() == 0) continue;
    const int code = word_code(w);
    LINKPROOF_ASSERT(code < kMaxWords && w.arity() <= 2, "raise kMaxWords, or add a reader of 3 arguments");
    t.prototypes[{w.name, static_cast<std::size_t>(w.arity())}] = w.arity() == 1 ? one[code] : two[code];
  }
}

const AtomTable& atoms() {
  static const AtomTable table = [] {
    AtomTable t;
    for (const Word& w : vocabulary())
      if (w.belongs_to(Language::Polygon) && w.arity() == 0) {
        GiNaC::symbol s(w.name);
        t.symbols.emplace(word_code(w), s);
        t.symtab[w.name] = s;
      }
    register_readers(t, std::make_integer_sequence<int, kMaxWords>{});
    return t;
  }();
  return table;
}

const Word* polygon_word_called(const std::string& name, int arity) { return find_word(Language::Polygon, name, arity); }

// --- The scanner ------------------------------------------------------------------------------

// Which inputs a sum binds, and the names of the index symbols it binds.
IndexBinding sum_binding(const Word& sum) {
  switch (sum.evaluation) {
    case Evaluation::SumJ: return IndexBinding::SumJ;
    case Evaluation::SumPairs: return IndexBinding::SumPairs;
    case Evaluation::SumPairsLt: return IndexBinding::SumPairsLt;
    default: throw InternalError("the sum '" + sum.name + "' binds no known indices");
  }
}
std::vector<std::string> bound_by(IndexBinding b) {
  const std::string& j = polygon_word(Evaluation::IndexJ).name;
  if (b == IndexBinding::SumJ) return {j};
  return {j, polygon_word(Evaluation::IndexL).name};
}

using Tok = TokenKind;
using Token = ExpressionToken;

class Scanner {
 public:
  Scanner(const std::string& text, const ExpressionContext& c, const PositionMap& pos)
      : text_(text), context_(c), positions_(pos) {}

  void run() {
    tokenize();
    size_t i = 0;
    std::set<std::string> bound;
    if (context_.j_is_free) {
      bound.insert(polygon_word(Evaluation::IndexJ).name);
      binding_ = IndexBinding::ForEachJ;
    }
    expression(i, bound, /*in_index=*/false, /*depth=*/0);
    if (tokens_[i].kind != Tok::End) fail(tokens_[i].offset, "unexpected '" + tokens_[i].text + "'");
  }

  /// The indexed words met, with their index text (parsed into GiNaC by the caller).
  struct RawIndexUse {
    std::string word;
    bool input_index;
    std::string index_text;
    IndexBinding binding;
    std::string where;
  };
  const std::vector<RawIndexUse>& index_uses() const { return uses_; }

  /// A part of the text as written (a divisor, or a word with its index), with its binding.
  struct RawWritten {
    std::string text;
    IndexBinding binding;
    std::string where;
  };
  /// The divisors as written (the text between two offsets, trimmed), with their binding.
  const std::vector<RawWritten>& divisors() const { return divisors_; }

  /// The quantity words as written (the word and its index), with their binding.
  const std::vector<RawWritten>& words() const { return words_; }

 private:
  std::string where(size_t offset) const {
    const auto [line, column] = positions_(offset);
    return context_.file + ":" + std::to_string(line) + ":" + std::to_string(column);
  }

  void note_divisor(size_t from, size_t to) {
    std::string t = text_.substr(from, to - from);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
    divisors_.push_back({std::move(t), binding_, where(from)});
  }

  [[noreturn]] void fail(size_t offset, const std::string& problem) const {
    throw InputError(where(offset), context_.field, problem);
  }

  void tokenize() {
    try {
      tokens_ = scan_expression(text_, ScanRules{.quoted_names = false, .square_brackets = true});
    } catch (const ScanError& e) {
      fail(e.offset, e.problem);
    }
  }

  // expression := ['+'|'-']* operand ('^' exponent)* (op ['+'|'-']* operand ('^' exponent)*)*
  // Returns a bound on the expression's degree (a number counts its digits): what GiNaC would
  // expand is refused before GiNaC sees it (kMaxExpressionDegree).
  std::size_t expression(size_t& i, const std::set<std::string>& bound, bool in_index, int depth) {
    if (depth > kMaxExpressionNesting)
      fail(tokens_[i].offset, "brackets and calls are nested more than " + std::to_string(kMaxExpressionNesting) +
                                  " levels deep (docs/limits.md)");
    std::size_t best = 0, term = 0;
    bool divides = false;  // the operand follows a '/'
    for (;;) {
      const size_t signs_at = tokens_[i].offset;
      int signs = 0;
      while (tokens_[i].kind == Tok::Op && (tokens_[i].text == "-" || tokens_[i].text == "+")) ++i, ++signs;
      if (signs > kMaxUnarySigns)
        fail(signs_at, std::to_string(signs) + " signs in a row; at most " + std::to_string(kMaxUnarySigns) +
                           " are accepted (docs/limits.md)");
      const size_t operand_at = tokens_[i].offset;
      std::size_t last = operand(i, bound, in_index, depth);
      term += last;
      while (tokens_[i].kind == Tok::Op && tokens_[i].text == "^") {
        const size_t caret = tokens_[i++].offset;
        bool negative = false;
        const std::size_t e = exponent(i, caret, negative);
        if (negative && !in_index) note_divisor(operand_at, caret);
        term += last * e - last;
        last *= e;
        if (tokens_[i].kind == Tok::Op && tokens_[i].text == "^")
          fail(tokens_[i].offset, "a power of a power needs brackets: write (a^b)^c");
        if (term > kMaxExpressionDegree) break;
      }
      if (term > kMaxExpressionDegree)
        fail(signs_at, "this term has degree (digits of numbers included) above " +
                           std::to_string(kMaxExpressionDegree) + ": it would expand beyond the budget (docs/limits.md)");
      if (divides && !in_index) note_divisor(signs_at, tokens_[i].offset);
      if (tokens_[i].kind != Tok::Op) return std::max(best, term);
      const Token& op = tokens_[i++];
      divides = op.text == "/";
      if (op.text == "+" || op.text == "-") best = std::max(best, term), term = 0;
      if (tokens_[i].kind == Tok::Op && tokens_[i].text != "-" && tokens_[i].text != "+")
        fail(tokens_[i].offset, "'" + tokens_[i].text + "' right after '" + op.text + "': an operand is missing");
      if (tokens_[i].kind == Tok::End || tokens_[i].kind == Tok::Close || tokens_[i].kind == Tok::Comma)
        fail(tokens_[i].offset, "an operand is missing after '" + op.text + "'");
    }
  }

  // The exponent after '^': an integer written as a number, 2 or (-1), |e| <= kMaxExponent
  // (GiNaC would otherwise try 10^(10^10)). Returns |e|.
  std::size_t exponent(size_t& i, size_t caret, bool& negative) {
    const auto refuse = [&] {
      fail(caret, "the exponent of '^' must be an integer from -" + std::to_string(kMaxExponent) + " to " +
                      std::to_string(kMaxExponent) + " written as a number, as in x^2 or x^(-1) (docs/limits.md)");
    };
    const bool bracket = tokens_[i].kind == Tok::Open && tokens_[i].text == "(";
    if (bracket) ++i;
    if (tokens_[i].kind == Tok::Op && (tokens_[i].text == "-" || tokens_[i].text == "+")) negative = tokens_[i++].text == "-";
    if (tokens_[i].kind != Tok::Number || tokens_[i].text.size() > 3) refuse();
    const std::size_t e = std::stoul(tokens_[i++].text);
    if (e > static_cast<std::size_t>(kMaxExponent)) refuse();
    if (bracket) {
      if (tokens_[i].kind != Tok::Close || tokens_[i].text != ")") refuse();
      ++i;
    }
    if (tokens_[i].kind == Tok::Number || tokens_[i].kind == Tok::Name ||
        (tokens_[i].kind == Tok::Open && tokens_[i].text == "("))
      fail(tokens_[i].offset, "an operator is missing before '" + tokens_[i].text + "' (write * for a product)");
    return std::max<std::size_t>(e, 1);
  }

  std::size_t operand(size_t& i, const std::set<std::string>& bound, bool in_index, int depth) {
    const Token& t = tokens_[i];
    std::size_t degree = 1;
    switch (t.kind) {
      case Tok::Number: degree = t.text.size(); ++i; break;
      case Tok::Open: {
        if (t.text == "[") fail(t.offset, "'[' must follow a name that takes an index, as in r[n-1]");
        ++i;
        degree = expression(i, bound, in_index, depth + 1);
        expect_close(i, '(', t.offset);
        break;
      }
      case Tok::Name: degree = name(i, bound, in_index, depth); break;
      default: fail(t.offset, t.kind == Tok::End ? "the expression ends where an operand is expected"
                                                 : "'" + t.text + "' where an operand is expected");
    }
    if (tokens_[i].kind == Tok::Number || tokens_[i].kind == Tok::Name ||
        (tokens_[i].kind == Tok::Open && tokens_[i].text == "("))
      fail(tokens_[i].offset, "an operator is missing before '" + tokens_[i].text + "' (write * for a product)");
    return std::max<std::size_t>(degree, 1);
  }

  void expect_close(size_t& i, char open, size_t open_offset) {
    const char want = open == '(' ? ')' : ']';
    if (tokens_[i].kind != Tok::Close)
      fail(tokens_[i].kind == Tok::End ? open_offset : tokens_[i].offset,
           tokens_[i].kind == Tok::End ? std::string("this '") + open + "' is never closed"
                                       : "expected '" + std::string(1, want) + "', got '" + tokens_[i].text + "'");
    if (tokens_[i].text[0] != want)
      fail(tokens_[i].offset, "'" + tokens_[i].text + "' closes the '" + std::string(1, open) + "' at column " +
                                  std::to_string(positions_(open_offset).second));
    ++i;
  }

  std::size_t name(size_t& i, const std::set<std::string>& bound, bool in_index, int depth) {
    const Token& t = tokens_[i++];
    const bool call = tokens_[i].kind == Tok::Open;
    if (!call) {
      const Word* w = polygon_word_called(t.text, 0);
      if (!w) {
        if (polygon_word_called(t.text, 1) || polygon_word_called(t.text, 2))
          fail(t.offset, "'" + t.text + "' needs " + (polygon_word_called(t.text, 1) ? "an index or argument, as in " + t.text + "[j]"
                                                                                     : std::string("two arguments")));
        fail(t.offset, "unknown name '" + t.text + "' (see `linkproof check-claim --vocabulary`)");
      }
      if (w->result == ClaimKind::Index) {
        const bool is_n = w->evaluation == Evaluation::IndexN;  // n is never bound: it is the polygon's
        if (!in_index && is_n) fail(t.offset, "'n' may only be used inside an index, as in r[n-1]");
        if (!is_n && !bound.count(t.text))
          fail(t.offset, "'" + t.text + "' is not bound here: use it inside sum_j(...)/sum_pairs(...) or with for_each: j");
        if (!in_index) fail(t.offset, "'" + t.text + "' is an index: use it inside [ ], as in omega[" + t.text + "]");
      } else if (in_index) {
        fail(t.offset, "'" + t.text + "' inside an index: an index is built from n, j, l and integers");
      } else {
        words_.push_back({t.text, binding_, where(t.offset)});
      }
      return 1;
    }
    const Token& open = tokens_[i++];
    // Count the arguments.
    std::vector<size_t> argument_starts{i};
    const Word* w = nullptr;
    const bool is_index = open.text == "[";
    // Look ahead to the matching close to count commas at depth 0.
    {
      int level = 0;
      size_t k = i;
      int args = 1;
      for (; tokens_[k].kind != Tok::End; ++k) {
        if (tokens_[k].kind == Tok::Open) ++level;
        if (tokens_[k].kind == Tok::Close) {
          if (level == 0) break;
          --level;
        }
        if (tokens_[k].kind == Tok::Comma && level == 0) ++args;
      }
      if (k == i) fail(open.offset, "empty " + std::string(is_index ? "index" : "argument list"));
      w = polygon_word_called(t.text, args);
      if (!w) {
        const Word* any = polygon_word_called(t.text, 1)   ? polygon_word_called(t.text, 1)
                          : polygon_word_called(t.text, 2) ? polygon_word_called(t.text, 2)
                                                           : polygon_word_called(t.text, 0);
        if (!any) fail(t.offset, "unknown name '" + t.text + "' (see `linkproof check-claim --vocabulary`)");
        fail(t.offset, "'" + t.text + "' takes " + std::to_string(any->arity()) + " argument(s), not " + std::to_string(args));
      }
    }
    if (in_index) fail(t.offset, "'" + t.text + "' inside an index: an index is built from n, j, l and integers");
    const bool indexed = w->is_indexed();
    if (indexed && !is_index) fail(open.offset, "'" + t.text + "' is indexed with [ ], as in " + t.text + "[j]");
    if (!indexed && is_index) fail(open.offset, "'" + t.text + "' is called with ( ), not indexed with [ ]");
    if (indexed) {
      const size_t first = tokens_[i].offset;
      size_t close = i, level = 0;
      for (; tokens_[close].kind != Tok::End; ++close) {
        if (tokens_[close].kind == Tok::Open) ++level;
        if (tokens_[close].kind == Tok::Close) {
          if (level == 0) break;
          --level;
        }
      }
      const bool input = w->arguments[0] == ClaimKind::InputIndex;
      uses_.push_back({w->name, input, text_.substr(first, tokens_[close].offset - first), binding_, where(t.offset)});
      words_.push_back({text_.substr(t.offset, tokens_[close].offset + 1 - t.offset), binding_, where(t.offset)});
    }
    const IndexBinding outer = binding_;
    std::set<std::string> inner = bound;
    if (w->is_sum()) {
      binding_ = sum_binding(*w);
      for (const std::string& b : bound_by(binding_)) {
        if (bound.count(b)) fail(t.offset, "'" + t.text + "' binds " + b + ", which is already bound here");
        inner.insert(b);
      }
    }
    std::size_t degree = 1;
    for (;;) {
      degree = std::max(degree, expression(i, inner, indexed, depth + 1));
      if (tokens_[i].kind == Tok::Comma) { ++i; continue; }
      break;
    }
    expect_close(i, open.text[0], open.offset);
    binding_ = outer;
    return indexed ? 1 : degree;
  }

  const std::string& text_;
  const ExpressionContext& context_;
  const PositionMap& positions_;
  std::vector<Token> tokens_;
  IndexBinding binding_ = IndexBinding::None;
  std::vector<RawIndexUse> uses_;
  std::vector<RawWritten> divisors_;
  std::vector<RawWritten> words_;
};

// --- Words that evaluation never reads ------------------------------------------------------

// A leaf of a compiled expression: a quantity word, its index (null for a global word) and the
// binding it is read under.
struct Leaf {
  const Word* word;
  const ClaimProgram::Index* index;
  IndexBinding binding;
};

bool same_index(const ClaimProgram::Index* a, const ClaimProgram::Index* b) {
  if (!a || !b) return a == b;
  if (a->affine != b->affine) return false;
  if (a->affine) return a->c0 == b->c0 && a->cn == b->cn && a->cj == b->cj && a->cl == b->cl;
  return a->expression.is_equal(b->expression);
}

bool is_leaf(const ClaimProgram::Node& n) {
  using Op = ClaimProgram::Op;
  return n.op == Op::Global || n.op == Op::InputScalar || n.op == Op::InputVector || n.op == Op::SideVector ||
         n.op == Op::SideScalar;
}

void collect_leaves(const ClaimProgram& p, int id, IndexBinding binding, std::vector<Leaf>& out) {
  const ClaimProgram::Node& n = p.nodes[static_cast<size_t>(id)];
  if (is_leaf(n)) {
    out.push_back({n.word, n.index >= 0 ? &p.indexes[static_cast<size_t>(n.index)] : nullptr, binding});
    return;
  }
  if (n.op == ClaimProgram::Op::IndexSum) binding = sum_binding(*n.word);
  for (int c : n.children) collect_leaves(p, c, binding, out);
}

// Sets `cancelled` on each word that the compiled expression does not read as written (the same
// word, index and binding). A word that does not compile to one leaf is marked too (evaluated
// on its own: the safe side). An expression that does not compile marks nothing: evaluating it
// fails with that error before any word matters.
void mark_cancelled_words(const GiNaC::ex& expression, IndexBinding top, std::vector<WrittenWord>& words) {
  if (words.empty()) return;
  std::vector<Leaf> read;
  try {
    const ClaimProgram& p = compiled_claim(expression);
    collect_leaves(p, p.root, top, read);
  } catch (const InputError&) {
    return;
  }
  for (WrittenWord& w : words) {
    const ClaimProgram* alone = nullptr;
    try {
      alone = &compiled_claim(w.expression);
    } catch (const InputError&) {
      w.cancelled = true;
      continue;
    }
    const ClaimProgram::Node& root = alone->nodes[static_cast<size_t>(alone->root)];
    const ClaimProgram::Index* index = root.index >= 0 ? &alone->indexes[static_cast<size_t>(root.index)] : nullptr;
    w.cancelled = !is_leaf(root) || std::none_of(read.begin(), read.end(), [&](const Leaf& l) {
      return l.word == root.word && l.binding == w.binding && same_index(l.index, index);
    });
  }
}

}  // namespace

PositionMap standalone_positions(const std::string& text) {
  return [text](size_t offset) {
    int line = 1, column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
      if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    return std::pair<int, int>{line, column};
  };
}

ClaimExpression ClaimExpression::parse(const std::string& text, const ExpressionContext& context,
                                       const PositionMap& positions) {
  Scanner scanner(text, context, positions);
  scanner.run();
  std::string ginac_text = text;
  for (char& ch : ginac_text) {
    if (ch == '[') ch = '(';
    if (ch == ']') ch = ')';
  }
  ClaimExpression e;
  e.text_ = text;
  try {
    GiNaC::parser reader(atoms().symtab, /*strict=*/true, atoms().prototypes);
    e.expression_ = reader(ginac_text);
  } catch (const std::exception& x) {
    // The scanner accepts only what GiNaC's grammar accepts; reaching here is a scanner gap.
    const auto [line, column] = positions(0);
    throw InputError(context.file + ":" + std::to_string(line) + ":" + std::to_string(column), context.field,
                     std::string("GiNaC could not parse the expression: ") + x.what());
  }
  e.field_ = context.field;
  for (const auto& u : scanner.index_uses()) {
    GiNaC::parser reader(atoms().symtab, /*strict=*/true, atoms().prototypes);
    GiNaC::ex index;
    try {
      index = reader(u.index_text);
    } catch (const std::exception& x) {
      throw InputError(u.where, context.field, "cannot read the index of " + u.word + "[" + u.index_text + "]: " + x.what());
    }
    e.index_uses_.push_back({u.word, u.input_index, index, u.index_text, u.binding, u.where});
  }
  for (const auto& d : scanner.divisors()) {
    std::string ginac_divisor = d.text;
    for (char& ch : ginac_divisor) {
      if (ch == '[') ch = '(';
      if (ch == ']') ch = ')';
    }
    GiNaC::ex divisor;
    try {
      GiNaC::parser reader(atoms().symtab, /*strict=*/true, atoms().prototypes);
      divisor = reader(ginac_divisor);  // a part of what parsed above
    } catch (const std::exception& x) {
      throw InputError(d.where, context.field, "cannot read the divisor " + d.text + ": " + x.what());
    }
    if (!GiNaC::is_exactly_a<GiNaC::numeric>(divisor)) e.divisors_.push_back({d.text, divisor, d.binding, d.where});
  }
  for (const auto& w : scanner.words()) {
    std::string ginac_word = w.text;
    for (char& ch : ginac_word) {
      if (ch == '[') ch = '(';
      if (ch == ']') ch = ')';
    }
    try {
      GiNaC::parser reader(atoms().symtab, /*strict=*/true, atoms().prototypes);
      e.words_.push_back({w.text, reader(ginac_word), w.binding, w.where, false});  // a part of what parsed above
    } catch (const std::exception& x) {
      throw InputError(w.where, context.field, "cannot read " + w.text + ": " + x.what());
    }
  }
  mark_cancelled_words(e.expression_, context.j_is_free ? IndexBinding::ForEachJ : IndexBinding::None, e.words_);
  return e;
}

namespace claim_atoms {

const GiNaC::symbol& symbol_of(int word_code) { return atoms().symbols.at(word_code); }

const GiNaC::symbol& index_symbol(Evaluation e) { return symbol_of(word_code(polygon_word(e))); }

int code_of_symbol(const GiNaC::ex& e) {
  if (!GiNaC::is_exactly_a<GiNaC::symbol>(e)) return -1;
  for (const auto& [code, s] : atoms().symbols)
    if (e.is_equal(s)) return code;
  return -1;
}

CanonicalForm& canonical_form() {
  static CanonicalForm form = CanonicalForm::with_atoms();
  return form;
}

int code_of_call(const GiNaC::ex& e) {
  using namespace GiNaC;
  if (is_ex_the_function(e, lp_word1) || is_ex_the_function(e, lp_word2))
    return GiNaC::ex_to<GiNaC::numeric>(e.op(0)).to_int();
  return -1;
}

}  // namespace claim_atoms

}  // namespace linkproof
