// Random exact polygons for sweeps and property tests. Every case is a pure function of
// (seed, n, index), so any case replays from those three numbers.
//
// Families (index mod 3): "scattered" (random joints in random order: often self-intersecting),
// "star" (joints sorted by angle around an interior point: simple, usually non-convex),
// "convex" (rational points of an ellipse in angular order). The numbering direction is
// reversed at random, so both clockwise and counter-clockwise polygons occur. Coordinates and
// rates are small rationals. Cases with coincident joints or at the dead centre are redrawn.
#pragma once

#include <cstdint>
#include <string>

#include "linkproof/geometry/polygon.h"

namespace linkproof {

struct RandomPolygonCase {
  std::uint64_t seed = 0;
  int n = 0;
  int index = 0;
  std::string family;
  bool clockwise_numbering = false;
  Polygon<Rational> polygon;
  InputRates<Rational> rates;
};

RandomPolygonCase generate_random_polygon(std::uint64_t seed, int n, int index);

/// A deterministic 64-bit generator (splitmix64): the same stream on every platform.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  /// Uniform integer in [lo, hi] (modulo bias below 2^-40 for the ranges used here).
  long uniform(long lo, long hi);

 private:
  std::uint64_t state_;
};

}  // namespace linkproof
