#include "core/stable_radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace linkproof {
namespace {

// An item with a key of W words and its order of arrival (and a heap-owning payload, so that
// the permutation's moves are checked on a type that is not trivially copyable).
template <std::size_t W>
struct Item {
  std::array<std::uint64_t, W> key;
  std::size_t arrival;
  std::string payload;
};

// Keys whose words vary only in the bits of `mask` (with the rest fixed), drawn from
// `distinct` values: many repeats, so stability is what decides the order.
template <std::size_t W>
std::vector<Item<W>> random_items(std::mt19937_64& rng, std::size_t n, std::uint64_t mask, std::uint64_t distinct) {
  std::vector<std::array<std::uint64_t, W>> pool(distinct);
  for (auto& k : pool)
    for (std::size_t w = 0; w < W; ++w) k[w] = (rng() & mask) | (0x0101000000000000ULL & ~mask);
  std::vector<Item<W>> items;
  for (std::size_t i = 0; i < n; ++i)
    items.push_back({pool[rng() % distinct], i, std::to_string(i) + (i % 2 ? std::string(24, 'x') : std::string())});
  return items;
}

template <std::size_t W>
void expect_same_as_std_stable_sort(std::vector<Item<W>> items) {
  std::vector<Item<W>> expected = items;
  std::stable_sort(expected.begin(), expected.end(), [](const Item<W>& a, const Item<W>& b) { return a.key < b.key; });
  stable_sort_by_key<W>(items, [](const Item<W>& x) { return x.key; });
  ASSERT_EQ(items.size(), expected.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    ASSERT_EQ(items[i].key, expected[i].key) << "at " << i;
    ASSERT_EQ(items[i].arrival, expected[i].arrival) << "at " << i;
    ASSERT_EQ(items[i].payload, expected[i].payload) << "at " << i;
  }
}

// Sizes on both sides of the radix threshold, one- and two-word keys, keys that differ in a few
// bytes (a sum over pairs), in every byte, or not at all. Seed printed by the failing message.
TEST(StableRadixSort, OrdersAsStdStableSortKeepingTheArrivalOfEqualKeys) {
  const std::uint64_t seed = 20261127;
  std::mt19937_64 rng(seed);
  SCOPED_TRACE("seed " + std::to_string(seed));
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{17}, kRadixMinimum - 1, kRadixMinimum,
                        kRadixMinimum + 1, std::size_t{5000}, std::size_t{20000}}) {
    for (const std::uint64_t mask : std::vector<std::uint64_t>{0xffff'ffff'0000'0000, ~std::uint64_t{0}, 0, 0x00ff'0000'0000'00ff}) {
      for (std::uint64_t distinct : {std::uint64_t{1}, std::uint64_t{7}, std::uint64_t{100000}}) {
        SCOPED_TRACE("n " + std::to_string(n) + " mask " + std::to_string(mask) + " distinct " + std::to_string(distinct));
        expect_same_as_std_stable_sort<1>(random_items<1>(rng, n, mask, distinct));
        expect_same_as_std_stable_sort<2>(random_items<2>(rng, n, mask, distinct));
      }
    }
  }
}

TEST(StableRadixSort, SortsReversedAndAlreadySortedInput) {
  std::vector<Item<1>> up, down;
  for (std::size_t i = 0; i < 3000; ++i) {
    up.push_back({{i / 3}, i, std::to_string(i)});
    down.push_back({{(3000 - i) / 3}, i, std::to_string(i)});
  }
  expect_same_as_std_stable_sort<1>(up);
  expect_same_as_std_stable_sort<1>(down);
}

}  // namespace
}  // namespace linkproof
