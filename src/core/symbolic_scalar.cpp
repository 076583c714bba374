#include "core/symbolic_scalar.h"

#include <sstream>

#include "linkproof/core/error.h"
#include "core/modular_point.h"

namespace linkproof {

GiNaC::ex to_ginac(const Rational& q) {
  return GiNaC::numeric(cln::cl_N(q));
}

namespace {
thread_local ZeroTestLog* current_log = nullptr;
}  // namespace

ZeroTestLog::ZeroTestLog() : previous_(current_log) { current_log = this; }
ZeroTestLog::~ZeroTestLog() { current_log = previous_; }
void ZeroTestLog::record(const GiNaC::ex& e) {
  if (current_log) current_log->tested_.push_back(e);
}

bool ScalarTraits<GiNaC::ex>::is_zero(const GiNaC::ex& x) {
  if (GiNaC::is_exactly_a<GiNaC::numeric>(x)) return x.is_zero();
  // Non-zero at one point where it is defined: not identically zero (modular_point.h); only a
  // "zero" answer needs the symbolic normal form.
  if (ModularPoint().shows_nonzero(x)) {
    ZeroTestLog::record(x);
    return false;
  }
  const GiNaC::ex v = GiNaC::normal(x);
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(v)) ZeroTestLog::record(v);
  return v.is_zero();
}

GiNaC::ex ScalarTraits<GiNaC::ex>::abs(const GiNaC::ex& x) {
  const GiNaC::ex v = GiNaC::normal(x);
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(v))
    throw UndefinedQuantity("|" + to_string(x) + "|", "the absolute value of a symbolic expression is not a rational function");
  return GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v));
}

double ScalarTraits<GiNaC::ex>::to_double(const GiNaC::ex& x) {
  const GiNaC::ex v = GiNaC::evalf(x);
  if (!GiNaC::is_a<GiNaC::numeric>(v)) throw InternalError("to_double of a symbolic expression");
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

std::string ScalarTraits<GiNaC::ex>::to_string(const GiNaC::ex& x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace linkproof
