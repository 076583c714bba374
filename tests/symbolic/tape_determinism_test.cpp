// Floating-point results of the engine do not depend on the run. GiNaC's operand order and its
// placement of signs and numeric factors between sums and products follow address-seeded hashes
// (ASLR) and symbol serials (creation order), so the Tape compiles a canonical form
// (symbolic/canonical_form.h), not GiNaC's trees. Pinned in one process (equal expressions built
// from symbols created in other orders give the same tape, instruction for instruction) and across
// processes (the test binary runs itself; each exec gets fresh addresses, and one child derives
// other polygon sizes first).
#include <gtest/gtest.h>

#include <cln/rational_io.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "check/random_polygon.h"
#include "symbolic/canonical_form.h"
#include "symbolic/canonical_order.h"
#include "symbolic/ground_truth.h"
#include "symbolic/tape.h"
#include "support/cli_run.h"

namespace linkproof {
namespace {

TEST(CanonicalOrder, EqualExpressionsFromDifferentSymbolObjectsGetEqualKeysAndOrders) {
  using namespace GiNaC;
  // Symbols created in opposite orders: GiNaC's serials (and so its operand order) differ.
  const symbol a1("a"), b1("b"), c1("c");
  const symbol c2("c"), b2("b"), a2("a");
  const ex e1 = a1 * b1 + pow(c1, 2) - 3 * a1 + numeric(1, 7) * b1 * c1;
  const ex e2 = numeric(1, 7) * c2 * b2 - 3 * a2 + pow(c2, 2) + b2 * a2;
  CanonicalOrder order;
  EXPECT_EQ(order.key(e1), order.key(e2));
  const std::vector<size_t> o1 = order.order(e1), o2 = order.order(e2);
  ASSERT_EQ(o1.size(), o2.size());
  for (size_t i = 0; i < o1.size(); ++i)
    EXPECT_EQ(CanonicalOrder::text(e1.op(o1[i])), CanonicalOrder::text(e2.op(o2[i]))) << "operand " << i;
  EXPECT_NE(order.key(e1), order.key(e1 + a1));
}

/// The tape as text: every instruction, operand, constant and output.
std::string tape_text(const Tape& t) {
  std::ostringstream out;
  for (const auto& in : t.code()) out << static_cast<int>(in.op) << " " << in.a << " " << in.b << " " << in.k << "\n";
  for (auto o : t.operands()) out << o << " ";
  out << "\n";
  for (const auto& c : t.constants()) {
    cln::fprint(out, c);
    out << " ";
  }
  out << "\n";
  for (auto o : t.outputs()) out << o << " ";
  return out.str();
}

TEST(CanonicalForm, SignsAndFactorsPlacedDifferentlyByGiNaCGiveOnePrimitivePart) {
  using namespace GiNaC;
  const symbol a("a"), b("b"), c("c");
  // GiNaC stores these as (b-a)*c or -(a-b)*c, 2*(2b-a)^-1/... depending on its hash order; as
  // functions they are one: content times the same primitive part.
  CanonicalForm form({a, b, c});
  const auto s1 = form.split((b - a) * c);
  const auto s2 = form.split((a - b) * c);
  EXPECT_EQ(s1.primitive, s2.primitive);
  EXPECT_TRUE(s1.content.is_equal(-s2.content));
  const auto s3 = form.split(pow(6 * a - 4 * b, -1));
  const auto s4 = form.split(pow(3 * a - 2 * b, -1));
  EXPECT_EQ(s3.primitive, s4.primitive);
  EXPECT_TRUE((s3.content * 2).is_equal(s4.content));
  // The primitive part of a sum has coprime integer coefficients, the canonically first positive.
  const CanonicalForm::Node& sum = form.node(form.split(numeric(3, 4) * a - numeric(3, 2) * b).primitive);
  ASSERT_EQ(sum.kind, CanonicalForm::Kind::Sum);
  ASSERT_EQ(sum.terms.size(), 2u);
  EXPECT_TRUE(sum.terms[0].second.is_pos_integer());
  EXPECT_TRUE(abs(sum.terms[0].second * sum.terms[1].second).is_equal(2));
  // Distinct functions stay distinct.
  EXPECT_NE(form.split(a - b).primitive, form.split(a + b).primitive);
  EXPECT_NE(form.split(a * c).primitive, form.split(a * pow(c, -1)).primitive);
}

TEST(TapeDeterminism, EqualExpressionsFromSymbolsCreatedInOtherOrdersCompileToOneTape) {
  using namespace GiNaC;
  // The same rational function built from symbol sets created in different orders (other serials,
  // hence other GiNaC hash orders and other sign placements): one tape.
  auto build = [](int junk, bool reversed) {
    std::vector<symbol> before;
    for (int i = 0; i < junk; ++i) before.emplace_back("junk");
    std::vector<symbol> v;
    if (reversed) {
      const symbol d("d"), c("c"), b("b"), a("a");
      v = {a, b, c, d};
    } else {
      const symbol a("a"), b("b"), c("c"), d("d");
      v = {a, b, c, d};
    }
    const ex &a = v[0], &b = v[1], &c = v[2], &d = v[3];
    const ex e = ((b - a) * (c - d) - (a - c) * (d - b) * 3) / (4 * d - 2 * a) +
                 pow((c - b) * (a - d), 2) * (numeric(3, 5) * a - numeric(6, 5) * c) / pow(a * d - b * c, 3);
    return tape_text(Tape({e, expand(e * (a - b))}, {a, b, c, d}, "test"));
  };
  const std::string reference = build(0, false);
  for (int junk = 0; junk < 8; ++junk)
    for (bool reversed : {false, true}) EXPECT_EQ(build(junk, reversed), reference) << "junk " << junk << " reversed " << reversed;
}

TEST(TapeDeterminism, MotionTapeDoesNotDependOnSymbolCreationOrderOrOtherDerivations) {
  // Other engines, derived first, take other symbol serials; the motion tape of n = 6 is the same
  // instruction list whatever was created before it.
  auto motion_tape = [](int warm_up) {
    GroundTruthEngine other;
    if (warm_up > 0) other.derivation(warm_up);
    GroundTruthEngine engine;
    return tape_text(engine.derivation(6).motion);
  };
  const std::string reference = motion_tape(0);
  for (int warm_up : {4, 5, 7, 9}) EXPECT_EQ(motion_tape(warm_up), reference) << "after deriving n = " << warm_up;
}

/// What double arithmetic gives for one random n-gon: the motion tape's values and error bounds
/// and the jet coefficients.
std::string motion_fingerprint(GroundTruthEngine& engine, int n) {
  std::ostringstream out;
  out.precision(17);
  const RandomPolygonCase c = generate_random_polygon(20261124, n, 0);
  const Polygon<Tracked<double>> p = c.polygon.convert<Tracked<double>>();
  const PolygonMotion<Tracked<double>> m = engine.motion(p, c.rates.convert<Tracked<double>>());
  for (const auto& x : m.omega_dot) out << x.v << " " << x.e << "\n";
  const auto [c1, c2] = engine.coefficients(p);
  for (const auto* v : {&c1.omega_dot, &c1.omega_sq, &c1.omega_pair, &c2.omega_pair})
    for (const auto& x : *v) out << x.v << " " << x.e << "\n";
  return out.str();
}

/// Everything double arithmetic produces for a 5-gon and a 9-gon, derived in the given order in
/// one engine, and a whole `check --arith double --json` of the hexagon.
std::string double_fingerprint(const std::vector<int>& order = {5, 9}) {
  GroundTruthEngine engine;
  std::map<int, std::string> by_n;
  for (int n : order) by_n[n] = motion_fingerprint(engine, n);
  return by_n[5] + by_n[9] +
         test::run_cli({"check", std::string(LINKPROOF_SOURCE_DIR) + "/verify/scenes/hexagon.yaml", "--arith", "double",
                        "--json"})
             .out;
}

// Not a test on its own: the body of the child processes of the next test.
TEST(TapeDeterminism, ChildWritesDoubleFingerprint) {
  const char* file = std::getenv("LINKPROOF_FINGERPRINT_FILE");
  if (file == nullptr) GTEST_SKIP() << "runs as the child of TapeDeterminism.DoubleResultsAreTheBytesOfAnyOtherRun";
  // LINKPROOF_FINGERPRINT_OTHER_ORDER: derive n = 7 first, then 9 before 5.
  const bool other_order = std::getenv("LINKPROOF_FINGERPRINT_OTHER_ORDER") != nullptr;
  std::ofstream(file, std::ios::binary) << (other_order ? double_fingerprint({7, 9, 5}) : double_fingerprint());
}

TEST(TapeDeterminism, DoubleResultsAreTheBytesOfAnyOtherRun) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();  // this test binary
  const std::string mine = double_fingerprint();
  for (int run = 0; run < 3; ++run) {
    const std::string file = ::testing::TempDir() + "linkproof_fingerprint_" + std::to_string(run) + ".txt";
    std::remove(file.c_str());
    // A fresh exec of the same binary: fresh addresses (ASLR), hence other GiNaC hash values.
    // Run 2 derives n = 7, 9, 5 in this order (other symbol serials for every size).
    const std::string command = std::string(run == 2 ? "LINKPROOF_FINGERPRINT_OTHER_ORDER=1 " : "") +
                                "LINKPROOF_FINGERPRINT_FILE='" + file + "' '" + self +
                                "' --gtest_filter=TapeDeterminism.ChildWritesDoubleFingerprint > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream in(file, std::ios::binary);
    std::ostringstream theirs;
    theirs << in.rdbuf();
    ASSERT_FALSE(theirs.str().empty()) << "the child wrote nothing to " << file;
    EXPECT_EQ(theirs.str(), mine) << "run " << run << " of the same binary gave other double results";
  }
}

}  // namespace
}  // namespace linkproof
