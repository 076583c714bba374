// Where a linkage's joints are and which way its prismatic axes point, in a scalar type T.
//
// The kinematics (mechanism_vector_route.h, linkage_motion.h, poles.h) read every joint position
// and axis through a JointGeometry. By default these are the linkage's own exact values converted
// to T; a caller may give them in T instead: Tracked positions whose radius is the uncertainty of
// recorded data (numerics/data_check.cpp), or symbols, so that one evaluation covers every
// configuration of a topology (proof/mechanism_proof.h).
#pragma once

#include <vector>

#include "core/scalar.h"
#include "linkproof/mechanism/linkage.h"

namespace linkproof {

template <class T>
struct JointGeometry {
  const std::vector<Vec2<T>>* at = nullptr;    ///< per joint; null: the linkage's positions
  const std::vector<Vec2<T>>* axis = nullptr;  ///< per joint (revolute entries unread); null: the linkage's axes

  Vec2<T> position(const Linkage& g, int joint) const {
    return at ? (*at)[static_cast<size_t>(joint)] : vec_from_rational<T>(g.joint(joint).at);
  }
  Vec2<T> direction(const Linkage& g, int joint) const {
    return axis ? (*axis)[static_cast<size_t>(joint)] : vec_from_rational<T>(g.joint(joint).axis);
  }
};

}  // namespace linkproof
