#include "claims/claim_program.h"

#include <memory>
#include <unordered_map>

#include "claims/claim_expression.h"
#include "linkproof/core/error.h"
#include "core/symbolic_scalar.h"

namespace linkproof {
namespace {

using Op = ClaimProgram::Op;

std::string text(const GiNaC::ex& e) { return ScalarTraits<GiNaC::ex>::to_string(e); }
InputError error(const std::string& problem) { return InputError("<claim>", "expression", problem); }

const GiNaC::symbol& index_symbol(const char* name) {
  return claim_atoms::symbol_of(word_code(*find_word(name, 0)));
}

/// The quantity a word with a value reads; a word of the vocabulary without one is a bug.
Quantity quantity_of(const Word& w) {
  using Q = Quantity;
  static const std::unordered_map<std::string, Quantity> table = {
      {"omega_out", Q::OmegaOut}, {"omega_cpl", Q::OmegaCpl}, {"omega_dot_out", Q::OmegaDotOut},
      {"omega_dot_cpl", Q::OmegaDotCpl}, {"D", Q::D}, {"cot_phi", Q::CotPhi}, {"rho", Q::Rho},
      {"rho_companion", Q::RhoCompanion}, {"omega", Q::Omega}, {"omega_dot", Q::OmegaDot}, {"i_out", Q::IOut},
      {"i_cpl", Q::ICpl}, {"cot_beta", Q::CotBeta}, {"cot_gamma", Q::CotGamma}, {"lambda", Q::Lambda}, {"mu", Q::Mu},
      {"i_out_closed", Q::IOutClosed}, {"i_cpl_closed", Q::ICplClosed}, {"lambda_closed", Q::LambdaClosed},
      {"mu_closed", Q::MuClosed}, {"fourbar_ratio_out", Q::FourbarRatioOut}, {"fourbar_ratio_cpl", Q::FourbarRatioCpl},
      {"fourbar_omega_out", Q::FourbarOmegaOut}, {"fourbar_omega_cpl", Q::FourbarOmegaCpl},
      {"fourbar_omega_dot_out", Q::FourbarOmegaDotOut}, {"fourbar_omega_dot_cpl", Q::FourbarOmegaDotCpl},
      {"Kp", Q::Kp}, {"Q", Q::Q}, {"Pp", Q::Pp}, {"r", Q::R}, {"K", Q::K}, {"acc", Q::Acc},
      {"side_omega", Q::SideOmega}, {"side_omega_dot", Q::SideOmegaDot}};
  const auto it = table.find(w.name);
  if (it == table.end()) throw InternalError("the vocabulary's word '" + w.name + "' has no quantity to read");
  return it->second;
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
      const Word& w = vocabulary()[static_cast<size_t>(code)];
      if (w.kind == WordKind::Index) throw error("'" + w.name + "' is an index, not a number");
      ClaimProgram::Node n;
      n.op = Op::Global;
      n.word = &w;
      n.quantity = quantity_of(w);
      return add(std::move(n));
    }
    if (const int code = claim_atoms::code_of_call(e); code >= 0) return call(vocabulary()[static_cast<size_t>(code)], e);
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
    const symbol &n = index_symbol("n"), &j = index_symbol("j"), &l = index_symbol("l");
    ClaimProgram::Index f;
    f.uses_j = arg.has(j);
    f.uses_l = arg.has(l);
    f.bare_bound = (f.uses_j || f.uses_l) && (arg.is_equal(j) || arg.is_equal(l));
    f.expression = arg;
    f.written = w.name + "[" + text(arg) + "]";
    if (f.uses_j || f.uses_l) {
      if (!f.bare_bound) f.bound_note = f.written + ": an index other than j, l, n, n-1, n-2";
      else if (w.name == "K" || w.name == "acc") f.bound_note = f.written + ": depends on every side before it";
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

  int call(const Word& w, const GiNaC::ex& e) {
    const GiNaC::ex& a0 = e.op(1);
    ClaimProgram::Node n;
    n.word = &w;
    switch (w.kind) {
      case WordKind::Sum: {
        const int body = value(a0);
        if (node(body).is_vector) throw error("a vector where a number is expected: " + text(a0));
        n.op = w.name == "sum_j" ? Op::SumJ : w.name == "sum_pairs" ? Op::SumPairs : Op::SumPairsLt;
        n.children = {body};
        return add(std::move(n));
      }
      case WordKind::VectorFunction: return vector_function(w, e);
      case WordKind::InputScalar: return indexed(std::move(n), Op::InputScalar, false, a0);
      case WordKind::InputVector: return indexed(std::move(n), Op::InputVector, true, a0);
      case WordKind::SideVector: return indexed(std::move(n), Op::SideVector, true, a0);
      case WordKind::SideScalar: return indexed(std::move(n), Op::SideScalar, false, a0);
      default: throw error("'" + w.name + "' cannot be called");
    }
  }

  /// A quantity read at an index: word[arg].
  int indexed(ClaimProgram::Node n, Op op, bool is_vector, const GiNaC::ex& arg) {
    n.op = op;
    n.is_vector = is_vector;
    n.quantity = quantity_of(*n.word);
    n.index = index(*n.word, arg);
    return add(std::move(n));
  }

  int vector_function(const Word& w, const GiNaC::ex& e) {
    const std::string& s = w.name;
    ClaimProgram::Node n;
    n.word = &w;
    const int a = value(e.op(1));
    if (!node(a).is_vector) throw error(s + "(...) needs a vector argument: " + text(e));
    n.children = {a};
    if (s == "norm2" || s == "vx" || s == "vy" || s == "perp") {
      n.op = s == "norm2" ? Op::Norm2 : s == "vx" ? Op::Vx : s == "vy" ? Op::Vy : Op::Perp;
      n.is_vector = n.op == Op::Perp;
      return add(std::move(n));
    }
    const int c = value(e.op(2));
    if (!node(c).is_vector) throw error(s + "(...) needs vector arguments: " + text(e));
    n.children.push_back(c);
    n.op = s == "dot" ? Op::Dot : Op::Cross;
    return add(std::move(n));
  }

  ClaimProgram& p_;
};

}  // namespace

int ClaimProgram::Index::substituted(int n, int j, int l) const {
  using namespace GiNaC;
  const ex v = expression.subs(lst{index_symbol("n") == n, index_symbol("j") == j, index_symbol("l") == l});
  if (!is_exactly_a<numeric>(v) || !ex_to<numeric>(v).is_integer())
    throw error("the index of " + written + " is not an integer");
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
