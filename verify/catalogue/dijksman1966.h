// The claims of Dijksman (1966), "Graphic method to determine the angular acceleration of links
// of compound mechanisms", J. Mechanisms 1, 73-81 (seed 000), with the conventions and errata
// of SPEC.md part A. One entry per equation; the erratum readings of SPEC A5 stand beside the
// correct ones with the expectation `fails`.
//
// Claim ids: dijksman1966.eqN (eq4 ... eq22, eq9a), dijksman1966.sec3, dijksman1966.companion,
// and <id>.<reading> for erratum readings (printed, unsigned_phi, j_lt_l, reversed_beta,
// unsigned_ratio).
#pragma once

#include <vector>

#include "linkproof/claims/claim.h"

namespace linkproof::dijksman1966 {

/// Ways of reading the acceleration formulas (22), the companion and sec. 3. The defaults are
/// the true reading (SPEC A3/A4); the first four fields are the seed's errata and misreadings
/// (SPEC A5); the last two exist to feed deliberately wrong formulas through the comparator.
struct FormulaReading {
  ConstructionReading construction;  ///< K'_j vs K_j, P'_j vs P_j, beta sign rule, signed ratios
  bool signed_phi = true;            ///< false: phi read as the unsigned drawn angle
  bool ordered_pairs = true;         ///< false: sum over j < l only (drops the factor 2 of sec. 3)
  int mixed_term_sign = +1;          ///< +1 as printed; -1 flips the mixed term; 0 drops it
  bool swap_mixed_ratios = false;    ///< i_{n-1,j} and i_{n-2,j} exchanged in the mixed term
};

/// Eq. (22): omega-dot_{n-1,n} = sum_j (lambda_j omega_j^2 + i_{n-1,j} omega-dot_j)
///   - cot phi sum_{j!=l} i_{n-1,j} i_{n-1,l} omega_j omega_l
///   - (r_{n-2} / (r_{n-1} sin phi)) sum_{j!=l} i_{n-2,j} i_{n-2,l} omega_j omega_l,
/// as the total (engine truth vs formula) and term by term (engine coefficient vs formula
/// coefficient of every omega-dot_j, omega_j^2, omega_j omega_l).
template <class T>
ClaimSides<T> eq22_sides(const PolygonContext<T>& c, const FormulaReading& reading);

/// The companion formula for omega-dot_{n-2,n} (SPEC A4), total and term by term.
template <class T>
ClaimSides<T> companion_sides(const PolygonContext<T>& c, const FormulaReading& reading);

/// Every claim of the paper and every erratum reading, in equation order.
const std::vector<Claim>& catalogue();

}  // namespace linkproof::dijksman1966
