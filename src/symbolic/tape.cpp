#include "linkproof/symbolic/tape.h"

#include <unordered_map>

#include "ex_text.h"
#include "linkproof/symbolic/canonical_order.h"

namespace linkproof {

using namespace GiNaC;

namespace {
struct ExHash {
  size_t operator()(const ex& e) const { return e.gethash(); }
};
}  // namespace

/// Flattens expressions into a Tape, memoising structurally equal subexpressions.
class TapeCompiler {
 public:
  TapeCompiler(Tape& tape, const std::vector<ex>& inputs) : tape_(tape) {
    for (size_t i = 0; i < inputs.size(); ++i) input_index_[inputs[i]] = static_cast<std::uint32_t>(i);
  }

  std::uint32_t compile(const ex& e) {
    if (auto it = memo_.find(e); it != memo_.end()) return it->second;
    const std::uint32_t slot = compile_uncached(e);
    memo_.emplace(e, slot);
    return slot;
  }

 private:
  std::uint32_t emit(Tape::Instruction in) {
    tape_.code_.push_back(in);
    return static_cast<std::uint32_t>(tape_.code_.size() - 1);
  }
  std::uint32_t emit_nary(Tape::Op op, const std::vector<std::uint32_t>& args) {
    if (args.size() == 1) return args.front();
    const auto first = static_cast<std::uint32_t>(tape_.operands_.size());
    tape_.operands_.insert(tape_.operands_.end(), args.begin(), args.end());
    return emit({op, first, static_cast<std::uint32_t>(args.size()), 0});
  }
  std::uint32_t power_slot(const ex& base, long k) {
    if (k == 1) return compile(base);
    return emit({Tape::Op::Power, compile(base), 0, static_cast<int>(k)});
  }

  std::uint32_t compile_uncached(const ex& e) {
    if (is_a<numeric>(e)) {
      const numeric& num = ex_to<numeric>(e);
      if (!num.is_rational()) throw InternalError("tape: non-rational constant " + ex_text(e));
      tape_.constants_.push_back(cln::the<cln::cl_RA>(num.to_cl_N()));
      return emit({Tape::Op::Constant, static_cast<std::uint32_t>(tape_.constants_.size() - 1), 0, 0});
    }
    if (is_a<symbol>(e)) {
      auto it = input_index_.find(e);
      if (it == input_index_.end()) throw InternalError("tape: symbol " + ex_text(e) + " is not an input");
      return emit({Tape::Op::Input, it->second, 0, 0});
    }
    // Operands in canonical order (canonical_order.h): GiNaC's own order depends on addresses,
    // and a floating-point sum or product evaluated in it would round differently in every run.
    if (is_a<add>(e)) {
      std::vector<std::uint32_t> args;
      for (size_t i : order_.order(e)) args.push_back(compile(e.op(i)));
      return emit_nary(Tape::Op::Sum, args);
    }
    if (is_a<mul>(e)) {
      // One quotient per product: numerator factors over the product of the negative powers.
      std::vector<std::uint32_t> num, den;
      for (size_t i : order_.order(e)) {
        const ex& f = e.op(i);
        if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_integer() &&
            ex_to<numeric>(f.op(1)).is_negative())
          den.push_back(power_slot(f.op(0), -ex_to<numeric>(f.op(1)).to_long()));
        else
          num.push_back(compile(f));
      }
      if (num.empty()) num.push_back(compile(ex(1)));
      const std::uint32_t top = emit_nary(Tape::Op::Product, num);
      if (den.empty()) return top;
      return emit({Tape::Op::Quotient, top, emit_nary(Tape::Op::Product, den), 0});
    }
    if (is_a<power>(e)) {
      const ex& expo = e.op(1);
      if (!is_a<numeric>(expo) || !ex_to<numeric>(expo).is_integer())
        throw InternalError("tape: non-integer power " + ex_text(e));
      const long k = ex_to<numeric>(expo).to_long();
      if (k == 0) return compile(ex(1));
      if (k > 0) return power_slot(e.op(0), k);
      return emit({Tape::Op::Quotient, compile(ex(1)), power_slot(e.op(0), -k), 0});
    }
    throw InternalError("tape: cannot compile " + ex_text(e));
  }

  Tape& tape_;
  CanonicalOrder order_;
  std::unordered_map<ex, std::uint32_t, ExHash, ex_is_equal> memo_;
  std::unordered_map<ex, std::uint32_t, ExHash, ex_is_equal> input_index_;
};

Tape::Tape(const std::vector<ex>& outputs, const std::vector<ex>& inputs, std::string denominator_name)
    : input_count_(inputs.size()), denominator_name_(std::move(denominator_name)) {
  TapeCompiler compiler(*this, inputs);
  for (const ex& o : outputs) outputs_.push_back(compiler.compile(o));
}

}  // namespace linkproof
