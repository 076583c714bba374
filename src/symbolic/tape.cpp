#include "symbolic/tape.h"

#include <map>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "linkproof/core/error.h"
#include "symbolic/canonical_form.h"

namespace linkproof {

using namespace GiNaC;

/// Emits the canonical form (canonical_form.h) of expressions as a Tape, one instruction list
/// per distinct primitive part: the tape depends on the functions compiled, not on how GiNaC
/// happened to store them in this run.
class TapeCompiler {
 public:
  TapeCompiler(Tape& tape, CanonicalForm form) : tape_(tape), form_(std::move(form)) {}

  std::uint32_t compile(const ex& e) { return compile(form_.split(e)); }
  std::uint32_t compile(const CanonicalForm::Split& s) { return term(s.primitive, s.content); }

 private:
  using Id = CanonicalForm::Id;

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

  /// One slot per distinct constant.
  std::uint32_t constant(const numeric& c) {
    std::ostringstream text;
    text << c;
    auto [it, fresh] = constants_.try_emplace(text.str(), 0);
    if (fresh) {
      tape_.constants_.push_back(cln::the<cln::cl_RA>(c.to_cl_N()));
      it->second = emit({Tape::Op::Constant, static_cast<std::uint32_t>(tape_.constants_.size() - 1), 0, 0});
    }
    return it->second;
  }

  /// c * node(p). A product takes the coefficient as its first factor (one instruction, as
  /// GiNaC's own c*x*y would be); anything else is multiplied by it.
  std::uint32_t term(Id p, const numeric& c) {
    if (c.is_zero()) return constant(c);
    if (c.is_equal(numeric(1))) return primitive(p);
    if (p == CanonicalForm::one) return constant(c);
    std::ostringstream text;
    text << p << "*" << c;
    if (auto it = terms_.find(text.str()); it != terms_.end()) return it->second;
    const std::uint32_t slot = form_.node(p).kind == CanonicalForm::Kind::Product
                                   ? product(form_.node(p), constant(c))
                                   : emit_nary(Tape::Op::Product, {constant(c), primitive(p)});
    terms_.emplace(text.str(), slot);
    return slot;
  }

  std::uint32_t power(Id base, int k) {
    if (k == 1) return primitive(base);
    auto [it, fresh] = powers_.try_emplace({base, k}, 0);
    if (fresh) it->second = emit({Tape::Op::Power, primitive(base), 0, k});
    return it->second;
  }

  /// One quotient per product: the coefficient and the positive powers over the product of the
  /// negative powers, each list in canonical order.
  std::uint32_t product(const CanonicalForm::Node& n, std::optional<std::uint32_t> coefficient) {
    std::vector<std::uint32_t> num, den;
    if (coefficient) num.push_back(*coefficient);
    for (const auto& [base, k] : n.factors) {
      if (k > 0)
        num.push_back(power(base, k));
      else
        den.push_back(power(base, -k));
    }
    if (num.empty()) num.push_back(constant(1));
    const std::uint32_t top = emit_nary(Tape::Op::Product, num);
    if (den.empty()) return top;
    return emit({Tape::Op::Quotient, top, emit_nary(Tape::Op::Product, den), 0});
  }

  std::uint32_t primitive(Id p) {
    if (auto it = slots_.find(p); it != slots_.end()) return it->second;
    const CanonicalForm::Node& n = form_.node(p);
    std::uint32_t slot = 0;
    switch (n.kind) {
      case CanonicalForm::Kind::One: slot = constant(1); break;
      case CanonicalForm::Kind::Symbol: slot = emit({Tape::Op::Input, n.input, 0, 0}); break;
      case CanonicalForm::Kind::Sum: {
        std::vector<std::uint32_t> args;
        args.reserve(n.terms.size());
        for (const auto& [t, c] : n.terms) args.push_back(term(t, c));
        slot = emit_nary(Tape::Op::Sum, args);
        break;
      }
      case CanonicalForm::Kind::Product: slot = product(n, std::nullopt); break;
      case CanonicalForm::Kind::Atom:  // only claim expressions have atoms (CanonicalForm::with_atoms)
        throw InternalError("Tape: an atom of a claim expression in a tape of the loop solution");
    }
    slots_.emplace(p, slot);
    return slot;
  }

  Tape& tape_;
  CanonicalForm form_;
  std::unordered_map<Id, std::uint32_t> slots_;
  std::unordered_map<std::string, std::uint32_t> terms_;
  std::unordered_map<std::string, std::uint32_t> constants_;
  std::map<std::pair<Id, int>, std::uint32_t> powers_;
};

Tape::Tape(const std::vector<ex>& outputs, const std::vector<ex>& inputs, std::string denominator_name)
    : input_count_(inputs.size()), denominator_name_(std::move(denominator_name)) {
  TapeCompiler compiler(*this, CanonicalForm(inputs));
  for (const ex& o : outputs) outputs_.push_back(compiler.compile(o));
}

Tape::Tape(CanonicalForm form, const std::vector<CanonicalForm::Split>& outputs, std::string denominator_name)
    : input_count_(form.input_count()), denominator_name_(std::move(denominator_name)) {
  TapeCompiler compiler(*this, std::move(form));
  for (const CanonicalForm::Split& o : outputs) outputs_.push_back(compiler.compile(o));
}

}  // namespace linkproof
