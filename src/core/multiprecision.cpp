#include "core/multiprecision.h"

#include <sstream>

namespace linkproof {

std::string format_cln_float(const cln::cl_F& x) {
  std::ostringstream os;
  os << x;
  std::string s = os.str();
  // CLN marks the float format in the exponent: L (long float), d, f, s. Decimal readers
  // expect 'e'; a zero exponent is dropped.
  const auto pos = s.find_first_of("Ldfs");
  if (pos == std::string::npos) return s;
  const std::string exponent = s.substr(pos + 1);
  s.resize(pos);
  if (exponent != "0") s += "e" + exponent;
  return s;
}

}  // namespace linkproof
