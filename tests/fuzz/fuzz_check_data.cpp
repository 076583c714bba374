// libFuzzer target: `check-data` on a fixed four-bar (io/motion_data.h, numerics/data_check.h).
// Any bytes as the CSV must give an InputError or a check; a check must never say "agrees" for a
// value whose difference or tolerance is not finite (NaN, infinity), and every comparison must
// be the exact rule of compare_recorded.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"
#include "io/motion_data.h"
#include "numerics/data_check.h"

namespace {

const linkproof::MechanismScene& fourbar() {
  static const linkproof::MechanismScene scene = linkproof::parse_mechanism_scene(R"(name: fourbar
mechanism:
  ground: g
  joints:
    - {name: O2, type: revolute, links: [g, crank], at: [0, 0]}
    - {name: A, type: revolute, links: [crank, coupler], at: [3, 4]}
    - {name: B, type: revolute, links: [coupler, rocker], at: [11, 10]}
    - {name: O4, type: revolute, links: [rocker, g], at: [11, 0]}
  inputs:
    - {link: crank, omega: 2, omega_dot: 5}
)", "fourbar.yaml");
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const linkproof::MechanismScene& scene = fourbar();
  linkproof::DataCheck check;
  try {
    check = linkproof::check_motion_data(scene, linkproof::parse_motion_data(text, "fuzz.csv", scene));
  } catch (const linkproof::InputError&) {
    return 0;
  }
  for (const auto& s : check.samples)
    for (const auto& c : s.checks)
      if (c.agrees() && !(std::isfinite(c.tolerance) && std::isfinite(c.difference))) std::abort();
  return 0;
}
