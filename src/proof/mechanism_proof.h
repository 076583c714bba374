// Mechanism claims proved for every configuration of a topology (`linkproof prove --file CLAIMS
// --topology SCENE`, `linkproof check-claim CLAIMS --topology SCENE`; docs/claims.md,
// "Mechanism claims: proofs for every configuration").
//
// Every configuration of a mechanism scene's topology (proof/topology_layout.h) is given by free
// coordinates: a position (x_G, y_G) per group of coincident joints and points, an axis (c_J, s_J)
// per prismatic joint with c_J^2 + s_J^2 = 1, and per input its rate and rate's derivative
// (w_L, wd_L for a link; v_J, vd_J for a slider). The link lengths follow from the positions, so
// *every* value of these symbols is a configuration: a rational function of them that is
// identically zero is zero on all of them. The proof:
//   1. the velocity system (loop closures and input rows, square: unknowns = rows) is solved
//      group by group in its block triangular form, by Cramer's rule within each group
//      (proof/symbolic_motion.h), and the acceleration system likewise with the same A; det A = 0
//      is where the inputs do not determine the motion (a dead centre or a change point), and
//      only there. With one input, the motion may be solved with another link as the driver
//      when that splits the system into smaller groups (symbolic_motion.h says why a proof
//      there is a proof of the claim as stated);
//   2. both sides of the claim are evaluated on these symbolic rates and positions, by the same
//      code as on a scene (mechanism/mechanism_data_claim.h);
//   3. lhs - rhs (each component) is brought to a numerator / denominator of expanded
//      polynomials, the numerator reduced by s_J^2 = 1 - c_J^2 (then it is A + sum s_J B: zero on
//      the circles iff every part is the zero polynomial). In packed polynomials the numerator
//      is kept with the factors it shares with its parts' divisors taken out, and only the rest
//      is expanded (proof/packed_normalizer.h).
// Numerator zero: `proved` when nothing was divided by a non-constant, else `proved_generically`
// with its exceptional set: the irreducible factors of every divisor (det A; omega(L) - omega(M)
// of a pole; v x a of a curvature centre; the cross product of meet's two lines; a written
// divisor), each named. On every configuration outside their zero sets the claim holds exactly.
// Numerator not zero: the claim is false on a dense set of configurations; a counterexample is
// searched by exact random configurations and shrunk (proof/mechanism_sampling.h) -> `disproved`.
// A claim false on a few random configurations is disproved that way before any symbolic work.
// When the symbolic normal form exceeds its time budget or its size limit, a randomized identity
// test decides instead (Schwartz-Zippel): the residual's numerator has total degree at most D
// (bounded from the expression, 1/det A of degree deg det, each axis read through
// u = ((1 - t^2), 2t) / (1 + t^2), which at most doubles it); at a random configuration with
// every coordinate, rate and t uniform among 2^40 integers it vanishes, if it is not the zero
// polynomial, with probability at most D / (2^40 - E) (E bounds the degree of what the
// evaluation divides by: a configuration where that vanishes is redrawn). Exact evaluation at
// T such configurations, all equal: `holds_with_probability`, with `failure_bound` =
// (D / (2^40 - E))^T, the chance that a false claim passes. Not a proof, and says so. When that
// cannot be done either (a system with redundant constraints, which is not square), the claim
// is judged on K random small configurations: `holds_on_samples`, and `argument` says why.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "claims/mechanism_claim.h"
#include "linkproof/check/check.h"
#include "linkproof/mechanism/mechanism_scene.h"
#include "proof/mechanism_sampling.h"
#include "proof/packed_polynomial.h"
#include "proof/prove.h"

namespace linkproof {

struct TopologyProofOptions {
  double seconds = 60;        ///< budget of the symbolic work per claim
  TopologySampling sampling;  ///< the counterexample search, and the samples when no proof is made
  int quick_samples = 4;      ///< configurations tried before the symbolic work (a fast disproof)
  proof_detail::PackedLimits packed_limits;  ///< what one normal form may cost (packed_polynomial.h)
};

struct TopologyProof {
  ClaimInfo info;
  ProofVerdict verdict = ProofVerdict::Error;  ///< proved, proved_generically, disproved, holds_on_samples, error
  std::vector<ExceptionalSet> except;          ///< proved_generically: where the proof does not reach
  std::vector<std::string> argument;           ///< the steps, for the report
  std::optional<MechanismCounterexample> counterexample;
  int samples_compared = 0;   ///< holds_on_samples: the K configurations compared
  int trials = 0;             ///< holds_with_probability: configurations compared (T)
  long degree_bound = 0;      ///< ... D, the residual numerator's total degree at most
  double failure_bound = 0;   ///< ... the chance that a false claim passes, at most
  int numerator_terms = 0;    ///< terms of the residual's numerator (its known factors taken out, packed_normalizer.h) before the reduction
  double seconds = 0;
  std::string error;          ///< verdict error: why no verdict (e.g. undefined on every configuration)
  bool undefined_everywhere = false;  ///< the error is that the claim is undefined on every configuration
  /// A true claim proved (or, not strict, holding on samples); an erratum disproved.
  bool is_as_expected() const;
};

struct TopologyProofRun {
  std::string topology;               ///< the scene's name
  std::vector<std::string> symbols;   ///< the free coordinates, in order
  std::vector<std::string> relations; ///< "c_D^2 + s_D^2 = 1", one per prismatic axis
  int unknowns = 0;                   ///< of the velocity system (its size)
  int det_terms = 0;                  ///< terms of det A expanded (0 if the system was not built)
  std::vector<int> groups;            ///< unknowns of each group of the system, in the order solved
  std::string proof_driver;           ///< the link that drove the proofs' motion if not the scene's input
  std::vector<int> proof_driver_groups;  ///< ... and its groups
  std::string system_note;            ///< why the system could not be solved symbolically, if so
  double seconds = 0;
  std::vector<TopologyProof> claims;
};

/// Proves, disproves or samples every claim (bound to `scene`'s names) over the topology of `scene`.
TopologyProofRun prove_topology(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                const TopologyProofOptions& options);

}  // namespace linkproof
