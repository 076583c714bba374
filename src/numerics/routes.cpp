#include "numerics/routes.h"

namespace linkproof {

std::string_view to_string(Route r) {
  switch (r) {
    case Route::Construction: return "construction";
    case Route::ClosedForms: return "closed-forms";
    case Route::DirectSolve: return "direct-solve";
    case Route::SymbolicTape: break;
  }
  return "symbolic-tape";
}

std::optional<Route> parse_route(std::string_view s) {
  for (Route r : kAllRoutes)
    if (to_string(r) == s) return r;
  return std::nullopt;
}

}  // namespace linkproof
