// Internal: GiNaC expressions as text for error messages.
#pragma once

#include <ginac/ginac.h>

#include <sstream>
#include <string>

namespace linkproof {
inline std::string ex_text(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}
}  // namespace linkproof
