// The "user's library" of the oracle consumer: a four-bar's angular accelerations by the
// classical vector loop (conventions §B), written in plain double as a kinematics library would.
#pragma once

#include <vector>

#include "linkproof/mechanism/linkage.h"

/// alpha of every link (ground, crank, coupler, rocker) of a linkproof::testing four-bar, given
/// its input (the crank's omega and omega-dot). `planted_bug` drops the coupler's centripetal
/// term omega3^2 r3 from the acceleration loop: the deliberate bug the oracle must catch.
std::vector<double> fourbar_alpha(const linkproof::Linkage& m, const std::vector<linkproof::MechanismInput>& inputs,
                                  bool planted_bug);

/// omega of every link (ground, crank, coupler, rocker), the velocity half of the same loop.
std::vector<double> my_fourbar_omega(const linkproof::Linkage& m, const std::vector<linkproof::MechanismInput>& inputs);

inline std::vector<double> my_fourbar_alpha(const linkproof::Linkage& m,
                                            const std::vector<linkproof::MechanismInput>& inputs) {
  return fourbar_alpha(m, inputs, false);
}
inline std::vector<double> buggy_fourbar_alpha(const linkproof::Linkage& m,
                                               const std::vector<linkproof::MechanismInput>& inputs) {
  return fourbar_alpha(m, inputs, true);
}
