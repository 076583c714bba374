// Dijksman (1984) (conventions §D): the eight-bar of Fig. 1 (links 0..7; ternary 0, 2, 4, 6;
// bars 1, 3, 5, 7; joints named by their two links, e.g. "12"), the section-3 pole constructions
// by line intersections, the relocation formulas (1'), (3'), (5'), (7'), (1'')-(7''), and the
// erratum readings: the printed (5') (distance from P65 on the left) and the printed P60 (double
// primes). The generic claims (poles, Euler-Savary, Bobillier, joint-joining) are in
// mechanism/curvature_analysis.h; this file holds only what names the paper's links.
#include <fmt/format.h>

#include "mechanism/curvature.h"
#include "mechanism/joint_joining.h"
#include "mechanism_catalogues.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof::catalogues {

namespace {

using PP = PlanePoint<Rational>;
const char* kSource = "Dijksman (1984), docs/conventions.md §D";
const char* kJoints[] = {"01", "12", "23", "34", "45", "56", "67", "70", "26", "04"};

// The joint between links a and b (names), or -1.
int joint_between(const Linkage& g, const std::string& a, const std::string& b) {
  const auto la = g.find_link(a), lb = g.find_link(b);
  if (!la || !lb) return -1;
  for (int j = 0; j < g.joint_count(); ++j) {
    const auto& J = g.joint(j);
    if (J.type == JointType::Revolute && ((J.links[0] == *la && J.links[1] == *lb) || (J.links[0] == *lb && J.links[1] == *la)))
      return j;
  }
  return -1;
}

bool is_eightbar(const MechanismContext& c) {
  const Linkage& g = c.scene.linkage;
  if (g.link_count() != 8 || g.joint_count() != 10 || c.truth.mobility != 1) return false;
  for (const char* j : kJoints)
    if (joint_between(g, std::string(1, j[0]), std::string(1, j[1])) < 0) return false;
  return true;
}

// The paper's quantities at one instant: joints J("12"), engine poles pole("2", "0"), the
// I points and the section-3 constructions.
struct EightBar {
  const Linkage& g;
  std::vector<LinkField<Rational>> fields;
  explicit EightBar(const MechanismContext& c) : g(c.scene.linkage), fields(c.truth.motion.fields) {}
  Vec2<Rational> J(const char* name) const { return g.joint(joint_between(g, std::string(1, name[0]), std::string(1, name[1]))).at; }
  int link(const std::string& n) const { return *g.find_link(n); }
  const LinkField<Rational>& field(const std::string& n) const { return fields[static_cast<size_t>(link(n))]; }
  PP pole(const std::string& a, const std::string& b) const { return construct_pole(field(a), field(b), "P_" + a + b); }
  // (p1 - p2) x (p3 - p4) with a named result that must be finite to go on.
  static Vec2<Rational> meet(const Vec2<Rational>& p1, const Vec2<Rational>& p2, const Vec2<Rational>& p3,
                             const Vec2<Rational>& p4, const std::string& name) {
    const PP p = intersect_lines(p1, p2, p3, p4, name);
    if (!p.is_finite()) throw UndefinedQuantity(name, p.kind == PP::Kind::AtInfinity ? "at infinity" : p.reason);
    return p.at;
  }
  Vec2<Rational> I17() const { return meet(J("12"), J("01"), J("67"), J("70"), "I17"); }
  Vec2<Rational> I35() const { return meet(J("56"), J("45"), J("23"), J("34"), "I35"); }
  Vec2<Rational> I13() const { return meet(J("23"), J("34"), J("12"), J("01"), "I13"); }
  Vec2<Rational> I57() const { return meet(J("56"), J("45"), J("67"), J("70"), "I57"); }
  Vec2<Rational> finite_pole(const std::string& a, const std::string& b) const {
    const PP p = pole(a, b);
    if (!p.is_finite()) throw UndefinedQuantity("P_" + a + b, "not a finite point");
    return p.at;
  }
};

void compare_point(ClaimSides<Rational>& s, const std::string& label, const Vec2<Rational>& a, const PP& b) {
  if (!b.is_finite()) throw UndefinedQuantity(label, "the engine's point is not finite");
  s.instances.push_back({label + ".x", a.x, b.at.x});
  s.instances.push_back({label + ".y", a.y, b.at.y});
}

// The linkage after first-order joint-joining on all four ternary links (Fig. 1B), solved.
MechanismSolution<Rational> fig1b_motion(const MechanismContext& c, Linkage& reduced) {
  reduced = c.scene.linkage;
  const std::pair<const char*, std::pair<const char*, const char*>> steps[] = {
      {"2", {"1", "3"}}, {"4", {"3", "5"}}, {"6", {"5", "7"}}, {"0", {"7", "1"}}};
  for (const auto& [t, bars] : steps) {
    const auto now = solve_rigid_body(reduced, c.scene.inputs, c.scene.source);
    JointJoiningRequest r{*reduced.find_link(t), {*reduced.find_link(bars.first), *reduced.find_link(bars.second)}, 1};
    JointJoiningStep step = join_joints(reduced, now.motion, r);
    if (!step.problem.empty()) throw UndefinedQuantity("first-order reduction on link " + std::string(t), step.problem);
    reduced = step.reduced;
  }
  return solve_rigid_body(reduced, c.scene.inputs, c.scene.source);
}

// Section 3: P63', P3'0 (poles of the reduced linkage), then P60, P64, P20, P24 (original poles).
ClaimSides<Rational> section3_poles(const MechanismContext& c, bool printed_p60) {
  const EightBar e(c);
  ClaimSides<Rational> s;
  const Vec2<Rational> I13 = e.I13(), I35 = e.I35();
  Vec2<Rational> P63p, P3p0;
  if (!printed_p60) {
    P63p = EightBar::meet(e.J("56"), e.J("45"), e.J("26"), I13, "P63'");
    P3p0 = EightBar::meet(e.J("12"), e.J("01"), I35, e.J("04"), "P3'0");
    Linkage reduced;
    const auto m = fig1b_motion(c, reduced);
    const auto& f = m.motion.fields;
    const auto field = [&](const char* n) { return f[static_cast<size_t>(*reduced.find_link(n))]; };
    compare_point(s, "P63' (reduced linkage, Fig. 1B)", P63p, construct_pole(field("6"), field("3"), "P63'"));
    compare_point(s, "P3'0 (reduced linkage, Fig. 1B)", P3p0, construct_pole(field("3"), field("0"), "P3'0"));
  } else {
    // The printed double primes read as bar 3'' of the section-4 alternative reduction (Fig. 5:
    // joining on links 4 and 0), whose joint 3''2 is relocated by (3'') and which no longer pivots
    // at I13, kept in the section-3 lines: P63'' = (65-54) x (62-3''2), P3''0 = (21-10) x (I35-40).
    const PP J32 = relocate_far_joint(e.finite_pole("2", "4"), e.J("34"), e.J("23"), I35, "3''2");
    if (!J32.is_finite()) throw UndefinedQuantity("3''2", "not a finite point");
    P63p = EightBar::meet(e.J("56"), e.J("45"), e.J("26"), J32.at, "P63''");
    P3p0 = EightBar::meet(e.J("12"), e.J("01"), I35, e.J("04"), "P3''0");
  }
  const Vec2<Rational> P60 = EightBar::meet(e.J("67"), e.J("70"), P63p, P3p0, "P60");
  compare_point(s, printed_p60 ? "P60 printed (67-70) x (63''-3''0)" : "P60 = (67-70) x (63'-3'0)", P60, e.pole("6", "0"));
  if (printed_p60) return s;
  const Vec2<Rational> P64 = EightBar::meet(P60, e.J("04"), e.J("56"), e.J("45"), "P64");
  compare_point(s, "P64 = (60-04) x (65-54)", P64, e.pole("6", "4"));
  const Vec2<Rational> P20 = EightBar::meet(e.J("12"), e.J("01"), e.J("26"), P60, "P20");
  compare_point(s, "P20 = (21-10) x (26-60)", P20, e.pole("2", "0"));
  const Vec2<Rational> P24 = EightBar::meet(e.J("23"), e.J("34"), P20, e.J("04"), "P24");
  compare_point(s, "P24 = (23-34) x (20-04)", P24, e.pole("2", "4"));
  return s;
}

// One relocation formula: ternary t, bar joint N on t, far joint F on x, double joint I. The far
// joint relocated by 1/(P F') = 1/(P F) + 1/(P I) - 1/(P N) must be the curvature centre of I
// (fixed in t) in the motion t/x. `printed_5p` measures the left side from P65 instead of P64.
struct Formula {
  const char* label;
  const char* t;
  const char* x;
  const char* N;
  const char* F;
  int I;  // 13, 57, 17, 35
};

Vec2<Rational> i_point(const EightBar& e, int which) {
  switch (which) {
    case 13: return e.I13();
    case 57: return e.I57();
    case 17: return e.I17();
    default: return e.I35();
  }
}

ClaimSides<Rational> relocation(const MechanismContext& c, const Formula& f, bool printed_5p) {
  const EightBar e(c);
  ClaimSides<Rational> s;
  const Vec2<Rational> I = i_point(e, f.I), N = e.J(f.N), F = e.J(f.F), P = e.finite_pole(f.t, f.x);
  PP Fp = relocate_far_joint(P, N, F, I, std::string("far joint of ") + f.label);
  if (printed_5p && Fp.is_finite()) {
    // 1/(P65 F') = [the same right-hand side, from P64]: F' = P65 + u / (|u|^2 rhs).
    const Vec2<Rational> u = F - N, P65 = e.J("56");
    const Rational rhs = Rational(1) / dot(F - P, u) + Rational(1) / dot(I - P, u) - Rational(1) / dot(N - P, u);
    Fp = PP::finite(P65 + (Rational(1) / (rhs * norm2(u))) * u);
  }
  if (!Fp.is_finite()) throw UndefinedQuantity(std::string("far joint of ") + f.label, "not a finite point");
  const PP centre = construct_curvature_centre(I, relative_point_motion(e.field(f.t), e.field(f.x), I),
                                               std::string("centre of I") + std::to_string(f.I));
  compare_point(s, fmt::format("{}: relocated {} vs centre of I{} in {}/{}", f.label, f.F, f.I, f.t, f.x), Fp.at, centre);
  return s;
}

const Formula kFormulas[] = {
    {"(1')", "2", "0", "12", "01", 13},  {"(3')", "2", "4", "23", "34", 13},  {"(5')", "6", "4", "56", "45", 57},
    {"(7')", "6", "0", "67", "70", 57},  {"(1'')", "0", "2", "01", "12", 17}, {"(3'')", "4", "2", "34", "23", 35},
    {"(5'')", "4", "6", "45", "56", 35}, {"(7'')", "0", "6", "70", "67", 17}};

MechanismClaim claim(std::string id, std::string statement, Expectation e, std::string note,
                     std::function<ClaimSides<Rational>(const MechanismContext&)> f) {
  return MechanismClaim{ClaimInfo{std::move(id), kSource, std::move(statement), e, std::move(note), 4, 0}, std::move(f),
                        is_eightbar};
}

}  // namespace

MechanismCatalogue dijksman1984_eightbar() {
  MechanismCatalogue cat;
  cat.name = "dijksman1984_eightbar";
  cat.claims.push_back(claim("dijksman1984.section3.poles",
                             "section 3: P63' = (65-54) x (62-I13), P3'0 = (21-10) x (I35-40) (poles of the linkage "
                             "reduced by four first-order joint-joinings, Fig. 1B), P60 = (67-70) x (63'-3'0), "
                             "P64 = (60-04) x (65-54), P20 = (21-10) x (26-60), P24 = (23-34) x (20-04) equal the "
                             "engine's poles",
                             Expectation::Holds, "", [](const MechanismContext& c) { return section3_poles(c, false); }));
  cat.claims.push_back(claim("dijksman1984.section3.P60.printed", "P60 = (67-70) x (63''-3''0) as printed (double primes)",
                             Expectation::Fails,
                             "erratum (docs/conventions.md §D): the double-primed bar 3'' of the Fig. 5 reduction (joint 3''2 relocated "
                             "by (3''), pivot I35) does not pivot at I13, so the section-3 line 21-10 does not carry "
                             "P3''0; P60 must be built from 63' and 3'0",
                             [](const MechanismContext& c) { return section3_poles(c, true); }));
  for (const Formula& f : kFormulas) {
    const std::string label = f.label;
    std::string id = "dijksman1984.eq";
    for (char ch : label)
      if (ch != '(' && ch != ')') id += ch == '\'' ? 'p' : ch;
    cat.claims.push_back(claim(id,
                               fmt::format("{}: 1/(P{}{} P') = 1/(P{}{} P{}) + 1/(P{}{} I{}) - 1/(P{}{} P{}) relocates "
                                           "joint {} to the curvature centre of I{} in the motion {}/{}",
                                           label, f.t, f.x, f.t, f.x, f.F, f.t, f.x, f.I, f.t, f.x, f.N, f.F, f.I, f.t, f.x),
                               Expectation::Holds, "", [f](const MechanismContext& c) { return relocation(c, f, false); }));
  }
  cat.claims.push_back(claim("dijksman1984.eq5p.printed",
                             "(5') as printed: 1/(P65 P5'4) = 1/(P64 P54) + 1/(P64 I57) - 1/(P64 P65)", Expectation::Fails,
                             "erratum (docs/conventions.md §D): the left side must be measured from P64, like the right side",
                             [](const MechanismContext& c) { return relocation(c, kFormulas[2], true); }));
  return cat;
}

}  // namespace linkproof::catalogues
