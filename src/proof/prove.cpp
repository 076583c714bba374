#include "proof/prove.h"

#include <algorithm>
#include <chrono>
#include <new>
#include <set>

#include "exceptional_set.h"
#include "core/symbolic_scalar.h"
#include "core/time_budget.h"
#include "proof/lift.h"
#include "symbolic/tape.h"
#include "rational_normal.h"
#include "symbolic_polygon.h"

namespace linkproof {

namespace {

using GiNaC::ex;
using ProveClock = std::chrono::steady_clock;
using namespace proof_detail;

double prove_seconds_since(ProveClock::time_point t) { return std::chrono::duration<double>(ProveClock::now() - t).count(); }

/// The per-n proof, with the sides named as `names` prints them in the exceptional set.
PerNProof prove_at(GroundTruthEngine& engine, const DataClaim& claim, int n, std::vector<std::string>* not_local,
                   std::vector<ExceptionalSet>* except, const SideNames& names, bool general) {
  const auto start = ProveClock::now();
  PerNProof r;
  r.n = n;
  const SymbolicPolygon sp = make_symbolic_polygon(n, names);
  const InputRates<ex> zero_rates{std::vector<ex>(static_cast<size_t>(n - 3), ex(0)),
                                  std::vector<ex>(static_cast<size_t>(n - 3), ex(0))};
  ZeroTestLog log;
  const PolygonContext<ex> ctx = build_polygon_context_from<ex>(engine, sp.polygon, zero_rates, false);
  std::vector<ex> compared, sides, claim_divisors, word_values;
  const std::string phase = "the per-n proof of " + claim.info.id + " at n = " + std::to_string(n);
  RationalNormalizer normalizer;  // shared by every coefficient: their common parts are normalised once
  const auto compare_at = [&](int j) {
    IndexBindings b;
    b.j = j;
    ClaimEvaluator<ex> eval(ctx, claim.reading);
    const RatePoly<ex> lhs = eval.scalar(claim.lhs, b);
    const RatePoly<ex> rhs = eval.scalar(claim.rhs, b);
    claim_divisors.insert(claim_divisors.end(), eval.divisors().begin(), eval.divisors().end());
    word_values.insert(word_values.end(), eval.word_values().begin(), eval.word_values().end());
    if (not_local) {
      for (const auto& v : eval.locality_violations()) not_local->push_back(v);
      if (lhs.degree() > 2 || rhs.degree() > 2) not_local->push_back("degree > 2 in the rates");
    }
    std::set<Monomial> monomials;
    for (const auto& t : lhs.terms()) monomials.insert(t.first);
    for (const auto& t : rhs.terms()) monomials.insert(t.first);
    for (const Monomial& m : monomials) {
      TimeBudget::check(phase);
      const ex l = lhs.coefficient(m), rr = rhs.coefficient(m);
      const ex d = l - rr;
      compared.push_back(d);
      sides.push_back(l);
      sides.push_back(rr);
      ++r.monomials;
      if (r.first_nonzero.empty() && !normalizer.is_zero(d))
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
  if (except && r.proved) {
    // At the base of a proof for every n, inputs 1 and 2 stand for any j and l.
    GiNaC::exmap l_as_j;
    if (general && n >= 5) {
      l_as_j[sp.x[1]] = sp.x[0];
      l_as_j[sp.y[1]] = sp.y[0];
    }
    // The divisors still in the compared expressions as built, those of the claim's own
    // expression and those of every word it was written with (which GiNaC may have cancelled
    // on the spot: D/D = 1, D*omega_out = N).
    std::vector<ex> divisors = divisors_in(sides);
    divisors.insert(divisors.end(), claim_divisors.begin(), claim_divisors.end());
    const std::vector<ex> of_words = divisors_in(word_values);
    divisors.insert(divisors.end(), of_words.begin(), of_words.end());
    *except = exceptional_sets(ctx, divisors, names, general ? &l_as_j : nullptr, normalizer);
  }
  r.seconds = prove_seconds_since(start);
  return r;
}

std::string list_of(const std::vector<int>& ns) {
  std::string s;
  for (size_t i = 0; i < ns.size(); ++i) {
    // Runs of consecutive n are written a..b.
    size_t k = i;
    while (k + 1 < ns.size() && ns[k + 1] == ns[k] + 1) ++k;
    s += (s.empty() ? "" : ", ") + std::to_string(ns[i]) + (k > i + 1 ? ".." + std::to_string(ns[k]) : "");
    if (k == i + 1) s += ", " + std::to_string(ns[k]);
    i = k;
  }
  return s;
}

std::string range_of(const ClaimInfo& info) {
  if (info.max_n == info.min_n) return "n = " + std::to_string(info.min_n);
  return "every n >= " + std::to_string(info.min_n) + (info.max_n ? " and <= " + std::to_string(info.max_n) : "");
}

void merge_except(std::vector<ExceptionalSet>& into, const std::vector<ExceptionalSet>& more) {
  for (const auto& e : more) {
    // One entry per degeneracy (at several n, or at n = 4 and the base, the same family).
    const bool seen = std::any_of(into.begin(), into.end(), [&](const ExceptionalSet& x) {
      return x.meaning == e.meaning && (x.polynomial == e.polynomial || e.meaning.rfind("unnamed", 0) != 0);
    });
    if (!seen) into.push_back(e);
  }
}

}  // namespace

std::string to_string(ProofVerdict v) {
  switch (v) {
    case ProofVerdict::Proved: return "proved";
    case ProofVerdict::ProvedGenerically: return "proved_generically";
    case ProofVerdict::ProvedFor: return "proved_for";
    case ProofVerdict::Disproved: return "disproved";
    case ProofVerdict::HoldsOnSamples: return "holds_on_samples";
    case ProofVerdict::HoldsWithProbability: return "holds_with_probability";
    case ProofVerdict::Error: return "error";
  }
  return "error";
}

bool ProofResult::is_as_expected() const {
  if (expected == Expectation::Fails) return verdict == ProofVerdict::Disproved;
  switch (verdict) {
    case ProofVerdict::Proved:
    case ProofVerdict::ProvedGenerically: return true;
    case ProofVerdict::ProvedFor:
    case ProofVerdict::HoldsOnSamples: return true;
    case ProofVerdict::HoldsWithProbability: return true;
    case ProofVerdict::Disproved:
    case ProofVerdict::Error: return false;
  }
  return false;
}

PerNProof prove_for_n(GroundTruthEngine& engine, const DataClaim& claim, int n, std::vector<std::string>* not_local,
                      std::vector<ExceptionalSet>* except) {
  return prove_at(engine, claim, n, not_local, except, numbered_side, false);
}

ProofResult prove_claim(GroundTruthEngine& engine, const DataClaim& claim, const ProveOptions& o) {
  const auto start = ProveClock::now();
  ProofResult r;
  r.id = claim.info.id;
  r.expected = claim.info.expected;
  const int lo = claim.info.min_n, hi = claim.info.max_n;  // hi = 0: no upper bound
  const auto clipped_search = [&](CounterexampleSearch s) {
    if (o.only_n) s.n_min = s.n_max = *o.only_n;
    return s;
  };
  try {
    bool disproved = false;
    bool all_n = false;  // the proofs cover every n of the claim's range
    const auto prove_n = [&](int n, std::vector<std::string>* not_local, const SideNames& names, bool general) {
      std::vector<ExceptionalSet> except;
      PerNProof p = prove_at(engine, claim, n, not_local, &except, names, general);
      r.per_n.push_back(p);
      if (!p.proved) {
        disproved = true;
        return false;
      }
      r.proved_n.push_back(n);
      merge_except(r.except, except);
      return true;
    };
    if (o.only_n) {
      if (!claim.info.applies_to(*o.only_n))
        throw InputError("<api>", "only_n", "claim " + claim.info.id + " does not apply to n = " + std::to_string(*o.only_n));
      prove_n(*o.only_n, nullptr, numbered_side, false);
      all_n = lo == hi;
    } else {
      // 1. The proofs the lift needs: n = 4 on its own (only the j-terms exist there), and the
      //    base n = max(lo, 5) where the sides of a pair and the last two are independent.
      const int base = std::max(lo, 5);
      const bool has_base = hi == 0 || hi >= base;
      if (lo == 4 && !prove_n(4, nullptr, general_side, true)) {
      } else if (has_base && prove_n(base, &r.not_local, base == 5 ? general_side : numbered_side, base == 5)) {
        // 2. The lift lemma for this claim, checked at an n with other sides (lift.h).
        if (hi == 0 || hi >= 6) {
          const LiftCheck lift = check_lift_lemma(engine, claim, std::max(lo, 6));
          for (const auto& v : lift.violations)
            if (std::find(r.not_local.begin(), r.not_local.end(), v) == r.not_local.end()) r.not_local.push_back(v);
          if (r.not_local.empty()) {
            all_n = true;
            r.argument = {
                "1. Per-n proof at n = " + std::to_string(base) + ": the sides and K_n are independent generic vectors "
                "(printed: r_j, r_l for two inputs, r_{n-2}, r_{n-1}, K_n = (px, py)); every coefficient of lhs - rhs "
                "(of omega-dot_j, omega_j^2, omega_j omega_l and the rate-free part) is identically 0 as a rational "
                "function of them (" + std::to_string(r.per_n.back().monomials) + " coefficients, GiNaC normal()).",
                "2. Lift lemma, checked for this claim (lift.h): (a) uniformity: its indices are j, l, n, n-1, n-2, every "
                "term of a sum carries rates of the sum's indices, degree <= 2 in the rates; (b) at n = " +
                    std::to_string(lift.n) + ", every one of its " + std::to_string(lift.coefficients) +
                    " coefficients, as evaluated (construction under the claim's reading, engine truth), reads no "
                    "side other than those of its monomial and r_{n-2}, r_{n-1}, K_n (symbol dependence, zero-tested).",
                "3. Hence at every n >= " + std::to_string(base) + " each coefficient of lhs - rhs is the function of step 1 "
                "with its sides substituted: identically 0.",
                lo == 4 ? "4. n = 4 (only the j-terms exist): its own per-n proof, above." : "4. The range starts at n = " +
                                                                                                  std::to_string(lo) + "."};
          }
        }
      }
      // 3. Per-n proofs for the rest of the range while the budget lasts: a finite range is
      //    covered by them when the lift does not apply; otherwise they re-check it, if asked.
      const auto ladder_start = ProveClock::now();
      for (int n = lo; !disproved && (!all_n || o.recheck_proved) && (hi == 0 || n <= hi); ++n) {
        if (std::find(r.proved_n.begin(), r.proved_n.end(), n) != r.proved_n.end()) continue;
        if (o.n_max && n > o.n_max) break;
        if (prove_seconds_since(ladder_start) > o.ladder_seconds) break;
        prove_n(n, nullptr, numbered_side, false);
      }
      std::sort(r.proved_n.begin(), r.proved_n.end());
      if (!all_n && hi != 0 && !disproved) all_n = static_cast<int>(r.proved_n.size()) == hi - lo + 1;
    }
    if (disproved) {
      CounterexampleSearch search = clipped_search(o.search);
      // A coefficient is not identically zero: rational points too, where integer ones miss it.
      search.rational_attempts_per_n = std::max(search.rational_attempts_per_n, 60);
      r.counterexample = find_counterexample(engine, claim, search);
      if (r.counterexample) {
        r.verdict = ProofVerdict::Disproved;
      } else {
        // A nonzero coefficient in generic coordinates, but no failing integer configuration
        // found: say so rather than claim either way.
        r.verdict = ProofVerdict::Error;
        r.error = "a coefficient of lhs - rhs is not identically zero (" + r.per_n.back().first_nonzero +
                  " at n = " + std::to_string(r.per_n.back().n) + "), but no exact counterexample was found";
      }
    } else {
      // A positive verdict only after the counterexample search found nothing (n = 4..8).
      CounterexampleSearch confirm = clipped_search(o.search);
      confirm.attempts_per_n = std::min(confirm.attempts_per_n, 10);
      confirm.shrink = true;
      r.counterexample = find_counterexample(engine, claim, confirm);
      if (r.counterexample && std::find(r.proved_n.begin(), r.proved_n.end(), r.counterexample->polygon.n()) ==
                                  r.proved_n.end() && !all_n) {
        r.verdict = ProofVerdict::Disproved;  // false at an n no proof covered
      } else if (r.counterexample) {
        r.verdict = ProofVerdict::Error;
        r.error = "internal inconsistency: the symbolic proof covers n = " +
                  std::to_string(r.counterexample->polygon.n()) + ", but an exact counterexample there fails";
      } else if (all_n) {
        r.verdict = r.except.empty() ? ProofVerdict::Proved : ProofVerdict::ProvedGenerically;
        r.scope = range_of(claim.info);
      } else {
        r.verdict = ProofVerdict::ProvedFor;
        r.scope = "n = " + list_of(r.proved_n) + " only (the claim's range: " + range_of(claim.info) + ")";
      }
    }
  } catch (const UndefinedQuantity& u) {
    // No symbolic form (|x| of an expression, for instance): exact instances decide.
    r.per_n.clear();
    r.proved_n.clear();
    r.except.clear();
    r.argument = {"no symbolic proof: " + std::string(u.what())};
    r.symbolic = false;
    r.counterexample = find_counterexample(engine, claim, clipped_search(o.search));
    if (r.counterexample) {
      r.verdict = ProofVerdict::Disproved;
    } else {
      r.verdict = ProofVerdict::Error;
      r.error = "no symbolic proof and no counterexample: " + std::string(u.what());
    }
  } catch (const std::bad_alloc&) {
    throw;  // out of memory (--max-memory-mb) ends the run: not an evaluation's error
  } catch (const std::exception& e) {
    refuse_if_ill_formed_user_claim(claim.info, e);  // a vector as a number, division by rates: exit 2
    r.verdict = ProofVerdict::Error;
    r.error = e.what();
  }
  r.seconds = prove_seconds_since(start);
  return r;
}

}  // namespace linkproof
