// Koshel et al. (conventions §C): the eight-link class-III mechanism with two sliders.
// Link names are the paper's: crank "1" (driven, omega1 constant), rocker "5" (the driver the
// paper switches to), frame "0"; joint "A" is the crank pin.
#include <fmt/format.h>

#include "mechanism/mechanism_vector_route.h"
#include "mechanism_catalogues.h"
#include "mechanism/mechanism_catalogue.h"

namespace linkproof::catalogues {

namespace {

const char* kKoshelClass3Source = "Koshel et al., docs/conventions.md §C";

MechanismSolution<Rational> solve_vector(const MechanismScene& s, const Linkage& g, const std::vector<MechanismInput>& in,
                                         bool coriolis = true) {
  return solve_mechanism<Rational>(
      g, in, rigid_body_constraint_matrix<Rational>(g),
      [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(g, qd, coriolis); }, s.source);
}

bool koshel_class3_applies(const MechanismContext& c) {
  const Linkage& g = c.scene.linkage;
  const auto one = g.find_link("1"), five = g.find_link("5");
  return c.truth.mobility == 1 && one && five && g.find_joint("A") && c.scene.inputs[0].kind == MechanismInput::Kind::Link &&
         c.scene.inputs[0].index == *one && !cln::zerop(c.truth.motion.omega[static_cast<size_t>(*five)]);
}

// The motion with link 5 as the driver at its true omega and the given trial omega-dot.
MechanismSolution<Rational> trial_plan(const MechanismContext& c, const Rational& epsilon5) {
  const Linkage& g = c.scene.linkage;
  const int five = *g.find_link("5");
  return solve_vector(c.scene, g, {MechanismInput{MechanismInput::Kind::Link, five,
                                                  c.truth.motion.omega[static_cast<size_t>(five)], epsilon5}});
}

// The mechanism referred to link `frame` (a kinematic inversion): every omega relative to it.
ClaimSides<Rational> inverted(const MechanismContext& c, bool coriolis) {
  const Linkage& g = c.scene.linkage;
  ClaimSides<Rational> s;
  const auto& m = c.truth.motion;
  for (int frame = 0; frame < g.link_count(); ++frame) {
    if (frame == g.ground()) continue;
    const Linkage moved(g.link_names(), frame, g.joints());
    const size_t f = static_cast<size_t>(frame);
    // Driven by the scene's input link relative to the new frame (by the old frame if the input
    // link is the new frame): a link input that can turn relative to the frame.
    const int driver = c.scene.inputs[0].index == frame ? g.ground() : c.scene.inputs[0].index;
    const size_t d = static_cast<size_t>(driver);
    const auto r = solve_vector(
        c.scene, moved,
        {MechanismInput{MechanismInput::Kind::Link, driver, m.omega[d] - m.omega[f], m.omega_dot[d] - m.omega_dot[f]}},
        coriolis);
    for (int l = 0; l < g.link_count(); ++l)
      s.instances.push_back({fmt::format("frame {}: omega_dot[{},{}]", g.link_name(frame), g.link_name(l), g.link_name(frame)),
                             r.motion.omega_dot[static_cast<size_t>(l)], m.omega_dot[static_cast<size_t>(l)] - m.omega_dot[f]});
  }
  return s;
}

bool has_moving_guide_after_inversion(const MechanismContext& c) {
  return koshel_class3_applies(c) && c.scene.linkage.prismatic_count() > 0;
}

}  // namespace

MechanismCatalogue koshel_class3() {
  MechanismCatalogue cat;
  cat.name = "koshel_class3";
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"koshel.driver5", kKoshelClass3Source,
                "with rocker 5 as the driver (omega5, epsilon5 of the true motion) every link has the same omega and "
                "epsilon as with crank 1 as the driver",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const int five = *c.scene.linkage.find_link("5");
        const auto r = trial_plan(c, c.truth.motion.omega_dot[static_cast<size_t>(five)]);
        ClaimSides<Rational> s;
        for (int l = 0; l < c.scene.linkage.link_count(); ++l) {
          const std::string n = c.scene.linkage.link_name(l);
          s.instances.push_back({"omega[" + n + "]", r.motion.omega[static_cast<size_t>(l)], c.truth.motion.omega[static_cast<size_t>(l)]});
          s.instances.push_back({"epsilon[" + n + "]", r.motion.omega_dot[static_cast<size_t>(l)],
                                 c.truth.motion.omega_dot[static_cast<size_t>(l)]});
        }
        return s;
      },
      koshel_class3_applies});
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"koshel.eq15.rescaling", kKoshelClass3Source,
                "step (15): the acceleration plan drawn from a trial epsilon5 = 1, rescaled as a whole so that the crank "
                "pin's acceleration a_A takes its true size, gives the true epsilon_i (compared squared: "
                "(|a_A|/|a_A trial|)^2 epsilon_i(trial)^2 = epsilon_i^2)",
                Expectation::Fails,
                "invalid step: the plan is affine in epsilon5 (a = a0 + epsilon5 b, a0 fixed by the velocities), so "
                "one scale factor cannot map it to the true plan (docs/conventions.md §C)",
                4, 0},
      [](const MechanismContext& c) {
        const Linkage& g = c.scene.linkage;
        const size_t A = static_cast<size_t>(*g.find_joint("A"));
        const auto trial = trial_plan(c, Rational(1));
        const Rational k2 = norm2(c.truth.motion.joint_a[A]) / norm2(trial.motion.joint_a[A]);
        ClaimSides<Rational> s;
        for (int l = 0; l < g.link_count(); ++l) {
          if (l == g.ground()) continue;
          const Rational& e = trial.motion.omega_dot[static_cast<size_t>(l)];
          const Rational& t = c.truth.motion.omega_dot[static_cast<size_t>(l)];
          s.instances.push_back({"epsilon[" + g.link_name(l) + "]^2", k2 * e * e, t * t});
        }
        return s;
      },
      koshel_class3_applies});
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"koshel.eq15.superposition", kKoshelClass3Source,
                "the correct use of the trial plan: epsilon_i = epsilon_i(0) + (epsilon1 - epsilon1(0)) omega_i/omega1, "
                "epsilon_i(0) from the plan with epsilon5 = 0 (false position on the affine map)",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) {
        const Linkage& g = c.scene.linkage;
        const size_t one = static_cast<size_t>(*g.find_link("1"));
        const auto zero = trial_plan(c, Rational(0));
        const auto& m = c.truth.motion;
        const Rational t = (m.omega_dot[one] - zero.motion.omega_dot[one]) / m.omega[one];
        ClaimSides<Rational> s;
        for (int l = 0; l < g.link_count(); ++l) {
          const size_t ll = static_cast<size_t>(l);
          s.instances.push_back({"epsilon[" + g.link_name(l) + "]", zero.motion.omega_dot[ll] + t * m.omega[ll], m.omega_dot[ll]});
        }
        return s;
      },
      koshel_class3_applies});
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"koshel.coriolis.inversion", kKoshelClass3Source,
                "referred to any moving link as the frame (its guides then move), the solve with the Coriolis term "
                "2 omega_guide sigma-dot J u gives every relative epsilon_ik unchanged",
                Expectation::Holds, "", 4, 0},
      [](const MechanismContext& c) { return inverted(c, true); }, has_moving_guide_after_inversion});
  cat.claims.push_back(MechanismClaim{
      ClaimInfo{"koshel.coriolis.dropped", kKoshelClass3Source,
                "the same without the Coriolis term gives the relative epsilon_ik unchanged",
                Expectation::Fails,
                "the Coriolis term of a prismatic pair is needed as soon as the guide moves (docs/conventions.md §C, prismatic pair)", 4,
                0},
      [](const MechanismContext& c) { return inverted(c, false); }, has_moving_guide_after_inversion});
  for (auto& step : koshel_printed_chain()) cat.claims.push_back(std::move(step));
  return cat;
}

}  // namespace linkproof::catalogues
