#include "exceptional_set.h"

#include <algorithm>
#include <functional>
#include <string>
#include <unordered_set>
#include <utility>

#include "core/symbolic_scalar.h"

namespace linkproof::proof_detail {

namespace {

using GiNaC::ex;

/// The irreducible non-constant factors of a polynomial, up to sign.
std::vector<ex> irreducible_factors(const ex& p) {
  std::vector<ex> out;
  const ex f = GiNaC::factor(GiNaC::expand(p));
  const auto take = [&out](const ex& t) {
    const ex base = GiNaC::is_exactly_a<GiNaC::power>(t) ? t.op(0) : t;
    if (!GiNaC::is_exactly_a<GiNaC::numeric>(base)) out.push_back(base);
  };
  if (GiNaC::is_exactly_a<GiNaC::mul>(f))
    for (size_t i = 0; i < f.nops(); ++i) take(f.op(i));
  else
    take(f);
  return out;
}

bool same_up_to_constant(const ex& a, const ex& b) { return GiNaC::is_exactly_a<GiNaC::numeric>(GiNaC::normal(a / b)); }

using Named = NamedDegeneracies;

/// Named degeneracies of conventions §A6 as polynomials in the symbolic polygon's coordinates: of the
/// sides (cheap), or of the construction's points (built only if a factor is still unnamed).
Named side_degeneracies(const PolygonContext<ex>& c, const SideNames& names) {
  Named v;
  const int n = c.n;
  const Vec2<ex> a = c.r(n - 2), b = c.r(n - 1);
  v.emplace_back(norm2(a), "r_{n-2} = 0: coincident joints");
  v.emplace_back(norm2(b), "r_{n-1} = 0: coincident joints");
  v.emplace_back(cross(a, b), "dead centre: D = r_{n-2} x r_{n-1} = 0 (the mechanism's singularity: the truth is undefined)");
  for (int j = 1; j <= n - 3; ++j) {
    const std::string s = names(j, n);
    const Vec2<ex> rj = c.r(j);
    v.emplace_back(cross(a, rj + b), "Q_" + s + " at infinity: r_{n-2} parallel to r_" + s + " + r_{n-1}");
    v.emplace_back(cross(rj, b), "P'_" + s + " at infinity: r_" + s + " parallel to r_{n-1}");
    v.emplace_back(cross(rj, a), "r_" + s + " parallel to r_{n-2}: Q_" + s + " = K'_" + s + ", beta_" + s + " undefined");
    v.emplace_back(norm2(rj + a + b), "K'_" + s + " = K_n: the ground line K_nK'_" + s + " is undefined");
    v.emplace_back(norm2(rj), "r_" + s + " = 0: coincident joints");
  }
  return v;
}

Named construction_degeneracies(const PolygonContext<ex>& c, const SideNames& names, RationalNormalizer& normalizer) {
  Named v;
  const int n = c.n;
  const auto numerator_of = [&normalizer](const ex& e) { return normalizer.numerator(e); };
  for (int j = 1; j <= n - 3; ++j) {
    const std::string s = names(j, n);
    const auto& k = c.construction_for()[static_cast<size_t>(j - 1)];
    if (!k.q.has_value() || !k.p_prime.has_value()) continue;
    const Vec2<ex> q = k.q.get(), p = k.p_prime.get(), kn1 = c.polygon.joint(n - 1), kn = c.polygon.joint(n),
                   kn2 = c.polygon.joint(n - 2);
    v.emplace_back(numerator_of(norm2(kn - q)), "Q_" + s + " = K_n: the reference segment of i_{n-1," + s + "} is null");
    v.emplace_back(numerator_of(norm2(p - kn2)), "P'_" + s + " = K_{n-2}: the reference segment of i_{n-2," + s + "} is null");
    v.emplace_back(numerator_of(cross(kn1 - q, p - q)), "beta_" + s + " = 0 or pi: Q_" + s + ", K_{n-1}, P'_" + s + " collinear");
    v.emplace_back(numerator_of(norm2(kn1 - q)), "Q_" + s + " = K_{n-1}: the ray Q_" + s + "K_{n-1} is null");
    v.emplace_back(numerator_of(cross(kn1 - p, q - p)), "gamma_" + s + " = 0 or pi: P'_" + s + ", K_{n-1}, Q_" + s + " collinear");
    v.emplace_back(numerator_of(norm2(kn1 - p)), "P'_" + s + " = K_{n-1}: the ray P'_" + s + "K_{n-1} is null");
    v.emplace_back(numerator_of(norm2(p - q)), "P'_" + s + " = Q_" + s + ": a ray of beta_" + s + " and gamma_" + s + " is null");
  }
  return v;
}

/// The meaning with input l read as input j: the base of a proof for every n names both.
std::string as_input_j(std::string m) {
  for (size_t p = 0; (p = m.find("_l", p)) != std::string::npos; ++p)
    if (p + 2 == m.size() || !std::isalnum(static_cast<unsigned char>(m[p + 2]))) m[p + 1] = 'j';
  return m;
}

}  // namespace

std::vector<ex> divisors_in(const std::vector<ex>& expressions) {
  std::vector<ex> out;
  std::unordered_set<ex, std::hash<ex>, GiNaC::ex_is_equal> seen;
  std::vector<ex> stack(expressions.begin(), expressions.end());
  while (!stack.empty()) {
    const ex e = stack.back();
    stack.pop_back();
    if (GiNaC::is_exactly_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e) || !seen.insert(e).second) continue;
    if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_negative() && !GiNaC::is_exactly_a<GiNaC::numeric>(e.op(0)))
      out.push_back(e.op(0));
    for (size_t i = 0; i < e.nops(); ++i) stack.push_back(e.op(i));
  }
  return out;
}

std::vector<NamedFactor> divisor_factors(const std::vector<ex>& divisors,
                                         const std::vector<std::function<NamedDegeneracies()>>& named_lists,
                                         RationalNormalizer& normalizer, bool all_meanings) {
  // The divisors' numerators, each once.
  std::vector<ex> rest;
  for (const ex& d : divisors) {
    const ex p = normalizer.numerator(d);
    if (GiNaC::is_exactly_a<GiNaC::numeric>(p)) continue;
    if (std::none_of(rest.begin(), rest.end(), [&](const ex& q) { return q.is_equal(p); })) rest.push_back(p);
  }
  // Named factors are divided out exactly (cheap); only what is left is factored (factoring the
  // large numerators of the construction's divisors as a whole is what costs).
  std::vector<NamedFactor> factors;
  const auto known = [&factors](const ex& f) {
    return std::any_of(factors.begin(), factors.end(), [&](const NamedFactor& g) { return same_up_to_constant(f, g.factor); });
  };
  // A degeneracy with no common factor with any numerator divides none of them: not factored.
  const auto shares_a_factor = [&rest](const ex& poly) {
    const ex h = GiNaC::expand(poly);
    if (GiNaC::is_exactly_a<GiNaC::numeric>(h)) return false;
    return std::any_of(rest.begin(), rest.end(), [&h](const ex& p) {
      try {
        return !GiNaC::is_exactly_a<GiNaC::numeric>(GiNaC::gcd(p, h));
      } catch (const std::exception&) {
        return true;  // not a polynomial gcd can take: factored as before
      }
    });
  };
  const auto strip = [&](const Named& degeneracies) {
    Named named;
    for (const auto& [poly, meaning] : degeneracies)
      if (shares_a_factor(poly))
        for (const ex& f : irreducible_factors(poly)) named.emplace_back(GiNaC::expand(f), meaning);
    for (ex& p : rest)
      for (const auto& named_factor : named) {
        const ex& g = named_factor.first;  // not a structured binding: clang 14 cannot capture one
        ex q;
        bool used = false;
        while (!GiNaC::is_exactly_a<GiNaC::numeric>(p) && GiNaC::divide(p, g, q)) {
          p = q;
          used = true;
        }
        if (used && !known(g)) factors.push_back({g, named_factor.second});
      }
    // A factor already taken out that another degeneracy also divides.
    if (all_meanings)
      for (NamedFactor& f : factors)
        for (const auto& [g, meaning] : named)
          if (f.meaning.find(meaning) == std::string::npos && same_up_to_constant(f.factor, g)) f.meaning += "; " + meaning;
    rest.erase(std::remove_if(rest.begin(), rest.end(), [](const ex& p) { return GiNaC::is_exactly_a<GiNaC::numeric>(p); }),
               rest.end());
  };
  for (const auto& list : named_lists) {
    if (rest.empty()) break;
    strip(list());
  }
  for (const ex& p : rest)
    for (const ex& f : irreducible_factors(p))
      if (!known(f)) factors.push_back({f, ""});
  return factors;
}

std::vector<ExceptionalSet> exceptional_sets(const PolygonContext<ex>& c, const std::vector<ex>& divisors,
                                             const SideNames& names, const GiNaC::exmap* l_as_j,
                                             RationalNormalizer& normalizer) {
  const std::vector<NamedFactor> named = divisor_factors(
      divisors, {[&] { return side_degeneracies(c, names); }, [&] { return construction_degeneracies(c, names, normalizer); }},
      normalizer);
  std::vector<ex> factors;
  std::vector<std::string> meanings;
  for (const NamedFactor& f : named) factors.push_back(f.factor), meanings.push_back(f.meaning);
  std::vector<ExceptionalSet> out;
  std::vector<std::string> kept;
  for (size_t i = 0; i < factors.size(); ++i) {
    std::string meaning = meanings[i].empty() ? "unnamed: a factor of a divisor" : meanings[i];
    ex factor = factors[i];
    if (l_as_j && !meanings[i].empty()) {
      const std::string general = as_input_j(meaning);
      if (general != meaning) {  // about l only: the same family as j's
        meaning = general;
        factor = factor.subs(*l_as_j);
      }
      if (std::find(kept.begin(), kept.end(), meaning) != kept.end()) continue;
      kept.push_back(meaning);
    }
    out.push_back({ScalarTraits<ex>::to_string(factor), meaning});
  }
  return out;
}

}  // namespace linkproof::proof_detail
