// Evaluates a claim expression (claim_expression.h) on a polygon context, generic over the
// scalar type: exact rationals, IEEE with error bounds, or GiNaC expressions (symbolic
// coordinates: a proof). The value of a scalar expression is a RatePoly: a polynomial in the
// input rates whose coefficients are numbers of the configuration.
//
// Locality (for proofs for every n, proof/prove.h). The argument that lifts a proof on generic
// vectors to every n needs each coefficient of a monomial in the rates to depend only on the
// sides the monomial involves and on r_{n-2}, r_{n-1}, K_n. The evaluator records where an
// expression breaks that: an index that names a particular input (r[1]), a joint or
// acceleration indexed by j (K_j depends on every side before it), a term of sum_j(...)
// without a rate of j (its total depends on n), a term of sum_pairs(...) without rates of
// both j and l.
#pragma once

#include <ginac/ginac.h>

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "linkproof/claims/claim_expression.h"
#include "linkproof/claims/polygon_context.h"
#include "linkproof/claims/rate_poly.h"
#include "linkproof/claims/vocabulary.h"
#include "linkproof/core/symbolic_scalar.h"

namespace linkproof {

/// How a claim reads the paper: the construction's reading and the sign of phi (SPEC A5).
struct ClaimReading {
  ConstructionReading construction;
  bool signed_phi = true;
};

/// Values of the index symbols j and l (0: unbound).
struct IndexBindings {
  int j = 0, l = 0;
};

template <class T>
class ClaimEvaluator {
 public:
  ClaimEvaluator(const PolygonContext<T>& c, ClaimReading reading) : c_(c), reading_(reading) {}

  /// The value of a scalar expression. Throws UndefinedQuantity where the configuration makes a
  /// quantity undefined, InputError for a claim that is not well formed at this n (an index out
  /// of range, a vector where a number is expected, division by rates).
  RatePoly<T> scalar(const GiNaC::ex& e, IndexBindings b = {}) {
    Value v = value(e, b);
    if (v.is_vector) throw error("a vector where a number is expected: " + text(e));
    return std::move(v.s);
  }

  /// Where the expression is not local (see above); empty if it is.
  const std::vector<std::string>& locality_violations() const { return violations_; }

  /// Every quantity the expression itself divided by (a proof lists where they vanish: the
  /// expression may cancel them, D/D = 1, and still be undefined where they are 0).
  const std::vector<T>& divisors() const { return divisors_; }

  /// Partial evaluation: a term of a sum whose input j makes a quantity undefined (Q_j at
  /// infinity, ...) is left out and j recorded here, instead of making the whole value
  /// undefined. In a local expression that term contributes only to monomials with a rate of
  /// j, so every other coefficient is still exact; the caller must treat the total and those
  /// monomials as undefined.
  void set_partial(bool on) { partial_ = on; }
  struct Undefined {
    std::string quantity, reason;
  };
  /// Left-out terms, keyed by the inputs of the term ({j} for sum_j, {j, l} for a pair): only
  /// monomials with rates of all of them are affected.
  const std::map<std::vector<int>, Undefined>& undefined_inputs() const { return undefined_inputs_; }

 private:
  struct Value {
    bool is_vector = false;
    RatePoly<T> s, x, y;
    static Value number(RatePoly<T> p) { Value v; v.s = std::move(p); return v; }
    static Value vec(RatePoly<T> x, RatePoly<T> y) {
      Value v;
      v.is_vector = true;
      v.x = std::move(x);
      v.y = std::move(y);
      return v;
    }
    static Value vec(const Vec2<T>& a) { return vec(RatePoly<T>(a.x), RatePoly<T>(a.y)); }
  };

  static std::string text(const GiNaC::ex& e) { return ScalarTraits<GiNaC::ex>::to_string(e); }
  static InputError error(const std::string& problem) { return InputError("<claim>", "expression", problem); }
  void note(const std::string& v) {
    for (const auto& x : violations_)
      if (x == v) return;
    violations_.push_back(v);
  }
  static RatePoly<T> constant(const T& x) { return RatePoly<T>(x); }
  static RatePoly<T> constant(long k) { return RatePoly<T>(from_int<T>(k)); }

  /// A rational constant of the claim in T; integers (most constants) through from_int, which
  /// knows which of them convert exactly and cheaply.
  static T number(const GiNaC::numeric& q) {
    if (q.is_integer() && GiNaC::abs(q) < GiNaC::numeric(1L << 62)) return from_int<T>(q.to_long());
    return from_rational<T>(cln::the<cln::cl_RA>(q.to_cl_N()));
  }

  Value value(const GiNaC::ex& e, const IndexBindings& b) {
    using namespace GiNaC;
    if (is_exactly_a<numeric>(e)) {
      const numeric& q = ex_to<numeric>(e);
      if (!q.is_rational()) throw error("the number " + text(e) + " is not rational");
      return Value::number(constant(number(q)));
    }
    if (is_exactly_a<power>(e)) {
      const ex& k = e.op(1);
      if (!is_exactly_a<numeric>(k) || !ex_to<numeric>(k).is_integer())
        throw error("only integer powers are allowed: " + text(e));
    }
    if (is_exactly_a<add>(e) || is_exactly_a<mul>(e) || is_exactly_a<power>(e)) {
      // The canonical form, not GiNaC's tree: GiNaC places signs and numeric factors between
      // sums and products in an address-dependent order (claim_atoms::canonical_form()).
      const CanonicalForm::Split s = claim_atoms::canonical_form().split(e);
      return scaled(form_value(s.primitive, e, b), s.content, e);
    }
    if (const int code = claim_atoms::code_of_symbol(e); code >= 0) return global(vocabulary()[static_cast<size_t>(code)], b);
    if (const int code = claim_atoms::code_of_call(e); code >= 0) return call(vocabulary()[static_cast<size_t>(code)], e, b);
    throw error("cannot evaluate " + text(e));
  }

  /// c * v; v itself if c is 1.
  Value scaled(Value v, const GiNaC::numeric& c, const GiNaC::ex& e) {
    if (c.is_equal(GiNaC::numeric(1))) return v;
    const Value k = Value::number(constant(number(c)));
    return multiply(k, v, e);
  }

  /// The value of a primitive part of claim_atoms::canonical_form(), operands in its canonical
  /// order; `e` is the expression it came from (for messages).
  Value form_value(CanonicalForm::Id id, const GiNaC::ex& e, const IndexBindings& b) {
    const CanonicalForm::Node& n = claim_atoms::canonical_form().node(id);
    switch (n.kind) {
      case CanonicalForm::Kind::One: return Value::number(constant(1));
      case CanonicalForm::Kind::Atom: {
        const GiNaC::ex atom = n.atom;  // value() may add nodes to the form: n may move
        return value(atom, b);
      }
      case CanonicalForm::Kind::Symbol: break;  // a form with atoms has no inputs
      case CanonicalForm::Kind::Sum: {
        // Copied: evaluating a term may add nodes to the form (new subexpressions of a call).
        const auto terms = n.terms;
        Value sum = scaled(form_value(terms[0].first, e, b), terms[0].second, e);
        for (size_t i = 1; i < terms.size(); ++i) {
          Value t = scaled(form_value(terms[i].first, e, b), terms[i].second, e);
          if (t.is_vector != sum.is_vector) throw error("a number added to a vector in " + text(e));
          if (sum.is_vector) {
            sum.x = sum.x + t.x;
            sum.y = sum.y + t.y;
          } else {
            sum.s = sum.s + t.s;
          }
        }
        return sum;
      }
      case CanonicalForm::Kind::Product: {
        const auto factors = n.factors;
        Value p;
        for (size_t i = 0; i < factors.size(); ++i) {
          const auto [base_id, k] = factors[i];
          Value f = form_value(base_id, e, b);
          if (k != 1) {
            if (f.is_vector) throw error("power of a vector: " + text(e) + " (use norm2 or dot)");
            RatePoly<T> r = constant(1);
            for (int q = 0; q < std::abs(k); ++q) r = r * f.s;
            if (k > 0) {
              f = Value::number(std::move(r));
            } else {
              RatePoly<T> inverse = constant(1) / r;  // tests r for zero
              divisors_.push_back(r.constant());
              f = Value::number(std::move(inverse));
            }
          }
          p = i == 0 ? std::move(f) : multiply(p, f, e);
        }
        return p;
      }
    }
    throw error("cannot evaluate " + text(e));
  }

  Value multiply(const Value& a, const Value& b, const GiNaC::ex& e) {
    if (a.is_vector && b.is_vector) throw error("product of two vectors in " + text(e) + " (use dot or cross)");
    if (a.is_vector) return Value::vec(a.x * b.s, a.y * b.s);
    if (b.is_vector) return Value::vec(a.s * b.x, a.s * b.y);
    return Value::number(a.s * b.s);
  }

  /// What index() needs of one index expression at this n, worked out once per (word, argument):
  /// an index expression is read by GiNaC (has, subs) only the first time, not once per term of
  /// a sum over pairs.
  struct IndexForm {
    bool uses_j = false, uses_l = false;
    bool affine = false;  ///< the index is c0 + cj j + cl l with integers c0, cj, cl
    int c0 = 0, cj = 0, cl = 0;
    bool noted = false;   ///< its locality note (if any) has been made
  };

  static const GiNaC::symbol& index_symbol(const char* name) {
    return claim_atoms::symbol_of(word_code(*find_word(name, 0)));
  }

  IndexForm index_form(const GiNaC::ex& arg) const {
    using namespace GiNaC;
    const symbol &n = index_symbol("n"), &j = index_symbol("j"), &l = index_symbol("l");
    IndexForm f;
    f.uses_j = arg.has(j);
    f.uses_l = arg.has(l);
    const ex v = arg.subs(n == c_.n);
    if (!v.is_polynomial(lst{j, l}) || v.degree(j) > 1 || v.degree(l) > 1) return f;
    const ex c0 = v.subs(lst{j == 0, l == 0}), cj = v.subs(lst{j == 1, l == 0}) - c0,
             cl = v.subs(lst{j == 0, l == 1}) - c0;
    for (const ex* c : {&c0, &cj, &cl})
      if (!is_exactly_a<numeric>(*c) || !ex_to<numeric>(*c).is_integer()) return f;
    if (!(v - c0 - cj * j - cl * l).expand().is_zero()) return f;
    f.affine = true;
    f.c0 = ex_to<numeric>(c0).to_int();
    f.cj = ex_to<numeric>(cj).to_int();
    f.cl = ex_to<numeric>(cl).to_int();
    return f;
  }

  /// The integer value of an index expression, checked against [1, hi], with locality notes.
  int index(const Word& w, const GiNaC::ex& arg, const IndexBindings& b, bool input_index) {
    using namespace GiNaC;
    const int n = c_.n;
    const auto key = std::pair(&w, &ex_to<basic>(arg));  // the claim's expression outlives the evaluator
    auto it = index_forms_.find(key);
    if (it == index_forms_.end()) it = index_forms_.emplace(key, index_form(arg)).first;
    IndexForm& f = it->second;
    int k;
    if (f.affine) {
      k = f.c0 + f.cj * b.j + f.cl * b.l;
    } else {
      const ex v = arg.subs(lst{index_symbol("n") == n, index_symbol("j") == b.j, index_symbol("l") == b.l});
      if (!is_exactly_a<numeric>(v) || !ex_to<numeric>(v).is_integer())
        throw error("the index of " + w.name + "[" + text(arg) + "] is not an integer");
      k = ex_to<numeric>(v).to_int();
    }
    const int hi = input_index ? n - 3 : n;
    if (k < 1 || k > hi)
      throw error(w.name + "[" + text(arg) + "] = " + w.name + "[" + std::to_string(k) + "] is out of range 1.." +
                  std::to_string(hi) + " at n = " + std::to_string(n));
    // Locality: a bound index alone (j or l) names the input's own side; n, n-1, n-2 name the
    // sides every coefficient may depend on. Anything else names a particular side. (An index
    // without j or l has the same value k every time, so one note is all it can make.)
    if (f.noted) return k;
    f.noted = true;
    const bool bare_bound =
        (f.uses_j || f.uses_l) && (arg.is_equal(index_symbol("j")) || arg.is_equal(index_symbol("l")));
    if (f.uses_j || f.uses_l) {
      if (!bare_bound) note(w.name + "[" + text(arg) + "]: an index other than j, l, n, n-1, n-2");
      else if (w.name == "K" || w.name == "acc")
        note(w.name + "[" + text(arg) + "]: depends on every side before it");
    } else if (k < n - 2) {
      note(w.name + "[" + text(arg) + "]: names a particular input side");
    }
    return k;
  }

  /// The words the evaluator tells apart, looked up once: the inner loops of a sum compare
  /// pointers, not names (string comparisons were ~10 % of a double check).
  struct Words {
    const Word* omega_out = &word_named("omega_out");
    const Word* omega_cpl = &word_named("omega_cpl");
    const Word* omega_dot_out = &word_named("omega_dot_out");
    const Word* omega_dot_cpl = &word_named("omega_dot_cpl");
    const Word* D = &word_named("D");
    const Word* cot_phi = &word_named("cot_phi");
    const Word* rho = &word_named("rho");
    const Word* rho_companion = &word_named("rho_companion");
    const Word* side_omega_dot = &word_named("side_omega_dot");
    const Word* omega = &word_named("omega");
    const Word* omega_dot = &word_named("omega_dot");
    const Word* i_out = &word_named("i_out");
    const Word* i_cpl = &word_named("i_cpl");
    const Word* cot_beta = &word_named("cot_beta");
    const Word* cot_gamma = &word_named("cot_gamma");
    const Word* lambda = &word_named("lambda");
    const Word* mu = &word_named("mu");
    const Word* Kp = &word_named("Kp");
    const Word* Q = &word_named("Q");
    const Word* i_out_closed = &word_named("i_out_closed");
    const Word* i_cpl_closed = &word_named("i_cpl_closed");
    const Word* lambda_closed = &word_named("lambda_closed");
    const Word* mu_closed = &word_named("mu_closed");
    const Word* fourbar_ratio_out = &word_named("fourbar_ratio_out");
    const Word* fourbar_ratio_cpl = &word_named("fourbar_ratio_cpl");
    const Word* fourbar_omega_out = &word_named("fourbar_omega_out");
    const Word* fourbar_omega_cpl = &word_named("fourbar_omega_cpl");
    const Word* fourbar_omega_dot_out = &word_named("fourbar_omega_dot_out");
    const Word* fourbar_omega_dot_cpl = &word_named("fourbar_omega_dot_cpl");
    const Word* r = &word_named("r");
    const Word* K = &word_named("K");
    const Word* dot = &word_named("dot");
    const Word* norm2 = &word_named("norm2");
    const Word* perp = &word_named("perp");
    const Word* vx = &word_named("vx");
    const Word* vy = &word_named("vy");
    const Word* sum_j = &word_named("sum_j");
    const Word* sum_pairs = &word_named("sum_pairs");
  };
  static const Words& words() {
    static const Words w;
    return w;
  }

  const FourBarConstruction<T>& construction(int j) {
    return c_.construction_for(reading_.construction)[static_cast<size_t>(j - 1)];
  }

  Value global(const Word& w, const IndexBindings&) {
    const std::string& s = w.name;
    if (w.kind == WordKind::Index) throw error("'" + s + "' is an index, not a number");
    if (&w == words().omega_out || &w == words().omega_cpl) {
      const auto& vc = c_.velocity_coefficients().get();
      const auto& coef = &w == words().omega_out ? vc.first : vc.second;
      RatePoly<T> p;
      for (int j = 1; j <= c_.inputs(); ++j)
        p += constant(coef[static_cast<size_t>(j - 1)]) * RatePoly<T>::variable({j, RateVariable::Omega});
      return Value::number(p);
    }
    if (&w == words().omega_dot_out || &w == words().omega_dot_cpl) {
      const auto& tc = &w == words().omega_dot_out ? c_.coefficients().get().first : c_.coefficients().get().second;
      return Value::number(acceleration_poly(tc, 0));
    }
    const ClosedForms<T>& cf = c_.closed().get();
    if (&w == words().D) return Value::number(constant(cf.D));
    if (reading_.signed_phi) {
      if (&w == words().cot_phi) return Value::number(constant(cf.cot_phi));
      if (&w == words().rho) return Value::number(constant(cf.rho));
      if (&w == words().rho_companion) return Value::number(constant(cf.rho_companion));
    } else {
      // The unsigned drawn angle |phi| (erratum A5.6): cot|phi| = r_{n-2}.r_{n-1}/|D|, sin|phi| = |sin phi|.
      const T abs_d = abs_value(cf.D);
      const Vec2<T> a = c_.r(c_.n - 2), bb = c_.r(c_.n - 1);
      if (&w == words().cot_phi) return Value::number(constant(dot(a, bb) / abs_d));
      if (&w == words().rho) return Value::number(constant(norm2(a) / abs_d));
      if (&w == words().rho_companion) return Value::number(constant(norm2(bb) / abs_d));
    }
    throw error("'" + s + "' is not a number");
  }

  /// sum_j ([omega-dot_j] omega-dot_j + [omega_j^2] omega_j^2) + sum_{j<l} [omega_j omega_l] omega_j omega_l
  /// for the inputs in `only` (0: all), from engine coefficients.
  RatePoly<T> acceleration_poly(const TermCoefficients<T>& tc, int only_j) {
    RatePoly<T> p;
    const int m = static_cast<int>(tc.omega_dot.size());
    for (int j = 1; j <= m; ++j) {
      const auto k = static_cast<size_t>(j - 1);
      const int as = only_j ? only_j : j;
      const auto w = RatePoly<T>::variable({as, RateVariable::Omega});
      p += constant(tc.omega_dot[k]) * RatePoly<T>::variable({as, RateVariable::OmegaDot});
      p += constant(tc.omega_sq[k]) * w * w;
    }
    for (int j = 1; j <= m; ++j)
      for (int l = j + 1; l <= m; ++l)
        p += constant(tc.omega_pair[pair_index(j, l, m)]) * RatePoly<T>::variable({j, RateVariable::Omega}) *
             RatePoly<T>::variable({l, RateVariable::Omega});
    return p;
  }

  Value call(const Word& w, const GiNaC::ex& e, const IndexBindings& b) {
    const std::string& s = w.name;
    const GiNaC::ex& a0 = e.op(1);
    switch (w.kind) {
      case WordKind::Sum: return Value::number(sum(w, a0, b));
      case WordKind::VectorFunction: return vector_function(w, e, b);
      case WordKind::InputScalar: return Value::number(input_scalar(w, index(w, a0, b, true)));
      case WordKind::InputVector: {
        const int j = index(w, a0, b, true);
        if (&w == words().Kp) return Value::vec(construction(j).k_prime);
        if (&w == words().Q) return Value::vec(construction(j).q.get());
        return Value::vec(construction(j).p_prime.get());
      }
      case WordKind::SideVector: {
        const int k = index(w, a0, b, false);
        if (&w == words().r) return Value::vec(c_.r(k));
        if (&w == words().K) return Value::vec(c_.polygon.joint(k));
        return acceleration_of_joint(k);
      }
      case WordKind::SideScalar: {
        const int k = index(w, a0, b, false);
        return Value::number(side_rate(k, &w == words().side_omega_dot));
      }
      default: throw error("'" + s + "' cannot be called");
    }
  }

  RatePoly<T> input_scalar(const Word& word, int j) {
    const std::string& s = word.name;
    const auto k = static_cast<size_t>(j - 1);
    if (&word == words().omega) return RatePoly<T>::variable({j, RateVariable::Omega});
    if (&word == words().omega_dot) return RatePoly<T>::variable({j, RateVariable::OmegaDot});
    if (&word == words().i_out) return constant(construction(j).i_out.get());
    if (&word == words().i_cpl) return constant(construction(j).i_cpl.get());
    if (&word == words().cot_beta) return constant(construction(j).cot_beta.get());
    if (&word == words().cot_gamma) return constant(construction(j).cot_gamma.get());
    if (&word == words().lambda) return constant(construction(j).lambda.get());
    if (&word == words().mu) return constant(construction(j).mu.get());
    if (&word == words().i_out_closed) return constant(c_.closed().get().i_out[k]);
    if (&word == words().i_cpl_closed) return constant(c_.closed().get().i_cpl[k]);
    if (&word == words().lambda_closed) return constant(c_.closed().get().lambda[k]);
    if (&word == words().mu_closed) return constant(c_.closed().get().mu[k]);
    const FourBarTruth<T>& fb = c_.four_bar(static_cast<int>(k) + 1);
    const auto w = RatePoly<T>::variable({j, RateVariable::Omega});
    if (&word == words().fourbar_ratio_out) return constant(fb.ratio_out.get());
    if (&word == words().fourbar_ratio_cpl) return constant(fb.ratio_cpl.get());
    if (&word == words().fourbar_omega_out) return constant(fb.ratio_out.get()) * w;
    if (&word == words().fourbar_omega_cpl) return constant(fb.ratio_cpl.get()) * w;
    if (&word == words().fourbar_omega_dot_out) return acceleration_poly(fb.coefficients.get().first, j);
    if (&word == words().fourbar_omega_dot_cpl) return acceleration_poly(fb.coefficients.get().second, j);
    throw error("'" + s + "' is not an input quantity");
  }

  /// omega_{k,n} or omega-dot_{k,n} of side k as a polynomial in the input rates.
  RatePoly<T> side_rate(int k, bool acceleration) {
    const int n = c_.n;
    if (k <= n - 3) return RatePoly<T>::variable({k, acceleration ? RateVariable::OmegaDot : RateVariable::Omega});
    if (k == n) return constant(0);
    const bool out = k == n - 1;
    if (!acceleration) {
      const auto& vc = c_.velocity_coefficients().get();
      RatePoly<T> p;
      for (int j = 1; j <= n - 3; ++j)
        p += constant((out ? vc.first : vc.second)[static_cast<size_t>(j - 1)]) *
             RatePoly<T>::variable({j, RateVariable::Omega});
      return p;
    }
    return acceleration_poly(out ? c_.coefficients().get().first : c_.coefficients().get().second, 0);
  }

  /// Acceleration of joint K_k along the chain from the fixed joint K_1 (eqs. 8, 12).
  Value acceleration_of_joint(int k) {
    RatePoly<T> ax, ay;
    for (int i = 1; i < k; ++i) {
      const Vec2<T> r = c_.r(i);
      const RatePoly<T> w = side_rate(i, false), wd = side_rate(i, true);
      const RatePoly<T> w2 = w * w;
      // omega-dot_i J r_i - omega_i^2 r_i, J r = (-r_y, r_x)
      ax = ax - wd * constant(r.y) - w2 * constant(r.x);
      ay = ay + wd * constant(r.x) - w2 * constant(r.y);
    }
    return Value::vec(ax, ay);
  }

  Value vector_function(const Word& word, const GiNaC::ex& e, const IndexBindings& b) {
    const std::string& s = word.name;
    const Value a = value(e.op(1), b);
    if (!a.is_vector) throw error(s + "(...) needs a vector argument: " + text(e));
    if (&word == words().norm2) return Value::number(a.x * a.x + a.y * a.y);
    if (&word == words().perp) return Value::vec(-a.y, a.x);
    if (&word == words().vx) return Value::number(a.x);
    if (&word == words().vy) return Value::number(a.y);
    const Value c = value(e.op(2), b);
    if (!c.is_vector) throw error(s + "(...) needs vector arguments: " + text(e));
    if (&word == words().dot) return Value::number(a.x * c.x + a.y * c.y);
    return Value::number(a.x * c.y - a.y * c.x);  // cross
  }

  RatePoly<T> sum(const Word& word, const GiNaC::ex& body, const IndexBindings& b) {
    const std::string& s = word.name;
    const int m = c_.inputs();
    RatePoly<T> total;
    if (&word == words().sum_j) {
      for (int j = 1; j <= m; ++j) {
        IndexBindings inner = b;
        inner.j = j;
        RatePoly<T> t;
        if (!summand(body, inner, t, {j})) continue;
        for (const auto& [mono, coef] : t.terms()) {
          if (!involves_input(mono, j)) {
            note("sum_j(...) has a term without a rate of j (" + monomial_label(mono) + "): its total depends on n");
            break;
          }
        }
        total += t;
      }
      return total;
    }
    const bool ordered = &word == words().sum_pairs;
    for (int j = 1; j <= m; ++j)
      for (int l = ordered ? 1 : j + 1; l <= m; ++l) {
        if (l == j) continue;
        IndexBindings inner = b;
        inner.j = j;
        inner.l = l;
        RatePoly<T> t;
        if (!summand(body, inner, t, {j, l})) continue;
        for (const auto& [mono, coef] : t.terms()) {
          if (!involves_input(mono, j) || !involves_input(mono, l)) {
            note(s + "(...) has a term without rates of both j and l (" + monomial_label(mono) + ")");
            break;
          }
        }
        total += t;
      }
    return total;
  }

  /// Evaluates one term of a sum; in partial mode an undefined quantity records the term's
  /// inputs as undefined and returns false.
  bool summand(const GiNaC::ex& body, const IndexBindings& b, RatePoly<T>& out, std::initializer_list<int> inputs) {
    if (!partial_) {
      out = scalar(body, b);
      return true;
    }
    try {
      out = scalar(body, b);
      return true;
    } catch (const UndefinedQuantity& u) {
      std::vector<int> key(inputs);
      std::sort(key.begin(), key.end());
      undefined_inputs_.emplace(key, Undefined{u.quantity(), u.reason()});
      return false;
    }
  }

  const PolygonContext<T>& c_;
  ClaimReading reading_;
  std::vector<std::string> violations_;
  std::vector<T> divisors_;
  bool partial_ = false;
  std::map<std::vector<int>, Undefined> undefined_inputs_;
  std::map<std::pair<const Word*, const GiNaC::basic*>, IndexForm> index_forms_;
};

}  // namespace linkproof
