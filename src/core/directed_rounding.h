// Directed rounding without changing the FPU's rounding mode: one step to the next float.
//
// The hardware rounds every double and long double operation to nearest (the default mode,
// which linkproof never changes). For an operation whose exact result is x and whose rounded
// result is r = RN(x):
//
//     next_up(r) >= x      and      next_down(r) <= x,
//
// because no float lies strictly between r and x (r is the nearest one), so x lies in
// [next_down(r), next_up(r)]. This holds in the whole range: for subnormal results (the floats
// there are evenly spaced by the least subnormal, and next_up(0) is that least subnormal), and
// at overflow (RN(x) = +inf, and next_up(+inf) = +inf). So `next_up(a + b)`, `next_up(a * b)`,
// `next_up(a / b)` are upward-rounded operations, at the cost of one integer step on the bit
// pattern instead of two writes of the control registers (fesetround) and `-frounding-math`
// for the whole library.
//
// Preconditions (what the compiler and the platform must keep): rounding to nearest, no
// flush-to-zero or denormals-are-zero (never -ffast-math / -Ofast), x87 precision control at
// 64 bits for long double (the Linux default), no contraction of a*b+c into an FMA across a
// next_up (a step on the bit pattern is not a floating-point operation, so it cannot be).
//
// Both steps are defined for every input: next_up leaves +inf, NaN and negative numbers
// (including -0) unchanged, next_down leaves +0, +inf, NaN and negative numbers unchanged.
// Radii are non-negative, and a divisor's margin (next_down) that is not positive means
// "unbounded" whatever its exact value, so nothing else is ever needed.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

namespace linkproof {

/// The least double above x, for x >= +0 finite; x itself for +inf, NaN and negative x.
inline double next_up(double x) {
  const std::uint64_t b = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(b + (b < 0x7ff0000000000000ULL ? 1 : 0));
}
/// The greatest double below x, for x > 0 finite; x itself for +0, +inf, NaN and negative x.
inline double next_down(double x) {
  const std::uint64_t b = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(b - (b - 1 < 0x7fefffffffffffffULL ? 1 : 0));
}

namespace directed_detail {
// x87 extended format: a 64-bit significand with an explicit integer bit, then 15 exponent
// bits and the sign (bytes 8-9); the remaining bytes of the 16-byte object are padding.
static_assert(std::numeric_limits<long double>::digits == 64, "long double must be the x87 80-bit format");
struct Extended {
  std::uint64_t significand;
  std::uint16_t sign_exponent;
};
inline Extended bits_of(long double x) {
  Extended e{};
  std::memcpy(&e.significand, &x, 8);
  std::memcpy(&e.sign_exponent, reinterpret_cast<const char*>(&x) + 8, 2);
  return e;
}
inline long double from_bits(Extended e) {
  long double x = 0;
  std::memcpy(&x, &e.significand, 8);
  std::memcpy(reinterpret_cast<char*>(&x) + 8, &e.sign_exponent, 2);
  return x;
}
constexpr std::uint64_t kIntegerBit = std::uint64_t{1} << 63;
}  // namespace directed_detail

/// The least long double above x, for x >= +0 finite; x itself for +inf, NaN and negative x.
inline long double next_up(long double x) {
  using namespace directed_detail;
  Extended e = bits_of(x);
  if (e.sign_exponent >= 0x7fff) return x;  // sign set, or exponent all ones (inf, NaN)
  if (++e.significand == 0) {               // 1.11..1 2^k -> 1.0 2^(k+1) (exponent 0x7fff: +inf)
    e.significand = kIntegerBit;
    ++e.sign_exponent;
  } else if (e.sign_exponent == 0 && e.significand == kIntegerBit) {
    e.sign_exponent = 1;  // the greatest subnormal's successor is the least normal number
  }
  return from_bits(e);
}
/// The greatest long double below x, for x > 0 finite; x itself for +0, +inf, NaN and negative x.
inline long double next_down(long double x) {
  using namespace directed_detail;
  Extended e = bits_of(x);
  if (e.sign_exponent >= 0x7fff || (e.sign_exponent == 0 && e.significand == 0)) return x;
  if (e.sign_exponent != 0 && e.significand == kIntegerBit) {  // a power of two
    --e.sign_exponent;
    e.significand = e.sign_exponent == 0 ? kIntegerBit - 1 : ~std::uint64_t{0};
  } else {
    --e.significand;
  }
  return from_bits(e);
}

/// The least double >= x (x a non-negative long double or double; +inf above double's range).
template <class F>
double round_up_to_double(F x) {
  const double d = static_cast<double>(x);  // rounded to nearest
  return static_cast<F>(d) < x ? next_up(d) : d;
}

}  // namespace linkproof
