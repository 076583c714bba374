#include "linkproof/testing/cases.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <ostream>

#include <algorithm>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "core/scalar.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof::testing {

namespace {

int sign(const Rational& q) { return cln::minusp(q) ? -1 : (cln::zerop(q) ? 0 : 1); }

LinkageJoint revolute(const std::string& name, int l0, int l1, const Point& at) {
  LinkageJoint j;
  j.name = name;
  j.links[0] = l0;
  j.links[1] = l1;
  j.at = at;
  return j;
}

LinkageJoint prismatic(const std::string& name, int guide, int slider, const Point& at, const Point& axis) {
  LinkageJoint j = revolute(name, guide, slider, at);
  j.type = JointType::Prismatic;
  j.axis = axis;
  return j;
}

/// A case from links, joints and one link input. A linkage the builders cannot make (e.g. a
/// zero axis) is left empty (no links), which is_well_posed refuses.
MechanismCase assemble(const std::string& family, std::vector<std::string> links, int ground,
                       std::vector<LinkageJoint> joints, int input_link, const Rational& omega,
                       const Rational& omega_dot) {
  MechanismCase c;
  c.family = family;
  c.scene.name = "generated-" + family;
  c.scene.source = "linkproof::testing";
  std::replace(c.scene.name.begin(), c.scene.name.end(), '/', '-');
  if (!linkage_problem(links, ground, joints).empty()) return c;
  c.scene.linkage = Linkage(std::move(links), ground, std::move(joints));
  c.scene.inputs.push_back({MechanismInput::Kind::Link, input_link, omega, omega_dot});
  return c;
}

Rational squared_distance(const Point& p, const Point& q) { return dot(q - p, q - p); }

}  // namespace

MechanismCase polygon_mechanism(const PolygonCase& p) {
  const int n = p.polygon.n();
  std::vector<std::string> links;
  std::vector<LinkageJoint> joints;
  for (int j = 1; j <= n; ++j) links.push_back(fmt::format("s{}", j));
  // K_j (0-based joint j-1) joins side j-1 (the one ending there) and side j.
  for (int j = 0; j < n; ++j) joints.push_back(revolute(fmt::format("K{}", j + 1), (j + n - 1) % n, j,
                                p.polygon.joints()[static_cast<size_t>(j)]));
  MechanismCase c;
  c.family = p.family;
  c.scene.name = "generated-" + p.family;
  std::replace(c.scene.name.begin(), c.scene.name.end(), '/', '-');
  c.scene.source = "linkproof::testing";
  if (!linkage_problem(links, n - 1, joints).empty()) return c;
  c.scene.linkage = Linkage(std::move(links), n - 1, std::move(joints));
  for (int j = 0; j + 3 < n; ++j)
    c.scene.inputs.push_back({MechanismInput::Kind::Link, j, p.rates.omega[static_cast<size_t>(j)],
                              p.rates.omega_dot[static_cast<size_t>(j)]});
  return c;
}

std::string_view to_string(GrashofClass c) {
  switch (c) {
    case GrashofClass::CrankRocker: return "crank-rocker";
    case GrashofClass::DoubleCrank: return "double-crank";
    case GrashofClass::DoubleRocker: return "double-rocker";
    case GrashofClass::ChangePoint: return "change-point";
    case GrashofClass::TripleRocker: return "triple-rocker";
  }
  return "?";
}

int sign_of_root_sum_difference(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  // x = (sqrt a + sqrt b) - (sqrt c + sqrt d); both sums >= 0, so sign x = sign of the difference
  // of their squares: u + 2 t with u = a + b - c - d and t = sqrt(ab) - sqrt(cd).
  const Rational u = a + b - c - d;
  const int st = sign(a * b - c * d);  // sign of t
  const int su = sign(u);
  if (st == 0) return su;
  if (su == 0 || su == st) return st;
  // Opposite signs: compare u^2 with 4 t^2 = 4 (ab + cd) - 8 sqrt(abcd): sign(u^2 - 4t^2) =
  // sign(w + 8 sqrt(abcd)) with w = u^2 - 4ab - 4cd.
  const Rational w = u * u - Rational(4) * a * b - Rational(4) * c * d;
  int s;  // sign(u^2 - 4 t^2)
  if (!cln::minusp(w)) {
    s = (cln::zerop(w) && cln::zerop(a * b * c * d)) ? 0 : 1;
  } else {
    s = sign(Rational(64) * a * b * c * d - w * w);  // sign(8 sqrt(abcd) - |w|)
  }
  // |u| > 2|t| (s > 0): u wins; |u| < 2|t|: t wins; equal: 0.
  return s > 0 ? su : (s < 0 ? st : 0);
}

GrashofClass classify_grashof(const Point& o2, const Point& a, const Point& b, const Point& o4) {
  // Squared lengths: 0 ground, 1 crank, 2 coupler, 3 rocker.
  std::array<Rational, 4> sq = {squared_distance(o2, o4), squared_distance(o2, a), squared_distance(a, b),
                                squared_distance(b, o4)};
  std::array<int, 4> order = {0, 1, 2, 3};
  std::sort(order.begin(), order.end(), [&](int i, int k) { return sq[static_cast<size_t>(i)] < sq[static_cast<size_t>(k)]; });
  const auto& s = sq[static_cast<size_t>(order[0])];
  const auto& p = sq[static_cast<size_t>(order[1])];
  const auto& q = sq[static_cast<size_t>(order[2])];
  const auto& l = sq[static_cast<size_t>(order[3])];
  const int g = sign_of_root_sum_difference(s, l, p, q);
  if (g > 0) return GrashofClass::TripleRocker;
  if (g == 0) return GrashofClass::ChangePoint;
  switch (order[0]) {
    case 0: return GrashofClass::DoubleCrank;
    case 2: return GrashofClass::DoubleRocker;
    default: return GrashofClass::CrankRocker;  // the shortest is the crank or the rocker
  }
}

MechanismCase make_fourbar(const Point& o2, const Point& a, const Point& b, const Point& o4, const Rational& omega,
                           const Rational& omega_dot) {
  return assemble(fmt::format("fourbar/{}", to_string(classify_grashof(o2, a, b, o4))),
                  {"ground", "crank", "coupler", "rocker"}, 0,
                  {revolute("O2", 0, 1, o2), revolute("A", 1, 2, a), revolute("B", 2, 3, b), revolute("O4", 3, 0, o4)}, 1,
                  omega, omega_dot);
}

/// A six-bar from a joint table {name, link, link} over joints A..G in order.
static MechanismCase six_bar(const std::string& family, std::vector<std::string> links, const int (&pairs)[7][2],
                      const std::array<Point, 7>& p, const Rational& omega, const Rational& omega_dot) {
  std::vector<LinkageJoint> joints;
  for (size_t i = 0; i < 7; ++i)
    joints.push_back(revolute(std::string(1, static_cast<char>('A' + i)), pairs[i][0], pairs[i][1], p[i]));
  return assemble(family, std::move(links), 0, std::move(joints), 1, omega, omega_dot);
}

MechanismCase make_watt_sixbar(const std::array<Point, 7>& p, const Rational& omega, const Rational& omega_dot) {
  // links: 0 ground, 1 AB, 2 BCD, 3 DE, 4 EF, 5 CFG; joints A..G
  static const int pairs[7][2] = {{0, 1}, {1, 2}, {2, 5}, {2, 3}, {3, 4}, {4, 5}, {0, 5}};
  return six_bar("sixbar/watt-i", {"ground", "AB", "BCD", "DE", "EF", "CFG"}, pairs, p, omega, omega_dot);
}

MechanismCase make_stephenson_sixbar(const std::array<Point, 7>& p, const Rational& omega, const Rational& omega_dot) {
  // links: 0 ground, 1 AB, 2 BCE, 3 CD, 4 EF, 5 FG; joints A..G
  static const int pairs[7][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {4, 5}, {5, 0}};
  return six_bar("sixbar/stephenson-iii", {"ground", "AB", "BCE", "CD", "EF", "FG"}, pairs, p, omega, omega_dot);
}

MechanismCase make_fig5_eightbar(const std::array<Point, 10>& p, const Rational& omega, const Rational& omega_dot) {
  static const int pairs[10][2] = {{1, 2}, {2, 3}, {3, 4}, {4, 0}, {0, 1}, {1, 5}, {5, 7}, {7, 4}, {5, 6}, {6, 3}};
  std::vector<LinkageJoint> joints;
  for (size_t i = 0; i < 10; ++i)
    joints.push_back(revolute(fmt::format("J{}{}", pairs[i][0], pairs[i][1]), pairs[i][0], pairs[i][1], p[i]));
  return assemble("eightbar/fig5", {"0", "1", "2", "3", "4", "5", "6", "7"}, 0, std::move(joints), 1, omega, omega_dot);
}

MechanismCase make_slider_crank(const Point& o, const Point& a, const Point& b, const Point& axis, const Rational& omega,
                                const Rational& omega_dot) {
  return assemble("slider/crank", {"ground", "crank", "rod", "slider"}, 0,
                  {revolute("O", 0, 1, o), revolute("A", 1, 2, a), revolute("B", 2, 3, b), prismatic("P", 0, 3, b, axis)},
                  1, omega, omega_dot);
}

MechanismCase make_inverted_slider_crank(const Point& o2, const Point& a, const Point& o4, const Rational& omega,
                                         const Rational& omega_dot) {
  return assemble("slider/inverted", {"ground", "crank", "block", "rocker"}, 0,
                  {revolute("O2", 0, 1, o2), revolute("A", 1, 2, a), prismatic("P", 3, 2, a, a - o4),
                   revolute("O4", 3, 0, o4)},
                  1, omega, omega_dot);
}

bool is_well_posed(const MechanismScene& scene) {
  const Linkage& g = scene.linkage;
  if (g.link_count() < 2) return false;
  // No two joints of one link at the same point (a link's direction would be undefined).
  for (int i = 0; i < g.joint_count(); ++i)
    for (int k = i + 1; k < g.joint_count(); ++k) {
      const LinkageJoint &a = g.joint(i), &b = g.joint(k);
      const bool share = a.links[0] == b.links[0] || a.links[0] == b.links[1] || a.links[1] == b.links[0] ||
                         a.links[1] == b.links[1];
      const bool same_pair = a.type == JointType::Prismatic || b.type == JointType::Prismatic;
      if (share && !same_pair && a.at.x == b.at.x && a.at.y == b.at.y) return false;
    }
  try {
    solve_mechanism<Rational>(
        g, scene.inputs, rigid_body_constraint_matrix<Rational>(g),
        [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(g, qd); }, scene.source);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

Rational compute_velocity_determinant(const MechanismScene& scene) {
  const Linkage& g = scene.linkage;
  if (g.link_count() < 2) throw InputError(scene.source, "mechanism", "no linkage: no velocity system");
  DenseMatrix<Rational> a = rigid_body_constraint_matrix<Rational>(g);
  std::vector<Rational> unused;
  append_input_rows(g, scene.inputs, a, unused, false, scene.source);
  const size_t n = static_cast<size_t>(g.unknown_count());
  if (a.size() != n)
    throw InputError(scene.source, "mechanism.inputs",
                     fmt::format("the velocity system has {} rows for {} unknowns: no determinant", a.size(), n));
  // Gaussian elimination with the first non-zero pivot (exact: any non-zero pivot will do).
  Rational det = 1;
  for (size_t c = 0; c < n; ++c) {
    size_t p = c;
    while (p < n && cln::zerop(a[p][c])) ++p;
    if (p == n) return 0;
    if (p != c) a.swap_rows(p, c), det = -det;
    det *= a[c][c];
    for (size_t r = c + 1; r < n; ++r) {
      if (cln::zerop(a[r][c])) continue;
      const Rational f = a[r][c] / a[c][c];
      for (size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  return det;
}

std::ostream& operator<<(std::ostream& os, GrashofClass c) { return os << to_string(c); }

std::ostream& operator<<(std::ostream& os, const MechanismCase& c) {
  return os << c.family << "\n" << (c.scene.linkage.link_count() ? mechanism_scene_to_yaml(c.scene) : "(no linkage)\n");
}

std::ostream& operator<<(std::ostream& os, const PolygonCase& c) {
  os << c.family << ": joints";
  for (const auto& k : c.polygon.joints()) os << " (" << format_rational(k.x) << ", " << format_rational(k.y) << ")";
  os << "; omega";
  for (const auto& w : c.rates.omega) os << " " << format_rational(w);
  os << "; omega_dot";
  for (const auto& w : c.rates.omega_dot) os << " " << format_rational(w);
  return os;
}

std::array<double, 2> joint_xy(const Linkage& g, const std::string& joint) {
  const auto j = g.find_joint(joint);
  if (!j) throw InputError("linkproof::testing", "joint_xy", "no joint named `" + joint + "`");
  const Point& p = g.joint(*j).at;
  return {ScalarTraits<double>::from_rational(p.x), ScalarTraits<double>::from_rational(p.y)};
}

}  // namespace linkproof::testing
