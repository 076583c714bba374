#include "claims/summand_program.h"

#include <algorithm>
#include <array>
#include <cstddef>

#include "claims/rate_poly.h"

namespace linkproof {
namespace {

using Op = ClaimProgram::Op;
using Emit = SummandProgram::Op;

/// The body cannot be compiled (it keeps the walk).
struct NotCompiled {};

/// A rate of a term's monomial as the tree writes it: the affine index c0 + cn n + cj j + cl l
/// and the kind. Equal rates are the same rate at every n, j and l.
using Rate = std::array<int, 5>;
/// A term's monomial as a sorted list of its rates.
using Rates = std::vector<Rate>;

/// A term: its register and its monomial.
struct Term {
  int reg = -1;
  Rates rates;
};

/// Two monomials unequal at every binding: different degrees, or different numbers of some kind.
bool never_equal(const Rates& a, const Rates& b) {
  if (a.size() != b.size()) return true;
  const auto dots = [](const Rates& r) {
    return std::count_if(r.begin(), r.end(), [](const Rate& x) { return x[4] == RateVariable::OmegaDot; });
  };
  return dots(a) != dots(b);
}

class Compiler {
 public:
  explicit Compiler(const ClaimProgram& p) : p_(p) {}

  SummandProgram compile(int body) {
    const std::vector<Term> value = scalar(body, true);
    for (const Term& t : value) out_.terms.push_back(t.reg);
    return std::move(out_);
  }

 private:
  const ClaimProgram::Node& node(int id) const { return p_.nodes[static_cast<size_t>(id)]; }

  int emit(Emit op, int a = -1, int b = -1, int node_id = -1) {
    out_.code.push_back({op, a, b, node_id});
    return static_cast<int>(out_.code.size()) - 1;
  }

  Term multiply(const Term& a, const Term& b) {
    Rates r = a.rates;
    r.insert(r.end(), b.rates.begin(), b.rates.end());
    std::sort(r.begin(), r.end());
    // A degree the monomial cannot hold is an input error the walk reports where it happens.
    if (static_cast<int>(r.size()) > Monomial::kMaxDegree) throw NotCompiled{};
    return {emit(Emit::Multiply, a.reg, b.reg), std::move(r)};
  }
  Term negate(const Term& a) { return {emit(Emit::Negate, a.reg), a.rates}; }

  /// a + b as RateValue adds: one term where the monomials are equal, else a polynomial (only
  /// where the value may be one: the body's own value, `poly_allowed`).
  void plus(std::vector<Term>& a, const Term& b, bool poly_allowed) {
    if (a.size() == 1 && a[0].rates == b.rates) {
      a[0].reg = emit(Emit::Add, a[0].reg, b.reg);
      return;
    }
    if (!poly_allowed || (a.size() == 1 && !never_equal(a[0].rates, b.rates))) throw NotCompiled{};
    a.push_back(b);
  }

  Term term(int id) {
    std::vector<Term> v = scalar(id, false);
    return v.front();
  }

  /// Mirrors ClaimEvaluator::scalar_of; `poly_allowed` where the value may have several terms.
  std::vector<Term> scalar(int id, bool poly_allowed) {
    const ClaimProgram::Node& n = node(id);
    switch (n.op) {
      case Op::Constant: return {Term{emit(Emit::Constant, -1, -1, id), {}}};
      case Op::Scale: {
        const Term c{emit(Emit::Constant, -1, -1, id), {}};
        return {multiply(c, term(n.children[0]))};
      }
      case Op::Sum: {
        std::vector<Term> s = {term(n.children[0])};
        for (size_t i = 1; i < n.children.size(); ++i) plus(s, term(n.children[i]), poly_allowed);
        return s;
      }
      case Op::Product: {
        Term p = term(n.children[0]);
        for (size_t i = 1; i < n.children.size(); ++i) p = multiply(p, term(n.children[i]));
        return {p};
      }
      case Op::Power: {
        // A negative exponent divides (tested for zero, recorded as a divisor by the walk); so
        // does 0 there (1 / 1), though the canonical form never makes one.
        if (n.exponent <= 0) throw NotCompiled{};
        const Term f = term(n.children[0]);
        Term r{emit(Emit::One), {}};
        for (int q = 0; q < n.exponent; ++q) r = multiply(r, f);
        return {r};
      }
      case Op::Global:
        switch (n.evaluation) {
          case Evaluation::D:
          case Evaluation::CotPhi:
          case Evaluation::Rho:
          case Evaluation::RhoCompanion: return {leaf(id, {})};
          default: throw NotCompiled{};  // the truth's rates: polynomials
        }
      case Op::InputScalar:
        switch (n.evaluation) {
          case Evaluation::InputOmega:
          case Evaluation::FourbarOmegaOut:
          case Evaluation::FourbarOmegaCpl: return {leaf(id, {rate(n, RateVariable::Omega)})};
          case Evaluation::InputOmegaDot: return {leaf(id, {rate(n, RateVariable::OmegaDot)})};
          case Evaluation::FourbarOmegaDotOut:
          case Evaluation::FourbarOmegaDotCpl: throw NotCompiled{};
          default: return {leaf(id, {})};  // a number of the construction, closed forms or four-bar j
        }
      case Op::Function:
        switch (n.evaluation) {
          case Evaluation::Norm2: {
            const auto [x, y] = vector(n.children[0]);
            std::vector<Term> s = {multiply(x, x)};
            plus(s, multiply(y, y), false);
            return s;
          }
          case Evaluation::Vx: return {vector(n.children[0]).first};
          case Evaluation::Vy: return {vector(n.children[0]).second};
          case Evaluation::Dot:
          case Evaluation::Cross: {
            const auto [ax, ay] = vector(n.children[0]);
            const auto [cx, cy] = vector(n.children[1]);
            if (n.evaluation == Evaluation::Dot) {
              std::vector<Term> s = {multiply(ax, cx)};
              plus(s, multiply(ay, cy), false);
              return s;
            }
            // minus(a, b) is a + (-b).
            std::vector<Term> s = {multiply(ax, cy)};
            const Term t = multiply(ay, cx);
            plus(s, negate(t), false);
            return s;
          }
          default: throw NotCompiled{};
        }
      default: throw NotCompiled{};  // a side's rate (a term or not by its index), a nested sum
    }
  }

  /// Mirrors ClaimEvaluator::vector_of: the two components' terms.
  std::pair<Term, Term> vector(int id) {
    const ClaimProgram::Node& n = node(id);
    switch (n.op) {
      case Op::Scale: {
        const Term c{emit(Emit::Constant, -1, -1, id), {}};
        const auto [x, y] = vector(n.children[0]);
        return {multiply(c, x), multiply(c, y)};
      }
      case Op::Sum: {
        auto [sx, sy] = vector(n.children[0]);
        for (size_t i = 1; i < n.children.size(); ++i) {
          const auto [tx, ty] = vector(n.children[i]);
          std::vector<Term> x = {sx}, y = {sy};
          plus(x, tx, false);
          plus(y, ty, false);
          sx = x.front();
          sy = y.front();
        }
        return {sx, sy};
      }
      case Op::Product: {
        bool is_vector = node(n.children[0]).is_vector;
        std::pair<Term, Term> pv;
        Term ps;
        if (is_vector) pv = vector(n.children[0]);
        else ps = term(n.children[0]);
        for (size_t i = 1; i < n.children.size(); ++i) {
          if (node(n.children[i]).is_vector) {
            const auto [x, y] = vector(n.children[i]);
            pv = {multiply(ps, x), multiply(ps, y)};
            is_vector = true;
          } else if (is_vector) {
            const Term s = term(n.children[i]);
            pv = {multiply(pv.first, s), multiply(pv.second, s)};
          } else {
            ps = multiply(ps, term(n.children[i]));
          }
        }
        return pv;
      }
      case Op::InputVector: return leaf_vector(id);
      case Op::SideVector:
        if (n.evaluation == Evaluation::JointAcc) throw NotCompiled{};  // polynomials in the rates
        return leaf_vector(id);
      case Op::Function:
        if (n.evaluation == Evaluation::Perp) {
          const auto [x, y] = vector(n.children[0]);
          return {negate(y), x};
        }
        throw NotCompiled{};
      default: throw NotCompiled{};
    }
  }

  Rate rate(const ClaimProgram::Node& n, RateVariable::Kind kind) const {
    const ClaimProgram::Index& f = p_.indexes[static_cast<size_t>(n.index)];
    if (!f.affine) throw NotCompiled{};  // its monomial could not be compared with another's
    return {f.c0, f.cn, f.cj, f.cl, kind};
  }

  Term leaf(int id, Rates rates) { return {emit(Emit::Leaf, -1, -1, id), std::move(rates)}; }
  std::pair<Term, Term> leaf_vector(int id) {
    const int x = emit(Emit::LeafVector, -1, -1, id);
    const int y = emit(Emit::Skip);
    return {Term{x, {}}, Term{y, {}}};
  }

  const ClaimProgram& p_;
  SummandProgram out_;
};

}  // namespace

std::optional<SummandProgram> compile_summand(const ClaimProgram& p, int body) {
  try {
    return Compiler(p).compile(body);
  } catch (const NotCompiled&) {
    return std::nullopt;
  }
}

}  // namespace linkproof
