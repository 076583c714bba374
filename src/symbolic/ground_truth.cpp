#include "symbolic/ground_truth.h"

#include <string>

#include "linkproof/core/error.h"
#include "symbolic/motion_tape.h"

namespace linkproof {

using namespace GiNaC;

namespace {

constexpr const char* kDenominator = "D = r_{n-2} x r_{n-1}";

std::vector<ex> make_inputs(const PolygonSymbols& s) {
  const int n = s.n();
  std::vector<ex> v;
  for (int j = 1; j <= n - 1; ++j) v.push_back(s.x(j));
  for (int j = 1; j <= n - 1; ++j) v.push_back(s.y(j));
  for (int j = 1; j <= n - 3; ++j) v.push_back(s.omega(j));
  for (int j = 1; j <= n - 3; ++j) v.push_back(s.omega_dot(j));
  return v;
}

/// Coefficients of E in the input rates, by differentiation (E is linear in omega-dot and a
/// quadratic form in omega). Each must be free of every rate symbol.
void append_coefficients(const ex& e, const PolygonSymbols& s, std::vector<ex>& out) {
  const int m = s.n() - 3;
  const size_t start = out.size();
  for (int j = 1; j <= m; ++j) out.push_back(e.diff(s.omega_dot(j)));
  std::vector<ex> first(static_cast<size_t>(m));
  for (int j = 1; j <= m; ++j) first[j - 1] = e.diff(s.omega(j));
  for (int j = 1; j <= m; ++j) out.push_back(first[j - 1].diff(s.omega(j)) / 2);
  for (int j = 1; j <= m; ++j)
    for (int l = j + 1; l <= m; ++l) out.push_back(first[j - 1].diff(s.omega(l)));
  for (size_t k = start; k < out.size(); ++k)
    for (int j = 1; j <= m; ++j)
      LINKPROOF_ASSERT(!out[k].has(s.omega(j)) && !out[k].has(s.omega_dot(j)),
                       "omega-dot must be linear in omega-dot_j and quadratic in omega_j");
}

}  // namespace

GroundTruthEngine::Derivation::Derivation(int n) : motion(derive_motion_tape(n, kDenominator)) {}

GroundTruthEngine::SymbolicDerivation::SymbolicDerivation(int n)
    : symbols(n), solution(derive_loop_solution(symbols)), inputs(make_inputs(symbols)) {}

Tape GroundTruthEngine::SymbolicDerivation::motion_tape() const {
  return Tape({solution.omega_n2, solution.omega_n1, solution.omega_dot_n2, solution.omega_dot_n1}, inputs,
              kDenominator);
}

const GroundTruthEngine::Derivation& GroundTruthEngine::derivation(int n) {
  auto& slot = cache_[n];
  if (!slot) slot = std::make_unique<Derivation>(n);
  return *slot;
}

const GroundTruthEngine::SymbolicDerivation& GroundTruthEngine::symbolic_derivation(int n) {
  auto& slot = symbolic_cache_[n];
  if (!slot) slot = std::make_unique<SymbolicDerivation>(n);
  return *slot;
}

const Tape& GroundTruthEngine::coefficient_tape(int n) {
  symbolic_derivation(n);
  SymbolicDerivation& d = *symbolic_cache_[n];
  if (!d.coefficients) {
    std::vector<ex> outputs;
    append_coefficients(d.solution.omega_dot_n1, d.symbols, outputs);
    append_coefficients(d.solution.omega_dot_n2, d.symbols, outputs);
    d.coefficients = std::make_unique<Tape>(outputs, d.inputs, kDenominator);
  }
  return *d.coefficients;
}

PolygonMotion<Rational> exact_polygon_motion(const Polygon<Rational>& polygon, const InputRates<Rational>& rates) {
  const std::string problem = polygon_input_problem(polygon);
  if (!problem.empty()) throw InputError("exact_polygon_motion", "polygon", problem);
  const auto inputs = static_cast<size_t>(polygon.n() - 3);
  if (rates.omega.size() != inputs || rates.omega_dot.size() != inputs)
    throw InputError("exact_polygon_motion", "rates",
                     "a polygon of " + std::to_string(polygon.n()) + " sides needs " + std::to_string(inputs) +
                         " omega and omega-dot values (one per input side 1..n-3)");
  if (cln::zerop(polygon.dead_centre_determinant()))
    throw InputError("exact_polygon_motion", "polygon",
                     "dead centre: D = r_{n-2} x r_{n-1} = 0, the velocity system is singular and no motion exists");
  static thread_local GroundTruthEngine engine;  // caches each n's derivation
  return engine.motion(polygon, rates);
}

}  // namespace linkproof
