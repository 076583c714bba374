// GiNaC expressions as a scalar type: the generic evaluation code (construction, closed forms,
// tapes, claim expressions) run over symbolic coordinates, which turns an evaluation into a
// proof object.
//
// The meaning of is_zero changes with the type: for an expression it is "identically zero as a
// rational function" (normal() of the expression is 0). A construction that divides by a
// polynomial that is not identically zero therefore goes on, and the result holds
// *generically*: the denominators it divided by are where it may fail (see proof/prove.h, which
// lists them). Expressions are not normalised after each operation (that would be quadratic in
// the work); only zero tests and final results are.
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <string_view>
#include <vector>

#include "linkproof/core/exact.h"
#include "core/scalar.h"

namespace linkproof {

/// Records every non-constant expression tested for zero while it lives (one per thread): the
/// quantities a symbolic evaluation divided by, or branched on. A proof lists where they
/// vanish (proof/prove.h).
class ZeroTestLog {
 public:
  ZeroTestLog();
  ~ZeroTestLog();
  ZeroTestLog(const ZeroTestLog&) = delete;
  ZeroTestLog& operator=(const ZeroTestLog&) = delete;
  const std::vector<GiNaC::ex>& tested() const { return tested_; }
  static void record(const GiNaC::ex& e);

 private:
  std::vector<GiNaC::ex> tested_;
  ZeroTestLog* previous_;
};

/// A rational number as a GiNaC numeric (exact).
GiNaC::ex to_ginac(const Rational& q);

template <>
struct ScalarTraits<GiNaC::ex> {
  static constexpr bool is_exact = true;
  static constexpr bool has_error_bound = false;
  static constexpr bool is_symbolic = true;
  static constexpr std::string_view name = "symbolic";
  static GiNaC::ex from_rational(const Rational& q) { return to_ginac(q); }
  /// Identically zero as a rational function of the symbols.
  static bool is_zero(const GiNaC::ex& x);
  /// Only defined for rational constants: |x| of a symbolic expression has no rational form.
  static GiNaC::ex abs(const GiNaC::ex& x);
  static double to_double(const GiNaC::ex& x);
  static std::string to_string(const GiNaC::ex& x);
};

}  // namespace linkproof
