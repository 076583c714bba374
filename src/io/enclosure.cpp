#include "enclosure.h"

#include <cln/integer.h>
#include <cln/rational.h>

#include <algorithm>
#include <map>

#include "linkproof/core/error.h"

namespace linkproof::placement {

namespace {

using cln::cl_I;

Rational pow2(long e) {
  return e >= 0 ? Rational(cln::ash(cl_I(1), e)) : Rational(1) / Rational(cln::ash(cl_I(1), -e));
}

// A non-exact value's midpoint rounded to a.bits significant bits (the change goes into the
// radius), and its radius rounded up to 32 significant bits: the rationals stay short.
Enclosure rounded(Enclosure a) {
  if (cln::zerop(a.rad)) return a;
  if (!cln::zerop(a.mid)) {
    const Rational m = nearest_on_grid(a.mid, pow2(binary_exponent(a.mid) - a.bits));
    a.rad = a.rad + cln::abs(m - a.mid);
    a.mid = m;
  }
  const Rational grid = pow2(binary_exponent(a.rad) - 32);
  a.rad = Rational(cln::ceiling1(a.rad / grid)) * grid;
  return a;
}

int bits_of(const Enclosure& a, const Enclosure& b) { return std::max(a.bits, b.bits); }

// atan(1/m) in units of 2^-F: the fixed-point sum and a bound on its error in units.
// p_n = floor(p_{n-1} / m^2) falls short of 2^F / m^(2n+1) by less than 1/(1 - 1/m^2) < 2 units,
// each term floor(p_n / (2n+1)) by less than 3; the sum stops at the first p_N = 0, where the
// rest of the alternating series is below the exact p_N < 2. So the error is below 3 (N + 2).
struct FixedSum {
  cl_I sum, error;
};
FixedSum atan_of_inverse(long m, long F) {
  const cl_I m2 = cl_I(m) * cl_I(m);
  cl_I p = cln::floor1(cln::ash(cl_I(1), F), cl_I(m));
  cl_I sum = 0;
  long n = 0;
  for (;; ++n) {
    const cl_I term = cln::floor1(p, cl_I(2 * n + 1));
    sum = n % 2 == 0 ? sum + term : sum - term;
    if (cln::zerop(p)) break;
    p = cln::floor1(p, m2);
  }
  return {sum, cl_I(3 * (n + 2))};
}

// sum_n (-1)^n y^(2n + first) / (2n + first)! in units of 2^-F for y = Y / 2^F, |y| < 1
// (first = 0: cos y, 1: sin y), and a bound on its error in units. Term t_n = floor(t_{n-1} y^2 /
// ((2n - 1 + first)(2n + first))) falls short of the exact term by less than n units (each step
// adds at most one, and multiplying by y^2 / (...) < 1 shrinks what came before); the sum stops
// at the first t_N = 0, where the rest of the alternating, decreasing series is below the exact
// t_N < N. So the error is below N (N + 1) / 2 + N <= (N + 2)^2.
FixedSum taylor(const cl_I& Y, long F, int first) {
  const cl_I Y2 = Y * Y, scale = cln::ash(cl_I(1), 2 * F);
  cl_I t = first == 0 ? cln::ash(cl_I(1), F) : cln::abs(Y);
  cl_I sum = t;
  long n = 1;
  for (;; ++n) {
    t = cln::floor1(t * Y2, scale * cl_I((2 * n - 1 + first) * (2 * n + first)));
    sum = n % 2 == 1 ? sum - t : sum + t;
    if (cln::zerop(t)) break;
  }
  if (first == 1 && cln::minusp(Y)) sum = -sum;
  return {sum, cl_I(n + 2) * cl_I(n + 2)};
}

Enclosure from_fixed(const FixedSum& s, long F, const Rational& extra_radius, int bits) {
  return rounded({Rational(s.sum) * pow2(-F), Rational(s.error) * pow2(-F) + extra_radius, bits});
}

}  // namespace

bool Enclosure::is_exact() const { return cln::zerop(rad); }

long binary_exponent(const Rational& q) {
  if (cln::zerop(q)) return 0;
  return static_cast<long>(cln::integer_length(cln::abs(cln::numerator(q)))) -
         static_cast<long>(cln::integer_length(cln::denominator(q)));
}

Rational nearest_on_grid(const Rational& m, const Rational& grid) { return Rational(cln::round1(m / grid)) * grid; }

Enclosure operator+(const Enclosure& a, const Enclosure& b) {
  return rounded({a.mid + b.mid, a.rad + b.rad, bits_of(a, b)});
}

Enclosure operator-(const Enclosure& a, const Enclosure& b) {
  return rounded({a.mid - b.mid, a.rad + b.rad, bits_of(a, b)});
}

Enclosure operator-(const Enclosure& a) { return {-a.mid, a.rad, a.bits}; }

Enclosure operator*(const Enclosure& a, const Enclosure& b) {
  // |xy - ab| <= |a| |y - b| + |b| |x - a| + |x - a| |y - b|
  return rounded({a.mid * b.mid, cln::abs(a.mid) * b.rad + cln::abs(b.mid) * a.rad + a.rad * b.rad, bits_of(a, b)});
}

Enclosure divide(const Enclosure& a, const Enclosure& b) {
  const Rational bm = cln::abs(b.mid);
  LINKPROOF_ASSERT(bm > b.rad, "division by an enclosure that contains 0");
  // x/y - a/b = ((x - a) b - a (y - b)) / (y b), and |y| >= |b| - r_b.
  return rounded({a.mid / b.mid, (a.rad * bm + cln::abs(a.mid) * b.rad) / ((bm - b.rad) * bm), bits_of(a, b)});
}

Enclosure sqrt_of(const Enclosure& a, int bits) {
  LINKPROOF_ASSERT(!cln::minusp(a.mid - a.rad), "sqrt of an enclosure that may be negative");
  if (a.is_exact()) {
    Rational root;
    if (cln::sqrtp(a.mid, &root)) return Enclosure::exact(root);
  }
  const int b = std::max(bits, a.bits);
  const Rational lo = a.mid - a.rad, hi = a.mid + a.rad;
  // floor(sqrt(floor(lo 4^k))) / 2^k <= sqrt(lo) and (floor(sqrt(ceil(hi 4^k))) + 1) / 2^k >
  // sqrt(hi); k gives about b significant bits of sqrt(hi).
  const long k = b + 2 - binary_exponent(hi) / 2;
  const Rational scale = pow2(2 * k), unit = pow2(-k);
  const Rational below = Rational(cln::isqrt(cln::floor1(lo * scale))) * unit;
  const Rational above = Rational(cln::isqrt(cln::ceiling1(hi * scale)) + 1) * unit;
  return rounded({(below + above) / 2, (above - below) / 2, b});
}

std::optional<int> decided_sign(const Enclosure& a) {
  if (a.is_exact()) return cln::zerop(a.mid) ? 0 : (cln::minusp(a.mid) ? -1 : 1);
  if (cln::plusp(a.mid - a.rad)) return 1;
  if (cln::minusp(a.mid + a.rad)) return -1;
  return std::nullopt;
}

Enclosure pi_enclosure(int bits) {
  thread_local std::map<int, Enclosure> computed;
  if (const auto it = computed.find(bits); it != computed.end()) return it->second;
  const long F = bits + 16;
  const FixedSum a5 = atan_of_inverse(5, F), a239 = atan_of_inverse(239, F);
  const FixedSum pi{16 * a5.sum - 4 * a239.sum, 16 * a5.error + 4 * a239.error};
  const Enclosure result = from_fixed(pi, F, 0, bits);
  computed.emplace(bits, result);
  return result;
}

CosSin cos_sin_of(const Enclosure& x, int bits) {
  if (x.is_exact() && cln::zerop(x.mid)) return {Enclosure::exact(1), Enclosure::exact(0)};
  const int b = std::max(bits, x.bits);
  LINKPROOF_ASSERT(cln::abs(x.mid) + x.rad <= pow2(30), "cos/sin of an argument beyond 2^30");
  // y = x - q pi/2 with q the nearest integer to x / (pi/2): |y| <= pi/4 plus roundings.
  const Enclosure half_pi = pi_enclosure(b + 40) * Enclosure::exact(Rational(1) / 2);
  const cl_I q = cln::round1(x.mid / half_pi.mid);
  const Enclosure y = x - Enclosure::exact(q) * half_pi;
  LINKPROOF_ASSERT(cln::abs(y.mid) < Rational(7) / 8, "argument reduction left |y| >= 7/8");
  const long F = b + 32;
  const cl_I Y = cln::round1(y.mid * pow2(F));
  // The series is summed at Y / 2^F; every y the enclosure stands for is within this of it, and
  // |cos' |, |sin' | <= 1.
  const Rational moved = y.rad + cln::abs(Rational(Y) * pow2(-F) - y.mid);
  const Enclosure c = from_fixed(taylor(Y, F, 0), F, moved, b), s = from_fixed(taylor(Y, F, 1), F, moved, b);
  switch (cln::cl_I_to_long(cln::mod(q, 4))) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

}  // namespace linkproof::placement
