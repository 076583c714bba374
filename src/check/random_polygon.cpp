#include "check/random_polygon.h"

#include <algorithm>
#include <cmath>

#include "linkproof/core/error.h"

namespace linkproof {

std::uint64_t SplitMix64::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

long SplitMix64::uniform(long lo, long hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<long>(next() % span);
}

namespace {

Rational small_rational(SplitMix64& rng, long range, long max_den) {
  const long q = rng.uniform(1, max_den);
  return Rational(rng.uniform(-range * q, range * q)) / Rational(q);
}

Rational nonzero_rational(SplitMix64& rng, long range, long max_den) {
  for (;;) {
    Rational r = small_rational(rng, range, max_den);
    if (!cln::zerop(r)) return r;
  }
}

double approx_angle(const Vec2<Rational>& p) { return std::atan2(cln::double_approx(p.y), cln::double_approx(p.x)); }

void sort_by_angle(std::vector<Vec2<Rational>>& pts) {
  std::stable_sort(pts.begin(), pts.end(),
                   [](const auto& a, const auto& b) { return approx_angle(a) < approx_angle(b); });
}

std::vector<Vec2<Rational>> draw_joints(SplitMix64& rng, int n, int family) {
  std::vector<Vec2<Rational>> pts;
  // Ranges grow with n so that large polygons do not run out of distinct joints.
  const long range = 40 + 2L * n;
  switch (family) {
    case 0:  // scattered
      for (int k = 0; k < n; ++k) pts.push_back({small_rational(rng, range, 6), small_rational(rng, range, 6)});
      break;
    case 1:  // star-shaped around the origin
      for (int k = 0; k < n; ++k) pts.push_back({nonzero_rational(rng, range, 4), nonzero_rational(rng, range, 4)});
      sort_by_angle(pts);
      break;
    default: {  // convex: rational points ((1-t^2)/(1+t^2) a, 2t/(1+t^2) b) of an ellipse
      const Rational a = rng.uniform(10, 40), b = rng.uniform(10, 40);
      for (int k = 0; k < n; ++k) {
        const Rational t = small_rational(rng, 6 + n / 4, 7 + n / 8);
        const Rational d = 1 + t * t;
        pts.push_back({a * (1 - t * t) / d, b * 2 * t / d});
      }
      sort_by_angle(pts);
    }
  }
  return pts;
}

}  // namespace

RandomPolygonCase generate_random_polygon(std::uint64_t seed, int n, int index) {
  LINKPROOF_ASSERT(n >= 4, "random polygons need n >= 4");
  SplitMix64 mixer(seed);
  const std::uint64_t s = mixer.next() ^ (0x100000001b3ULL * static_cast<std::uint64_t>(n)) ^
                          (0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(index + 1));
  SplitMix64 rng(s);
  RandomPolygonCase c;
  c.seed = seed;
  c.n = n;
  c.index = index;
  const int family = index % 3;
  c.family = family == 0 ? "scattered" : family == 1 ? "star" : "convex";
  for (int attempt = 0; attempt < 10000; ++attempt) {
    std::vector<Vec2<Rational>> pts = draw_joints(rng, n, family);
    c.clockwise_numbering = rng.uniform(0, 1) == 1;
    if (c.clockwise_numbering) std::reverse(pts.begin(), pts.end());
    std::rotate(pts.begin(), pts.begin() + rng.uniform(0, n - 1), pts.end());  // which side is fixed
    Polygon<Rational> p(std::move(pts));
    if (!polygon_input_problem(p).empty() || cln::zerop(p.dead_centre_determinant())) continue;
    c.polygon = std::move(p);
    c.rates = {};
    for (int j = 0; j < n - 3; ++j) {
      c.rates.omega.push_back(small_rational(rng, 5, 4));
      c.rates.omega_dot.push_back(small_rational(rng, 5, 4));
    }
    return c;
  }
  throw InternalError("could not draw a valid random polygon");
}

}  // namespace linkproof
