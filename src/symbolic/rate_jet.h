// Forward-mode differentiation of a compiled solution with respect to the input rates.
//
// The exact omega and omega-dot of the dependent sides are polynomials of degree <= 2 in the
// input rates omega_j, omega-dot_j (docs/conventions.md §A4), with coefficients that are functions of the side
// components. A RateJet<T> holds such a polynomial,
//
//   c + sum_v L_v r_v + sum_{v <= w} Q_vw r_v r_w      (r_v: the rate variables)
//
// with sparse, sorted linear and quadratic parts. Evaluating the ground truth's motion tape
// (tape.h) over jets, with the side components as numbers and the rates as variables, gives
// every term coefficient of the solution at once: L_v = dE/dr_v, Q_vv = (1/2) d^2E/dr_v^2,
// Q_vw = d^2E/dr_v dr_w. This is the differentiated loop closure itself, read off term by term;
// nothing of the paper's construction enters.
//
// Cost: constants cost what TapeEvaluator<T> costs; a value linear in m rates costs O(m) per
// operation, and the product of two such values O(m^2) (the Theta(m^2) pair terms). On the
// motion tape (size O(n)) a whole evaluation is O(n^2) operations in T.
//
// The constant part is tracked structurally (`has_constant`): a rate variable has none, and a
// product of two jets without one has none. The product of two jets then has a linear part only
// from factors that do have a constant, so omega-dot (a form with no constant, linear in the
// omega-dot_j, quadratic in the omega_j) has no linear omega_j entries at all, not entries
// whose value happens to be 0 * 1.
//
// Operations are the tape's (sum, product, quotient, integer power). A quotient by a value that
// contains rates, or a product of degree > 2 in the rates, is an InternalError: the solution is
// a polynomial of degree 2 in the rates with rate-free denominators, or the engine is wrong.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "linkproof/core/error.h"
#include "core/scalar.h"
#include "core/stable_radix_sort.h"
#include "symbolic/tape.h"

namespace linkproof {

template <class T>
struct RateJet {
  T constant;
  std::vector<std::pair<std::uint32_t, T>> linear;     ///< (v, L_v), sorted by v, v unique
  std::vector<std::pair<std::uint64_t, T>> quadratic;  ///< (quadratic_key(v, w), Q_vw), v <= w, sorted, unique
  bool has_constant = true;  ///< false: the constant part is structurally absent (then `constant` is 0)

  bool is_constant() const { return linear.empty() && quadratic.empty(); }
  /// The key of r_v r_w with v <= w: sorts by v, then w.
  static std::uint64_t quadratic_key(std::uint32_t v, std::uint32_t w) {
    return static_cast<std::uint64_t>(v) << 32 | w;
  }
  static std::pair<std::uint32_t, std::uint32_t> quadratic_vars(std::uint64_t key) {
    return {static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key & 0xffffffffu)};
  }
};

/// Evaluates a tape over RateJet<T>: inputs [0, first_rate) are numbers, inputs
/// [first_rate, input_count) are the rate variables 0, 1, ... Not thread-safe; reusable.
template <class T>
class TapeJetEvaluator {
 public:
  TapeJetEvaluator(const Tape& tape, size_t first_rate)
      : tape_(&tape), first_rate_(first_rate), registers_(tape.size()), last_use_(tape.size()) {
    LINKPROOF_ASSERT(first_rate <= tape.input_count(), "jet: rate inputs out of range");
    constants_.reserve(tape.constants().size());
    for (const auto& c : tape.constants()) constants_.push_back(from_rational<T>(c));
    // The last instruction that reads each register (outputs: past the end). A jet of the
    // solution's quadratic part holds O(m^2) terms; at n = 1000 keeping every register to the
    // end held hundreds of MB.
    const auto& code = tape.code();
    for (size_t i = 0; i < code.size(); ++i) {
      last_use_[i] = i;
      tape.for_each_operand(code[i], [&](std::uint32_t k) { last_use_[k] = i; });
    }
    for (auto o : tape.outputs()) last_use_[o] = code.size();
  }

  /// Every output as a jet. `numbers` holds the first_rate numeric inputs.
  std::vector<RateJet<T>> operator()(const std::vector<T>& numbers) {
    LINKPROOF_ASSERT(numbers.size() == first_rate_, "jet: numeric input count mismatch");
    const auto& code = tape_->code();
    const auto& ops = tape_->operands();
    const T zero = from_int<T>(0), one = from_int<T>(1);
    for (size_t i = 0; i < code.size(); ++i) {
      const Tape::Instruction& in = code[i];
      RateJet<T>& r = registers_[i];
      switch (in.op) {
        case Tape::Op::Input:
          if (in.a < first_rate_) {
            r = {numbers[in.a], {}, {}};
          } else {
            r = {zero, {{static_cast<std::uint32_t>(in.a - first_rate_), one}}, {}, false};
          }
          break;
        case Tape::Op::Constant: r = {constants_[in.a], {}, {}}; break;
        case Tape::Op::Sum: r = sum(ops.data() + in.a, in.b); break;
        case Tape::Op::Product: {
          RateJet<T> acc = registers_[ops[in.a]];
          for (std::uint32_t t = 1; t < in.b; ++t) acc = multiply(acc, registers_[ops[in.a + t]]);
          r = std::move(acc);
          break;
        }
        case Tape::Op::Quotient: {
          const RateJet<T>& den = registers_[in.b];
          if (!den.is_constant()) throw InternalError("jet: a denominator of the solution contains rates");
          if (linkproof::is_zero(den.constant))
            throw UndefinedQuantity(tape_->denominator_name(), "division by zero in the symbolic solution");
          r = divide(registers_[in.a], den.constant);
          break;
        }
        case Tape::Op::Power: {
          const RateJet<T>& base = registers_[in.a];
          RateJet<T> acc = base;
          for (int p = 1; p < in.k; ++p) acc = multiply(acc, base);
          r = std::move(acc);
          break;
        }
      }
      release_operands(in, i);
    }
    std::vector<RateJet<T>> out;
    out.reserve(tape_->outputs().size());
    for (auto o : tape_->outputs()) out.push_back(registers_[o]);
    return out;
  }

 private:
  /// Frees the registers that instruction i read for the last time.
  void release_operands(const Tape::Instruction& in, size_t i) {
    tape_->for_each_operand(in, [&](std::uint32_t k) {
      if (last_use_[k] == i) registers_[k] = RateJet<T>{};
    });
  }

  /// Merges (key, value) pairs given in operand order: equal keys are added in that order, so
  /// floating-point results depend only on the tape.
  template <class K>
  static void combine(std::vector<std::pair<K, T>>& v) {
    stable_sort_by_key<1>(v, [](const std::pair<K, T>& e) { return std::array<std::uint64_t, 1>{e.first}; });
    size_t w = 0;
    for (size_t i = 0; i < v.size(); ++i) {
      if (w > 0 && v[w - 1].first == v[i].first) {
        v[w - 1].second = v[w - 1].second + v[i].second;
      } else {
        if (w != i) v[w] = std::move(v[i]);
        ++w;
      }
    }
    v.resize(w);
  }

  RateJet<T> sum(const std::uint32_t* args, std::uint32_t count) const {
    RateJet<T> r{from_int<T>(0), {}, {}, false};
    size_t lin = 0, quad = 0;
    for (std::uint32_t t = 0; t < count; ++t) {
      const RateJet<T>& x = registers_[args[t]];
      if (x.has_constant) {
        r.constant = r.has_constant ? r.constant + x.constant : x.constant;
        r.has_constant = true;
      }
      lin += x.linear.size();
      quad += x.quadratic.size();
    }
    if (lin > 0) {
      r.linear.reserve(lin);
      for (std::uint32_t t = 0; t < count; ++t) {
        const auto& l = registers_[args[t]].linear;
        r.linear.insert(r.linear.end(), l.begin(), l.end());
      }
      combine(r.linear);
    }
    if (quad > 0) {
      r.quadratic.reserve(quad);
      for (std::uint32_t t = 0; t < count; ++t) {
        const auto& q = registers_[args[t]].quadratic;
        r.quadratic.insert(r.quadratic.end(), q.begin(), q.end());
      }
      combine(r.quadratic);
    }
    return r;
  }

  static RateJet<T> scale(const RateJet<T>& a, const T& k) {
    RateJet<T> r{a.has_constant ? a.constant * k : a.constant, a.linear, a.quadratic, a.has_constant};
    for (auto& [v, c] : r.linear) c = c * k;
    for (auto& [v, c] : r.quadratic) c = c * k;
    return r;
  }

  static RateJet<T> divide(const RateJet<T>& a, const T& d) {
    RateJet<T> r{a.has_constant ? a.constant / d : a.constant, a.linear, a.quadratic, a.has_constant};
    for (auto& [v, c] : r.linear) c = c / d;
    for (auto& [v, c] : r.quadratic) c = c / d;
    return r;
  }

  static RateJet<T> multiply(const RateJet<T>& a, const RateJet<T>& b) {
    if (b.is_constant()) return scale(a, b.constant);
    if (a.is_constant()) {
      RateJet<T> r = scale(b, a.constant);
      return r;
    }
    if (!a.quadratic.empty() || !b.quadratic.empty())
      throw InternalError("jet: a product of degree > 2 in the rates in the solution");
    const bool both = a.has_constant && b.has_constant;
    RateJet<T> r{both ? a.constant * b.constant : from_int<T>(0), {}, {}, both};
    r.linear.reserve(a.linear.size() + b.linear.size());
    if (b.has_constant)
      for (const auto& [v, c] : a.linear) r.linear.emplace_back(v, c * b.constant);
    if (a.has_constant)
      for (const auto& [v, c] : b.linear) r.linear.emplace_back(v, a.constant * c);
    combine(r.linear);
    r.quadratic.reserve(a.linear.size() * b.linear.size());
    for (const auto& [v, cv] : a.linear)
      for (const auto& [w, cw] : b.linear)
        r.quadratic.emplace_back(RateJet<T>::quadratic_key(std::min(v, w), std::max(v, w)), cv * cw);
    combine(r.quadratic);
    return r;
  }

  const Tape* tape_;
  size_t first_rate_;
  std::vector<T> constants_;
  std::vector<RateJet<T>> registers_;
  std::vector<size_t> last_use_;  ///< per register: the last instruction that reads it
};

}  // namespace linkproof
