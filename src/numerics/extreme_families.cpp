#include "numerics/extreme_families.h"

#include <cln/integer.h>

#include "check/random_polygon.h"

namespace linkproof {

namespace {

using V = Vec2<Rational>;

V scaled(const Rational& s, const V& v) { return {s * v.x, s * v.y}; }

/// The polygon with sides r_1..r_{n-1} from K_1 = (0, 0); side n closes it.
Polygon<Rational> from_sides(const std::vector<V>& sides) {
  std::vector<V> joints{{0, 0}};
  for (const V& r : sides) joints.push_back(joints.back() + r);
  return Polygon<Rational>(std::move(joints));
}

// The pentagon of conventions §A8: r_1 = (1,4), r_2 = (4,1), r_3 = a = (2,-4), r_4 = b = (-4,-3).
const V kR1{1, 4}, kR2{4, 1}, kA{2, -4}, kB{-4, -3};

InputRates<Rational> a8_rates() { return {{2, -1}, {1, 3}}; }

ExtremeCase pentagon_with(const V& r1, const V& r2, const V& a, const V& b) {
  return {from_sides({r1, r2, a, b}), a8_rates()};
}

Rational pow10(int k) {
  Rational p = 1;
  for (int i = 0; i < (k < 0 ? -k : k); ++i) p = p * 10;
  return k >= 0 ? p : 1 / p;
}

/// 10^-k for k in `exponents`, then exactly 0.
std::vector<Rational> epsilons(std::initializer_list<int> exponents) {
  std::vector<Rational> v;
  for (int k : exponents) v.push_back(pow10(-k));
  v.push_back(0);
  return v;
}

std::vector<Rational> powers(int from, int to, int step) {
  std::vector<Rational> v;
  for (int k = from; k <= to; k += step) v.push_back(pow10(k));
  return v;
}

ExtremeFamily degeneracy(std::string name, std::string description, std::string quantity,
                         std::function<ExtremeCase(const Rational&)> make) {
  ExtremeFamily f;
  f.name = std::move(name);
  f.description = std::move(description);
  f.parameter = "epsilon";
  f.degenerate_quantity = std::move(quantity);
  f.make = std::move(make);
  f.quick_values = epsilons({0, 2, 4, 6, 8, 10, 12, 14, 16});
  f.full_values = epsilons({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 18, 20, 25, 30, 40, 60, 100});
  return f;
}

std::vector<ExtremeFamily> make_families() {
  const V ja = perp(kA), jb = perp(kB);
  const Rational half = Rational(1) / 2;
  std::vector<ExtremeFamily> fs;
  {
    ExtremeFamily f = degeneracy("dead_centre", "r_{n-1} = -3/2 r_{n-2} + eps J r_{n-2}: D = 20 eps -> 0",
                                 "D = r_{n-2} x r_{n-1}", [=](const Rational& e) {
                                   return pentagon_with(kR1, kR2, kA, scaled(Rational(-3) / 2, kA) + scaled(e, ja));
                                 });
    f.singular = true;
    fs.push_back(std::move(f));
  }
  fs.push_back(degeneracy("q_infinity", "r_1 = -r_{n-1} + r_{n-2}/2 + eps J r_{n-2}: Q_1 -> infinity", "Q_1",
                          [=](const Rational& e) {
                            return pentagon_with(scaled(-1, kB) + scaled(half, kA) + scaled(e, ja), kR2, kA, kB);
                          }));
  fs.push_back(degeneracy("beta_zero", "r_1 = r_{n-2}/2 + eps J r_{n-2}: beta_1 -> 0 (Q_1 -> K'_1, P'_1 -> K_{n-1})",
                          "beta_1", [=](const Rational& e) {
                            return pentagon_with(scaled(half, kA) + scaled(e, ja), kR2, kA, kB);
                          }));
  fs.push_back(degeneracy("p_infinity", "r_1 = r_{n-1}/2 + eps J r_{n-1}: P'_1 -> infinity", "P'_1",
                          [=](const Rational& e) {
                            return pentagon_with(scaled(half, kB) + scaled(e, jb), kR2, kA, kB);
                          }));
  fs.push_back(degeneracy("q_at_k", "r_1 = -r_{n-2} + r_{n-1}/2 + eps J r_{n-1}: Q_1 -> K_{n-1}", "beta_1",
                          [=](const Rational& e) {
                            return pentagon_with(scaled(-1, kA) + scaled(half, kB) + scaled(e, jb), kR2, kA, kB);
                          }));
  fs.push_back(degeneracy("kprime_at_kn", "r_1 = -(r_{n-2} + r_{n-1}) + eps (1, 1): K'_1 -> K_n", "Q_1",
                          [=](const Rational& e) {
                            return pentagon_with(scaled(-1, kA + kB) + V{e, e}, kR2, kA, kB);
                          }));
  {
    ExtremeFamily f;
    f.name = "length_ratio";
    f.description = "r_{n-2} scaled by s: coupler length ratio s";
    f.parameter = "s";
    f.make = [=](const Rational& s) { return pentagon_with(kR1, kR2, scaled(s, kA), kB); };
    f.quick_values = powers(-8, 8, 4);
    f.full_values = powers(-8, 8, 1);
    fs.push_back(std::move(f));
  }
  {
    ExtremeFamily f;
    f.name = "omega_scale";
    f.description = "omega_1 = 2 s, omega_2 = -1: angular velocity ratio s";
    f.parameter = "s";
    f.make = [=](const Rational& s) {
      ExtremeCase c = pentagon_with(kR1, kR2, kA, kB);
      c.rates.omega[0] = 2 * s;
      return c;
    };
    f.quick_values = powers(-6, 6, 3);
    f.full_values = powers(-6, 6, 1);
    fs.push_back(std::move(f));
  }
  {
    ExtremeFamily f;
    f.name = "large_n";
    f.description = "scattered random polygon (seed 1966, index 0) with n sides";
    f.parameter = "n";
    f.make = [](const Rational& n) {
      const RandomPolygonCase c = generate_random_polygon(1966, static_cast<int>(cln::double_approx(n)), 0);
      return ExtremeCase{c.polygon, c.rates};
    };
    for (int n : {5, 10, 20, 50}) f.quick_values.push_back(n);
    for (int n : {5, 10, 20, 50, 100, 200, 500, 1000}) f.full_values.push_back(n);
    fs.push_back(std::move(f));
  }
  return fs;
}

}  // namespace

const std::vector<ExtremeFamily>& extreme_families() {
  static const std::vector<ExtremeFamily> families = make_families();
  return families;
}

const ExtremeFamily* find_extreme_family(const std::string& name) {
  for (const ExtremeFamily& f : extreme_families())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace linkproof
