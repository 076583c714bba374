// A planar linkage of rigid links connected by revolute and prismatic pairs (docs/conventions.md §A7, §C):
// the link-joint graph, its mobility count and an independent loop basis.
//
// Model (one instant):
// - A link is the rigid body through its joints; it has a name and nothing else. One link is the
//   ground (frame): its omega and omega-dot are 0, every other rate is relative to it.
// - A joint connects two distinct links and sits at an exact point `at`.
//     revolute:  both links share the point `at` (a pin).
//     prismatic: links[0] is the GUIDE link (the axis u is fixed in it), links[1] the SLIDER;
//                the slider's point at `at` moves along the guide's line through `at`, direction u.
//                Its sliding coordinate sigma (slider point minus guide point, along u) is 0 at
//                this instant; sigma-dot and sigma-ddot are the sliding velocity and acceleration.
// - Mobility (Gruebler): M = 3 (L - 1) - 2 J for L links and J lower pairs (each removes 2 of the
//   3 planar freedoms). The rank of the velocity constraints gives the true mobility; both are
//   reported (they differ for over-constrained linkages, e.g. a parallelogram with a redundant bar).
// - Loop basis: a spanning tree of the link graph grown breadth-first from the ground; each joint
//   outside the tree (a chord) closes one independent loop, so there are J - L + 1 loops (the
//   cycle rank of the graph). A loop is the cyclic list of joint crossings chord, tree path back.
//
// Validation (linkage_problem): at least two links, link indices in range, the two links of a
// joint distinct, non-zero axis for a prismatic pair, every link reachable from the ground
// (a disconnected link cannot be driven). Problems are returned as text; the scene reader turns
// them into InputError naming the field.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkproof/core/exact.h"
#include "linkproof/geometry/vec2.h"

namespace linkproof {

enum class JointType { Revolute, Prismatic };

struct LinkageJoint {
  std::string name;
  JointType type = JointType::Revolute;
  /// Link indices. Prismatic: links[0] the guide (axis fixed in it), links[1] the slider.
  int links[2] = {0, 0};
  Vec2<Rational> at;    ///< joint position
  Vec2<Rational> axis;  ///< prismatic only: the guide direction u (any non-zero length)
};

/// Passing from one link into the next through a joint.
struct JointCrossing {
  int joint = 0;
  int from = 0, to = 0;  ///< link indices
};

/// One independent loop: crossings c_0..c_{k-1}; between c_i and c_{i+1} (cyclically) the loop
/// runs inside link c_i.to == c_{i+1}.from, from joint c_i to joint c_{i+1}.
struct LinkageLoop {
  std::vector<JointCrossing> crossings;
};

class Linkage {
 public:
  Linkage() = default;
  /// Builds the graph, the spanning tree and the loop basis. Precondition: linkage_problem() of
  /// the same arguments is empty (checked by LINKPROOF_ASSERT).
  Linkage(std::vector<std::string> link_names, int ground, std::vector<LinkageJoint> joints);

  int link_count() const { return static_cast<int>(links_.size()); }
  int joint_count() const { return static_cast<int>(joints_.size()); }
  int ground() const { return ground_; }
  const std::string& link_name(int i) const { return links_[static_cast<size_t>(i)]; }
  const std::vector<std::string>& link_names() const { return links_; }
  const LinkageJoint& joint(int j) const { return joints_[static_cast<size_t>(j)]; }
  const std::vector<LinkageJoint>& joints() const { return joints_; }
  std::optional<int> find_link(const std::string& name) const;
  std::optional<int> find_joint(const std::string& name) const;

  /// Gruebler's count 3 (L - 1) - 2 J.
  int grubler_mobility() const { return 3 * (link_count() - 1) - 2 * joint_count(); }
  int prismatic_count() const;

  /// The independent loops (J - L + 1 of them).
  const std::vector<LinkageLoop>& loops() const { return loops_; }
  /// Breadth-first order of the links from the ground, and for every link except the ground
  /// the tree crossing that reaches it (tree_entry(ground) is unused).
  const std::vector<int>& tree_order() const { return order_; }
  const JointCrossing& tree_entry(int link) const { return entry_[static_cast<size_t>(link)]; }

  /// The two points a crossing passes through are the same joint position `at`; the vector
  /// from the slider's point to the guide's point is sigma u (0 now). +1 when the crossing enters
  /// the slider (P_to - P_from = +sigma u), -1 when it enters the guide, 0 for a revolute.
  int sliding_sign(const JointCrossing& c) const;

  /// The kinematic unknowns q-dot (and q-ddot), in this order: omega of every moving link
  /// (ground excluded), then sigma-dot of every prismatic joint. -1 where a link (the ground) or
  /// a joint (revolute) has none.
  int unknown_count() const { return unknown_count_; }
  int unknown_of_link(int link) const { return link_unknown_[static_cast<size_t>(link)]; }
  int unknown_of_joint(int joint) const { return joint_unknown_[static_cast<size_t>(joint)]; }
  /// Constraint rows: 2 per loop (x, y of its closure), then 1 per prismatic joint
  /// (omega_slider - omega_guide = 0), in joint order.
  int constraint_count() const { return 2 * static_cast<int>(loops_.size()) + prismatic_count(); }

 private:
  int unknown_count_ = 0;
  std::vector<int> link_unknown_, joint_unknown_;
  std::vector<std::string> links_;
  int ground_ = 0;
  std::vector<LinkageJoint> joints_;
  std::vector<int> order_;
  std::vector<JointCrossing> entry_;
  std::vector<LinkageLoop> loops_;
};

/// An input of a scene: the rates of a link relative to the ground (omega, omega-dot), or the
/// sliding rates of a prismatic joint (sigma-dot, sigma-ddot along its axis u; u's length is the unit).
struct MechanismInput {
  enum class Kind { Link, Slider } kind = Kind::Link;
  int index = 0;  ///< link or joint index
  Rational rate, rate_dot;
};

/// Empty if the arguments make a valid Linkage, else what is wrong (naming links and joints).
std::string linkage_problem(const std::vector<std::string>& link_names, int ground,
                            const std::vector<LinkageJoint>& joints);

}  // namespace linkproof
