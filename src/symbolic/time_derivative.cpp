#include "symbolic/time_derivative.h"

#include "linkproof/core/error.h"
#include "ex_text.h"

namespace linkproof {

using namespace GiNaC;

void TimeDerivative::set_rate(const symbol& s, const ex& rate) { rate_[s] = rate; }

ex TimeDerivative::apply(const ex& e) const {
  if (is_a<numeric>(e)) return 0;
  if (is_a<symbol>(e)) {
    auto it = rate_.find(e);
    return it == rate_.end() ? ex(0) : it->second;
  }
  if (is_a<add>(e)) {
    exvector terms;
    terms.reserve(e.nops());
    for (size_t i = 0; i < e.nops(); ++i) {
      ex d = apply(e.op(i));
      if (!d.is_zero()) terms.push_back(d);
    }
    return dynallocate<add>(terms);
  }
  if (is_a<mul>(e)) {  // product rule
    exvector terms;
    for (size_t i = 0; i < e.nops(); ++i) {
      ex d = apply(e.op(i));
      if (d.is_zero()) continue;
      exvector factors;
      factors.reserve(e.nops());
      for (size_t k = 0; k < e.nops(); ++k) factors.push_back(k == i ? d : e.op(k));
      terms.push_back(dynallocate<mul>(factors));
    }
    return dynallocate<add>(terms);
  }
  if (is_a<power>(e)) {
    const ex& base = e.op(0);
    const ex& expo = e.op(1);
    if (!is_a<numeric>(expo)) throw InternalError("time derivative: non-numeric exponent in " + ex_text(e));
    return expo * pow(base, expo - 1) * apply(base);
  }
  if (is_ex_the_function(e, cos)) return -sin(e.op(0)) * apply(e.op(0));
  if (is_ex_the_function(e, sin)) return cos(e.op(0)) * apply(e.op(0));
  throw InternalError("time derivative: no rule for " + ex_text(e));
}

}  // namespace linkproof
