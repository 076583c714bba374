#include "core/modular_point.h"

#include <cln/integer.h>
#include <cln/rational.h>

#include <functional>
#include <string>

namespace linkproof {

namespace {

using u64 = std::uint64_t;
__extension__ using u128 = unsigned __int128;
constexpr u64 P = ModularPoint::kPrime;

u64 reduce(u128 x) {
  u64 r = static_cast<u64>(x & P) + static_cast<u64>(x >> 61);
  r = (r & P) + (r >> 61);
  return r >= P ? r - P : r;
}
u64 add_mod(u64 a, u64 b) { return reduce(static_cast<u128>(a) + b); }
u64 mul_mod(u64 a, u64 b) { return reduce(static_cast<u128>(a) * b); }
u64 pow_mod(u64 a, u64 k) {
  u64 r = 1;
  for (; k; k >>= 1, a = mul_mod(a, a))
    if (k & 1) r = mul_mod(r, a);
  return r;
}
u64 inverse(u64 a) { return pow_mod(a, P - 2); }  // a != 0 (Fermat)

u64 splitmix(u64 x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

u64 integer_mod(const cln::cl_I& z) { return cln::cl_I_to_UQ(cln::mod(z, cln::cl_I(P))); }

}  // namespace

std::optional<u64> ModularPoint::value(const GiNaC::ex& e) {
  const GiNaC::basic* key = &GiNaC::ex_to<GiNaC::basic>(e);
  const auto it = memo_.find(key);
  if (it != memo_.end()) return it->second.second;
  const std::optional<u64> v = compute(e);
  memo_.emplace(key, std::make_pair(e, v));
  return v;
}

std::optional<u64> ModularPoint::compute(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    return splitmix(std::hash<std::string>{}(name) ^ seed_) % P;
  }
  if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric& q = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!q.is_rational()) return std::nullopt;
    const cln::cl_RA r = cln::the<cln::cl_RA>(q.to_cl_N());
    const u64 den = integer_mod(cln::denominator(r));
    if (den == 0) return std::nullopt;
    return mul_mod(integer_mod(cln::numerator(r)), inverse(den));
  }
  if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    const bool is_add = GiNaC::is_exactly_a<GiNaC::add>(e);
    u64 acc = is_add ? 0 : 1;
    for (size_t i = 0; i < e.nops(); ++i) {
      const auto v = value(e.op(i));
      if (!v) return std::nullopt;
      acc = is_add ? add_mod(acc, *v) : mul_mod(acc, *v);
    }
    return acc;
  }
  if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
    const auto b = value(e.op(0));
    if (!b) return std::nullopt;
    const cln::cl_I k = cln::the<cln::cl_I>(GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_cl_N());
    const u64 exponent = cln::cl_I_to_UQ(cln::mod(cln::abs(k), cln::cl_I(P - 1)));  // Fermat, for b != 0
    if (cln::minusp(k)) {
      if (*b == 0) return std::nullopt;  // a denominator vanishes at the point
      return pow_mod(inverse(*b), exponent);
    }
    if (*b == 0) return cln::zerop(k) ? 1 : 0;
    return pow_mod(*b, exponent);
  }
  return std::nullopt;
}

}  // namespace linkproof
