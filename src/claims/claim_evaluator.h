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

#include <algorithm>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "claims/claim_expression.h"
#include "claims/claim_program.h"
#include "claims/pair_sum.h"
#include "claims/polygon_context.h"
#include "claims/rate_poly.h"
#include "claims/rate_value.h"
#include "claims/summand_program.h"
#include "claims/vocabulary.h"
#include "core/symbolic_scalar.h"

namespace linkproof {

/// How a claim reads the paper: the construction's reading and the sign of phi (docs/conventions.md §A5).
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
    const ClaimProgram& p = compiled_claim(e);  // throws for an expression ill formed at every n
    if (p.nodes[static_cast<size_t>(p.root)].is_vector) throw error("a vector where a number is expected: " + text(e));
    std::vector<char>& noted = noted_[&p];
    noted.resize(p.indexes.size());
    program_ = &p;
    noted_now_ = &noted;
    return std::move(scalar_of(p.root, b)).to_poly();
  }

  /// The value of one side of a claim: its expression, undefined wherever a divisor of the side
  /// as written vanishes, also one GiNaC cancelled when it built the expression (Z*X/Z, 0/Z,
  /// (1/Z)^0: claim_expression.h). Each divisor is evaluated for every binding of its indices
  /// (every j of a sum_j, every pair of a sum_pairs) and recorded in divisors(). A divisor that
  /// is zero makes the side undefined (in partial mode only the term of its sum's inputs); one
  /// that is identically zero in symbolic coordinates is an ill-formed claim (InputError); in
  /// floating point one that is not distinguishable from zero makes the side's error bound
  /// unbounded, as the division would have.
  ///
  /// Likewise a quantity word that the side as written reads but its expression does not (GiNaC
  /// cancelled it: 0*X, X - X, X^0) is evaluated on its own for every binding, so that the side
  /// is undefined where the word is. In a proof (T = GiNaC::ex) every word is evaluated and its
  /// values are kept in word_values(): D*omega_out reads omega_out = N/D although the product is
  /// N, and the proof's exceptional set must list D.
  RatePoly<T> scalar(const ClaimExpression& side, IndexBindings b = {}) {
    std::optional<T> possibly_zero;
    for (const WrittenDivisor& d : side.divisors()) written_divisor(d, b, possibly_zero);
    bool word_possibly_undefined = false;
    for (const WrittenWord& w : side.words())
      if (w.cancelled || kKeepsWordValues) written_word(w, b, word_possibly_undefined);
    RatePoly<T> v = scalar(side.expression(), b);
    if (possibly_zero) v = v.right_scaled(*possibly_zero);
    if constexpr (ScalarTraits<T>::has_error_bound)
      if (word_possibly_undefined) {
        // Every coefficient, and the constant one (a side the word cancelled from may be 0,
        // and a product with an exact 0 stays exact), is unbounded: inconclusive, never holds.
        T one = from_int<T>(1), unknown = from_int<T>(0);
        one.e = ScalarTraits<T>::Traits::unbounded();
        unknown.e = ScalarTraits<T>::Traits::unbounded();
        v = v.right_scaled(one);
        v.add(Monomial{}, std::move(unknown));
      }
    return v;
  }

  /// Where the expression is not local (see above); empty if it is.
  const std::vector<std::string>& locality_violations() const { return violations_; }

  /// Every quantity the expression itself divided by (a proof lists where they vanish: the
  /// expression may cancel them, D/D = 1, and still be undefined where they are 0).
  const std::vector<T>& divisors() const { return divisors_; }
  /// In a proof: the value of every quantity word the sides were written with, for every
  /// binding (the proof lists where their divisors vanish).
  const std::vector<T>& word_values() const { return word_values_; }

  /// Partial evaluation: a term of a sum whose input j makes a quantity undefined (Q_j at
  /// infinity, ...) is left out and j recorded here, instead of making the whole value
  /// undefined. In a local expression that term contributes only to monomials with a rate of
  /// j, so every other coefficient is still exact; the caller must treat the total and those
  /// monomials as undefined.
  void set_partial(bool on) { partial_ = on; }
  struct Undefined {
    std::string quantity, reason;
  };

  /// Walks every sum's body, also where it has a compiled program (claims/summand_program.h): the
  /// reference route SummandProgram.* compares the programs with.
  void set_walk_only(bool on) { walk_only_ = on; }
  /// Left-out terms, keyed by the inputs of the term ({j} for sum_j, {j, l} for a pair): only
  /// monomials with rates of all of them are affected.
  const std::map<std::vector<int>, Undefined>& undefined_inputs() const { return undefined_inputs_; }

 private:
  using Op = ClaimProgram::Op;
  using Node = ClaimProgram::Node;

  using Scalar = RateValue<T>;
  struct Vector {
    Scalar x, y;
  };
  static Scalar plus(Scalar a, const Scalar& b) { return std::move(a) + b; }
  static Scalar minus(Scalar a, const Scalar& b) { return std::move(a) - b; }
  static Scalar negated(const Scalar& a) { return -a; }
  static Scalar times(const Scalar& a, const Scalar& b) { return a * b; }
  static Vector times(const Vector& a, const Scalar& b) { return {a.x * b, a.y * b}; }
  static Vector times(const Scalar& a, const Vector& b) { return {a * b.x, a * b.y}; }

  static Scalar constant(const T& x) { return Scalar::term(x); }
  static Scalar constant(long k) { return Scalar::term(from_int<T>(k)); }
  static Scalar rate(int j, RateVariable::Kind kind) { return Scalar::term(from_int<T>(1), Monomial{RateVariable{j, kind}.id()}); }
  static Vector vec(const Vec2<T>& a) { return {constant(a.x), constant(a.y)}; }

  /// A rational constant of the claim in T; integers (most constants) through from_int, which
  /// knows which of them convert exactly and cheaply.
  static T number(const Node& n) { return n.small_integer ? from_int<T>(n.integer) : from_rational<T>(n.rational); }

  static std::string text(const GiNaC::ex& e) { return ScalarTraits<GiNaC::ex>::to_string(e); }
  static InputError error(const std::string& problem) { return InputError("<claim>", "expression", problem); }
  void note(const std::string& v) {
    for (const auto& x : violations_)
      if (x == v) return;
    violations_.push_back(v);
  }

  const Node& node(int id) const { return program_->nodes[static_cast<size_t>(id)]; }

  Scalar scalar_of(int id, const IndexBindings& b) {
    const Node& n = node(id);
    switch (n.op) {
      case Op::Constant: return constant(number(n));
      case Op::Scale: return times(constant(number(n)), scalar_of(n.children[0], b));
      case Op::Sum: {
        Scalar s = scalar_of(n.children[0], b);
        for (size_t i = 1; i < n.children.size(); ++i) s = plus(std::move(s), scalar_of(n.children[i], b));
        return s;
      }
      case Op::Product: {
        Scalar p = scalar_of(n.children[0], b);
        for (size_t i = 1; i < n.children.size(); ++i) p = times(p, scalar_of(n.children[i], b));
        return p;
      }
      case Op::Power: return power(scalar_of(n.children[0], b), n.exponent);
      case Op::Global: return global(n);
      case Op::InputScalar: return input_scalar(n, index(n, b, true));
      case Op::SideScalar: return side_rate(index(n, b, false), side_acceleration(n));
      case Op::Function: return scalar_function(n, b);
      case Op::IndexSum: return Scalar::poly(sum(n, b));
      default: break;
    }
    throw InternalError("claim program: a vector node where a number was compiled");
  }

  /// The words of vectors whose value is a number.
  Scalar scalar_function(const Node& n, const IndexBindings& b) {
    switch (n.evaluation) {
      case Evaluation::Norm2: {
        const Vector a = vector_of(n.children[0], b);
        return plus(times(a.x, a.x), times(a.y, a.y));
      }
      case Evaluation::Vx: return vector_of(n.children[0], b).x;
      case Evaluation::Vy: return vector_of(n.children[0], b).y;
      case Evaluation::Dot: {
        const Vector a = vector_of(n.children[0], b), c = vector_of(n.children[1], b);
        return plus(times(a.x, c.x), times(a.y, c.y));
      }
      case Evaluation::Cross: {
        const Vector a = vector_of(n.children[0], b), c = vector_of(n.children[1], b);
        return minus(times(a.x, c.y), times(a.y, c.x));
      }
      default: throw InternalError("claim program: the word '" + n.word->name + "' has no evaluation as a number");
    }
  }

  /// side_omega[k] (false) or side_omega_dot[k] (true).
  static bool side_acceleration(const Node& n) {
    switch (n.evaluation) {
      case Evaluation::SideOmega: return false;
      case Evaluation::SideOmegaDot: return true;
      default: throw InternalError("claim program: the word '" + n.word->name + "' is no rate of a side");
    }
  }

  Vector vector_of(int id, const IndexBindings& b) {
    const Node& n = node(id);
    switch (n.op) {
      case Op::Scale: return times(constant(number(n)), vector_of(n.children[0], b));
      case Op::Sum: {
        Vector s = vector_of(n.children[0], b);
        for (size_t i = 1; i < n.children.size(); ++i) {
          Vector t = vector_of(n.children[i], b);
          s.x = plus(std::move(s.x), t.x);
          s.y = plus(std::move(s.y), t.y);
        }
        return s;
      }
      case Op::Product: {
        // One factor is the vector; the product keeps the order of the factors.
        bool vector = node(n.children[0]).is_vector;
        Vector pv;
        Scalar ps;
        if (vector) pv = vector_of(n.children[0], b);
        else ps = scalar_of(n.children[0], b);
        for (size_t i = 1; i < n.children.size(); ++i) {
          if (node(n.children[i]).is_vector) {
            pv = times(ps, vector_of(n.children[i], b));
            vector = true;
          } else if (vector) {
            pv = times(pv, scalar_of(n.children[i], b));
          } else {
            ps = times(ps, scalar_of(n.children[i], b));
          }
        }
        return pv;
      }
      case Op::InputVector: return input_vector(n, index(n, b, true));
      case Op::SideVector: return side_vector(n, index(n, b, false));
      case Op::Function: {
        if (n.evaluation != Evaluation::Perp) break;
        const Vector a = vector_of(n.children[0], b);
        return {negated(a.y), a.x};
      }
      default: break;
    }
    throw InternalError("claim program: a number node where a vector was compiled");
  }

  Vector input_vector(const Node& n, int j) {
    switch (n.evaluation) {
      case Evaluation::Kp: return vec(construction(j).k_prime);
      case Evaluation::Q: return vec(construction(j).q.get());
      case Evaluation::Pp: return vec(construction(j).p_prime.get());
      default: throw error("'" + n.word->name + "' is not an input vector");
    }
  }

  Vector side_vector(const Node& n, int k) {
    switch (n.evaluation) {
      case Evaluation::R: return vec(c_.r(k));
      case Evaluation::K: return vec(c_.polygon.joint(k));
      case Evaluation::JointAcc: return acceleration_of_joint(k);
      default: throw error("'" + n.word->name + "' is not a side vector");
    }
  }

  /// f^k, k != 1, as repeated products from 1; k < 0 divides 1 by f^|k| (tested for zero) and
  /// records the divisor.
  Scalar power(const Scalar& f, int k) {
    Scalar r = constant(1);
    for (int q = 0; q < std::abs(k); ++q) r = times(r, f);
    if (k > 0) return r;
    if (r.is_term() && r.monomial().empty()) {
      // Tested like every divisor of the construction: exactly (a symbolic proof records it in
      // its exceptional set; an exact check reports the claim undefined where it vanishes).
      if (linkproof::is_zero(r.coefficient()))
        throw UndefinedQuantity("a divisor in the claim's expression", "it is zero at this configuration");
      Scalar inverse = constant(from_int<T>(1) / r.coefficient());
      divisors_.push_back(r.coefficient());
      return inverse;
    }
    RatePoly<T> d = std::move(r).to_poly();
    RatePoly<T> inverse = RatePoly<T>(from_int<T>(1)) / d;  // refuses rates, tests for zero
    divisors_.push_back(d.constant());
    return Scalar::poly(std::move(inverse));
  }

  static constexpr bool kKeepsWordValues = std::is_same_v<T, GiNaC::ex>;

  /// f(bindings) for every binding of a written part's indices (every j of a sum_j, every pair
  /// of a sum_pairs). In partial mode an undefined quantity in a sum leaves out that term's
  /// inputs instead of making the side undefined.
  template <class F>
  void at_each_binding(IndexBinding binding, const IndexBindings& b, const F& f) {
    const auto at = [&](const IndexBindings& bb, std::vector<int> inputs) {
      try {
        f(bb);
      } catch (const UndefinedQuantity& u) {
        if (!partial_ || inputs.empty()) throw;
        std::sort(inputs.begin(), inputs.end());
        undefined_inputs_.emplace(std::move(inputs), Undefined{u.quantity(), u.reason()});
      }
    };
    const int m = c_.inputs();
    switch (binding) {
      case IndexBinding::None:
      case IndexBinding::ForEachJ: at(b, {}); return;
      case IndexBinding::SumJ:
        for (int j = 1; j <= m; ++j) at({j, b.l}, {j});
        return;
      case IndexBinding::SumPairs:
      case IndexBinding::SumPairsLt:
        for (int j = 1; j <= m; ++j)
          for (int l = binding == IndexBinding::SumPairs ? 1 : j + 1; l <= m; ++l)
            if (l != j) at({j, l}, {j, l});
        return;
    }
  }

  /// Evaluates one written divisor at each binding of its indices (see scalar(ClaimExpression)).
  /// `possibly_zero` receives d * (1/d) for a floating-point d not distinguishable from 0: about 1,
  /// with an unbounded error bound.
  void written_divisor(const WrittenDivisor& d, const IndexBindings& b, std::optional<T>& possibly_zero) {
    at_each_binding(d.binding, b, [&](const IndexBindings& bb) {
      const RatePoly<T> v = scalar(d.expression, bb);
      if (!v.is_constant()) throw error("division by an expression that contains rates: " + d.text);
      T value = v.constant();
      if (linkproof::is_zero(value)) {
        if constexpr (std::is_same_v<T, GiNaC::ex>)
          throw error("the divisor " + d.text + " (" + d.where +
                      ") is identically zero: the claim is undefined at every configuration");
        throw UndefinedQuantity("the divisor " + d.text + " of the claim as written", "it is zero at this configuration");
      }
      if constexpr (ScalarTraits<T>::has_error_bound) {
        T one = value * (from_int<T>(1) / value);
        if (ScalarTraits<T>::Traits::is_unbounded(one.e)) possibly_zero = std::move(one);
      }
      divisors_.push_back(std::move(value));
    });
  }

  /// Evaluates a written word for every binding (its value is discarded, or kept in a proof);
  /// an undefined word throws UndefinedQuantity as in the expression, and in floating point
  /// one whose bound is unbounded (not distinguishable from undefined) sets possibly_undefined.
  /// Its locality notes are not the side's (the side does not read it, or reads it and makes
  /// the notes itself).
  void written_word(const WrittenWord& w, const IndexBindings& b, bool& possibly_undefined) {
    // Notes made here are dropped, and so is the record of which were made: a side that is the
    // word alone compiles to the same program and must make its notes itself.
    struct SideNotes {  // restored however the evaluation ends
      ClaimEvaluator& e;
      size_t count;
      std::map<const ClaimProgram*, std::vector<char>> noted;
      ~SideNotes() {
        std::swap(e.noted_, noted);
        e.violations_.resize(count);
      }
    } side_notes{*this, violations_.size(), {}};
    std::swap(noted_, side_notes.noted);
    at_each_binding(w.binding, b, [&](const IndexBindings& bb) {
      const ClaimProgram& p = compiled_claim(w.expression);
      std::vector<char>& noted = noted_[&p];
      noted.resize(p.indexes.size());
      program_ = &p;
      noted_now_ = &noted;
      if (node(p.root).is_vector) {
        Vector v = vector_of(p.root, bb);
        read_word_value(std::move(v.x), possibly_undefined);
        read_word_value(std::move(v.y), possibly_undefined);
      } else {
        read_word_value(scalar_of(p.root, bb), possibly_undefined);
      }
    });
  }

  void read_word_value(Scalar v, bool& possibly_undefined) {
    const RatePoly<T> poly = std::move(v).to_poly();
    for (const auto& t : poly.terms()) {
      if constexpr (kKeepsWordValues) word_values_.push_back(t.second);
      if constexpr (ScalarTraits<T>::has_error_bound)
        possibly_undefined = possibly_undefined || ScalarTraits<T>::Traits::is_unbounded(t.second.e);
    }
  }

  /// The value of an index (a node's), checked against [1, n - 3] for an input and [1, n] for
  /// a side, with its locality note made the first time.
  int index(const Node& node, const IndexBindings& b, bool input_index) {
    const ClaimProgram::Index& f = program_->indexes[static_cast<size_t>(node.index)];
    const int n = c_.n;
    const int k = f.at(n, b.j, b.l);
    const int hi = input_index ? n - 3 : n;
    if (k < 1 || k > hi)
      throw error(f.written + " = " + node.word->name + "[" + std::to_string(k) + "] is out of range 1.." +
                  std::to_string(hi) + " at n = " + std::to_string(n));
    // Locality: a bound index alone (j or l) names the input's own side; n, n-1, n-2 name the
    // sides every coefficient may depend on. Anything else names a particular side. (An index
    // without j or l has the same value k every time, so one note is all it can make.)
    char& noted = (*noted_now_)[static_cast<size_t>(node.index)];
    if (noted) return k;
    noted = 1;
    if (f.uses_j || f.uses_l) {
      if (!f.bound_note.empty()) note(f.bound_note);
    } else if (k < n - 2) {
      note(f.written + ": names a particular input side");
    }
    return k;
  }


  const FourBarConstruction<T>& construction(int j) {
    return c_.construction_for(reading_.construction)[static_cast<size_t>(j - 1)];
  }

  Scalar global(const Node& n) {
    using Q = Evaluation;
    switch (n.evaluation) {
      case Q::OmegaOut:
      case Q::OmegaCpl: {
        const auto& vc = c_.velocity_coefficients().get();
        const auto& coef = n.evaluation == Q::OmegaOut ? vc.first : vc.second;
        RatePoly<T> p;
        for (int j = 1; j <= c_.inputs(); ++j)
          p += RatePoly<T>(coef[static_cast<size_t>(j - 1)]) * RatePoly<T>::variable({j, RateVariable::Omega});
        return Scalar::poly(std::move(p));
      }
      case Q::OmegaDotOut: return Scalar::poly(acceleration_poly(c_.coefficients().get().first, 0));
      case Q::OmegaDotCpl: return Scalar::poly(acceleration_poly(c_.coefficients().get().second, 0));
      case Q::D: return constant(c_.closed().get().D);
      case Q::CotPhi:
      case Q::Rho:
      case Q::RhoCompanion: {
        const ClosedForms<T>& cf = c_.closed().get();
        if (reading_.signed_phi) return constant(n.evaluation == Q::CotPhi ? cf.cot_phi : n.evaluation == Q::Rho ? cf.rho : cf.rho_companion);
        // The unsigned drawn angle |phi| (erratum §A5.6): cot|phi| = r_{n-2}.r_{n-1}/|D|, sin|phi| = |sin phi|.
        const T abs_d = abs_value(cf.D);
        const Vec2<T> a = c_.r(c_.n - 2), bb = c_.r(c_.n - 1);
        return constant((n.evaluation == Q::CotPhi ? dot(a, bb) : norm2(n.evaluation == Q::Rho ? a : bb)) / abs_d);
      }
      default: throw error("'" + n.word->name + "' is not a number");
    }
  }

  /// sum_j ([omega-dot_j] omega-dot_j + [omega_j^2] omega_j^2) + sum_{j<l} [omega_j omega_l] omega_j omega_l
  /// from engine coefficients; `only_j` (a four-bar's, which has one input): as the rates of input
  /// only_j. Each monomial occurs once, so the terms are appended in the monomials' order (no
  /// sorting); each coefficient is c * 1 (* 1) as the product of c with its rate variables.
  RatePoly<T> acceleration_poly(const TermCoefficients<T>& tc, int only_j) {
    const int m = static_cast<int>(tc.omega_dot.size());
    if (only_j && m != 1) throw InternalError("acceleration_poly: a four-bar's coefficients with " + std::to_string(m) + " inputs");
    const T one = from_int<T>(1);
    const auto id = [](int j, RateVariable::Kind kind) { return RateVariable{j, kind}.id(); };
    RatePoly<T> p;
    for (int j = 1; j <= m; ++j) {
      const int as = only_j ? only_j : j;
      // In the monomials' order: omega_j^2 < omega_j omega_l (l > j) < omega-dot_j < omega_{j+1} ...
      p.add(Monomial{id(as, RateVariable::Omega), id(as, RateVariable::Omega)},
            tc.omega_sq[static_cast<size_t>(j - 1)] * one * one);
      for (int l = j + 1; l <= m; ++l)
        p.add(Monomial{id(j, RateVariable::Omega), id(l, RateVariable::Omega)},
              tc.omega_pair[pair_index(j, l, m)] * one * one);
      p.add(Monomial{id(as, RateVariable::OmegaDot)}, tc.omega_dot[static_cast<size_t>(j - 1)] * one);
    }
    return p;
  }

  Scalar input_scalar(const Node& n, int j) {
    using Q = Evaluation;
    const auto k = static_cast<size_t>(j - 1);
    switch (n.evaluation) {
      case Q::InputOmega: return rate(j, RateVariable::Omega);
      case Q::InputOmegaDot: return rate(j, RateVariable::OmegaDot);
      case Q::IOut: return constant(construction(j).i_out.get());
      case Q::ICpl: return constant(construction(j).i_cpl.get());
      case Q::CotBeta: return constant(construction(j).cot_beta.get());
      case Q::CotGamma: return constant(construction(j).cot_gamma.get());
      case Q::Lambda: return constant(construction(j).lambda.get());
      case Q::Mu: return constant(construction(j).mu.get());
      case Q::IOutClosed: return constant(c_.closed().get().i_out[k]);
      case Q::ICplClosed: return constant(c_.closed().get().i_cpl[k]);
      case Q::LambdaClosed: return constant(c_.closed().get().lambda[k]);
      case Q::MuClosed: return constant(c_.closed().get().mu[k]);
      case Q::FourbarRatioOut: return constant(c_.four_bar(j).ratio_out.get());
      case Q::FourbarRatioCpl: return constant(c_.four_bar(j).ratio_cpl.get());
      case Q::FourbarOmegaOut: return times(constant(c_.four_bar(j).ratio_out.get()), rate(j, RateVariable::Omega));
      case Q::FourbarOmegaCpl: return times(constant(c_.four_bar(j).ratio_cpl.get()), rate(j, RateVariable::Omega));
      case Q::FourbarOmegaDotOut: return Scalar::poly(acceleration_poly(c_.four_bar(j).coefficients.get().first, j));
      case Q::FourbarOmegaDotCpl: return Scalar::poly(acceleration_poly(c_.four_bar(j).coefficients.get().second, j));
      default: throw error("'" + n.word->name + "' is not an input quantity");
    }
  }

  /// omega_{k,n} or omega-dot_{k,n} of side k as a polynomial in the input rates.
  Scalar side_rate(int k, bool acceleration) {
    const int n = c_.n;
    if (k <= n - 3) return rate(k, acceleration ? RateVariable::OmegaDot : RateVariable::Omega);
    if (k == n) return constant(0);
    const bool out = k == n - 1;
    if (!acceleration) {
      const auto& vc = c_.velocity_coefficients().get();
      RatePoly<T> p;
      for (int j = 1; j <= n - 3; ++j)
        p += RatePoly<T>((out ? vc.first : vc.second)[static_cast<size_t>(j - 1)]) *
             RatePoly<T>::variable({j, RateVariable::Omega});
      return Scalar::poly(std::move(p));
    }
    return Scalar::poly(acceleration_poly(out ? c_.coefficients().get().first : c_.coefficients().get().second, 0));
  }

  /// Acceleration of joint K_k along the chain from the fixed joint K_1 (eqs. 8, 12).
  Vector acceleration_of_joint(int k) {
    Scalar ax = Scalar::poly({}), ay = Scalar::poly({});
    for (int i = 1; i < k; ++i) {
      const Vec2<T> r = c_.r(i);
      const Scalar w = side_rate(i, false), wd = side_rate(i, true);
      const Scalar w2 = times(w, w);
      // omega-dot_i J r_i - omega_i^2 r_i, J r = (-r_y, r_x)
      ax = minus(minus(std::move(ax), times(wd, constant(r.y))), times(w2, constant(r.x)));
      ay = minus(plus(std::move(ay), times(wd, constant(r.x))), times(w2, constant(r.y)));
    }
    return {std::move(ax), std::move(ay)};
  }

  /// sum_j, sum_pairs, sum_pairs_lt of the node's body, with the locality notes of its terms.
  RatePoly<T> sum(const Node& node, const IndexBindings& b) {
    const int body = node.children[0];
    const int m = c_.inputs();
    const SummandProgram* program = prepared_program(node);
    RatePoly<T> total;
    if (node.evaluation == Evaluation::SumJ) {
      for (int j = 1; j <= m; ++j) {
        IndexBindings inner = b;
        inner.j = j;
        Scalar t;
        if (!summand(program, body, inner, t, {j})) continue;
        check_terms(t, [j](const Monomial& mono) { return involves_input(mono, j); }, [](const Monomial& mono) {
          return "sum_j(...) has a term without a rate of j (" + monomial_label(mono) + "): its total depends on n";
        });
        t.add_to(total);
      }
      return total;
    }
    // Ordered pairs: omega_a omega_b receives (a, b) and later (b, a), out of order (pair_sum.h).
    if (node.evaluation != Evaluation::SumPairs && node.evaluation != Evaluation::SumPairsLt)
      throw InternalError("claim program: the sum '" + node.word->name + "' has no evaluation");
    const bool ordered = node.evaluation == Evaluation::SumPairs;
    PairSum<T> pairs(ordered ? m : 0);
    for (int j = 1; j <= m; ++j)
      for (int l = ordered ? 1 : j + 1; l <= m; ++l) {
        if (l == j) continue;
        IndexBindings inner = b;
        inner.j = j;
        inner.l = l;
        Scalar t;
        if (!summand(program, body, inner, t, {j, l})) continue;
        check_terms(
            t, [j, l](const Monomial& mono) { return involves_input(mono, j) && involves_input(mono, l); },
            [&](const Monomial& mono) {
              return node.word->name + "(...) has a term without rates of both j and l (" + monomial_label(mono) + ")";
            });
        if (!ordered) t.add_to(total);
        else if (t.is_term()) pairs.add(t.monomial(), t.coefficient());
        else pairs.add(t.polynomial());
      }
    return ordered ? pairs.total() : total;
  }

  /// Notes the first term of t that is not `local` (at most one note per summand).
  template <class Local, class Message>
  void check_terms(const Scalar& t, Local local, Message message) {
    if (t.is_term()) {
      if (!local(t.monomial())) note(message(t.monomial()));
      return;
    }
    for (const auto& [mono, coef] : t.polynomial().terms())
      if (!local(mono)) {
        note(message(mono));
        return;
      }
  }

  /// Evaluates one term of a sum; in partial mode an undefined quantity records the term's
  /// inputs as undefined and returns false.
  bool summand(const SummandProgram* program, int body, const IndexBindings& b, Scalar& out,
               std::initializer_list<int> inputs) {
    if (!partial_) {
      out = program ? run(*program, b) : scalar_of(body, b);
      return true;
    }
    try {
      out = program ? run(*program, b) : scalar_of(body, b);
      return true;
    } catch (const UndefinedQuantity& u) {
      std::vector<int> key(inputs);
      std::sort(key.begin(), key.end());
      undefined_inputs_.emplace(key, Undefined{u.quantity(), u.reason()});
      return false;
    }
  }

  /// The compiled program of a sum's body, its constants placed in their registers (they are
  /// the same at every j and l) and its leaves' values forgotten; null where the body is walked.
  const SummandProgram* prepared_program(const Node& sum_node) {
    if (walk_only_ || !sum_node.summand) return nullptr;
    const SummandProgram& p = *sum_node.summand;
    if (registers_.size() < p.code.size()) registers_.resize(p.code.size());
    const size_t slots = p.code.size() * static_cast<size_t>(c_.n + 1);
    if (leaf_values_.size() < slots) leaf_values_.resize(slots);
    leaf_known_.assign(slots, 0);
    for (size_t i = 0; i < p.code.size(); ++i) {
      const SummandProgram::Instruction& in = p.code[i];
      if (in.op == SummandProgram::Op::Constant) registers_[i] = {number(node(in.node)), {}};
      else if (in.op == SummandProgram::Op::One) registers_[i] = {from_int<T>(1), {}};
    }
    return &p;
  }

  /// The slot of leaf instruction i's value at bindings b in leaf_values_ (-1: none, where the
  /// index is out of range and its evaluation throws). A leaf's value depends only on the value
  /// k of its index (a global's on nothing), so the walk's evaluation at a k is made once per
  /// sum and reused: the same value, and its index check and locality note were made then, at
  /// the walk's first evaluation of it. A leaf that throws is not kept, so it throws again.
  std::ptrdiff_t leaf_slot(size_t i, int node_id, const IndexBindings& b) const {
    const Node& n = node(node_id);
    const int k = n.index < 0 ? 0 : program_->indexes[static_cast<size_t>(n.index)].at(c_.n, b.j, b.l);
    if (k < 0 || k > c_.n) return -1;
    return static_cast<std::ptrdiff_t>(i * static_cast<size_t>(c_.n + 1) + static_cast<size_t>(k));
  }

  /// One term of a sum by its body's program at bindings b (see claims/summand_program.h): the
  /// value the walk gives, by the same operations on the coefficients in the same order.
  Scalar run(const SummandProgram& p, const IndexBindings& b) {
    using SOp = SummandProgram::Op;
    const auto one_term = [](const Scalar& v) -> Register {
      if (!v.is_term()) throw InternalError("summand program: a leaf's value is not one term");
      return {v.coefficient(), v.monomial()};
    };
    for (size_t i = 0; i < p.code.size(); ++i) {
      const SummandProgram::Instruction& in = p.code[i];
      Register& r = registers_[i];
      switch (in.op) {
        case SOp::Leaf: {
          const std::ptrdiff_t slot = leaf_slot(i, in.node, b);
          if (slot >= 0 && leaf_known_[static_cast<size_t>(slot)]) {
            r = leaf_values_[static_cast<size_t>(slot)];
            break;
          }
          r = one_term(scalar_of(in.node, b));
          if (slot >= 0) {
            leaf_values_[static_cast<size_t>(slot)] = r;
            leaf_known_[static_cast<size_t>(slot)] = 1;
          }
          break;
        }
        case SOp::LeafVector: {
          // x in slot i's row, y in row i + 1's (the Skip's).
          const std::ptrdiff_t slot = leaf_slot(i, in.node, b);
          const auto y_slot = static_cast<size_t>(slot + c_.n + 1);
          if (slot >= 0 && leaf_known_[static_cast<size_t>(slot)]) {
            r = leaf_values_[static_cast<size_t>(slot)];
            registers_[i + 1] = leaf_values_[y_slot];
            break;
          }
          const Vector v = vector_of(in.node, b);
          r = one_term(v.x);
          registers_[i + 1] = one_term(v.y);
          if (slot >= 0) {
            leaf_values_[static_cast<size_t>(slot)] = r;
            leaf_values_[y_slot] = registers_[i + 1];
            leaf_known_[static_cast<size_t>(slot)] = 1;
          }
          break;
        }
        case SOp::Skip:
        case SOp::Constant:
        case SOp::One: break;
        case SOp::Add: {
          const Register &x = registers_[static_cast<size_t>(in.a)], &y = registers_[static_cast<size_t>(in.b)];
          if (x.m != y.m) throw InternalError("summand program: a sum of terms of two monomials compiled as one term");
          r.c = x.c + y.c;
          r.m = x.m;
          break;
        }
        case SOp::Multiply: {
          const Register &x = registers_[static_cast<size_t>(in.a)], &y = registers_[static_cast<size_t>(in.b)];
          r.c = x.c * y.c;
          r.m = Monomial::product(x.m, y.m);
          break;
        }
        case SOp::Negate: {
          const Register& x = registers_[static_cast<size_t>(in.a)];
          r.c = -x.c;
          r.m = x.m;
          break;
        }
      }
    }
    const Register& first = registers_[static_cast<size_t>(p.terms[0])];
    if (p.terms.size() == 1) return Scalar::term(first.c, first.m);
    if (first.m == registers_[static_cast<size_t>(p.terms[1])].m)
      throw InternalError("summand program: terms of one monomial compiled as a polynomial");
    RatePoly<T> poly;
    for (const int t : p.terms) poly.add(registers_[static_cast<size_t>(t)].m, registers_[static_cast<size_t>(t)].c);
    return Scalar::poly(std::move(poly));
  }

  /// A register of a summand program: a one-term value.
  struct Register {
    T c;
    Monomial m;
  };

  const PolygonContext<T>& c_;
  ClaimReading reading_;
  std::vector<std::string> violations_;
  std::vector<T> divisors_;
  std::vector<T> word_values_;  ///< in a proof: written_word's values
  bool partial_ = false;
  std::map<std::vector<int>, Undefined> undefined_inputs_;
  const ClaimProgram* program_ = nullptr;  ///< the program scalar() evaluates
  /// Per program: whether each index's locality note has been made (an evaluator may evaluate
  /// several expressions: both sides of a claim).
  std::map<const ClaimProgram*, std::vector<char>> noted_;
  std::vector<char>* noted_now_ = nullptr;
  bool walk_only_ = false;
  std::vector<Register> registers_;  ///< of the summand program being run
  std::vector<Register> leaf_values_;  ///< its leaves' values in this sum (leaf_slot)
  std::vector<char> leaf_known_;
};

}  // namespace linkproof
