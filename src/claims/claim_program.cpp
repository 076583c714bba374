#include "claims/claim_program.h"

#include <algorithm>
#include <memory>
#include <unordered_map>

#include "claims/claim_expression.h"
#include "claims/summand_program.h"
#include "linkproof/core/error.h"
#include "core/symbolic_scalar.h"

namespace linkproof {
namespace {

using Op = ClaimProgram::Op;

std::string text(const GiNaC::ex& e) { return ScalarTraits<GiNaC::ex>::to_string(e); }
InputError error(const std::string& problem) { return InputError("<claim>", "expression", problem); }

using claim_atoms::index_symbol;

/// A node reading or computing the word w.
ClaimProgram::Node word_node(Op op, const Word& w) {
  ClaimProgram::Node n;
  n.op = op;
  n.word = &w;
  n.evaluation = w.evaluation;
  n.is_vector = w.result == ClaimKind::Vector;
  return n;
}

// Mirrors the evaluation the program replaces: value() of a GiNaC expression, form_value() of a
// canonical form's node, call() of a vocabulary word, in that order, so that errors come in the
// same order and the nodes are evaluated in the same order.
class Compiler {
 public:
  explicit Compiler(ClaimProgram& p) : p_(p) {}

  int value(const GiNaC::ex& e) {
    using namespace GiNaC;
    if (is_exactly_a<numeric>(e)) {
      const numeric& q = ex_to<numeric>(e);
      if (!q.is_rational()) throw error("the number " + text(e) + " is not rational");
      return constant(q);
    }
    if (is_exactly_a<power>(e)) {
      const ex& k = e.op(1);
      if (!is_exactly_a<numeric>(k) || !ex_to<numeric>(k).is_integer())
        throw error("only integer powers are allowed: " + text(e));
    }
    if (is_exactly_a<GiNaC::add>(e) || is_exactly_a<mul>(e) || is_exactly_a<power>(e)) {
      // The canonical form, not GiNaC's tree: GiNaC places signs and numeric factors between
      // sums and products in an address-dependent order (claim_atoms::canonical_form()).
      const CanonicalForm::Split s = claim_atoms::canonical_form().split(e);
      return scaled(form_value(s.primitive, e), s.content, e);
    }
    if (const int code = claim_atoms::code_of_symbol(e); code >= 0) {
      const Word& w = word_of_code(code);
      if (w.result == ClaimKind::Index) throw error("'" + w.name + "' is an index, not a number");
      return add(word_node(Op::Global, w));
    }
    if (const int code = claim_atoms::code_of_call(e); code >= 0) return call(word_of_code(code), e);
    throw error("cannot evaluate " + text(e));
  }

  const ClaimProgram::Node& node(int id) const { return p_.nodes[static_cast<size_t>(id)]; }

 private:
  int add(ClaimProgram::Node n) {
    p_.nodes.push_back(std::move(n));
    return static_cast<int>(p_.nodes.size()) - 1;
  }

  static void set_constant(ClaimProgram::Node& n, const GiNaC::numeric& q) {
    if (q.is_integer() && GiNaC::abs(q) < GiNaC::numeric(1L << 62)) {
      n.small_integer = true;
      n.integer = q.to_long();
    }
    n.rational = cln::the<cln::cl_RA>(q.to_cl_N());
  }

  int constant(const GiNaC::numeric& q) {
    ClaimProgram::Node n;
    n.op = Op::Constant;
    set_constant(n, q);
    return add(std::move(n));
  }

  /// c * child; the child itself if c is 1.
  int scaled(int child, const GiNaC::numeric& c, const GiNaC::ex&) {
    if (c.is_equal(GiNaC::numeric(1))) return child;
    ClaimProgram::Node n;
    n.op = Op::Scale;
    n.is_vector = node(child).is_vector;
    set_constant(n, c);
    n.children = {child};
    return add(std::move(n));
  }

  int form_value(CanonicalForm::Id id, const GiNaC::ex& e) {
    // Copied: compiling a part may add nodes to the form (new subexpressions of a call).
    const CanonicalForm::Node n = claim_atoms::canonical_form().node(id);
    switch (n.kind) {
      case CanonicalForm::Kind::One: return constant(GiNaC::numeric(1));
      case CanonicalForm::Kind::Atom: return value(n.atom);
      case CanonicalForm::Kind::Symbol: break;  // a form with atoms has no inputs
      case CanonicalForm::Kind::Sum: {
        ClaimProgram::Node sum;
        sum.op = Op::Sum;
        for (size_t i = 0; i < n.terms.size(); ++i) {
          const int t = scaled(form_value(n.terms[i].first, e), n.terms[i].second, e);
          if (i == 0) sum.is_vector = node(t).is_vector;
          else if (node(t).is_vector != sum.is_vector) throw error("a number added to a vector in " + text(e));
          sum.children.push_back(t);
        }
        return add(std::move(sum));
      }
      case CanonicalForm::Kind::Product: {
        ClaimProgram::Node product;
        product.op = Op::Product;
        for (size_t i = 0; i < n.factors.size(); ++i) {
          const auto [base_id, k] = n.factors[i];
          int f = form_value(base_id, e);
          if (k != 1) {
            if (node(f).is_vector) throw error("power of a vector: " + text(e) + " (use norm2 or dot)");
            ClaimProgram::Node power;
            power.op = Op::Power;
            power.exponent = k;
            power.children = {f};
            f = add(std::move(power));
          }
          if (i > 0 && product.is_vector && node(f).is_vector)
            throw error("product of two vectors in " + text(e) + " (use dot or cross)");
          product.is_vector = product.is_vector || node(f).is_vector;
          product.children.push_back(f);
        }
        return add(std::move(product));
      }
    }
    throw error("cannot evaluate " + text(e));
  }

  int index(const Word& w, const GiNaC::ex& arg) {
    using namespace GiNaC;
    const symbol &n = index_symbol(Evaluation::IndexN), &j = index_symbol(Evaluation::IndexJ),
                 &l = index_symbol(Evaluation::IndexL);
    ClaimProgram::Index f;
    f.uses_j = arg.has(j);
    f.uses_l = arg.has(l);
    f.bare_bound = (f.uses_j || f.uses_l) && (arg.is_equal(j) || arg.is_equal(l));
    f.expression = arg;
    f.written = w.name + "[" + text(arg) + "]";
    if (f.uses_j || f.uses_l) {
      if (!f.bare_bound) f.bound_note = f.written + ": an index other than j, l, n, n-1, n-2";
      else if (w.evaluation == Evaluation::K || w.evaluation == Evaluation::JointAcc) f.bound_note = f.written + ": depends on every side before it";
    }
    if (arg.is_polynomial(lst{n, j, l}) && arg.degree(n) <= 1 && arg.degree(j) <= 1 && arg.degree(l) <= 1) {
      const ex c0 = arg.subs(lst{n == 0, j == 0, l == 0});
      const ex cn = arg.subs(lst{n == 1, j == 0, l == 0}) - c0, cj = arg.subs(lst{n == 0, j == 1, l == 0}) - c0,
               cl = arg.subs(lst{n == 0, j == 0, l == 1}) - c0;
      bool integers = true;
      for (const ex* c : {&c0, &cn, &cj, &cl})
        integers = integers && is_exactly_a<numeric>(*c) && ex_to<numeric>(*c).is_integer() &&
                   GiNaC::abs(ex_to<numeric>(*c)) < numeric(1 << 20);
      if (integers && (arg - c0 - cn * n - cj * j - cl * l).expand().is_zero()) {
        f.affine = true;
        f.c0 = ex_to<numeric>(c0).to_int();
        f.cn = ex_to<numeric>(cn).to_int();
        f.cj = ex_to<numeric>(cj).to_int();
        f.cl = ex_to<numeric>(cl).to_int();
      }
    }
    p_.indexes.push_back(std::move(f));
    return static_cast<int>(p_.indexes.size()) - 1;
  }

  // What the word's arguments are decides the node: a sum of its body, a quantity read at an
  // index, or a function of vectors (the vocabulary's argument and result kinds).
  int call(const Word& w, const GiNaC::ex& e) {
    const GiNaC::ex& a0 = e.op(1);
    if (w.is_sum()) {
      const int body = value(a0);
      if (node(body).is_vector) throw error("a vector where a number is expected: " + text(a0));
      ClaimProgram::Node n = word_node(Op::IndexSum, w);
      n.children = {body};
      if (std::optional<SummandProgram> s = compile_summand(p_, body)) n.summand = std::make_shared<const SummandProgram>(std::move(*s));
      return add(std::move(n));
    }
    if (w.is_indexed()) {
      const bool input = w.arguments[0] == ClaimKind::InputIndex, vector = w.result == ClaimKind::Vector;
      ClaimProgram::Node n = word_node(input ? (vector ? Op::InputVector : Op::InputScalar)
                                             : (vector ? Op::SideVector : Op::SideScalar), w);
      n.index = index(w, a0);
      return add(std::move(n));
    }
    if (std::all_of(w.arguments.begin(), w.arguments.end(), [](ClaimKind k) { return k == ClaimKind::Vector; }))
      return vector_function(w, e);
    throw error("'" + w.name + "' cannot be called");
  }

  int vector_function(const Word& w, const GiNaC::ex& e) {
    ClaimProgram::Node n = word_node(Op::Function, w);
    for (int k = 0; k < w.arity(); ++k) {
      const int a = value(e.op(static_cast<size_t>(k) + 1));
      if (!node(a).is_vector)
        throw error(w.name + (k == 0 ? "(...) needs a vector argument: " : "(...) needs vector arguments: ") + text(e));
      n.children.push_back(a);
    }
    return add(std::move(n));
  }

  ClaimProgram& p_;
};

}  // namespace

int ClaimProgram::Index::substituted(int n, int j, int l) const {
  using namespace GiNaC;
  const ex v = expression.subs(lst{index_symbol(Evaluation::IndexN) == n, index_symbol(Evaluation::IndexJ) == j,
                                   index_symbol(Evaluation::IndexL) == l});
  if (!is_exactly_a<numeric>(v) || !ex_to<numeric>(v).is_integer())
    throw error("the index of " + written + " is not an integer");
  // to_int() would wrap a larger one (2^32 + 1 read as 1) and name another side.
  if (GiNaC::abs(ex_to<numeric>(v)) > numeric(1 << 30)) throw error("the index of " + written + " is " + text(v) + ", out of range");
  return ex_to<numeric>(v).to_int();
}

const ClaimProgram& compiled_claim(const GiNaC::ex& e) {
  static std::unordered_map<GiNaC::ex, std::unique_ptr<const ClaimProgram>, std::hash<GiNaC::ex>, GiNaC::ex_is_equal>
      programs;
  auto it = programs.find(e);
  if (it != programs.end()) return *it->second;
  auto p = std::make_unique<ClaimProgram>();
  Compiler c(*p);
  p->root = c.value(e);  // throws for an ill-formed expression: nothing is kept
  return *programs.emplace(e, std::move(p)).first->second;
}

}  // namespace linkproof
