// Internal: 64-bit hashing that is the same in every run, for keys of expression structure
// (canonical_order.cpp, canonical_form.cpp). Never std::hash: not promised to be stable.
#pragma once

#include <cstdint>
#include <string_view>

namespace linkproof::structure_hash {

/// splitmix64's finaliser over a combination of h and x: well mixed, order-sensitive.
inline std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
  std::uint64_t z = h ^ (x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// FNV-1a of a text.
inline std::uint64_t text_hash(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

}  // namespace linkproof::structure_hash
