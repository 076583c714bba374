// A compiled GiNaC expression: a straight-line program ("tape") evaluated over any scalar type.
//
// Rational-function expressions (sums, products, integer powers of symbols and rational
// constants) are flattened into instructions, sharing structurally equal subexpressions, so
// that the size of the tape is the size of the expression's DAG. Evaluating the tape is route
// (d) "evaluation of the symbolic expression", in exact, tracked or plain floating arithmetic
// through one code path.
//
// What is compiled is the canonical form of the expressions (canonical_form.h), not GiNaC's
// trees: GiNaC's operand order and its placement of signs and numeric factors between sums and
// products depend on addresses (ASLR) and symbol serials. Two runs, processes or symbol-creation
// orders that compile equal expressions get the same tape, instruction for instruction, so
// floating-point results and error bounds are the same bytes. Every sum is evaluated as
// content * (sum with coprime integer coefficients), its operands and those of every product in
// the canonical order.
#pragma once

#include <ginac/ginac.h>

#include <cstdint>
#include <string>
#include <vector>

#include "linkproof/core/error.h"
#include "core/scalar.h"
#include "symbolic/canonical_form.h"

namespace linkproof {

class Tape {
 public:
  enum class Op : std::uint8_t { Input, Constant, Sum, Product, Quotient, Power };
  struct Instruction {
    Op op;
    std::uint32_t a = 0;  ///< Input/Constant: index; Sum/Product: first operand slot; Quotient/Power: operand
    std::uint32_t b = 0;  ///< Sum/Product: operand count; Quotient: denominator
    int k = 0;            ///< Power: exponent (>= 2)
  };

  /// Compiles `outputs` as functions of `inputs` (symbols). Any other symbol, a non-rational
  /// constant or a non-polynomial function is an InternalError. `denominator_name` names the
  /// quantity reported as undefined when a division by exact zero occurs.
  Tape(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
       std::string denominator_name);
  /// Compiles `outputs`, built with the builders of `form` (no GiNaC trees), as functions of
  /// its inputs. Equal canonical forms give the same tape whichever way they were made.
  Tape(CanonicalForm form, const std::vector<CanonicalForm::Split>& outputs, std::string denominator_name);

  size_t input_count() const { return input_count_; }
  /// Number of instructions: the size of the shared DAG.
  size_t size() const { return code_.size(); }

  const std::vector<Instruction>& code() const { return code_; }
  const std::vector<std::uint32_t>& operands() const { return operands_; }
  const std::vector<Rational>& constants() const { return constants_; }
  const std::vector<std::uint32_t>& outputs() const { return outputs_; }
  /// f(k) for every register k that instruction `in` reads.
  template <class F>
  void for_each_operand(const Instruction& in, F f) const {
    switch (in.op) {
      case Op::Sum:
      case Op::Product:
        for (std::uint32_t t = 0; t < in.b; ++t) f(operands_[in.a + t]);
        break;
      case Op::Quotient:
        f(in.a);
        f(in.b);
        break;
      case Op::Power: f(in.a); break;
      case Op::Input:
      case Op::Constant: break;
    }
  }
  const std::string& denominator_name() const { return denominator_name_; }

 private:
  size_t input_count_;
  std::vector<Instruction> code_;
  std::vector<std::uint32_t> operands_;
  std::vector<Rational> constants_;
  std::vector<std::uint32_t> outputs_;
  std::string denominator_name_;
  friend class TapeCompiler;
};

/// Evaluates a tape over scalar type T. Reuses its registers between calls; not thread-safe.
template <class T>
class TapeEvaluator {
 public:
  explicit TapeEvaluator(const Tape& tape) : tape_(&tape), registers_(tape.size()) {
    constants_.reserve(tape.constants().size());
    for (const auto& c : tape.constants()) constants_.push_back(from_rational<T>(c));
  }

  /// Evaluates all outputs. `inputs` must have tape.input_count() entries. A division by an
  /// exact zero throws UndefinedQuantity(tape.denominator_name()).
  std::vector<T> operator()(const std::vector<T>& inputs) {
    LINKPROOF_ASSERT(inputs.size() == tape_->input_count(), "tape input count mismatch");
    const auto& code = tape_->code();
    const auto& ops = tape_->operands();
    for (size_t i = 0; i < code.size(); ++i) {
      const Tape::Instruction& in = code[i];
      switch (in.op) {
        case Tape::Op::Input: registers_[i] = inputs[in.a]; break;
        case Tape::Op::Constant: registers_[i] = constants_[in.a]; break;
        case Tape::Op::Sum: {
          T acc = registers_[ops[in.a]];
          for (std::uint32_t t = 1; t < in.b; ++t) acc = acc + registers_[ops[in.a + t]];
          registers_[i] = acc;
          break;
        }
        case Tape::Op::Product: {
          T acc = registers_[ops[in.a]];
          for (std::uint32_t t = 1; t < in.b; ++t) acc = acc * registers_[ops[in.a + t]];
          registers_[i] = acc;
          break;
        }
        case Tape::Op::Quotient: {
          const T& den = registers_[in.b];
          if (linkproof::is_zero(den))
            throw UndefinedQuantity(tape_->denominator_name(), "division by zero in the symbolic solution");
          registers_[i] = registers_[in.a] / den;
          break;
        }
        case Tape::Op::Power: {
          const T& base = registers_[in.a];
          T acc = base;
          for (int p = 1; p < in.k; ++p) acc = acc * base;
          registers_[i] = acc;
          break;
        }
      }
    }
    std::vector<T> out;
    out.reserve(tape_->outputs().size());
    for (auto o : tape_->outputs()) out.push_back(registers_[o]);
    return out;
  }

 private:
  const Tape* tape_;
  std::vector<T> constants_;
  std::vector<T> registers_;
};

}  // namespace linkproof
