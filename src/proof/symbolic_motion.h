// The motion of every configuration of a mechanism topology at once: the rates as rational
// functions of the free coordinates (proof/mechanism_proof.h, step 1).
//
// The velocity system A q' = b (loop closures and input rows) is put in block triangular form
// (core/block_triangular.h) and solved group by group: the unknowns of each block by Cramer's
// rule on the block alone, with the groups solved before it moved to the right-hand side. The
// acceleration system has the same A. Each block's determinant is non-zero exactly where det A
// is (det A is their product up to its sign), so nothing is lost, and a mechanism made of dyads
// inverts 2 x 2 determinants instead of one determinant of the whole system.
//
// 1/det of a block is a symbol delta_b: every rate is then a polynomial in the coordinates and
// the deltas, and the normal forms take no gcd with powers of the determinants
// (clear_inverse_determinants puts them back).
//
// The driver: the same motions can be parametrized by other inputs. With one input, another
// link as the driver can split the system into smaller groups (Koshel's class-III mechanism
// driven by its crank is one group of six unknowns; driven by its rocker 5 it is dyads).
// best_proof_driver picks the link whose groups are smallest. Why a proof with another driver is
// a proof of the claim as stated: on the configurations where both drivers determine the
// motion (both determinants non-zero, a dense open set when neither vanishes identically) the
// motion driven by the scene's input at (w, wd) is the motion driven by the other link at its
// own rates in that motion, since both solve the same constraints; so lhs - rhs, a rational
// function of the coordinates and the scene's (w, wd), vanishes on a dense set and is therefore
// the zero rational function: it is zero wherever it is defined.
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

#include "core/dense_matrix.h"
#include "linkproof/mechanism/mechanism_scene.h"
#include "mechanism/mechanism_solve.h"

namespace linkproof {

/// The free coordinates of a topology as GiNaC symbols (proof/mechanism_proof.h).
struct SymbolicConfiguration {
  std::vector<std::string> names;                  ///< every symbol, in order
  std::vector<Vec2<GiNaC::ex>> joint_at, point_at, axis;  ///< per joint, per point, per joint
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> unit_axes;  ///< (c, s) with c^2 + s^2 = 1
  std::vector<std::string> relations;              ///< "c^2 + s^2 = 1", one per axis
  std::vector<InputValue<GiNaC::ex>> inputs;       ///< the scene's inputs' rates as symbols
};

SymbolicConfiguration symbolic_configuration(const MechanismScene& s);

/// delta stands for 1 / det, det a block's determinant (a polynomial in the coordinates).
struct InverseDeterminant {
  GiNaC::symbol delta;
  GiNaC::ex det;
};

struct SymbolicMotion {
  std::string note;  ///< why there is none (a system that is not square)
  bool singular_everywhere = false;
  int unknowns = 0;
  GiNaC::ex det;                   ///< det A of the whole system, expanded
  std::vector<int> block_sizes;    ///< the groups' unknowns, in the order solved
  std::vector<InverseDeterminant> inverses;  ///< one per block whose determinant is not a constant
  std::vector<MechanismInput> inputs;        ///< the driver(s) the system was built with
  std::vector<InputValue<GiNaC::ex>> input_values;  ///< their rates as symbols
  MechanismMotion<GiNaC::ex> motion;
  /// The same linkage with every rate a free symbol (omega_L, alpha_L, sd_J, sdd_J), and the map
  /// from those symbols to the solved rates: a claim that holds for every value of them needs
  /// no loop closure (a rigid-body identity).
  MechanismMotion<GiNaC::ex> free_rates;
  GiNaC::exmap solved_rates;

  /// Whether e contains a delta (it depends on the solved motion).
  bool has_inverse(const GiNaC::ex& e) const;
};

/// The motion of `c`'s configurations driven by `inputs` at the rates `values` (symbols).
SymbolicMotion solve_symbolically(const MechanismScene& s, const SymbolicConfiguration& c,
                                  const std::vector<MechanismInput>& inputs,
                                  const std::vector<InputValue<GiNaC::ex>>& values);

/// The sizes of the groups of the velocity system with `inputs` as drivers, largest first;
/// nullopt if it is not square or structurally singular.
std::optional<std::vector<int>> group_sizes(const MechanismScene& s, const std::vector<MechanismInput>& inputs);

/// For a scene with one input: the other links as single drivers, in the order to try them
/// (groups strictly smaller than the scene's own, smallest first); empty when none is smaller.
std::vector<MechanismInput> better_proof_drivers(const MechanismScene& s);

}  // namespace linkproof
