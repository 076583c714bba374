#include "proof/mechanism_proof.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <unordered_map>

#include "check/random_polygon.h"
#include "core/symbolic_scalar.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"
#include "mechanism/mechanism_solve.h"
#include "mechanism/mechanism_vector_route.h"
#include "proof/exceptional_set.h"
#include "proof/packed_normalizer.h"
#include "proof/rational_normal.h"
#include "proof/symbolic_motion.h"
#include "proof/topology_layout.h"

namespace linkproof {

namespace {

// Whether an expression reads the motion: a rate, a velocity or acceleration, a pole, a centre
// of curvature, a sliding rate (not positions or axes alone).
bool reads_motion(const MechanismNode& n) {
  if (n.op == MechanismNode::Op::Call) {
    switch (n.word->evaluation) {
      case Evaluation::Omega:
      case Evaluation::OmegaRelative:
      case Evaluation::Alpha:
      case Evaluation::AlphaRelative:
      case Evaluation::Velocity:
      case Evaluation::VelocityRelative:
      case Evaluation::Acceleration:
      case Evaluation::AccelerationRelative:
      case Evaluation::Pole:
      case Evaluation::Centre:
      case Evaluation::CentreAt:
      case Evaluation::SlidingV:
      case Evaluation::SlidingA: return true;
      default: break;
    }
  }
  return std::any_of(n.children.begin(), n.children.end(), [](const MechanismNode& c) { return reads_motion(c); });
}

using GiNaC::ex;
using ProofClock = std::chrono::steady_clock;
using proof_detail::NamedDegeneracies;
using proof_detail::RationalNormalizer;

double since(ProofClock::time_point t) { return std::chrono::duration<double>(ProofClock::now() - t).count(); }

// p(x, delta_1, ..) with delta_b = 1/det_b (symbolic_motion.h) as a polynomial in x alone:
// det_b^k p for each b in turn, k the degree in delta_b. Where no det_b vanishes it vanishes
// exactly where p does, so p is zero on the configurations iff this is. With c_i the coefficient
// of delta^i (i = l..k) it is sum c_i det^(k-i), by Horner's rule; the expansions are the
// normalizer's (under its deadline; GiNaC's expand of such products is quadratic).
ex clear_delta(const ex& p, const SymbolicMotion& m, RationalNormalizer& normalizer) {
  ex e = GiNaC::expand(p);
  for (const InverseDeterminant& inv : m.inverses) {
    if (!e.has(inv.delta)) continue;
    ex out = e.coeff(inv.delta, e.ldegree(inv.delta));
    for (int i = e.ldegree(inv.delta) + 1; i <= e.degree(inv.delta); ++i)
      out = normalizer.expanded_sum({{out, inv.det}, {e.coeff(inv.delta, i), 1}});
    e = GiNaC::expand(out);
  }
  return e;
}

// p reduced by s^2 = 1 - c^2 for every unit axis (c, s): zero iff p vanishes on the circles.
ex reduce_on_circles(ex p, const std::vector<std::pair<ex, ex>>& axes, RationalNormalizer& normalizer) {
  for (const auto& [c, s] : axes) {
    p = GiNaC::expand(p);
    if (!p.has(s)) continue;
    std::vector<std::pair<ex, ex>> products;
    for (int k = p.ldegree(s); k <= p.degree(s); ++k)
      products.emplace_back(p.coeff(s, k), GiNaC::expand(GiNaC::pow(s, k % 2) * GiNaC::pow(1 - c * c, k / 2)));
    p = normalizer.expanded_sum(products);
  }
  return GiNaC::expand(p);
}

// The degeneracies a claim's words bring (the header comment): evaluated on the symbolic frame.
void claim_degeneracies(const MechanismNode& n, const MechanismFrameOf<ex>& f, NamedDegeneracies& out) {
  for (const MechanismNode& c : n.children) claim_degeneracies(c, f, out);
  const auto value = [&](size_t k) { return evaluate_mechanism_expression(n.children[k], f); };
  const auto vec = [&](size_t k) {
    const MechanismValueOf<ex> v = value(k);
    return Vec2<ex>{v.x, v.y};
  };
  try {
    if (n.op == MechanismNode::Op::Divide) {
      out.emplace_back(value(1).x, fmt::format("the divisor {} is 0", n.children[1].text));
    } else if (n.op == MechanismNode::Op::Power && n.exponent < 0) {
      out.emplace_back(value(0).x, fmt::format("{} is 0: its negative power is undefined", n.children[0].text));
    } else if (n.op == MechanismNode::Op::Call) {
      const auto& a = n.children;
      const auto field = [&](size_t k) { return f.fields[static_cast<size_t>(a[k].index)]; };
      switch (n.word->evaluation) {
        case Evaluation::Pole:
          out.emplace_back(field(0).omega - field(1).omega,
                           fmt::format("omega({0}) = omega({1}): {2} is at infinity (a relative translation) or undefined",
                                       a[0].text, a[1].text, n.text));
          break;
        case Evaluation::Centre:
        case Evaluation::CentreAt: {
          const Vec2<ex> X = n.word->evaluation == Evaluation::CentreAt ? vec(0)
                             : a[0].is_tracer_point                        ? f.point_at[static_cast<size_t>(a[0].index)]
                                                                           : f.joint_at[static_cast<size_t>(a[0].index)];
          const RelativePointMotion<ex> m = relative_point_motion(field(1), field(2), X);
          out.emplace_back(cross(m.v, m.a), fmt::format("v x a = 0 for {0}: the point is on the inflection circle or at the "
                                                         "pole, {1} is at infinity or undefined", a[0].text, n.text));
          break;
        }
        case Evaluation::Meet:
          out.emplace_back(cross(vec(1) - vec(0), vec(3) - vec(2)),
                           fmt::format("the lines of {} are parallel or a line is a single point", n.text));
          break;
        default: break;
      }
    }
  } catch (const UndefinedQuantity&) {
    // The claim's own evaluation reports it.
  }
}

struct ClaimValues {
  std::vector<std::pair<std::string, ex>> residuals;  // (component, lhs - rhs)
  std::vector<ex> sides;
};

ClaimValues claim_values(const MechanismDataClaim& claim, const MechanismFrameOf<ex>& f) {
  const MechanismValueOf<ex> l = evaluate_mechanism_expression(claim.lhs.root(), f);
  const MechanismValueOf<ex> r = evaluate_mechanism_expression(claim.rhs.root(), f);
  ClaimValues v;
  if (claim.lhs.kind() == ClaimKind::Vector) {
    v.residuals = {{"x", l.x - r.x}, {"y", l.y - r.y}};
    v.sides = {l.x, l.y, r.x, r.y};
  } else {
    v.residuals = {{"total", l.x - r.x}};
    v.sides = {l.x, r.x};
  }
  return v;
}

// The claim on random exact configurations (a disproof, or evidence when no proof is made).
SampleResult sample_claim(const MechanismScene& s, const MechanismDataClaim& claim, TopologySampling o, int count) {
  o.count = count;
  return std::move(sample_topology(s, {claim}, o).claims.front());
}

void take_samples(TopologyProof& p, SampleResult r, const TopologySampling& o, const std::string& why) {
  switch (r.verdict) {
    case TopologyVerdict::Disproved:
      p.verdict = ProofVerdict::Disproved;
      p.counterexample = std::move(r.counterexample);
      p.argument.push_back(fmt::format("false on random exact configuration {} (seed {}), shrunk in {} steps to the "
                                       "counterexample scene below", p.counterexample->configuration, o.seed,
                                       p.counterexample->shrink_steps));
      return;
    case TopologyVerdict::HoldsOnSamples:
      p.verdict = ProofVerdict::HoldsOnSamples;
      p.samples_compared = r.compared;
      p.argument.push_back(fmt::format("{}; exactly equal on {} random exact configurations of the topology (seed {}): "
                                       "evidence, NOT a proof", why, r.compared, o.seed));
      return;
    case TopologyVerdict::Undefined:
    case TopologyVerdict::Inconclusive:  // not reached: the prover samples exactly
      p.verdict = ProofVerdict::Error;
      p.error = fmt::format("{}; and the claim is undefined on every configuration drawn: {}: {}", why,
                            r.undefined_quantity, r.undefined_reason);
      return;
  }
}

// Degree bounds of an expression DAG as a rational function of the symbols, num / den, with
// each delta_b read as 1 / det_b (the header comment). Memoised: the DAG's shared nodes are visited once.
class DegreeBounds {
 public:
  struct Bound {
    long num = 0, den = 0;
  };
  explicit DegreeBounds(const SymbolicMotion& m) {
    for (const InverseDeterminant& inv : m.inverses) det_degree_[inv.delta] = total_degree(inv.det);
  }

  Bound of(const ex& e) {
    if (const auto it = memo_.find(e); it != memo_.end()) return it->second;
    const Bound b = compute(e);
    memo_.emplace(e, b);
    return b;
  }

  static long total_degree(const ex& polynomial) {
    const ex p = GiNaC::expand(polynomial);
    long most = 0;
    const auto term_degree = [](const ex& t) {
      long d = 0;
      const auto factor = [&d](const ex& f) {
        if (GiNaC::is_a<GiNaC::symbol>(f)) d += 1;
        else if (GiNaC::is_exactly_a<GiNaC::power>(f)) d += GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_long();
      };
      if (GiNaC::is_exactly_a<GiNaC::mul>(t))
        for (size_t i = 0; i < t.nops(); ++i) factor(t.op(i));
      else
        factor(t);
      return d;
    };
    if (GiNaC::is_exactly_a<GiNaC::add>(p))
      for (size_t i = 0; i < p.nops(); ++i) most = std::max(most, term_degree(p.op(i)));
    else
      most = term_degree(p);
    return most;
  }

 private:
  Bound compute(const ex& e) {
    if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) return {0, 0};
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto inverse = det_degree_.find(e);
      return inverse != det_degree_.end() ? Bound{0, inverse->second} : Bound{1, 0};
    }
    if (GiNaC::is_exactly_a<GiNaC::add>(e)) {  // over the product of the denominators
      std::vector<Bound> parts;
      long den = 0;
      for (size_t i = 0; i < e.nops(); ++i) parts.push_back(of(e.op(i))), den += parts.back().den;
      long num = 0;
      for (const Bound& b : parts) num = std::max(num, b.num + den - b.den);
      return {num, den};
    }
    if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
      Bound out;
      for (size_t i = 0; i < e.nops(); ++i) {
        const Bound b = of(e.op(i));
        out.num += b.num, out.den += b.den;
      }
      return out;
    }
    if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
      const Bound b = of(e.op(0));
      const long k = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_long();
      return k >= 0 ? Bound{k * b.num, k * b.den} : Bound{-k * b.den, -k * b.num};
    }
    throw NoDegreeBound{};
  }

 public:
  struct NoDegreeBound {};

 private:
  std::map<ex, long, GiNaC::ex_is_less> det_degree_;  // per delta_b: deg det_b
  std::unordered_map<ex, Bound, std::hash<ex>, GiNaC::ex_is_equal> memo_;
};

constexpr double kIdentityTestRange = 1099511627776.0;  // 2^40: each coordinate, rate and t
constexpr int kIdentityTestTrials = 3;
// On GiNaC's route (the rigid-body test, the divisors, and residuals the packed polynomials
// cannot hold), expansions beyond this many terms go to the identity test: one would take
// minutes. The packed route has its own limits (PackedLimits).
constexpr double kTermLimit = 5e5;

class TopologyProver {
 public:
  TopologyProver(const MechanismScene& s, const TopologyProofOptions& o) : scene_(s), options_(o) {}

  TopologyProof prove(const MechanismDataClaim& claim) {
    const auto start = ProofClock::now();
    TopologyProof p;
    p.info = claim.info;
    // A wrong claim usually fails on the first configurations: disproved without symbolic work.
    std::optional<SampleResult> quick;
    if (options_.quick_samples > 0) quick = sample_claim(scene_, claim, options_.sampling, options_.quick_samples);
    if (quick && quick->verdict == TopologyVerdict::Disproved)
      take_samples(p, std::move(*quick), options_.sampling, "");
    else
      prove_symbolically(claim, p, start);
    p.seconds = since(start);
    return p;
  }

  TopologyProofRun run(const std::vector<MechanismDataClaim>& claims) {
    const auto start = ProofClock::now();
    TopologyProofRun r;
    r.topology = scene_.name;
    r.symbols = config_.names;
    r.relations = config_.relations;
    r.unknowns = scene_.linkage.unknown_count();
    for (const MechanismDataClaim& c : claims) {
      r.claims.push_back(prove(c));
      // In a claim file a claim that exists nowhere is not well formed: bad input naming it, as
      // in the polygon language (a divisor identically zero), not an error of the program.
      const TopologyProof& p = r.claims.back();
      if (p.undefined_everywhere && !c.info.file.empty()) throw InputError(c.info.file, "claim '" + c.info.id + "'", p.error);
    }
    if (motion_) {
      r.system_note = motion_->note;
      if (motion_->note.empty()) r.det_terms = static_cast<int>(GiNaC::is_exactly_a<GiNaC::add>(motion_->det) ? motion_->det.nops() : 1);
      r.groups = motion_->block_sizes;
    }
    if (!routes_.empty()) {
      r.proof_driver = driver_name(*routes_.front());
      r.proof_driver_groups = routes_.front()->block_sizes;
    }
    r.seconds = since(start);
    return r;
  }

 private:
  // The motion driven by the scene's inputs: what the claims are about.
  const SymbolicMotion& motion() {
    if (!motion_) motion_ = std::make_unique<SymbolicMotion>(solve_symbolically(scene_, config_, scene_.inputs, config_.inputs));
    return *motion_;
  }

  // The k-th motion the residuals may be normalized in (nullptr past the last): driven by the
  // links whose groups are smaller than the scene's driver's, smallest first (symbolic_motion.h
  // says why a proof there is a proof), else the scene's own. Drivers with groups of the same
  // sizes give normal forms of different sizes: one may fit the limits where another does not.
  const SymbolicMotion* route(size_t k) {
    if (!candidates_) candidates_ = better_proof_drivers(scene_);
    while (routes_.size() <= k && next_candidate_ < candidates_->size()) {
      const MechanismInput& in = (*candidates_)[next_candidate_++];
      const std::string& link = scene_.linkage.link_names()[static_cast<size_t>(in.index)];
      const std::vector<InputValue<ex>> rates{{GiNaC::symbol("w_" + link + "_driver"), GiNaC::symbol("wd_" + link + "_driver")}};
      std::unique_ptr<SymbolicMotion> m;
      try {
        m = std::make_unique<SymbolicMotion>(solve_symbolically(scene_, config_, {in}, rates));
      } catch (const std::exception&) {  // GiNaC's (a pole): this driver is of no use
        continue;
      }
      if (m->singular_everywhere || !m->note.empty() || vanishes_on_circles(m->det)) continue;
      routes_.push_back(std::move(m));
    }
    if (k < routes_.size()) return routes_[k].get();
    return routes_.empty() && k == 0 ? &motion() : nullptr;
  }

  std::string driver_name(const SymbolicMotion& r) const {
    return scene_.linkage.link_names()[static_cast<size_t>(r.inputs.front().index)];
  }

  static bool has_input_rate(const SymbolicMotion& m, const ex& e) {
    for (const InputValue<ex>& v : m.input_values)
      if (e.has(v.rate) || e.has(v.rate_dot)) return true;
    return false;
  }

  std::string driver_argument(const SymbolicMotion& r) const {
    const auto groups = [](const std::vector<int>& sizes) { return fmt::format("{}", fmt::join(sizes, ", ")); };
    const SymbolicMotion& own = *motion_;
    return fmt::format(
        "solved with link {} as the driver (groups of {} unknowns in the order solved, against {} with the scene's "
        "input): wherever both "
        "drivers determine the motion it is the same motion, so lhs - rhs, a rational function of the coordinates and "
        "the scene's input rates, vanishes on a dense set and is the zero function",
        scene_.linkage.link_names()[static_cast<size_t>(r.inputs.front().index)], groups(r.block_sizes),
        groups(own.block_sizes));
  }

  // The claim's divisors in motion m, as polynomials (deltas cleared): the words' degeneracies,
  // named, and the divisions left in the evaluated sides.
  struct ClaimDivisors {
    NamedDegeneracies named;
    std::vector<ex> left;
    bool depend_on(const SymbolicMotion& m) const {
      for (const auto& [poly, meaning] : named)
        if (has_input_rate(m, poly)) return true;
      for (const ex& d : left)
        if (has_input_rate(m, d)) return true;
      return false;
    }
  };
  ClaimDivisors divisors_of(const MechanismDataClaim& claim, const SymbolicMotion& m, const MechanismFrameOf<ex>& frame,
                            const ClaimValues& values, RationalNormalizer& normalizer) {
    ClaimDivisors d;
    claim_degeneracies(claim.lhs.root(), frame, d.named);
    claim_degeneracies(claim.rhs.root(), frame, d.named);
    for (auto& [poly, meaning] : d.named) poly = clear_delta(normalizer.numerator(poly), m, normalizer);
    for (const ex& x : proof_detail::divisors_in(values.sides)) d.left.push_back(clear_delta(normalizer.numerator(x), m, normalizer));
    return d;
  }

  void prove_symbolically(const MechanismDataClaim& claim, TopologyProof& p, ProofClock::time_point start) {
    const SymbolicMotion& m = motion();
    if (m.singular_everywhere) {
      p.verdict = ProofVerdict::Error;
      p.error = m.note;
      return;
    }
    if (!m.note.empty()) return judge_on_samples(claim, p, "no symbolic proof: " + m.note);
    if (vanishes_on_circles(m.det)) {
      p.verdict = ProofVerdict::Error;
      p.error = "the velocity system is singular on every configuration whose axes are unit vectors (det A = 0 there)";
      return;
    }
    const auto deadline = start + std::chrono::duration_cast<ProofClock::duration>(std::chrono::duration<double>(options_.seconds));
    try {
      if (prove_for_free_rates(claim, p, m, deadline)) return;
    } catch (const proof_detail::NormalizerOutOfTime&) {
      // Not within the budget with free rates: the solved rates are tried next.
    } catch (const UndefinedQuantity&) {
      // Undefined for free rates (e.g. omega(L) - omega(M) is 0 for every rate): decided below.
    } catch (const GiNaC::pole_error&) {
    }
    // The residual in the motion of the driver with the smallest groups (symbolic_motion.h),
    // the scene's own unless another link splits the system further; past a size limit there,
    // in the next such driver's.
    for (size_t k = 0;; ++k) {
      const SymbolicMotion& r = *route(k);  // k = 0 always has one; a later k is checked below
      const TopologyProof before = p;
      try {
        return decide_in(r, claim, p, deadline);
      } catch (const UndefinedQuantity& u) {
        p.verdict = ProofVerdict::Error;
        p.undefined_everywhere = true;
        p.error = fmt::format("undefined on every configuration of the topology: {}: {}", u.quantity(), u.reason());
      } catch (const GiNaC::pole_error&) {
        p.verdict = ProofVerdict::Error;
        p.undefined_everywhere = true;
        p.error = "undefined on every configuration of the topology: a division by an expression that is identically 0";
      } catch (const proof_detail::NormalizerOutOfTime& limit) {
        const std::string why =
            fmt::format("{}no symbolic normal form within the budget ({})",
                        &r == &m ? "" : fmt::format("with link {} as the driver: ", driver_name(r)), limit.why);
        if (!limit.deadline && route(k + 1) != nullptr) {
          p = before;
          p.argument.push_back(fmt::format("{}; link {} drives next", why, driver_name(*route(k + 1))));
          continue;
        }
        identity_test(claim, p, m, why);
      }
      return;
    }
  }

  // Steps 1-3 with the residual in motion r (the header comment): proved, proved generically or
  // disproved into p. Throws what the normal forms throw.
  void decide_in(const SymbolicMotion& r, const MechanismDataClaim& claim, TopologyProof& p,
                 ProofClock::time_point deadline) {
    const SymbolicMotion& m = motion();
    const bool driven_otherwise = &r != &m;
    const MechanismFrameOf<ex> frame(scene_, r.motion, config_.joint_at, config_.point_at, config_.axis, true);
    const ClaimValues values = claim_values(claim, frame);
    RationalNormalizer normalizer(false);  // the denominators are known: no gcds (rational_normal.h)
    normalizer.set_term_limit(kTermLimit);
    normalizer.set_deadline(deadline);
    // A claim that reads the motion is about a mechanism whose velocities exist only where det A
    // != 0, whatever its residual's denominators say: a solved rate whose Cramer numerator is
    // identically 0 is 0, with no trace of det A.
    bool uses_motion = reads_motion(claim.lhs.root()) || reads_motion(claim.rhs.root());
    proof_detail::PackedNormalizer packed;
    packed.set_deadline(deadline);
    packed.set_limits(options_.packed_limits);
    std::vector<std::pair<ex, ex>> inverses;  // (delta_b, det_b)
    for (const InverseDeterminant& inv : r.inverses) inverses.emplace_back(inv.delta, inv.det);
    packed.set_inverses(inverses);
    for (const auto& [component, residual] : values.residuals) {
      uses_motion = uses_motion || r.has_inverse(residual) || (driven_otherwise && has_input_rate(r, residual));
      const ResidualNumerator n = residual_numerator(residual, r, normalizer, packed);
      p.numerator_terms += static_cast<int>(n.terms);
      if (n.reduced_terms != 0) return disprove(claim, p, component, n.reduced_terms);
    }
    if (driven_otherwise) p.argument.push_back(driver_argument(r));
    p.argument.push_back(fmt::format(
        "lhs - rhs is identically zero as a rational function of the {} coordinates{}{}", config_.names.size(),
        config_.relations.empty() ? "" : " on the unit circles of the axes",
        p.numerator_terms == 0 ? "" : fmt::format(" (its numerator, known factors taken out: {} terms, vanishes there)", p.numerator_terms)));
    NamedDegeneracies motion_named{{m.det, "dead centre or change point: det A = 0, the loop closures and the inputs do "
                                          "not determine the velocities"}};
    // What was divided by, as polynomials in the coordinates: det A where the rates enter, the
    // claim's own divisors as written (GiNaC simplifies x/x to 1 when it builds an expression:
    // the words' degeneracies keep them), and the divisors left in the expressions. With
    // another driver they are the scene's only if they contain no rate; else they are taken
    // again in the scene's own motion.
    ClaimDivisors claim_divisors = divisors_of(claim, r, frame, values, normalizer);
    if (driven_otherwise && claim_divisors.depend_on(r)) {
      const MechanismFrameOf<ex> own(scene_, m.motion, config_.joint_at, config_.point_at, config_.axis, true);
      claim_divisors = divisors_of(claim, m, own, claim_values(claim, own), normalizer);
    }
    const NamedDegeneracies& claim_named = claim_divisors.named;
    std::vector<ex> divisors;
    if (uses_motion) divisors.push_back(m.det);
    for (const auto& [poly, meaning] : claim_named) {
      if (vanishes_on_circles(poly)) return undefined_everywhere(p, meaning);
      divisors.push_back(poly);
    }
    divisors.insert(divisors.end(), claim_divisors.left.begin(), claim_divisors.left.end());
    const std::vector<proof_detail::NamedFactor> factors = proof_detail::divisor_factors(
        divisors, {[&] { return motion_named; }, [&] { return claim_named; }}, normalizer, true);
    if (!take_exceptions(p, factors, [&](const ex& f) { return vanishes_on_circles(f); })) return;
    p.verdict = p.except.empty() ? ProofVerdict::Proved : ProofVerdict::ProvedGenerically;
    p.argument.push_back(p.except.empty() ? std::string("no division by a non-constant: it holds on every configuration")
                                          : fmt::format("it holds on every configuration outside the zero sets of the {} "
                                                        "factor(s) listed", p.except.size()));
  }

  // Step 0 (the header comment): lhs - rhs with every rate a free symbol. True if it decided
  // the claim: zero for all rates, a rigid-body identity proved on every configuration (the
  // dead centres included: it holds for whatever rates the constraints admit there).
  bool prove_for_free_rates(const MechanismDataClaim& claim, TopologyProof& p, const SymbolicMotion& m,
                            ProofClock::time_point deadline) {
    const MechanismFrameOf<ex> frame(scene_, m.free_rates, config_.joint_at, config_.point_at, config_.axis, true);
    const ClaimValues values = claim_values(claim, frame);
    RationalNormalizer normalizer(false);
    normalizer.set_term_limit(kTermLimit);
    normalizer.set_deadline(deadline);
    for (const auto& [component, residual] : values.residuals)
      if (!vanishes_on_circles(normalizer.numerator(residual))) return false;
    NamedDegeneracies named;
    claim_degeneracies(claim.lhs.root(), frame, named);
    claim_degeneracies(claim.rhs.root(), frame, named);
    // A polynomial in the free rates that is 0 once the solved rates are put in.
    const auto vanishes = [&](const ex& poly) {
      RationalNormalizer solved(false);
      return vanishes_on_circles(clear_delta(solved.numerator(poly.subs(m.solved_rates)), m, solved));
    };
    std::vector<ex> divisors;
    for (auto& [poly, meaning] : named) {  // the claim's divisors as written (see step 1)
      poly = normalizer.numerator(poly);
      if (vanishes(poly)) {
        undefined_everywhere(p, meaning);
        return true;
      }
      divisors.push_back(poly);
    }
    for (const ex& d : proof_detail::divisors_in(values.sides)) divisors.push_back(normalizer.numerator(d));
    const std::vector<proof_detail::NamedFactor> factors =
        proof_detail::divisor_factors(divisors, {[&] { return named; }}, normalizer, true);
    if (!take_exceptions(p, factors, vanishes)) return true;
    p.verdict = p.except.empty() ? ProofVerdict::Proved : ProofVerdict::ProvedGenerically;
    p.argument.push_back(fmt::format(
        "lhs - rhs is identically zero for every value of the links' rates (omega_L, alpha_L{}) and of the {} "
        "coordinates{}: a rigid-body identity, the loop closures are not needed",
        m.free_rates.slide.empty() ? "" : ", sd_J, sdd_J", config_.names.size(),
        config_.relations.empty() ? "" : " (axes on the unit circles)"));
    p.argument.push_back(p.except.empty() ? std::string("no division by a non-constant: it holds on every configuration, "
                                                        "for any rates the constraints admit")
                                          : fmt::format("it holds wherever none of the {} factor(s) listed vanishes",
                                                        p.except.size()));
    return true;
  }

  // A polynomial that is zero iff the residual is, with r's deltas read as 1 / det_b (`terms`),
  // and the terms left of it once reduced on the circles (0: it vanishes on every
  // configuration). In packed polynomials when they can hold it: the core of the residual's
  // factored normal form (packed_normalizer.h), `packed` knowing the deltas. Else in GiNaC's: the
  // numerator of RationalNormalizer's normal form, the deltas cleared.
  struct ResidualNumerator {
    size_t terms = 0, reduced_terms = 0;
  };
  ResidualNumerator residual_numerator(const ex& residual, const SymbolicMotion& r, RationalNormalizer& normalizer,
                                       proof_detail::PackedNormalizer& packed) const {
    try {
      const proof_detail::PackedPolynomial n = packed.core(residual);
      return {n.terms(), proof_detail::reduce_on_circles(n, config_.unit_axes, packed).terms()};
    } catch (const proof_detail::PackedUnsupported&) {
    } catch (const proof_detail::PackedOverflow&) {
    }
    const auto terms = [](const ex& e) -> size_t { return GiNaC::is_exactly_a<GiNaC::add>(e) ? e.nops() : !e.is_zero(); };
    const ex numerator = clear_delta(normalizer.numerator(residual), r, normalizer);
    return {terms(numerator), terms(reduce_on_circles(numerator, config_.unit_axes, normalizer))};
  }

  bool vanishes_on_circles(const ex& polynomial) const {
    RationalNormalizer expansions(false);
    return reduce_on_circles(polynomial, config_.unit_axes, expansions).is_zero();
  }

  void judge_on_samples(const MechanismDataClaim& claim, TopologyProof& p, const std::string& why) {
    take_samples(p, sample_claim(scene_, claim, options_.sampling, options_.sampling.count), options_.sampling, why);
  }

  // The factors as the claim's exceptional set; false, with the claim an error, if one of them
  // is 0 on every configuration (`vanishes`).
  template <class Vanishes>
  static bool take_exceptions(TopologyProof& p, const std::vector<proof_detail::NamedFactor>& factors, Vanishes vanishes) {
    for (const proof_detail::NamedFactor& f : factors) {
      if (vanishes(f.factor)) {
        p.verdict = ProofVerdict::Error;
        p.undefined_everywhere = true;
        p.error = fmt::format("the claim is undefined on every configuration of the topology: it divides by {}, which "
                              "is 0 on every configuration", to_text(f.factor));
        return false;
      }
      p.except.push_back({to_text(f.factor), f.meaning.empty() ? "unnamed: a factor of a divisor" : f.meaning});
    }
    return true;
  }

  // A claim whose degeneracy `meaning` holds on every configuration (with the solved rates).
  static void undefined_everywhere(TopologyProof& p, const std::string& meaning) {
    p.verdict = ProofVerdict::Error;
    p.undefined_everywhere = true;
    p.error = "the claim is undefined on every configuration of the topology: " + meaning + " everywhere";
  }

  // The randomized identity test (the header comment); samples if it cannot be done.
  void identity_test(const MechanismDataClaim& claim, TopologyProof& p, const SymbolicMotion& m, const std::string& why) {
    const MechanismFrameOf<ex> frame(scene_, m.motion, config_.joint_at, config_.point_at, config_.axis, true);
    const ClaimValues values = claim_values(claim, frame);
    DegreeBounds bounds(m);
    long num = 0, den = bounds.of(m.det).num;  // the singular configurations are redrawn too
    try {
      for (const auto& [component, residual] : values.residuals) {
        const DegreeBounds::Bound b = bounds.of(residual);
        num = std::max(num, b.num);
        den += b.den;
      }
    } catch (const DegreeBounds::NoDegreeBound&) {
      return judge_on_samples(claim, p, why + "; no degree bound for a randomized identity test");
    }
    if (!config_.unit_axes.empty()) num *= 2, den *= 2;  // through u(t) = ((1 - t^2), 2t) / (1 + t^2)
    const double per_trial = static_cast<double>(num) / (kIdentityTestRange - static_cast<double>(den));
    SplitMix64 rng(options_.sampling.seed * 0xD1B54A32D192ED03ull + 0x1D5ull);
    const auto draw = [&rng] {
      const std::uint64_t bits = rng.next() >> 24;  // 40 random bits
      return Rational(static_cast<long long>(bits)) - Rational(1LL << 39);
    };
    const TopologyLayout layout = topology_layout(scene_);
    int passed = 0, attempts = 0;
    for (; passed < kIdentityTestTrials && attempts < 20 * kIdentityTestTrials; ++attempts) {
      TopologyValues v;
      for (int g = 0; g < layout.groups(); ++g) v.positions.push_back({draw(), draw()});
      for (const LinkageJoint& j : scene_.linkage.joints()) {
        if (j.type != JointType::Prismatic) {
          v.axes.push_back({0, 0});
          continue;
        }
        const Rational t = draw(), w = 1 + t * t;
        v.axes.push_back({(1 - t * t) / w, 2 * t / w});
      }
      for (size_t k = 0; k < scene_.inputs.size(); ++k) v.rate.push_back(draw()), v.rate_dot.push_back(draw());
      const MechanismScene s = topology_configuration(scene_, layout, v, fmt::format("counterexample-{}", claim.info.id));
      std::optional<MechanismSolution<Rational>> solution;
      try {
        solution = solve_mechanism<Rational>(
            s.linkage, s.inputs, rigid_body_constraint_matrix<Rational>(s.linkage),
            [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(s.linkage, qd); }, s.source);
      } catch (const InputError&) {
        continue;  // singular here: redrawn
      }
      const MechanismFrame exact(s, solution->motion);
      const ClaimSides<Rational> sides = evaluate_mechanism_claim(claim, exact);
      bool defined = true, equal = true;
      for (const auto& c : sides.instances) {
        defined = defined && c.lhs.has_value() && c.rhs.has_value();
        equal = equal && defined && c.lhs.get() == c.rhs.get();
      }
      if (!defined) continue;
      if (!equal) {  // a counterexample (large); a small one is searched, else this one is given
        p.argument.push_back(why);
        SampleResult r = sample_claim(scene_, claim, options_.sampling, options_.sampling.count);
        if (r.verdict == TopologyVerdict::Disproved) return take_samples(p, std::move(r), options_.sampling, why);
        MechanismCounterexample cx;
        cx.scene = s;
        cx.scene.source = "counterexample";
        cx.scene_yaml = mechanism_scene_to_yaml(cx.scene);
        cx.outcome = run_mechanism_claim(to_mechanism_claim(claim), MechanismContext{cx.scene, *solution});
        p.verdict = ProofVerdict::Disproved;
        p.counterexample = std::move(cx);
        p.argument.push_back("false on a random configuration with 40-bit coordinates (not shrunk)");
        return;
      }
      ++passed;
    }
    if (passed < kIdentityTestTrials)
      return judge_on_samples(claim, p, why + fmt::format("; only {} of {} random configurations with 40-bit "
                                                          "coordinates were defined", passed, attempts));
    p.verdict = ProofVerdict::HoldsWithProbability;
    p.trials = passed;
    p.degree_bound = num;
    p.failure_bound = std::pow(per_trial, passed);
    p.argument.push_back(why);
    p.argument.push_back(fmt::format(
        "randomized identity test: lhs - rhs has a numerator of total degree at most {}; exactly equal at {} random "
        "configurations with every coordinate, rate{} uniform among 2^40 integers; a false claim passes with "
        "probability at most ({} / (2^40 - {}))^{} = {:.2e}. NOT a proof",
        num, passed, config_.unit_axes.empty() ? "" : " and axis parameter", num, den, passed, p.failure_bound));
  }

  void disprove(const MechanismDataClaim& claim, TopologyProof& p, const std::string& component, size_t terms) {
    const std::string why = fmt::format("lhs - rhs{} is not identically zero: its numerator (known factors taken out) is a "
                                        "non-zero polynomial of {} terms",
                                        component == "total" ? "" : " (" + component + ")", terms);
    p.argument.push_back(why);
    SampleResult r = sample_claim(scene_, claim, options_.sampling, options_.sampling.count);
    if (r.verdict == TopologyVerdict::Disproved) return take_samples(p, std::move(r), options_.sampling, why);
    p.verdict = ProofVerdict::Error;
    p.error = why + fmt::format(", but no counterexample was found on {} random exact configurations (seed {})",
                                r.compared, options_.sampling.seed);
  }

  const MechanismScene& scene_;
  TopologyProofOptions options_;
  SymbolicConfiguration config_ = symbolic_configuration(scene_);
  std::unique_ptr<SymbolicMotion> motion_;
  std::optional<std::vector<MechanismInput>> candidates_;  // better drivers than the scene's
  size_t next_candidate_ = 0;
  std::vector<std::unique_ptr<SymbolicMotion>> routes_;  // those built and usable, in order
};

}  // namespace

bool TopologyProof::is_as_expected() const {
  if (info.expected == Expectation::Fails) return verdict == ProofVerdict::Disproved;
  return verdict == ProofVerdict::Proved || verdict == ProofVerdict::ProvedGenerically ||
         verdict == ProofVerdict::HoldsWithProbability || verdict == ProofVerdict::HoldsOnSamples;
}

TopologyProofRun prove_topology(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                const TopologyProofOptions& options) {
  return TopologyProver(scene, options).run(claims);
}

}  // namespace linkproof
