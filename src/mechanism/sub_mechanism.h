// The part of a mechanism that an asked output needs (a scene's `ask`, check/ask.h).
//
// Assur's structure: a mechanism is its ground and input links plus groups of links, each group
// determined once the links it hangs on are known; a group that no asked link hangs on, directly
// or through others, can be left out. Such a group has no freedom of its own when its outer
// joints are held: 3 |X| = 2 J_X (J_X the joints touching it), so it has an even number of links
// (a dyad: 2 links, 3 joints; a triad: 4 links, 6 joints; ...).
//
// The search is structural, the decision exact: a connected set X of links outside `required`
// with 3 |X| = 2 J_X is left out only if the rest, on its own, is a mechanism whose own inputs
// fix its motion (exact ranks of its velocity constraints). Soundness does not rest on the
// theory: the rest's constraints are a subset of the whole's, the whole's motion satisfies them,
// and they have one solution, so every kept link moves in the rest exactly as in the whole.
// Groups larger than kMaxGroupLinks are not searched (kept: the answer is still exact, only less
// is saved).
#pragma once

#include <vector>

#include "linkproof/mechanism/mechanism_scene.h"

namespace linkproof {

inline constexpr int kMaxGroupLinks = 6;

struct SubMechanism {
  /// The kept links (in the original order), the joints between them, the inputs, and the
  /// points, dimensions and second-order requests that involve only kept links and joints.
  MechanismScene scene;
  std::vector<int> kept_links;   ///< original index of each link of `scene`
  std::vector<int> kept_joints;  ///< original index of each joint of `scene`
};

/// True if the linkage's velocity constraints and `inputs` fix its motion: mobility (by exact
/// rank) equal to the number of inputs, and the inputs independent.
bool inputs_fix_motion(const Linkage& g, const std::vector<MechanismInput>& inputs);

/// The scene restricted to the links in `keep` (original indices; the ground and every input's
/// links must be among them, and they must be connected to the ground through joints between
/// them), links in the original order.
SubMechanism restrict_mechanism(const MechanismScene& s, std::vector<int> keep);

/// The smallest sub-mechanism found, by leaving out groups one at a time (see above), that
/// contains every link of `required` (the ground and the input links are always kept).
/// Precondition: the whole scene is determined (inputs_fix_motion).
SubMechanism determined_sub_mechanism(const MechanismScene& s, const std::vector<int>& required);

}  // namespace linkproof
