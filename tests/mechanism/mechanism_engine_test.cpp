// The mechanism engine: symbolic loop closure (GiNaC) and rigid-body vector route, exact.
#include <gtest/gtest.h>

#include "mechanism/mechanism_vector_route.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_closure.h"
#include "mechanism/mechanism_solve.h"

namespace linkproof {
namespace {

std::string scene_path(const std::string& name) {
  return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/mechanisms/" + name;
}

MechanismSolution<Rational> solve_symbolic(const MechanismScene& s) {
  MechanismClosure closure(s.linkage);
  return solve_mechanism<Rational>(
      s.linkage, s.inputs, closure.constraint_matrix(),
      [&](const std::vector<Rational>& qd) { return closure.acceleration_rhs(qd); }, s.source);
}

MechanismSolution<Rational> solve_vector(const MechanismScene& s) {
  return solve_mechanism<Rational>(
      s.linkage, s.inputs, rigid_body_constraint_matrix<Rational>(s.linkage),
      [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(s.linkage, qd); },
      s.source);
}

Rational omega_of(const MechanismScene& s, const MechanismSolution<Rational>& m, const std::string& link) {
  return m.motion.omega[static_cast<size_t>(*s.linkage.find_link(link))];
}
Rational omega_dot_of(const MechanismScene& s, const MechanismSolution<Rational>& m, const std::string& link) {
  return m.motion.omega_dot[static_cast<size_t>(*s.linkage.find_link(link))];
}

TEST(MechanismEngine, EightBarOfFig5ReproducesConventionsA8Exactly) {
  const MechanismScene s = load_mechanism_scene(scene_path("fig5_eightbar.yaml"));
  const auto m = solve_symbolic(s);
  EXPECT_EQ(m.mobility, 1);
  EXPECT_EQ(s.linkage.loops().size(), 3u);
  const char* expected[] = {"0", "1", "-7/317", "60/317", "159/317", "-20/317", "-279/317", "22/317"};
  for (int l = 0; l < 8; ++l)
    EXPECT_EQ(format_rational(omega_of(s, m, std::to_string(l))), expected[l]) << "link " << l;
  EXPECT_EQ(format_rational(omega_dot_of(s, m, "4")), "171151479/318550130");
  EXPECT_EQ(format_rational(omega_dot_of(s, m, "1") - omega_dot_of(s, m, "2")), "8471254/159275065");
}

TEST(MechanismEngine, SymbolicClosureAndVectorRouteGiveTheSameSystem) {
  for (const char* name : {"fig5_eightbar.yaml", "seed001_fourbar.yaml"}) {
    const MechanismScene s = load_mechanism_scene(scene_path(name));
    MechanismClosure closure(s.linkage);
    EXPECT_EQ(closure.constraint_matrix(), rigid_body_constraint_matrix<Rational>(s.linkage)) << name;
    EXPECT_EQ(closure.acceleration_matrix(), closure.constraint_matrix()) << name;
    const auto a = solve_symbolic(s), b = solve_vector(s);
    EXPECT_EQ(a.qdot, b.qdot) << name;
    EXPECT_EQ(a.qddot, b.qddot) << name;
    for (const Rational& r : closure.position_residual()) EXPECT_TRUE(cln::zerop(r)) << name;
  }
}

TEST(MechanismEngine, FourBarOfSeed001ReproducesConventionsB) {
  const MechanismScene s = load_mechanism_scene(scene_path("seed001_fourbar.yaml"));
  const auto m = solve_symbolic(s);
  EXPECT_EQ(format_rational(omega_of(s, m, "3")), "-3/4");
  EXPECT_EQ(format_rational(omega_of(s, m, "4")), "7/20");
  EXPECT_EQ(format_rational(omega_dot_of(s, m, "3")), "63/160");
  EXPECT_EQ(format_rational(omega_dot_of(s, m, "4")), "3109/800");
}

}  // namespace
}  // namespace linkproof
