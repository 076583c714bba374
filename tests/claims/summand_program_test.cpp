// SummandProgram: a sum's body compiled to straight-line code gives what walking the body's tree
// gives, bit for bit (values and error bounds), with the same undefined inputs, locality notes,
// divisors and errors; and a body is compiled only where the tree alone decides every step.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "check/random_polygon.h"
#include "claims/claim_evaluator.h"
#include "claims/data_claim.h"
#include "claims/summand_program.h"
#include "core/inline_rational.h"
#include "core/tracked.h"
#include "io/claim_file.h"
#include "linkproof/io/scene.h"

namespace linkproof {
namespace {

std::string read_source(const std::string& relative) {
  std::ifstream in(std::string(LINKPROOF_SOURCE_DIR) + "/" + relative);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Bodies that exercise every instruction: vectors (leaves, scaled, summed, perp, dot, cross,
// norm2, components), powers, negation, polynomials of two monomials, globals, four-bar rates;
// and bodies that must be walked: monomials equal at some bindings only, a division, a
// polynomial-valued quantity.
const char* const kSummandBodies = R"(claims:
  - id: vectors
    source: test
    statement: s
    lhs: sum_j(dot(Q[j], r[n-1])*omega[j]^2 + cross(Kp[j], Pp[j])*omega_dot[j])
    rhs: sum_pairs(dot(perp(r[j]), 2*r[l] - K[l])*omega[j]*omega[l]) + sum_j(norm2(3*Kp[j])*vx(Q[j])*vy(perp(Pp[j]))*omega[j]^2)
  - id: globals
    source: test
    statement: s
    lhs: sum_pairs_lt(i_cpl[j]*omega[l]*omega[j] - i_out[l]*omega[j]*omega[l]) + sum_j(fourbar_omega_out[j]*omega[j] + cot_phi*rho*D*omega[j]^2)
    rhs: sum_j((i_out[j] - 2*i_cpl[j])^3*omega_dot[j] - rho_companion*mu[j]*omega[j]^2 + i_out_closed[j]*lambda_closed[j]*omega_dot[j])
  - id: walked
    source: test
    statement: s
    lhs: sum_j(omega[j]*omega[1] + omega[1]^2) + sum_j(lambda[j]^(-1)*omega[j]^2)
    rhs: sum_j(fourbar_omega_dot_out[j]) + sum_j(side_omega[j]*i_out[j])
  - id: angles
    source: test
    statement: s
    lhs: sum_j(i_out[j]*omega[j]^2)
    rhs: sum_pairs(cot_beta[j]*cot_gamma[l]*omega[j]*omega[l])
)";

template <class T>
struct SummandSideRun {
  std::string error;
  std::vector<std::pair<Monomial, T>> terms;
  std::vector<std::string> undefined, violations;
  std::vector<T> divisors;
};

template <class T>
SummandSideRun<T> run_summand_side(const DataClaim& claim, const ClaimExpression& side, const PolygonContext<T>& c, int j, bool walk) {
  ClaimEvaluator<T> eval(c, claim.reading);
  eval.set_partial(true);
  eval.set_walk_only(walk);
  SummandSideRun<T> r;
  IndexBindings b;
  b.j = j;
  try {
    r.terms = eval.scalar(side, b).terms();
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  for (const auto& [inputs, u] : eval.undefined_inputs()) {
    std::string key;
    for (int i : inputs) key += std::to_string(i) + ",";
    r.undefined.push_back(key + u.quantity + ": " + u.reason);
  }
  r.violations = eval.locality_violations();
  r.divisors = eval.divisors();
  return r;
}

template <class F>
bool same_summand_bits(const Tracked<F>& a, const Tracked<F>& b) {
  const auto same = [](const auto& x, const auto& y) {
    return (std::isnan(x) && std::isnan(y)) || (x == y && std::signbit(x) == std::signbit(y));
  };
  return same(a.v, b.v) && same(a.e, b.e);
}
bool same_summand_bits(const InlineRational& a, const InlineRational& b) { return a == b; }

template <class T>
void expect_same_side(const SummandSideRun<T>& compiled, const SummandSideRun<T>& walked, const std::string& where) {
  EXPECT_EQ(compiled.error, walked.error) << where;
  EXPECT_EQ(compiled.undefined, walked.undefined) << where;
  EXPECT_EQ(compiled.violations, walked.violations) << where;
  ASSERT_EQ(compiled.divisors.size(), walked.divisors.size()) << where;
  for (size_t i = 0; i < compiled.divisors.size(); ++i) EXPECT_TRUE(same_summand_bits(compiled.divisors[i], walked.divisors[i])) << where;
  ASSERT_EQ(compiled.terms.size(), walked.terms.size()) << where;
  for (size_t i = 0; i < compiled.terms.size(); ++i) {
    EXPECT_EQ(compiled.terms[i].first, walked.terms[i].first) << where << ": term " << i;
    EXPECT_TRUE(same_summand_bits(compiled.terms[i].second, walked.terms[i].second))
        << where << ": " << monomial_label(compiled.terms[i].first);
  }
}

/// The number of sums in e whose body has a program.
int compiled_sum_count(const ClaimExpression& e) {
  int k = 0;
  for (const auto& n : compiled_claim(e.expression()).nodes) k += n.op == ClaimProgram::Op::IndexSum && n.summand != nullptr;
  return k;
}

struct SummandCase {
  std::string name;
  Polygon<Rational> polygon;
  InputRates<Rational> rates;
};

std::vector<SummandCase> summand_cases() {
  std::vector<SummandCase> out;
  for (int n = 4; n <= 9; ++n)
    for (int index = 0; index < 3; ++index) {
      const RandomPolygonCase c = generate_random_polygon(2811, n, index);  // seed 2811
      out.push_back({"random seed 2811 n=" + std::to_string(n) + " #" + std::to_string(index) + " " + c.family, c.polygon, c.rates});
    }
  for (const char* scene : {"pentagon.yaml", "hexagon.yaml", "degenerate/q_at_infinity.yaml", "degenerate/p_prime_at_infinity.yaml",
                            "degenerate/beta_undefined.yaml", "degenerate/q_at_joint.yaml", "degenerate/k_prime_at_ground.yaml"}) {
    const PolygonScene s = load_polygon_scene(std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/" + scene);
    out.push_back({scene, s.polygon, s.rates});
  }
  return out;
}

template <class T>
int compare_summand_routes(const std::vector<DataClaim>& claims) {
  GroundTruthEngine engine;
  int compared = 0;
  for (const SummandCase& k : summand_cases()) {
    const PolygonContext<T> c = build_polygon_context<T>(engine, k.polygon, k.rates);
    for (const DataClaim& claim : claims)
      for (const ClaimExpression* side : {&claim.lhs, &claim.rhs}) {
        const int j_last = claim.for_each_j ? c.inputs() : 0;
        for (int j = claim.for_each_j ? 1 : 0; j <= j_last; ++j) {
          const std::string where = k.name + ", claim " + claim.info.id + (side == &claim.lhs ? " lhs" : " rhs") + " j=" + std::to_string(j);
          expect_same_side(run_summand_side(claim, *side, c, j, false), run_summand_side(claim, *side, c, j, true), where);
          compared += compiled_sum_count(*side) > 0;
        }
      }
  }
  return compared;
}

std::vector<DataClaim> every_summand_claim() {
  std::vector<DataClaim> all;
  for (const auto& [text, source] : {std::pair{read_source("verify/claims/dijksman1966.yaml"), "dijksman1966.yaml"},
                                     std::pair{read_source("verify/claims/wrong_variants.yaml"), "wrong_variants.yaml"},
                                     std::pair{std::string(kSummandBodies), "bodies"}}) {
    const ClaimFile f = parse_claim_file(text, source);
    all.insert(all.end(), f.claims.begin(), f.claims.end());
  }
  return all;
}

TEST(SummandProgram, GivesTheWalksValuesBitForBitInDouble) {
  const int compared = compare_summand_routes<Tracked<double>>(every_summand_claim());
  EXPECT_GT(compared, 500);  // sides with a compiled sum, over all cases
}

TEST(SummandProgram, GivesTheWalksValuesBitForBitInLongDouble) {
  EXPECT_GT(compare_summand_routes<Tracked<long double>>(every_summand_claim()), 500);
}

TEST(SummandProgram, GivesTheWalksValuesExactly) {
  EXPECT_GT(compare_summand_routes<InlineRational>(every_summand_claim()), 500);
}

// A claim file refuses an index out of range at some n when it is read; an expression checked on
// its own meets it at the last j, in the middle of a sum: the same error by both routes.
TEST(SummandProgram, AnIndexOutOfRangeInACompiledBodyIsTheWalksError) {
  DataClaim claim;
  claim.lhs = ClaimExpression::parse("sum_j(i_out[j+1]*omega[j])");
  ASSERT_EQ(compiled_sum_count(claim.lhs), 1);
  GroundTruthEngine engine;
  const RandomPolygonCase k = generate_random_polygon(2811, 7, 0);
  const PolygonContext<Tracked<double>> c = build_polygon_context<Tracked<double>>(engine, k.polygon, k.rates);
  const SummandSideRun<Tracked<double>> compiled = run_summand_side(claim, claim.lhs, c, 0, false);
  EXPECT_NE(compiled.error.find("out of range 1..4 at n = 7"), std::string::npos) << compiled.error;
  expect_same_side(compiled, run_summand_side(claim, claim.lhs, c, 0, true), "i_out[j+1]");
}

TEST(SummandProgram, CompilesABodyOnlyWhereItsTreeDecidesEveryStep) {
  const auto program = [](const std::string& text) -> const SummandProgram* {
    const ClaimProgram& p = compiled_claim(ClaimExpression::parse(text).expression());
    return p.nodes[static_cast<size_t>(p.root)].summand.get();
  };
  const SummandProgram* pairs = program("sum_pairs(i_out[j]*i_out[l]*omega[j]*omega[l])");
  ASSERT_NE(pairs, nullptr);
  EXPECT_EQ(pairs->terms.size(), 1u);
  // Two monomials unequal at every j (degree 2 in omega, degree 1 in omega-dot): a polynomial.
  const SummandProgram* two = program("sum_j(lambda[j]*omega[j]^2 + i_out[j]*omega_dot[j])");
  ASSERT_NE(two, nullptr);
  EXPECT_EQ(two->terms.size(), 2u);
  // One monomial in two terms: one term.
  const SummandProgram* one = program("sum_j(i_out[j]*omega[j] + 2*i_cpl[j]*omega[j])");
  ASSERT_NE(one, nullptr);
  EXPECT_EQ(one->terms.size(), 1u);
  // Monomials equal at j = 1 only, a division, polynomial-valued quantities, a side's rate, a
  // joint's acceleration: walked.
  for (const char* walked : {"sum_j(omega[j]*omega[1] + omega[1]^2)", "sum_j(lambda[j]^(-1)*omega[j]^2)",
                             "sum_j(fourbar_omega_dot_out[j])", "sum_j(side_omega[j]*i_out[j])",
                             "sum_j(omega_dot_out*i_out[j])", "sum_j(dot(acc[j], r[j])*omega[j])"})
    EXPECT_EQ(program(walked), nullptr) << walked;
}

}  // namespace
}  // namespace linkproof
