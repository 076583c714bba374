// The degenerate configurations of Dijksman's construction (conventions §A6), one bundled scene per
// family in verify/scenes/degenerate/, each an exact rational polygon that meets its condition
// exactly (checked here from the loaded scene, not taken on trust from its description).
//
// What conventions §A6 requires, family by family: only the dead centre D = 0 is a singularity of the
// mechanism (everything undefined); elsewhere the construction forms 0 * infinity, so the claims
// that use the broken part of the construction for index j are `undefined`, naming the quantity,
// while the claims built on the engine and the closed forms still hold, the closed forms give the
// continuous limit, and the term-by-term entries of (22) that do not involve j still hold. A claim
// expected to hold must never say `fails` here.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "exit_status.h"
#include "dijksman1966.h"
#include "check/check_polygon.h"
#include "report/comparison_text.h"
#include "report/number_text.h"
#include "geometry/closed_forms.h"
#include "geometry/construction.h"
#include "linkproof/io/scene.h"
#include "symbolic/ground_truth.h"
#include "geometry/zero_vector.h"

namespace linkproof {
namespace {

// ---- scenes and conditions -------------------------------------------------------------------

std::string degenerate_dir() { return std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/degenerate"; }

PolygonScene load(const std::string& family) { return load_polygon_scene(degenerate_dir() + "/" + family + ".yaml"); }

Rational q(long p, long d = 1) { return Rational(p) / Rational(d); }

bool same_point(const Vec2<Rational>& a, const Vec2<Rational>& b) { return a.x == b.x && a.y == b.y; }

/// The configuration as exact rationals, for failure messages.
std::string describe(const PolygonScene& s) {
  std::string out = s.name + ": K =";
  for (const auto& k : s.polygon.joints()) out += " (" + format_rational(k.x) + ", " + format_rational(k.y) + ")";
  out += "; omega =";
  for (const auto& w : s.rates.omega) out += " " + format_rational(w);
  out += "; omega_dot =";
  for (const auto& w : s.rates.omega_dot) out += " " + format_rational(w);
  return out;
}

/// The per-index conditions of conventions §A6 (the dead centre is a property of the whole polygon).
enum class Condition { QAtInfinity, BetaUndefined, PPrimeAtInfinity, QAtOutputJoint, KPrimeAtGround };

std::string to_string(Condition c) {
  switch (c) {
    case Condition::QAtInfinity: return "Q_j at infinity";
    case Condition::BetaUndefined: return "beta_j undefined (r_j || r_{n-2})";
    case Condition::PPrimeAtInfinity: return "P'_j at infinity (r_j || r_{n-1})";
    case Condition::QAtOutputJoint: return "Q_j = K_{n-1}";
    case Condition::KPrimeAtGround: return "K'_j = K_n";
  }
  return "?";
}

/// Which conditions of conventions §A6 input side j meets, by their defining quantities, exactly.
/// With a = r_{n-2}, b = r_{n-1} and K'_j - K_n = -(r_j + a + b):
///   K'_j = K_n         r_j + a + b = 0
///   Q_j at infinity    a x (r_j + b) = 0   (ground line K_nK'_j parallel to the coupler line)
///   Q_j = K_{n-1}      (r_j + a) x b = 0   (K'_j on the output line K_{n-1}K_n)
///   beta_j undefined   r_j x a = 0
///   P'_j at infinity   r_j x b = 0
/// The two conditions on Q_j are vacuous when K'_j = K_n (no ground line), so they are counted
/// only when K'_j != K_n.
std::set<Condition> conditions_at(const Polygon<Rational>& p, int j) {
  const int n = p.n();
  const Vec2<Rational> a = p.side(n - 2), b = p.side(n - 1), r = p.side(j);
  std::set<Condition> c;
  const bool ground = is_zero_vector(r + a + b);
  if (ground) c.insert(Condition::KPrimeAtGround);
  if (!ground && cln::zerop(cross(a, r + b))) c.insert(Condition::QAtInfinity);
  if (!ground && cln::zerop(cross(r + a, b))) c.insert(Condition::QAtOutputJoint);
  if (cln::zerop(cross(r, a))) c.insert(Condition::BetaUndefined);
  if (cln::zerop(cross(r, b))) c.insert(Condition::PPrimeAtInfinity);
  return c;
}

// ---- checking --------------------------------------------------------------------------------

GroundTruthEngine& engine() {
  static GroundTruthEngine e;  // derivations are cached per n; GiNaC stays on the test thread
  return e;
}

PolygonCheck run(const PolygonScene& s, Arithmetic a = Arithmetic::Exact) {
  return check_polygon(engine(), dijksman1966::catalogue(), s.name, s.polygon, s.rates, a);
}

const ClaimOutcome* find_claim(const PolygonCheck& c, const std::string& id) {
  for (const auto& o : c.claims)
    if (o.info.id == id) return &o;
  return nullptr;
}

/// True if the headline or any instance or term of `o` is undefined for one of `names`.
bool names_any(const ClaimOutcome& o, const std::set<std::string>& names) {
  if (names.count(o.headline.undefined_quantity)) return true;
  for (const auto* group : {&o.instances, &o.terms})
    for (const auto& c : *group)
      if (c.verdict == Verdict::Undefined && names.count(c.undefined_quantity)) return true;
  return false;
}

std::string summary(const ClaimOutcome& o) {
  std::string s = o.info.id + " -> " + std::string(to_string(o.verdict)) + " [" + o.headline.label + "]";
  if (!o.headline.undefined_quantity.empty()) s += " undefined: " + o.headline.undefined_quantity;
  if (!o.error.empty()) s += " error: " + o.error;
  return s;
}

/// One family of conventions §A6 at index j: the claims the construction breaks, with the names that may
/// be reported for them, and the claims that must still hold.
struct Family {
  std::string file;
  int n = 0, j = 0;
  Condition condition;
  std::map<std::string, std::set<std::string>> undefined;  ///< claim id -> acceptable quantity names
  std::set<std::string> holds;
};

std::string id(const std::string& eq) { return "dijksman1966." + eq; }

/// The undefined claims `eqs`, all naming one of `names`.
void add_undefined(Family& f, std::initializer_list<std::string> eqs, const std::set<std::string>& names) {
  for (const auto& e : eqs) f.undefined[id(e)] = names;
}
void add_holds(Family& f, std::initializer_list<std::string> eqs) {
  for (const auto& e : eqs) f.holds.insert(id(e));
}

// Claims built on the engine (ground truth, four-bars solved exactly) and the closed forms only.
const std::initializer_list<std::string> kEngineOnly = {"eq13", "eq14", "eq18", "eq19", "eq20"};

Family q_at_infinity() {
  Family f{"q_at_infinity", 6, 1, Condition::QAtInfinity, {}, {}};
  add_undefined(f, {"eq4", "eq5", "eq9", "eq9a", "eq10", "eq11", "eq21", "eq22", "companion"}, {"Q_1", "i_{n-1,1}"});
  add_holds(f, kEngineOnly);
  add_holds(f, {"eq6"});  // P'_1 is finite
  return f;
}

Family beta_undefined() {
  Family f{"beta_undefined", 5, 1, Condition::BetaUndefined, {}, {}};
  add_undefined(f, {"eq9", "eq9a", "eq22", "sec3"}, {"beta_1"});
  add_undefined(f, {"companion"}, {"gamma_1"});  // P'_1 = K_4: the ray P'_1K_4 is null too
  add_holds(f, kEngineOnly);
  add_holds(f, {"eq4", "eq5", "eq6", "eq10", "eq11", "eq21"});  // the ratios exist (i_{4,1} = 0)
  return f;
}

Family p_prime_at_infinity() {
  Family f{"p_prime_at_infinity", 6, 2, Condition::PPrimeAtInfinity, {}, {}};
  add_undefined(f, {"eq6", "eq9", "eq9a", "eq10", "eq11", "eq21", "eq22", "companion"}, {"P'_2", "i_{n-2,2}"});
  add_holds(f, kEngineOnly);
  add_holds(f, {"eq4", "eq5"});  // Q_2 is finite
  return f;
}

Family q_at_joint() {
  Family f{"q_at_joint", 6, 1, Condition::QAtOutputJoint, {}, {}};
  add_undefined(f, {"eq9", "eq9a", "eq22"}, {"beta_1"});
  add_undefined(f, {"companion"}, {"gamma_1"});  // P'_1 = K'_1: rays P'_1K_5 and P'_1Q_1 coincide
  add_holds(f, kEngineOnly);
  add_holds(f, {"eq4", "eq5", "eq6", "eq10", "eq11", "eq21"});
  return f;
}

Family k_prime_at_ground() {
  Family f{"k_prime_at_ground", 5, 1, Condition::KPrimeAtGround, {}, {}};
  add_undefined(f, {"eq4", "eq5", "eq9", "eq9a", "eq10", "eq11", "eq21", "eq22", "sec3", "companion"},
                {"Q_1", "i_{n-1,1}"});
  add_holds(f, kEngineOnly);
  add_holds(f, {"eq6"});  // P'_1 = K_5
  return f;
}

std::vector<Family> regular_families() {
  return {q_at_infinity(), beta_undefined(), p_prime_at_infinity(), q_at_joint(), k_prime_at_ground()};
}

/// The scene of family f meets f's condition at f.j exactly, no other condition at any index,
/// and is not a dead centre.
void expect_exact_condition(const Family& f, const PolygonScene& s) {
  SCOPED_TRACE(describe(s));
  ASSERT_EQ(s.polygon.n(), f.n);
  EXPECT_FALSE(cln::zerop(s.polygon.dead_centre_determinant())) << "the mechanism must be regular";
  for (int k = 1; k <= f.n - 3; ++k) {
    const std::set<Condition> got = conditions_at(s.polygon, k);
    const std::set<Condition> want = k == f.j ? std::set<Condition>{f.condition} : std::set<Condition>{};
    EXPECT_EQ(got, want) << "j = " << k << ": expected " << (k == f.j ? to_string(f.condition) : "none");
  }
}

/// Every true claim the family breaks is undefined and names the broken quantity; every true
/// claim that does not depend on it holds; no claim expected to hold fails; exit status 0.
void expect_family_verdicts(const Family& f, const PolygonCheck& check) {
  EXPECT_FALSE(check.dead_centre);
  EXPECT_EQ(cli::exit_status(check.claims), 0);
  for (const auto& [claim, names] : f.undefined) {
    const ClaimOutcome* o = find_claim(check, claim);
    ASSERT_NE(o, nullptr) << claim << " not evaluated";
    EXPECT_EQ(o->verdict, Verdict::Undefined) << summary(*o);
    std::string accepted;
    for (const auto& nm : names) accepted += " " + nm;
    EXPECT_TRUE(names_any(*o, names)) << summary(*o) << "; expected it to name one of:" << accepted;
  }
  for (const auto& claim : f.holds) {
    const ClaimOutcome* o = find_claim(check, claim);
    ASSERT_NE(o, nullptr) << claim << " not evaluated";
    EXPECT_EQ(o->verdict, Verdict::Holds) << summary(*o);
  }
  for (const auto& o : check.claims) {
    EXPECT_NE(o.verdict, Verdict::Error) << summary(o);
    EXPECT_FALSE(o.is_unexpected_failure()) << summary(o);
  }
}

/// The indices a term label refers to: "omega_dot[2]" -> {2}, "omega[1]*omega[3]" -> {1, 3}.
std::set<int> term_indices(const std::string& label) {
  static const std::regex index(R"(\[(\d+)\])");
  std::set<int> out;
  for (auto it = std::sregex_iterator(label.begin(), label.end(), index); it != std::sregex_iterator(); ++it)
    out.insert(std::stoi((*it)[1].str()));
  return out;
}

/// Term by term, (22) (and sec. 3 and the companion, where they apply) still holds for every
/// monomial that does not involve the degenerate index j: omega-dot_k and omega_k^2 for k != j,
/// omega_k omega_l for k, l != j. Their number is 2 (m - 1) + (m - 1)(m - 2) / 2, m = n - 3.
/// (sec. 3 names i_{4,1} outside any sum, so a degenerate j = 1 makes it undefined as a whole:
/// only sums can leave one input's terms out exactly.)
void expect_terms_without_j_hold(const PolygonCheck& check, int j) {
  const int others = check.n - 4;
  const size_t expected = static_cast<size_t>(2 * others + others * (others - 1) / 2);
  for (const std::string claim : {"eq22", "companion"}) {
    const ClaimOutcome* o = find_claim(check, id(claim));
    if (!o) continue;  // sec3 applies to n = 5 only
    SCOPED_TRACE(o->info.id);
    size_t seen = 0;
    for (const auto& t : o->terms) {
      const std::set<int> idx = term_indices(t.label);
      ASSERT_FALSE(idx.empty()) << "unrecognised term label " << t.label;
      if (idx.count(j)) continue;
      ++seen;
      EXPECT_EQ(t.verdict, Verdict::Holds) << t.label << ": " << to_string(t.verdict) << " " << t.undefined_quantity
                                           << " lhs " << lhs_text(t) << " rhs " << rhs_text(t);
    }
    EXPECT_EQ(seen, expected) << "terms not involving j = " << j;
  }
}

// ---- 1. dead centre --------------------------------------------------------------------------

TEST(DegenerateGeometry, DeadCentreLeavesSidesNMinus2AndNMinus1UndefinedAndEveryClaimUndefined) {
  const PolygonScene s = load("dead_centre");
  SCOPED_TRACE(describe(s));
  ASSERT_EQ(s.polygon.n(), 6);
  const int n = s.polygon.n();
  EXPECT_TRUE(cln::zerop(cross(s.polygon.side(n - 2), s.polygon.side(n - 1)))) << "D = r_4 x r_5 must be 0";
  EXPECT_THROW(compute_closed_forms(s.polygon), UndefinedQuantity);

  const PolygonCheck check = run(s);
  EXPECT_TRUE(check.dead_centre);
  EXPECT_FALSE(check.dead_centre_reason.empty());
  EXPECT_EQ(number_text(check.determinant), "0");
  ASSERT_EQ(check.omega.size(), 6u);
  ASSERT_EQ(check.omega_dot.size(), 6u);
  // The inputs and the fixed side are known; sides n-2 and n-1 are not.
  ASSERT_TRUE(check.omega[0].has_value());
  EXPECT_EQ(number_text(*check.omega[0]), "1");
  ASSERT_TRUE(check.omega[2].has_value());
  EXPECT_EQ(number_text(*check.omega[2]), "3");
  ASSERT_TRUE(check.omega_dot[0].has_value());
  EXPECT_EQ(number_text(*check.omega_dot[0]), "1/2");
  ASSERT_TRUE(check.omega[5].has_value());
  EXPECT_EQ(number_text(*check.omega[5]), "0");
  for (int side : {n - 2, n - 1}) {
    EXPECT_FALSE(check.omega[side - 1].has_value()) << "omega_{" << side << ",6} = " << number_text(*check.omega[side - 1]);
    EXPECT_FALSE(check.omega_dot[side - 1].has_value()) << "omega-dot_{" << side << ",6} = " << number_text(*check.omega_dot[side - 1]);
  }
  EXPECT_FALSE(check.claims.empty());
  for (const auto& o : check.claims) {
    EXPECT_EQ(o.verdict, Verdict::Undefined) << summary(o);
    EXPECT_FALSE(o.headline.undefined_quantity.empty()) << summary(o);
  }
  EXPECT_EQ(cli::exit_status(check.claims), 0);
}

// ---- 2. Q_j at infinity ----------------------------------------------------------------------

TEST(DegenerateGeometry, QAtInfinityMakesConstructionClaimsUndefinedButClosedFormsHold) {
  const Family f = q_at_infinity();
  const PolygonScene s = load(f.file);
  expect_exact_condition(f, s);
  SCOPED_TRACE(describe(s));
  const Polygon<Rational>& p = s.polygon;
  EXPECT_TRUE(cln::zerop(cross(p.side(4), p.side(1) + p.side(5))));  // r_4 x (r_1 + r_5) = 0

  // The construction: Q_1 does not exist, P'_1 does.
  const FourBarConstruction<Rational> c = construct_four_bar(p, 1);
  EXPECT_FALSE(c.q.has_value());
  EXPECT_EQ(c.q.quantity(), "Q_1");
  EXPECT_TRUE(c.p_prime.has_value());
  EXPECT_FALSE(c.i_out.has_value());
  EXPECT_FALSE(c.lambda.has_value());

  // The closed forms give the limit: i_{5,1} = 1, lambda_1 finite.
  const ClosedForms<Rational> cf = compute_closed_forms(p);
  EXPECT_EQ(cf.i_out[0], q(1));
  EXPECT_EQ(cf.lambda[0], q(51, 76));

  const PolygonCheck check = run(s);
  expect_family_verdicts(f, check);
  expect_terms_without_j_hold(check, f.j);
}

// ---- 3. beta_j undefined ---------------------------------------------------------------------

TEST(DegenerateGeometry, BetaUndefinedWhenInputParallelToCouplerMakesEq9aUndefinedAndRatioZero) {
  const Family f = beta_undefined();
  const PolygonScene s = load(f.file);
  expect_exact_condition(f, s);
  SCOPED_TRACE(describe(s));
  const Polygon<Rational>& p = s.polygon;
  EXPECT_TRUE(cln::zerop(cross(p.side(1), p.side(3))));  // r_1 || r_3

  // Q_1 = K'_1 and P'_1 = K_4: the two rays of beta_1 coincide.
  const FourBarConstruction<Rational> c = construct_four_bar(p, 1);
  ASSERT_TRUE(c.q.has_value());
  ASSERT_TRUE(c.p_prime.has_value());
  EXPECT_TRUE(same_point(c.q.get(), c.k_prime));
  EXPECT_TRUE(same_point(c.p_prime.get(), p.joint(4)));
  EXPECT_FALSE(c.cot_beta.has_value());
  EXPECT_EQ(c.cot_beta.quantity(), "beta_1");
  ASSERT_TRUE(c.i_out.has_value());
  EXPECT_EQ(c.i_out.get(), q(0));

  const ClosedForms<Rational> cf = compute_closed_forms(p);
  EXPECT_EQ(cf.i_out[0], q(0));
  EXPECT_EQ(cf.lambda[0], q(-5, 22));  // finite

  const PolygonCheck check = run(s);
  expect_family_verdicts(f, check);
  expect_terms_without_j_hold(check, f.j);
}

// ---- 4. P'_j at infinity ---------------------------------------------------------------------

TEST(DegenerateGeometry, PPrimeAtInfinityMakesEq6UndefinedAndCouplerRatioZero) {
  const Family f = p_prime_at_infinity();
  const PolygonScene s = load(f.file);
  expect_exact_condition(f, s);
  SCOPED_TRACE(describe(s));
  const Polygon<Rational>& p = s.polygon;
  EXPECT_TRUE(cln::zerop(cross(p.side(2), p.side(5))));  // r_2 || r_5

  const FourBarConstruction<Rational> c = construct_four_bar(p, 2);
  EXPECT_TRUE(c.q.has_value());
  EXPECT_FALSE(c.p_prime.has_value());
  EXPECT_EQ(c.p_prime.quantity(), "P'_2");
  EXPECT_FALSE(c.i_cpl.has_value());

  const ClosedForms<Rational> cf = compute_closed_forms(p);
  EXPECT_EQ(cf.i_cpl[1], q(0));
  EXPECT_EQ(cf.i_out[1], q(-1, 2));

  const PolygonCheck check = run(s);
  expect_family_verdicts(f, check);
  expect_terms_without_j_hold(check, f.j);
}

// ---- 5. Q_j = K_{n-1} ------------------------------------------------------------------------

TEST(DegenerateGeometry, QAtOutputJointMakesBetaUndefinedButEq4StillHolds) {
  const Family f = q_at_joint();
  const PolygonScene s = load(f.file);
  expect_exact_condition(f, s);
  SCOPED_TRACE(describe(s));
  const Polygon<Rational>& p = s.polygon;
  EXPECT_TRUE(cln::zerop(cross(p.side(1) + p.side(4), p.side(5))));  // K'_1 on line K_5K_6

  // Q_1 = K_5: the ray Q_1K_5 is null, so beta_1 does not exist; i_{5,1} does.
  const FourBarConstruction<Rational> c = construct_four_bar(p, 1);
  ASSERT_TRUE(c.q.has_value());
  EXPECT_TRUE(same_point(c.q.get(), p.joint(5)));
  EXPECT_FALSE(c.cot_beta.has_value());
  EXPECT_EQ(c.cot_beta.quantity(), "beta_1");
  ASSERT_TRUE(c.i_out.has_value());

  const ClosedForms<Rational> cf = compute_closed_forms(p);
  EXPECT_EQ(c.i_out.get(), cf.i_out[0]);
  EXPECT_EQ(cf.i_out[0], q(-1, 2));
  EXPECT_EQ(cf.lambda[0], q(6, 19));  // finite

  const PolygonCheck check = run(s);
  expect_family_verdicts(f, check);
  const ClaimOutcome* eq4 = find_claim(check, id("eq4"));
  ASSERT_NE(eq4, nullptr);
  ASSERT_GE(eq4->instances.size(), 1u);
  EXPECT_EQ(eq4->instances[0].label, "j=1");
  EXPECT_EQ(eq4->instances[0].verdict, Verdict::Holds);
  EXPECT_EQ(lhs_text(eq4->instances[0]), "-1/2");
  expect_terms_without_j_hold(check, f.j);
}

// ---- 6. K'_j = K_n ---------------------------------------------------------------------------

TEST(DegenerateGeometry, KPrimeAtGroundPivotMakesQUndefinedWithRatioOneAndLambdaZero) {
  const Family f = k_prime_at_ground();
  const PolygonScene s = load(f.file);
  expect_exact_condition(f, s);
  SCOPED_TRACE(describe(s));
  const Polygon<Rational>& p = s.polygon;

  const FourBarConstruction<Rational> c = construct_four_bar(p, 1);
  EXPECT_TRUE(same_point(c.k_prime, p.joint(5)));  // K'_1 = K_3 - r_1 = K_5
  EXPECT_FALSE(c.q.has_value());
  EXPECT_EQ(c.q.quantity(), "Q_1");
  ASSERT_TRUE(c.p_prime.has_value());
  EXPECT_TRUE(same_point(c.p_prime.get(), p.joint(5)));

  const ClosedForms<Rational> cf = compute_closed_forms(p);
  EXPECT_EQ(cf.i_out[0], q(1));
  EXPECT_EQ(cf.i_cpl[0], q(1));
  EXPECT_EQ(cf.lambda[0], q(0));

  const PolygonCheck check = run(s);
  expect_family_verdicts(f, check);
  expect_terms_without_j_hold(check, f.j);
}

// ---- across families -------------------------------------------------------------------------

// The closed-form limits are the mechanism's own: the engine's exact coefficients of
// omega-dot_j and omega_j^2 in omega-dot_{n-1,n} are i_{n-1,j} and lambda_j, and in
// omega-dot_{n-2,n} they are i_{n-2,j} and mu_j, at the degenerate index as everywhere else.
TEST(DegenerateGeometry, EngineTermCoefficientsEqualTheClosedFormLimitsAtTheDegenerateIndex) {
  for (const Family& f : regular_families()) {
    const PolygonScene s = load(f.file);
    SCOPED_TRACE(describe(s));
    const ClosedForms<Rational> cf = compute_closed_forms(s.polygon);
    const auto [out, cpl] = engine().coefficients(s.polygon);
    const size_t k = static_cast<size_t>(f.j - 1);
    EXPECT_EQ(out.omega_dot[k], cf.i_out[k]);
    EXPECT_EQ(out.omega_sq[k], cf.lambda[k]);
    EXPECT_EQ(cpl.omega_dot[k], cf.i_cpl[k]);
    EXPECT_EQ(cpl.omega_sq[k], cf.mu[k]);
  }
}

TEST(DegenerateGeometry, EveryBundledDegenerateSceneParsesAndIsCovered) {
  std::set<std::string> expected{"dead_centre"};
  for (const Family& f : regular_families()) expected.insert(f.file);
  std::set<std::string> found;
  for (const auto& e : std::filesystem::directory_iterator(degenerate_dir())) {
    if (e.path().extension() != ".yaml") continue;
    const std::string stem = e.path().stem().string();
    found.insert(stem);
    const PolygonScene s = load_polygon_scene(e.path().string());
    EXPECT_FALSE(s.name.empty()) << stem;
    EXPECT_EQ(s.source, e.path().string());
    EXPECT_TRUE(s.polygon.n() == 5 || s.polygon.n() == 6) << stem;
    EXPECT_EQ(polygon_input_problem(s.polygon), "") << stem;
    EXPECT_EQ(cli::exit_status(run(s).claims), 0) << stem;
  }
  EXPECT_EQ(found, expected);
}

// Floating point cannot tell an exactly degenerate construction from a nearly degenerate one
// (a zero with a nonzero error bound is not zero): there the broken claims may be inconclusive
// instead of undefined, but a true claim must never fail.
TEST(DegenerateGeometry, FloatingPointNeverFailsATrueClaimOnTheDegenerateScenes) {
  for (const Family& f : regular_families()) {
    const PolygonScene s = load(f.file);
    SCOPED_TRACE(describe(s));
    for (Arithmetic a : {Arithmetic::Double, Arithmetic::LongDouble, Arithmetic::Mp30, Arithmetic::Mp1000}) {
      SCOPED_TRACE(std::string(to_string(a)));
      const PolygonCheck check = run(s, a);
      EXPECT_EQ(cli::exit_status(check.claims), 0);
      for (const auto& o : check.claims) {
        EXPECT_NE(o.verdict, Verdict::Error) << summary(o);
        EXPECT_FALSE(o.is_unexpected_failure()) << summary(o);
        if (f.undefined.count(o.info.id)) {
          EXPECT_TRUE(o.verdict == Verdict::Undefined || o.verdict == Verdict::Inconclusive) << summary(o);
        }
      }
    }
  }
}

// check.h: at the dead centre "the ground truth does not exist; every claim is then undefined"
// and omega is "nullopt where undefined". The check knows D = 0 exactly (it sets dead_centre from
// the exact polygon), so this must hold in every arithmetic, not only in exact rationals.
TEST(DegenerateGeometry, DeadCentreIsUndefinedInFloatingPointToo) {
  const PolygonScene s = load("dead_centre");
  SCOPED_TRACE(describe(s));
  const int n = s.polygon.n();
  for (Arithmetic a : {Arithmetic::Double, Arithmetic::LongDouble, Arithmetic::Mp30, Arithmetic::Mp1000}) {
    SCOPED_TRACE(std::string(to_string(a)));
    const PolygonCheck check = run(s, a);
    ASSERT_TRUE(check.dead_centre);
    ASSERT_FALSE(check.claims.empty());
    EXPECT_EQ(cli::exit_status(check.claims), 0);
    for (int side : {n - 2, n - 1}) {
      EXPECT_FALSE(check.omega[side - 1].has_value());
      EXPECT_FALSE(check.omega_dot[side - 1].has_value());
    }
    for (const auto& o : check.claims) EXPECT_EQ(o.verdict, Verdict::Undefined) << summary(o);
  }
}

}  // namespace
}  // namespace linkproof
