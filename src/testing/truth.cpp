#include "linkproof/testing/truth.h"


#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/scalar.h"
#include "core/tracked.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof::testing {

namespace {

/// Exact: from the exact joint differences. Tracked<double>: from every joint rounded to double
/// (with that rounding in its radius), as a double library receives them: so the bound also
/// covers the cancellation in differences of nearby joints (A - O2 of a tiny crank).
template <class T>
MechanismSolution<T> solve_vector_route(const MechanismScene& s) {
  const Linkage& g = s.linkage;
  std::vector<Vec2<T>> at;
  for (const auto& j : g.joints()) at.push_back(vec_from_rational<T>(j.at));
  const JointGeometry<T> positions{ScalarTraits<T>::is_exact ? nullptr : &at};
  return solve_mechanism<T>(
      g, s.inputs, rigid_body_constraint_matrix<T>(g, positions),
      [&](const std::vector<T>& qd) { return rigid_body_acceleration_rhs<T>(g, qd, true, positions); }, s.source);
}

BoundedDouble bounded(const Tracked<double>& x) {
  // A radius that is NaN (inf * 0 after a lost pivot) bounds nothing.
  return {x.v, std::isfinite(x.e) ? x.e : std::numeric_limits<double>::infinity()};
}

}  // namespace

std::vector<double> MechanismTruth::alpha_doubles() const {
  std::vector<double> out;
  for (const auto& l : links) out.push_back(ScalarTraits<double>::from_rational(l.alpha));
  return out;
}

std::vector<double> MechanismTruth::omega_doubles() const {
  std::vector<double> out;
  for (const auto& l : links) out.push_back(nearest_double(l.omega));
  return out;
}

size_t MechanismTruth::link_index(std::string_view name) const {
  for (size_t k = 0; k < links.size(); ++k)
    if (links[k].link == name) return k;
  throw std::out_of_range("scene `" + scene + "` has no link named `" + std::string(name) + "`");
}

MechanismTruth compute_truth(const MechanismScene& scene) {
  const MechanismSolution<Rational> exact = solve_vector_route<Rational>(scene);
  MechanismTruth t;
  t.scene = scene.name;
  const Linkage& g = scene.linkage;
  std::vector<BoundedDouble> w(static_cast<size_t>(g.link_count())), a = w;
  try {
    const MechanismSolution<Tracked<double>> approx = solve_vector_route<Tracked<double>>(scene);
    for (size_t l = 0; l < w.size(); ++l) {
      w[l] = bounded(approx.motion.omega[l]);
      a[l] = bounded(approx.motion.omega_dot[l]);
    }
  } catch (const InputError&) {
    // The exact solve succeeded, so double elimination misjudged a rank: nothing is bounded.
    for (size_t l = 0; l < w.size(); ++l) {
      const double inf = std::numeric_limits<double>::infinity();
      w[l] = {ScalarTraits<double>::from_rational(exact.motion.omega[l]), inf};
      a[l] = {ScalarTraits<double>::from_rational(exact.motion.omega_dot[l]), inf};
    }
  }
  for (int l = 0; l < g.link_count(); ++l) {
    const size_t i = static_cast<size_t>(l);
    t.links.push_back({g.link_name(l), l == g.ground(), exact.motion.omega[i], exact.motion.omega_dot[i], w[i], a[i]});
  }
  return t;
}

}  // namespace linkproof::testing
