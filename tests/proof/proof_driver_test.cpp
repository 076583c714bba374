// The symbolic motion solved group by group, and proofs with another link as the driver
// (proof/symbolic_motion.h): Koshel's class-III mechanism splits into dyads when link 3 drives
// it, a claim that was only `holds_with_probability` with the crank's one group of four is
// proved, and the exceptional set stays the scene's (its det A, its input rates).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/claim_file.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"
#include "support/topology_claims.h"
#include "proof/mechanism_proof.h"
#include "proof/symbolic_motion.h"
#include "core/symbolic_scalar.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"

namespace linkproof {
namespace {


const char* kClass3 = "verify/scenes/mechanisms/seed003_class3.yaml";
const char* kKoshelClaims = "verify/claims/mechanisms/koshel_class3.yaml";

std::vector<MechanismDataClaim> only(std::vector<MechanismDataClaim> claims, const std::string& id) {
  std::erase_if(claims, [&](const MechanismDataClaim& c) { return c.info.id != id; });
  return claims;
}

std::string koshel_lhs(const std::string& id) {
  const YAML::Node file = YAML::LoadFile(test::source_path(kKoshelClaims));
  for (const YAML::Node& c : file["claims"])
    if ("koshel." + c["id"].as<std::string>() == id) {
      std::string lhs = c["lhs"].as<std::string>();
      std::replace(lhs.begin(), lhs.end(), '\n', ' ');  // one line, to be quoted in another file
      return lhs;
    }
  throw std::runtime_error("no claim " + id);
}

GiNaC::ex number(const Rational& q) { return GiNaC::numeric(cln::cl_N(q)); }

// The symbolic motion at the scene's own configuration, with the driver's rates `rate`, `rate_dot`.
std::vector<GiNaC::ex> omegas_and_alphas_at(const MechanismScene& s, const SymbolicConfiguration& c, const SymbolicMotion& m,
                                            const Rational& rate, const Rational& rate_dot) {
  GiNaC::exmap at;
  for (int j = 0; j < s.linkage.joint_count(); ++j) {
    const LinkageJoint& joint = s.linkage.joint(j);
    at[c.joint_at[static_cast<size_t>(j)].x] = number(joint.at.x);
    at[c.joint_at[static_cast<size_t>(j)].y] = number(joint.at.y);
    if (joint.type == JointType::Prismatic) {
      at[c.axis[static_cast<size_t>(j)].x] = number(joint.axis.x);
      at[c.axis[static_cast<size_t>(j)].y] = number(joint.axis.y);
    }
  }
  at[m.input_values.front().rate] = number(rate);
  at[m.input_values.front().rate_dot] = number(rate_dot);
  for (const InverseDeterminant& inv : m.inverses) at[inv.delta] = 1 / inv.det.subs(at);
  std::vector<GiNaC::ex> out;
  for (const GiNaC::ex& w : m.motion.omega) out.push_back(GiNaC::normal(w.subs(at)));
  for (const GiNaC::ex& a : m.motion.omega_dot) out.push_back(GiNaC::normal(a.subs(at)));
  return out;
}

TEST(ProofDriver, AMechanismOfDyadsBehindItsCrankKeepsItsOwnDriver) {
  const MechanismScene s = load_mechanism_scene(test::source_path("verify/scenes/mechanisms/seed001_fourbar.yaml"));
  EXPECT_EQ(group_sizes(s, s.inputs), (std::vector<int>{2, 1}));
  EXPECT_TRUE(better_proof_drivers(s).empty());
}

TEST(ProofDriver, KoshelsClassThreeMechanismSplitsIntoDyadsWhenLinkThreeDrives) {
  const MechanismScene s = load_mechanism_scene(test::source_path(kClass3));
  EXPECT_EQ(group_sizes(s, s.inputs), (std::vector<int>{4, 2, 1, 1, 1}));
  const std::vector<MechanismInput> better = better_proof_drivers(s);
  ASSERT_FALSE(better.empty());
  EXPECT_EQ(s.linkage.link_names()[static_cast<size_t>(better.front().index)], "3");
  EXPECT_EQ(group_sizes(s, {better.front()}), (std::vector<int>{2, 2, 2, 1, 1, 1}));
}

TEST(ProofDriver, BothDriversSolvedByGroupsGiveTheSceneExactMotion) {
  // The symbolic rates of the class-III mechanism, at the bundled scene's coordinates, against
  // the exact solve of that scene: with the crank driving at the scene's rates, and with link 3
  // driving at its own rates in that motion (the fact a proof with another driver rests on).
  const MechanismScene s = load_mechanism_scene(test::source_path(kClass3));
  const MechanismSolution<Rational> exact = solve_mechanism<Rational>(
      s.linkage, s.inputs, rigid_body_constraint_matrix<Rational>(s.linkage),
      [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(s.linkage, qd); }, s.source);
  std::vector<GiNaC::ex> expected;
  for (const Rational& w : exact.motion.omega) expected.push_back(number(w));
  for (const Rational& a : exact.motion.omega_dot) expected.push_back(number(a));
  const SymbolicConfiguration c = symbolic_configuration(s);
  const SymbolicMotion own = solve_symbolically(s, c, s.inputs, c.inputs);
  ASSERT_TRUE(own.note.empty()) << own.note;
  EXPECT_EQ(omegas_and_alphas_at(s, c, own, s.inputs[0].rate, s.inputs[0].rate_dot), expected);
  const MechanismInput three = better_proof_drivers(s).front();
  const std::vector<InputValue<GiNaC::ex>> rates{{GiNaC::symbol("w3"), GiNaC::symbol("wd3")}};
  const SymbolicMotion other = solve_symbolically(s, c, {three}, rates);
  EXPECT_EQ(other.block_sizes.size(), 6u);
  const auto k = static_cast<size_t>(three.index);
  EXPECT_EQ(omegas_and_alphas_at(s, c, other, exact.motion.omega[k], exact.motion.omega_dot[k]), expected);
}

TEST(ProofDriver, KoshelsDyadPlanForEpsilonThreeIsProvedWithTheScenesDeadCentresAsItsExceptions) {
  const MechanismScene s = load_mechanism_scene(test::source_path(kClass3));
  const std::vector<MechanismDataClaim> claims =
      only(test::bind_all(load_mechanism_claim_file(test::source_path(kKoshelClaims)), s), "koshel.driver5.epsilon3");
  ASSERT_EQ(claims.size(), 1u);
  const TopologyProofRun run = prove_topology(s, claims, {});
  const TopologyProof& p = run.claims.front();
  ASSERT_EQ(p.verdict, ProofVerdict::ProvedGenerically) << to_string(p.verdict) << ": " << p.error << "\n" << fmt::format("{}", fmt::join(p.argument, "\n"));
  EXPECT_EQ(run.proof_driver, "3");
  EXPECT_EQ(run.groups, (std::vector<int>{1, 4, 1, 2, 1}));
  // Every exception is a polynomial in the scene's symbols (none of the other driver's rates),
  // and the dead centres are factors of the scene's own det A.
  const SymbolicConfiguration c = symbolic_configuration(s);
  GiNaC::symtab table;
  for (const std::string& name : c.names) table[name] = GiNaC::symbol(name);
  GiNaC::parser reader(table, true);  // strict: a symbol not of the scene throws
  const GiNaC::ex det = reader(to_text(solve_symbolically(s, c, s.inputs, c.inputs).det));
  int dead_centres = 0;
  for (const ExceptionalSet& e : p.except) {
    GiNaC::ex factor;
    ASSERT_NO_THROW(factor = reader(e.polynomial)) << e.polynomial;
    if (e.meaning.find("dead centre") == std::string::npos) continue;
    ++dead_centres;
    GiNaC::ex quotient;
    EXPECT_TRUE(GiNaC::divide(det, factor, quotient)) << e.polynomial;
  }
  EXPECT_GE(dead_centres, 1);
}

TEST(ProofDriver, ADivisorWithARateIsNamedInTheScenesOwnRates) {
  // The dyad plan's claim multiplied and divided by omega(1): with link 3 driving, omega(1) is a
  // solved rate; the exception must be the scene's own w_1 = 0.
  const MechanismScene s = load_mechanism_scene(test::source_path(kClass3));
  const std::string yaml = "claims:\n  - id: plan_over_omega1\n    source: test\n    statement: test\n    lhs: >\n      (" +
                           koshel_lhs("koshel.driver5.epsilon3") + ")*omega(\"1\")/omega(\"1\")\n    rhs: alpha(\"3\")\n";
  const TopologyProofRun run = prove_topology(s, test::bind_all(parse_mechanism_claim_file(yaml, "test.yaml"), s), {});
  const TopologyProof& p = run.claims.front();
  ASSERT_EQ(p.verdict, ProofVerdict::ProvedGenerically) << to_string(p.verdict) << ": " << p.error << "\n" << fmt::format("{}", fmt::join(p.argument, "\n"));
  EXPECT_EQ(run.proof_driver, "3");
  bool named = false;
  for (const ExceptionalSet& e : p.except) {
    EXPECT_EQ(e.polynomial.find("_driver"), std::string::npos) << e.polynomial << ": " << e.meaning;
    named = named || (e.polynomial == "w_1" && e.meaning.find("omega(\"1\")") != std::string::npos);
  }
  EXPECT_TRUE(named) << "no exception w_1 = 0 for the divisor omega(\"1\")";
}

}  // namespace
}  // namespace linkproof
