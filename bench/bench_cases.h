// Random polygons shared by the benchmarks: drawn once, outside every timed loop, from a fixed
// seed that is printed in the benchmark context so any timing can be replayed on the same data.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "check/random_polygon.h"

namespace linkproof::bench {

/// Seed of every random case in linkproof_bench (replay: generate_random_polygon(seed, n, i)).
inline constexpr std::uint64_t kSeed = 1966;

/// Largest n for which each family is drawn. The generator redraws a polygon with coincident
/// joints, and its families take joints from small sets of rationals, so at large n almost
/// every draw collides (the birthday problem):
///   convex (index mod 3 = 2): ellipse points with parameter t = p/q, |t| <= 6, q <= 7, about
///     217 values: no valid draw beyond n ~ 50; 10000 redraws, then InternalError (27 s at n = 1000);
///   star (index mod 3 = 1): about 480^2 joints: 2-10 s of redraws per case at n = 1000.
/// Scattered polygons (about 960^2 joints) are drawn in milliseconds at every n used here.
inline constexpr int kMaxConvexN = 48;
inline constexpr int kMaxStarN = 300;

/// The first `count` cases of generate_random_polygon(kSeed, n, i), i = 0, 1, ..., of the
/// families that can be drawn quickly at this n. Drawn once per (n, count) and cached, so that
/// benchmarks over the same n time the same polygons. families() names the families used.
inline const std::vector<RandomPolygonCase>& make_cases(int n, int count) {
  static const bool context_added = [] {
    benchmark::AddCustomContext("linkproof_seed", std::to_string(kSeed));
    return true;
  }();
  (void)context_added;
  static std::map<std::pair<int, int>, std::vector<RandomPolygonCase>> cache;
  std::vector<RandomPolygonCase>& cases = cache[{n, count}];
  if (!cases.empty()) return cases;
  for (int i = 0; static_cast<int>(cases.size()) < count; ++i) {
    if ((i % 3 == 2 && n > kMaxConvexN) || (i % 3 == 1 && n > kMaxStarN)) continue;
    cases.push_back(generate_random_polygon(kSeed, n, i));
  }
  return cases;
}

/// The families present in `cases`, e.g. "scattered+star", for the benchmark's label.
inline std::string families(const std::vector<RandomPolygonCase>& cases) {
  std::string out;
  for (const char* f : {"scattered", "star", "convex"}) {
    for (const RandomPolygonCase& c : cases) {
      if (c.family != f) continue;
      if (!out.empty()) out += '+';
      out += f;
      break;
    }
  }
  return out;
}

}  // namespace linkproof::bench
