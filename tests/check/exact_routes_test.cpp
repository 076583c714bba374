// The exact arithmetic computes in InlineRational (core/inline_rational.h). Its values must be
// CLN's to the last digit: every claim of the catalogue, evaluated on random polygons of both
// scalar types through the same generic code (engine, construction, four-bars, claims), gives
// the same sides, comparison by comparison, defined or undefined alike.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "dijksman1966.h"
#include "check/random_polygon.h"
#include "claims/data_claim.h"
#include "claims/polygon_context.h"
#include "core/inline_rational.h"

namespace linkproof {
namespace {

template <class A, class B>
void expect_same_side(const Defined<A>& a, const Defined<B>& b, const std::string& where) {
  ASSERT_EQ(a.has_value(), b.has_value()) << where;
  if (a.has_value()) {
    ASSERT_EQ(to_exact(a.get()), to_exact(b.get())) << where;
  } else {
    ASSERT_EQ(a.quantity(), b.quantity()) << where;
  }
}

template <class A, class B>
int expect_same_comparisons(const std::vector<Comparison<A>>& a, const std::vector<Comparison<B>>& b,
                            const std::string& where) {
  EXPECT_EQ(a.size(), b.size()) << where;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    const std::string at = where + " " + b[k].full_label();
    EXPECT_EQ(a[k].full_label(), b[k].full_label()) << at;
    expect_same_side(a[k].lhs, b[k].lhs, at + " lhs");
    expect_same_side(a[k].rhs, b[k].rhs, at + " rhs");
  }
  return static_cast<int>(a.size());
}

TEST(ExactRoutes, InlineAndCLNRationalsGiveEveryClaimTheSameSidesOnRandomPolygons) {
  constexpr std::uint64_t kSeed = 20261128;
  std::printf("ExactRoutes seed %llu (replay: generate_random_polygon(seed, n, index))\n",
              static_cast<unsigned long long>(kSeed));
  GroundTruthEngine engine;
  int comparisons = 0, polygons = 0;
  for (int n = 4; n <= 9; ++n) {
    for (int index = 0; index < 50; ++index) {
      const RandomPolygonCase c = generate_random_polygon(kSeed, n, index);
      const auto reference = build_polygon_context<Rational>(engine, c.polygon, c.rates);
      const auto inline_ctx = build_polygon_context<InlineRational>(engine, c.polygon, c.rates);
      ++polygons;
      for (const DataClaim& claim : dijksman1966::claim_file().claims) {
        if (!claim.info.applies_to(n)) continue;
        const std::string where = claim.info.id + " n=" + std::to_string(n) + " index=" + std::to_string(index);
        const ClaimSides<Rational> a = evaluate_data_claim(claim, reference);
        const ClaimSides<InlineRational> b = evaluate_data_claim(claim, inline_ctx);
        comparisons += expect_same_comparisons(a.instances, b.instances, where);
        comparisons += expect_same_comparisons(a.terms, b.terms, where);
        if (HasFatalFailure()) return;
      }
    }
  }
  std::printf("%d polygons, %d comparisons\n", polygons, comparisons);
  EXPECT_GE(comparisons, 10000);
}

// A side's value at the rates, its terms multiplied out and added one by one in CLN rationals
// (the reference for the evaluation's balanced, grouped sums); nullopt where it is undefined.
std::optional<Rational> sequential_value(const SideValue<InlineRational>& v, const InputRates<Rational>& rates) {
  if (!v.poly.has_value() || !v.undefined_inputs.empty()) return std::nullopt;
  Rational sum = 0;
  for (const auto& [m, coefficient] : v.poly.get().terms()) {
    Rational t = coefficient.to_rational();
    for (int i = 0; i < m.size(); ++i) {
      const RateVariable r = RateVariable::from_id(m[i]);
      const auto at = static_cast<size_t>(r.index - 1);
      t = t * (r.kind == RateVariable::Omega ? rates.omega[at] : rates.omega_dot[at]);
    }
    sum = sum + t;
  }
  return sum;
}

// An exact claim computes a total once when both sides are the same polynomial (data_claim.h).
// Every total must still be its own side's value at the rates: checked here against the side's
// terms summed one by one in CLN rationals, on claims that hold and on the wrong variants of
// the catalogue, whose sides differ.
TEST(ExactRoutes, EveryTotalIsItsOwnSidesValueAtTheRates) {
  constexpr std::uint64_t kSeed = 20261129;
  std::printf("ExactRoutes totals seed %llu\n", static_cast<unsigned long long>(kSeed));
  GroundTruthEngine engine;
  int totals = 0, differing = 0;
  for (int n = 4; n <= 8; ++n) {
    for (int index = 0; index < 6; ++index) {
      const RandomPolygonCase c = generate_random_polygon(kSeed, n, index);
      const auto ctx = build_polygon_context<InlineRational>(engine, c.polygon, c.rates);
      for (const DataClaim& claim : dijksman1966::claim_file().claims) {
        if (!claim.info.applies_to(n)) continue;
        const ClaimSides<InlineRational> sides = evaluate_data_claim(claim, ctx);
        for (size_t k = 0; k < sides.instances.size(); ++k) {
          const int j = claim.for_each_j ? static_cast<int>(k) + 1 : 0;
          const std::string where = claim.info.id + " n=" + std::to_string(n) + " index=" + std::to_string(index) +
                                    " " + sides.instances[k].full_label();
          const Comparison<InlineRational>& total = sides.instances[k];
          const std::optional<Rational> values[2] = {sequential_value(evaluate_side(claim, claim.lhs, ctx, j), c.rates),
                                                     sequential_value(evaluate_side(claim, claim.rhs, ctx, j), c.rates)};
          for (int s = 0; s < 2; ++s) {
            const Defined<InlineRational>& got = s == 0 ? total.lhs : total.rhs;
            ASSERT_EQ(got.has_value(), values[s].has_value()) << where << (s == 0 ? " lhs" : " rhs");
            if (got.has_value()) {
              ASSERT_EQ(got.get().to_rational(), *values[s]) << where << (s == 0 ? " lhs" : " rhs");
            }
          }
          ++totals;
          if (values[0] && values[1] && *values[0] != *values[1]) ++differing;
        }
      }
    }
  }
  std::printf("%d totals, %d with sides of different values\n", totals, differing);
  EXPECT_GE(totals, 1000);
  EXPECT_GE(differing, 100);  // the wrong variants: totals whose sides differ were checked too
}

}  // namespace
}  // namespace linkproof
