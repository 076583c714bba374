#include "linkproof/proof/prove.h"

#include <algorithm>

#include <chrono>
#include <map>
#include <set>

#include "linkproof/core/symbolic_scalar.h"
#include "linkproof/symbolic/loop_closure.h"
#include "linkproof/symbolic/tape.h"

namespace linkproof {

namespace {

using GiNaC::ex;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// The n-gon in generic coordinates: side r_k = (x_k, y_k) for k = 1..n-1 and K_n = (px, py);
/// joints K_n, K_{n-1} = K_n - r_{n-1}, ..., K_1 = K_2 - r_1 (side n closes the loop). The 2n
/// symbols are independent, so a rational function of them that is zero is zero for every
/// polygon where it is defined.
struct SymbolicPolygon {
  std::vector<GiNaC::realsymbol> x, y;  // [k-1]
  GiNaC::realsymbol px{"px"}, py{"py"};
  Polygon<ex> polygon;
  std::vector<ex> symbols() const {
    std::vector<ex> s(x.begin(), x.end());
    s.insert(s.end(), y.begin(), y.end());
    s.push_back(px);
    s.push_back(py);
    return s;
  }
};

SymbolicPolygon make_symbolic_polygon(int n) {
  SymbolicPolygon s;
  for (int k = 1; k <= n - 1; ++k) {
    s.x.emplace_back("x" + std::to_string(k));
    s.y.emplace_back("y" + std::to_string(k));
  }
  std::vector<Vec2<ex>> joints(static_cast<size_t>(n));
  joints[static_cast<size_t>(n - 1)] = {s.px, s.py};
  for (int k = n - 1; k >= 1; --k)
    joints[static_cast<size_t>(k - 1)] = {joints[static_cast<size_t>(k)].x - s.x[static_cast<size_t>(k - 1)],
                                          joints[static_cast<size_t>(k)].y - s.y[static_cast<size_t>(k - 1)]};
  s.polygon = Polygon<ex>(joints);
  return s;
}

/// The irreducible non-constant factors of a polynomial, up to sign.
std::vector<ex> irreducible_factors(const ex& p) {
  std::vector<ex> out;
  const ex f = GiNaC::factor(GiNaC::expand(p));
  const auto take = [&out](const ex& t) {
    ex base = GiNaC::is_exactly_a<GiNaC::power>(t) ? t.op(0) : t;
    if (GiNaC::is_exactly_a<GiNaC::numeric>(base)) return;
    out.push_back(base);
  };
  if (GiNaC::is_exactly_a<GiNaC::mul>(f))
    for (size_t i = 0; i < f.nops(); ++i) take(f.op(i));
  else
    take(f);
  return out;
}

bool same_up_to_constant(const ex& a, const ex& b) {
  return GiNaC::is_exactly_a<GiNaC::numeric>(GiNaC::normal(a / b));
}

/// Named degeneracies of SPEC A6 as polynomials in the symbolic polygon's coordinates: of the
/// sides (cheap), or of the construction's points (built only if a factor is still unnamed).
std::vector<std::pair<ex, std::string>> side_degeneracies(const PolygonContext<ex>& c) {
  std::vector<std::pair<ex, std::string>> v;
  const int n = c.n;
  const Vec2<ex> a = c.r(n - 2), b = c.r(n - 1);
  v.emplace_back(norm2(a), "r_{n-2} = 0: coincident joints");
  v.emplace_back(norm2(b), "r_{n-1} = 0: coincident joints");
  v.emplace_back(cross(a, b), "dead centre: D = r_{n-2} x r_{n-1} = 0 (the mechanism's singularity: the truth is undefined)");
  for (int j = 1; j <= n - 3; ++j) {
    const std::string s = std::to_string(j);
    const Vec2<ex> rj = c.r(j);
    v.emplace_back(cross(a, rj + b), "Q_" + s + " at infinity: r_{n-2} parallel to r_" + s + " + r_{n-1}");
    v.emplace_back(cross(rj, b), "P'_" + s + " at infinity: r_" + s + " parallel to r_{n-1}");
    v.emplace_back(cross(rj, a), "r_" + s + " parallel to r_{n-2}: Q_" + s + " = K'_" + s + ", beta_" + s + " undefined");
    v.emplace_back(norm2(rj + a + b), "K'_" + s + " = K_n: the ground line K_nK'_" + s + " is undefined");
    v.emplace_back(norm2(rj), "r_" + s + " = 0: coincident joints");
  }
  return v;
}

std::vector<std::pair<ex, std::string>> construction_degeneracies(const PolygonContext<ex>& c) {
  std::vector<std::pair<ex, std::string>> v;
  const int n = c.n;
  const auto numerator_of = [](const ex& e) { return GiNaC::numer(GiNaC::normal(e)); };
  for (int j = 1; j <= n - 3; ++j) {
    const std::string s = std::to_string(j);
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

/// Factors of the quantities the evaluation divided by (tested for zero first: construction
/// steps, tape quotients) and of the sides' denominators, each named if it matches a named
/// degeneracy.
std::vector<ExceptionalSet> exceptional_sets(const PolygonContext<ex>& c, const std::vector<ex>& tested,
                                             const std::vector<ex>& sides) {
  std::vector<ex> factors;
  const auto add_factors = [&](const ex& p) {
    for (const ex& f : irreducible_factors(p)) {
      bool seen = false;
      for (const ex& g : factors) seen = seen || same_up_to_constant(f, g);
      if (!seen) factors.push_back(f);
    }
  };
  for (const ex& e : tested) {
    add_factors(GiNaC::numer(e));
    add_factors(GiNaC::denom(e));
  }
  for (const ex& e : sides) add_factors(GiNaC::denom(GiNaC::normal(e)));
  std::vector<std::string> meanings(factors.size());
  const auto name_from = [&](const std::vector<std::pair<ex, std::string>>& degeneracies) {
    std::vector<std::pair<ex, std::string>> named;
    for (auto& [poly, meaning] : degeneracies)
      for (const ex& f : irreducible_factors(poly)) named.emplace_back(f, meaning);
    for (size_t i = 0; i < factors.size(); ++i)
      for (const auto& [g, m] : named)
        if (meanings[i].empty() && same_up_to_constant(factors[i], g)) meanings[i] = m;
  };
  name_from(side_degeneracies(c));
  if (std::any_of(meanings.begin(), meanings.end(), [](const std::string& m) { return m.empty(); }))
    name_from(construction_degeneracies(c));
  std::vector<ExceptionalSet> out;
  for (size_t i = 0; i < factors.size(); ++i)
    out.push_back({ScalarTraits<ex>::to_string(factors[i]),
                   meanings[i].empty() ? "unnamed: a factor of a denominator" : meanings[i]});
  return out;
}

}  // namespace

std::string to_string(ProofVerdict v) {
  switch (v) {
    case ProofVerdict::Proved: return "proved";
    case ProofVerdict::ProvedGenerically: return "proved_generically";
    case ProofVerdict::Disproved: return "disproved";
    case ProofVerdict::HoldsOnSamples: return "holds_on_samples";
    case ProofVerdict::Error: return "error";
  }
  return "error";
}

bool ProofResult::is_as_expected() const {
  if (verdict == ProofVerdict::Error) return false;
  if (expected == Expectation::Fails) return verdict == ProofVerdict::Disproved;
  return verdict != ProofVerdict::Disproved;
}

PerNProof prove_for_n(GroundTruthEngine& engine, const DataClaim& claim, int n, std::vector<std::string>* not_local,
                      std::vector<ExceptionalSet>* except) {
  const auto start = Clock::now();
  PerNProof r;
  r.n = n;
  const SymbolicPolygon sp = make_symbolic_polygon(n);
  const InputRates<ex> zero_rates{std::vector<ex>(static_cast<size_t>(n - 3), ex(0)),
                                  std::vector<ex>(static_cast<size_t>(n - 3), ex(0))};
  ZeroTestLog log;
  const PolygonContext<ex> ctx = build_polygon_context_from<ex>(engine, sp.polygon, zero_rates, false);
  std::vector<ex> compared, sides;
  const auto compare_at = [&](int j) {
    IndexBindings b;
    b.j = j;
    ClaimEvaluator<ex> eval(ctx, claim.reading);
    const RatePoly<ex> lhs = eval.scalar(claim.lhs.expression(), b);
    const RatePoly<ex> rhs = eval.scalar(claim.rhs.expression(), b);
    if (not_local) {
      for (const auto& v : eval.locality_violations()) not_local->push_back(v);
      if (lhs.degree() > 2 || rhs.degree() > 2) not_local->push_back("degree > 2 in the rates");
    }
    std::set<Monomial> monomials;
    for (const auto& t : lhs.terms()) monomials.insert(t.first);
    for (const auto& t : rhs.terms()) monomials.insert(t.first);
    for (const Monomial& m : monomials) {
      const ex l = lhs.coefficient(m), rr = rhs.coefficient(m);
      const ex d = l - rr;
      compared.push_back(d);
      sides.push_back(l);
      sides.push_back(rr);
      ++r.monomials;
      if (r.first_nonzero.empty() && !ScalarTraits<ex>::is_zero(d))
        r.first_nonzero = (j ? "j=" + std::to_string(j) + ": " : "") + monomial_label(m);
    }
  };
  if (claim.for_each_j)
    for (int j = 1; j <= n - 3; ++j) compare_at(j);
  else
    compare_at(0);
  r.proved = r.first_nonzero.empty();
  for (const ex& e : compared) r.tree_size += expression_tree_size(e);
  r.dag_size = Tape(compared, sp.symbols(), "claim").size();
  // A copy: naming the factors may build the construction, which logs zero tests of its own.
  const std::vector<ex> tested = log.tested();
  if (except && r.proved) *except = exceptional_sets(ctx, tested, sides);
  r.seconds = since(start);
  return r;
}

ProofResult prove_claim(GroundTruthEngine& engine, const DataClaim& claim, const ProveOptions& o) {
  const auto start = Clock::now();
  ProofResult r;
  r.id = claim.info.id;
  r.expected = claim.info.expected;
  const auto search = [&](const CounterexampleSearch& s) {
    r.counterexample = find_counterexample(engine, claim, s);
    if (r.counterexample) r.verdict = ProofVerdict::Disproved;
  };
  try {
    const int lo = claim.info.min_n;
    const int hi = claim.info.max_n;
    bool proved_somewhere = false, disproved = false;
    if (o.only_n) {
      if (!claim.info.applies_to(*o.only_n))
        throw InputError("<command line>", "--n", "claim " + claim.info.id + " does not apply to n = " + std::to_string(*o.only_n));
      PerNProof p = prove_for_n(engine, claim, *o.only_n, nullptr, &r.except);
      r.per_n.push_back(p);
      r.scope = "n = " + std::to_string(*o.only_n);
      proved_somewhere = p.proved;
      disproved = !p.proved;
    } else {
      // For every n: the proof at n = 5 (or at the claim's only n) and the lifting argument.
      const int base = hi == 0 ? std::max(lo, 5) : lo;
      PerNProof p = prove_for_n(engine, claim, base, &r.not_local, &r.except);
      r.per_n.push_back(p);
      disproved = !p.proved;
      if (p.proved) {
        proved_somewhere = true;
        if (hi != 0 && hi == lo) {
          r.scope = "n = " + std::to_string(lo);
          r.argument.push_back("every coefficient of lhs - rhs at n = " + std::to_string(lo) +
                               " is identically 0 in generic coordinates (" + std::to_string(p.monomials) + " coefficients)");
        } else if (r.not_local.empty()) {
          r.scope = "every n >= " + std::to_string(lo) + (hi ? " and <= " + std::to_string(hi) : "");
          r.argument = {
              "1. At n = 5 the sides r_1..r_4 and K_5 are independent generic vectors; every coefficient of lhs - rhs "
              "(of omega-dot_j, omega_j^2, omega_j omega_l, and the rate-free part) is identically 0 as a rational "
              "function of them (" + std::to_string(p.monomials) + " coefficients, GiNaC normal()).",
              "2. The exact omega-dot_{n-1,n}, omega-dot_{n-2,n} solve sum_k (omega-dot_k J r_k - omega_k^2 r_k) = 0 "
              "by Cramer's rule on the columns J r_{n-2}, J r_{n-1}: each term of the sum involves one side, and "
              "omega_{n-2}, omega_{n-1} are sums of one-side terms, so the coefficient of a monomial in the input "
              "rates is one function of the sides it names and r_{n-2}, r_{n-1}, the same at every n.",
              "3. The claim is local in the same sense: its indices are j, l, n, n-1, n-2, every term of a sum "
              "carries rates of the sum's indices, and it has degree <= 2 in the rates; the construction of "
              "four-bar j uses r_j, r_{n-2}, r_{n-1} and K_n only.",
              "4. Hence at any n the coefficient of omega-dot_j, omega_j^2 (and of omega_j omega_l) in lhs - rhs is the "
              "function of step 1 with (r_1, r_2, r_3, r_4, K_5) := (r_j, r_l, r_{n-2}, r_{n-1}, K_n): identically 0.",
              "5. n = 4 has only the j-terms, which step 1 covers. Per-n proofs below re-check the whole identity directly."};
        } else {
          r.scope = "n = " + std::to_string(base);
        }
      }
      // The per-n ladder: the whole identity at n = lo, lo+1, ... while the budget lasts.
      const auto ladder_start = Clock::now();
      for (int n = lo; !disproved && (hi == 0 || n <= hi); ++n) {
        if (o.n_max && n > o.n_max) break;
        if (since(ladder_start) > o.ladder_seconds) break;
        if (n == base) continue;
        PerNProof q = prove_for_n(engine, claim, n);
        r.per_n.push_back(q);
        if (!q.proved) disproved = true;
      }
      if (!r.not_local.empty() && !disproved) {
        int top = lo;
        for (const auto& q : r.per_n) top = std::max(top, q.n);
        r.scope = "n = " + std::to_string(lo) + ".." + std::to_string(top) + " (no proof for every n: the claim is not local)";
      }
    }
    if (disproved) {
      CounterexampleSearch s = o.search;
      if (o.only_n) s.n_min = s.n_max = *o.only_n;
      r.counterexample = find_counterexample(engine, claim, s);
      if (r.counterexample) {
        r.verdict = ProofVerdict::Disproved;
      } else {
        // A nonzero coefficient in generic coordinates, but no failing integer configuration
        // found: say so rather than claim either way.
        r.verdict = ProofVerdict::Error;
        r.error = "a coefficient of lhs - rhs is not identically zero, but no exact counterexample was found";
      }
    } else if (proved_somewhere) {
      r.verdict = r.except.empty() ? ProofVerdict::Proved : ProofVerdict::ProvedGenerically;
    }
  } catch (const UndefinedQuantity& u) {
    // No symbolic form (|x| of an expression, for instance): exact instances decide.
    r.per_n.clear();
    r.argument = {"no symbolic proof: " + std::string(u.what())};
    CounterexampleSearch s = o.search;
    if (o.only_n) s.n_min = s.n_max = *o.only_n;
    search(s);
    if (!r.counterexample) {
      r.verdict = ProofVerdict::Error;
      r.error = "no symbolic proof and no counterexample: " + std::string(u.what());
    }
  } catch (const std::exception& e) {
    r.verdict = ProofVerdict::Error;
    r.error = e.what();
  }
  r.seconds = since(start);
  return r;
}

}  // namespace linkproof
