// Stable sort by unsigned integer keys, in time linear in the number of items: the sort that
// merges the terms of a rate polynomial (claims/rate_poly.h) and of a rate jet
// (symbolic/rate_jet.h), where a polynomial of a check at n = 1000 has about a million terms.
//
// A key is W 64-bit words compared as one unsigned integer, word 0 most significant (the order
// of Monomial and of the jets' variable keys). Least-significant-digit radix sort on bytes:
// one counting pass per byte, from the least significant one up, each pass stable, so the
// result is the stable sort's (items with equal keys keep their order of arrival, which is
// what makes the sums of equal monomials the same bits as before). Bytes equal in every key
// are skipped: the keys of a sum over pairs differ in two or four bytes of sixteen.
//
// The passes move small records, not the items: (key, index) entries, or, when at most four
// bytes vary, those bytes packed above the index in one 64-bit word. The items are then
// gathered once into their sorted places (one move per item). Below kRadixMinimum items
// std::stable_sort is cheaper than the 256-entry histograms.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace linkproof {

inline constexpr std::size_t kRadixMinimum = 256;

namespace radix_detail {
template <std::size_t W>
struct Entry {
  std::array<std::uint64_t, W> key;
  std::uint32_t index;
};
/// The two arrays of entries, kept per thread between calls (one pair per key size, whatever
/// the items): a polynomial of a million terms needs 48 MB of them, and fresh pages each time
/// (the kernel clears every page) would cost as much as the passes.
template <std::size_t W>
struct Buffers {
  std::vector<Entry<W>> entries, entries_out;     // full keys with the index
  std::vector<std::uint64_t> packed, packed_out;  // up to four key bytes above the index
  std::vector<std::uint32_t> order;               // the sorted order of the items
};
template <std::size_t W>
Buffers<W>& buffers() {
  thread_local Buffers<W> b;
  return b;
}
/// One stable counting pass: `from` ordered by the byte digit(record) into `to` (same size).
template <class Record, class Digit>
void counting_pass(const std::vector<Record>& from, std::vector<Record>& to, Digit digit) {
  std::array<std::size_t, 257> start{};
  for (const Record& r : from) ++start[digit(r) + 1];
  for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
  for (const Record& r : from) to[start[digit(r)]++] = r;
}
}  // namespace radix_detail

/// Sorts `items` stably by key_of(item), a std::array<std::uint64_t, W> (word 0 most
/// significant): the order std::stable_sort gives with that comparison.
template <std::size_t W, class Item, class KeyOf>
void stable_sort_by_key(std::vector<Item>& items, KeyOf key_of) {
  using Key = std::array<std::uint64_t, W>;
  const std::size_t n = items.size();
  if (n < kRadixMinimum || n >= UINT32_MAX) {
    std::stable_sort(items.begin(), items.end(),
                     [&](const Item& a, const Item& b) { return key_of(a) < key_of(b); });
    return;
  }
  using Entry = radix_detail::Entry<W>;
  radix_detail::Buffers<W>& buf = radix_detail::buffers<W>();
  Key any{}, all{};
  all.fill(~std::uint64_t{0});
  for (const Item& item : items) {
    const Key key = key_of(item);
    for (std::size_t w = 0; w < W; ++w) any[w] |= key[w], all[w] &= key[w];
  }
  // The bytes that differ between some keys, most significant first (word, shift).
  std::vector<std::pair<std::size_t, int>> varying;
  for (std::size_t w = 0; w < W; ++w)
    for (int shift = 56; shift >= 0; shift -= 8)
      if ((((any[w] ^ all[w]) >> shift) & 0xff) != 0) varying.emplace_back(w, shift);
  if (varying.empty()) return;  // every key equal: the order of arrival is the order
  std::vector<std::uint32_t>& order = buf.order;
  order.resize(n);
  if (varying.size() <= 4) {
    // Up to four varying bytes (a sum over pairs at n <= 16000): packed with the index into one
    // 64-bit word, key above index, a third of the memory traffic of the full entries.
    std::vector<std::uint64_t>& a = buf.packed;
    std::vector<std::uint64_t>& b = buf.packed_out;
    a.resize(n);
    b.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Key key = key_of(items[i]);
      std::uint64_t packed = 0;
      for (const auto& [w, shift] : varying) packed = (packed << 8) | ((key[w] >> shift) & 0xff);
      a[i] = (packed << 32) | i;
    }
    for (int shift = 32; shift < 32 + 8 * static_cast<int>(varying.size()); shift += 8) {
      radix_detail::counting_pass(a, b, [shift](std::uint64_t r) { return (r >> shift) & 0xff; });
      a.swap(b);
    }
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(a[i]);
  } else {
    std::vector<Entry>& a = buf.entries;
    std::vector<Entry>& b = buf.entries_out;
    a.resize(n);
    b.resize(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = {key_of(items[i]), static_cast<std::uint32_t>(i)};
    for (auto it = varying.rbegin(); it != varying.rend(); ++it) {
      const auto [w, shift] = *it;
      radix_detail::counting_pass(a, b, [w = w, shift = shift](const Entry& e) { return (e.key[w] >> shift) & 0xff; });
      a.swap(b);
    }
    for (std::size_t i = 0; i < n; ++i) order[i] = a[i].index;
  }
  // Gathered into a new array: each read is independent of the others, so the processor
  // overlaps their cache misses (following the permutation's cycles in place chains them, and
  // was slower than std::stable_sort at a million items).
  std::vector<Item> sorted;
  sorted.reserve(n);
  for (std::size_t i = 0; i < n; ++i) sorted.push_back(std::move(items[order[i]]));
  items.swap(sorted);
}

}  // namespace linkproof
