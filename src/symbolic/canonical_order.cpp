#include "symbolic/canonical_order.h"

#include <algorithm>
#include <functional>
#include <sstream>
#include <string_view>

#include "structure_hash.h"

namespace linkproof {

using namespace GiNaC;
using structure_hash::mix;
using structure_hash::text_hash;

namespace {

std::string leaf_text(const ex& e) {
  std::ostringstream o;
  o << e;
  return o.str();
}

}  // namespace

std::uint64_t CanonicalOrder::key(const ex& e) {
  if (auto it = keys_.find(e); it != keys_.end()) return it->second;
  std::uint64_t k;
  if (is_exactly_a<add>(e) || is_exactly_a<mul>(e)) {
    std::vector<std::uint64_t> parts;
    parts.reserve(e.nops());
    for (size_t i = 0; i < e.nops(); ++i) parts.push_back(key(e.op(i)));
    std::sort(parts.begin(), parts.end());  // a multiset: GiNaC's order does not enter
    k = text_hash(is_exactly_a<add>(e) ? "+" : "*");
    for (std::uint64_t p : parts) k = mix(k, p);
  } else if (e.nops() == 0) {
    k = mix(text_hash(ex_to<basic>(e).class_name()), text_hash(leaf_text(e)));
  } else {
    k = text_hash(is_exactly_a<function>(e) ? ex_to<function>(e).get_name() : ex_to<basic>(e).class_name());
    for (size_t i = 0; i < e.nops(); ++i) k = mix(k, key(e.op(i)));
  }
  keys_.emplace(e, k);
  return k;
}

std::vector<size_t> CanonicalOrder::order(const ex& e) {
  std::vector<std::pair<std::uint64_t, size_t>> keyed;
  keyed.reserve(e.nops());
  for (size_t i = 0; i < e.nops(); ++i) keyed.emplace_back(key(e.op(i)), i);
  std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    return text(e.op(a.second)) < text(e.op(b.second));  // rare: equal keys
  });
  std::vector<size_t> out;
  out.reserve(keyed.size());
  for (const auto& k : keyed) out.push_back(k.second);
  return out;
}

std::string CanonicalOrder::text(const ex& e) {
  if (is_exactly_a<add>(e) || is_exactly_a<mul>(e)) {
    std::vector<std::string> parts;
    for (size_t i = 0; i < e.nops(); ++i) parts.push_back(text(e.op(i)));
    std::sort(parts.begin(), parts.end());
    std::string k = is_exactly_a<add>(e) ? "+(" : "*(";
    for (const auto& x : parts) k += x + ",";
    return k + ")";
  }
  if (e.nops() == 0) return leaf_text(e);
  std::string k = is_exactly_a<power>(e) ? "^(" : std::string(ex_to<basic>(e).class_name()) + "(";
  for (size_t i = 0; i < e.nops(); ++i) k += text(e.op(i)) + ",";
  return k + ")";
}

}  // namespace linkproof
