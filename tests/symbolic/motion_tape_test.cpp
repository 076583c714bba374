// The motion tape built without GiNaC trees (symbolic/motion_tape.h) is the tape of GiNaC's
// derivation (symbolic/loop_closure.h), instruction for instruction: GiNaC stays the reference.
#include <gtest/gtest.h>

#include <cln/rational_io.h>

#include <sstream>
#include <string>

#include "symbolic/canonical_form.h"
#include "symbolic/ground_truth.h"
#include "symbolic/motion_tape.h"

namespace linkproof {
namespace {

/// The first place where two tapes differ, or "" when they are the same tape.
std::string first_difference(const Tape& direct, const Tape& reference) {
  if (direct.input_count() != reference.input_count()) return "input count";
  if (direct.denominator_name() != reference.denominator_name()) return "denominator name";
  const auto& a = direct.code();
  const auto& b = reference.code();
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (a[i].op != b[i].op || a[i].a != b[i].a || a[i].b != b[i].b || a[i].k != b[i].k)
      return "instruction " + std::to_string(i) + " of " + std::to_string(b.size());
  if (a.size() != b.size())
    return "instruction count " + std::to_string(a.size()) + " against " + std::to_string(b.size());
  if (direct.operands() != reference.operands()) return "operand lists";
  if (direct.outputs() != reference.outputs()) return "outputs";
  if (direct.constants().size() != reference.constants().size()) return "constant count";
  for (size_t i = 0; i < direct.constants().size(); ++i)
    if (direct.constants()[i] != reference.constants()[i]) return "constant " + std::to_string(i);
  return "";
}

TEST(MotionTape, IsTheTapeOfGiNaCsDerivationInstructionForInstruction) {
  std::vector<int> sizes;
  for (int n = 4; n <= 40; ++n) sizes.push_back(n);
  for (int n : {64, 101, 257, 1000}) sizes.push_back(n);
  for (int n : sizes) {
    GroundTruthEngine engine;
    const Tape& direct = engine.derivation(n).motion;
    const Tape reference = engine.symbolic_derivation(n).motion_tape();
    EXPECT_EQ(first_difference(direct, reference), "") << "n = " << n;
    EXPECT_GT(direct.size(), static_cast<size_t>(4 * n)) << "n = " << n;
  }
}

TEST(MotionTape, InputNamesAreThoseOfThePolygonsSymbolsInTheTapesOrder) {
  GroundTruthEngine engine;
  const auto& d = engine.symbolic_derivation(6);
  const std::vector<std::string> names = motion_tape_input_names(6);
  ASSERT_EQ(names.size(), d.inputs.size());
  for (size_t i = 0; i < names.size(); ++i)
    EXPECT_EQ(names[i], GiNaC::ex_to<GiNaC::symbol>(d.inputs[i]).get_name()) << "input " << i;
}

TEST(CanonicalFormBuilders, GiveWhatSplittingGiNaCsTreeOfTheSameShapeGives) {
  using namespace GiNaC;
  const symbol x("x"), y("y");
  const std::vector<ex> inputs{x, y};
  // GiNaC stores the sign and factor of each sum as it likes; the canonical form does not care.
  const ex tree = (2 * x - 4 * y) * pow(3 * y - x, -2) * x + numeric(5, 3) * pow(x, 2) - (y - x) * (x - y);
  CanonicalForm from_tree(inputs);
  const CanonicalForm::Split s = from_tree.split(tree);

  CanonicalForm built(std::vector<std::string>{"x", "y"});
  const auto bx = built.input(0), by = built.input(1);
  auto times = [&](int c, const CanonicalForm::Split& v) { return built.product({built.number(c), v}); };
  const auto first = built.product({built.sum({times(2, bx), times(-4, by)}),
                                    built.power(built.sum({times(3, by), times(-1, bx)}), -2), bx});
  const auto second = built.product({built.number(numeric(5, 3)), built.power(bx, 2)});
  const auto third = built.product(
      {built.number(-1), built.sum({by, times(-1, bx)}), built.sum({bx, times(-1, by)})});
  const auto b = built.sum({first, second, third});

  EXPECT_EQ(b.content, s.content);
  // The same structure: compiled, the two give the same tape.
  const Tape t1(std::move(from_tree), {s}, "D");
  const Tape t2(std::move(built), {b}, "D");
  EXPECT_EQ(first_difference(t2, t1), "");
  EXPECT_GT(t1.size(), 6u);
}

}  // namespace
}  // namespace linkproof
