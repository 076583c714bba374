#include "proof/topology_configurations.h"

#include <cln/integer.h>
#include <fmt/format.h>

#include <chrono>

#include "check/arithmetic_types.h"
#include "check/judge.h"
#include "check/random_polygon.h"
#include "linkproof/io/mechanism_scene.h"
#include "mechanism/mechanism_data_claim.h"
#include "mechanism/mechanism_vector_route.h"
#include "mechanism/zero_length_driver.h"

namespace linkproof {

namespace {

// Rational unit directions (Pythagorean triples): |u| = 1 exactly, so sliding_v is rational.
const Vec2<SmallFraction> kUnitDirections[] = {{{1, 1}, {0, 1}}, {{3, 5}, {4, 5}}, {{5, 13}, {12, 13}}, {{8, 17}, {15, 17}}};

using Layout = TopologyLayout;

using Config = TopologyValues;

MechanismScene build_scene(const MechanismScene& topology, const Layout& layout, const Config& c, const std::string& name) {
  return topology_configuration(topology, layout, c, name);
}

SmallFraction random_rate(SplitMix64& rng, bool nonzero) {
  long p = rng.uniform(-9, 9);
  if (nonzero && p == 0) p = 1;
  return {p, rng.uniform(1, 4)};
}

// Configuration `index` of `seed`: integer positions in [-range, range], Pythagorean axes, rates
// p/q with |p| <= 9, q <= 4 (the input rate never 0).
TopologyDraw random_config(const MechanismScene& topology, const Layout& layout, std::uint64_t seed, int index, int range) {
  SplitMix64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(index) * 0xBF58476D1CE4E5B9ull + 0x51ull);
  TopologyDraw c;
  c.positions.reserve(static_cast<size_t>(layout.groups()));
  for (int g = 0; g < layout.groups(); ++g) {
    const long x = rng.uniform(-range, range);
    c.positions.push_back({{x, 1}, {rng.uniform(-range, range), 1}});
  }
  c.axes.reserve(topology.linkage.joints().size());
  for (const LinkageJoint& j : topology.linkage.joints()) {
    Vec2<SmallFraction> u = kUnitDirections[rng.uniform(0, 3)];
    if (rng.uniform(0, 1)) std::swap(u.x, u.y);
    for (long turn = rng.uniform(0, 3); turn > 0; --turn) u = {{-u.y.p, u.y.d}, u.x};  // +90 degrees
    c.axes.push_back(j.type == JointType::Prismatic ? u : Vec2<SmallFraction>{});
  }
  for (size_t k = 0; k < topology.inputs.size(); ++k) {
    c.rate.push_back(random_rate(rng, true));
    c.rate_dot.push_back(random_rate(rng, false));
  }
  return c;
}

// The exact motion by the rigid-body route; nullopt for a singular velocity system.
std::optional<MechanismSolution<Rational>> solve(const MechanismScene& s) {
  try {
    return solve_mechanism<Rational>(
        s.linkage, s.inputs, rigid_body_constraint_matrix<Rational>(s.linkage),
        [&](const std::vector<Rational>& qd) { return rigid_body_acceleration_rhs<Rational>(s.linkage, qd); }, s.source);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// Fails / Holds / Undefined of one claim on one solved configuration (no evidence kept).
template <class T>
Verdict quick_verdict(const MechanismDataClaim& claim, const MechanismFrameOf<T>& frame, std::string* quantity,
                      std::string* reason) {
  const ClaimSides<T> sides = evaluate_mechanism_claim(claim, frame);
  Verdict v = Verdict::Holds;
  for (const auto& c : sides.instances) {
    if (!c.lhs.has_value() || !c.rhs.has_value()) {
      const auto& u = c.lhs.has_value() ? c.rhs : c.lhs;
      if (quantity && quantity->empty()) *quantity = u.quantity(), *reason = u.reason();
      v = combine(v, Verdict::Undefined);
    } else {
      v = combine(v, c.lhs.get() == c.rhs.get() ? Verdict::Holds : Verdict::Fails);
    }
  }
  return v;
}

// True if the scene reader accepts a configuration of the topology as written, a counterexample
// must replay. Of what the reader checks, only a driven link of zero length depends on the
// positions, and it is tested here on the values (a YAML round trip per failing configuration
// was most of a sweep with wrong claims); TopologyConfigurations.ReplayableIsWhatTheSceneReaderAccepts
// compares the two on every bundled topology, and each written counterexample is read back.
bool is_readable(const MechanismScene& topology, const Layout& layout, const Config& c) {
  std::vector<Vec2<Rational>> at;
  at.reserve(layout.joint_group.size());
  for (const int g : layout.joint_group) at.push_back(c.positions[static_cast<size_t>(g)]);
  return !zero_length_driver(topology.linkage, topology.inputs, at).has_value();
}

// The verdict of one claim on a configuration solved in a floating arithmetic T (Tracked<F>):
// every comparison judged with its derived bound; the first inconclusive one's reason is kept.
template <class T>
Verdict floating_verdict(const MechanismDataClaim& claim, const MechanismFrameOf<T>& frame, SampleResult& r) {
  Verdict v = Verdict::Holds;
  try {
    const ClaimSides<T> sides = evaluate_mechanism_claim(claim, frame);
    for (const Comparison<T>& c : sides.instances) {
      const ComparisonOutcome o = judge(c);
      if (o.verdict == Verdict::Undefined && r.undefined_quantity.empty())
        r.undefined_quantity = o.undefined_quantity, r.undefined_reason = o.reason;
      if (o.verdict == Verdict::Inconclusive && !r.first_inconclusive) r.first_inconclusive = o;
      v = combine(v, o.verdict);
    }
  } catch (const cln::floating_point_exception& e) {  // e.g. an exponent overflow of a CLN float
    if (!r.first_inconclusive) {
      ComparisonOutcome o;
      o.label = "total";
      o.verdict = Verdict::Inconclusive;
      o.reason = e.what();
      r.first_inconclusive = std::move(o);
    }
    return Verdict::Inconclusive;
  }
  return v;
}

// The verdict of each open claim (not `done`) on configuration s, solved and judged in T, each
// claim's time added to `seconds`; nullopt where s is singular in T. A floating failure is
// confirmed exactly: the bounds are rigorous, so the exact sides must differ, and the
// counterexample that is shrunk and written is an exact one.
template <class T, class NameOf>
std::optional<std::vector<Verdict>> configuration_verdicts(const MechanismScene& topology, const Layout& layout,
                                                           const TopologyDraw& config, const NameOf& name_of,
                                                           const std::vector<MechanismDataClaim>& claims,
                                                           const std::vector<bool>& done,
                                                           std::vector<SampleResult>& results,
                                                           std::vector<double>& seconds) {
  using Clock = std::chrono::steady_clock;
  // Solved from the values in T alone (the topology's linkage, the configuration's geometry):
  // the scene is built only for a failure, which must be confirmed and replayed.
  TopologyValuesIn<T> values = topology_values_in<T>(topology, layout, config);
  std::optional<MechanismSolution<T>> solution;
  try {
    const JointGeometry<T> geo = values.geometry();
    const Linkage& g = topology.linkage;
    solution = solve_mechanism<T>(
        g, topology.inputs, rigid_body_constraint_matrix<T>(g, geo),
        [&](const std::vector<T>& qd) { return rigid_body_acceleration_rhs<T>(g, qd, true, geo); },
        topology.source,  // its errors only say "singular here" (nullopt): no name is made for them
        &values.inputs, geo, JointMotion::Skip);  // the claims read the links' fields
  } catch (const InputError&) {
    return std::nullopt;
  } catch (const cln::floating_point_exception&) {
    return std::nullopt;
  }
  // The positions move into the frame (nothing reads `values` after). The sampled axes are
  // exactly unit vectors (Pythagorean directions).
  const MechanismFrameOf<T> frame(topology, solution->motion, std::move(values.joint_at), std::move(values.point_at),
                                  std::move(values.axis), true);
  std::optional<MechanismSolution<Rational>> exact;
  std::optional<MechanismScene> s;
  std::vector<Verdict> out(claims.size(), Verdict::Holds);
  for (size_t k = 0; k < claims.size(); ++k) {
    if (done[k]) continue;
    const auto t0 = Clock::now();
    SampleResult& r = results[k];
    if constexpr (ScalarTraits<T>::is_exact) {
      out[k] = quick_verdict(claims[k], frame, &r.undefined_quantity, &r.undefined_reason);
    } else {
      out[k] = floating_verdict(claims[k], frame, r);
      if (out[k] == Verdict::Fails) {
        if (!s) s = build_scene(topology, layout, config.exact(), name_of());
        if (!exact) exact = solve(*s);
        LINKPROOF_ASSERT(exact.has_value(), "a floating failure on a configuration that is singular exactly");
        const MechanismFrame exact_frame(*s, exact->motion);
        LINKPROOF_ASSERT(quick_verdict(claims[k], exact_frame, nullptr, nullptr) == Verdict::Fails,
                         "a floating failure the exact sides do not confirm");
      }
    }
    seconds[k] += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  return out;
}

bool still_fails(const MechanismDataClaim& claim, const MechanismScene& topology, const Layout& layout, const Config& c,
                 const std::string& name) {
  if (!is_readable(topology, layout, c)) return false;
  const MechanismScene s = build_scene(topology, layout, c, name);
  const auto solution = solve(s);
  if (!solution) return false;
  const MechanismFrame frame(s, solution->motion);
  return quick_verdict(claim, frame, nullptr, nullptr) == Verdict::Fails;
}

// Size of a rational for shrinking: |numerator| + denominator.
Rational size_of(const Rational& q) {
  const cln::cl_I n = cln::abs(cln::numerator(q)), d = cln::denominator(q);
  return Rational(n) + Rational(d);
}

std::vector<Rational> smaller_integers(const Rational& x) {
  std::vector<Rational> out{0};
  const cln::cl_I t = cln::truncate1(x);
  if (t != 0) out.push_back(cln::truncate1(t, 2));
  if (t > 0) out.push_back(t - cln::cl_I(1));
  if (t < 0) out.push_back(t + cln::cl_I(1));
  if (Rational(t) != x) out.push_back(t);
  return out;
}

std::vector<Rational> smaller_rates(const Rational& x, bool nonzero) {
  std::vector<Rational> out;
  if (!nonzero) out.push_back(0);
  out.push_back(1);
  out.push_back(-1);
  for (const Rational& r : smaller_integers(x))
    if (!nonzero || r != 0) out.push_back(r);
  return out;
}

// Shrinks a failing configuration one value at a time (see the header comment).
MechanismCounterexample shrink_failure(const MechanismDataClaim& claim, const MechanismScene& topology, const Layout& layout,
                               Config c, int index, const TopologySampling& o) {
  MechanismCounterexample cx;
  cx.configuration = index;
  const std::string name = fmt::format("counterexample-{}", claim.info.id);
  const auto accept = [&](Config candidate) {
    if (cx.shrink_tried >= o.shrink_budget) return false;
    ++cx.shrink_tried;
    if (!still_fails(claim, topology, layout, candidate, name)) return false;
    c = std::move(candidate);
    ++cx.shrink_steps;
    return true;
  };
  for (bool changed = true; changed && cx.shrink_tried < o.shrink_budget;) {
    changed = false;
    for (size_t g = 0; g < c.positions.size(); ++g)
      for (int axis = 0; axis < 2; ++axis) {
        const Rational current = axis ? c.positions[g].y : c.positions[g].x;
        for (const Rational& v : smaller_integers(current)) {
          if (!(size_of(v) < size_of(current))) continue;
          Config t = c;
          (axis ? t.positions[g].y : t.positions[g].x) = v;
          if (accept(std::move(t))) { changed = true; break; }
        }
      }
    for (size_t j = 0; j < c.axes.size(); ++j) {
      if (topology.linkage.joint(static_cast<int>(j)).type != JointType::Prismatic) continue;
      for (const Vec2<Rational>& u : {Vec2<Rational>{1, 0}, Vec2<Rational>{0, 1}}) {
        if (c.axes[j].x == u.x && c.axes[j].y == u.y) break;
        Config t = c;
        t.axes[j] = u;
        if (accept(std::move(t))) { changed = true; break; }
      }
    }
    for (size_t k = 0; k < c.rate.size(); ++k)
      for (int dot = 0; dot < 2; ++dot) {
        const Rational current = dot ? c.rate_dot[k] : c.rate[k];
        for (const Rational& v : smaller_rates(current, !dot)) {
          if (!(size_of(v) < size_of(current)) && !(size_of(v) == size_of(current) && v > current)) continue;
          Config t = c;
          (dot ? t.rate_dot[k] : t.rate[k]) = v;
          if (accept(std::move(t))) { changed = true; break; }
        }
      }
  }
  cx.scene = build_scene(topology, layout, c, name);
  cx.scene.source = "counterexample";
  cx.scene_yaml = mechanism_scene_to_yaml(cx.scene);
  try {  // it replays: the scene reader accepts what was written
    parse_mechanism_scene(cx.scene_yaml, "counterexample");
  } catch (const InputError& e) {
    LINKPROOF_ASSERT(false, std::string("a counterexample the scene reader refuses: ") + e.what());
  }
  const auto solution = solve(cx.scene);
  LINKPROOF_ASSERT(solution.has_value(), "a shrunk counterexample that does not solve");
  const MechanismContext ctx{cx.scene, *solution};
  cx.outcome = run_mechanism_claim(to_mechanism_claim(claim), ctx);
  return cx;
}

}  // namespace

TopologyConfigurations::TopologyConfigurations(const MechanismScene& scene, const std::vector<MechanismDataClaim>& claims,
                                               const TopologySampling& options)
    : scene_(scene), claims_(claims), options_(options), layout_(topology_layout(scene)) {}

TopologyValues TopologyConfigurations::values(int index) const {
  return random_config(scene_, layout_, options_.seed, index, options_.coordinate_range).exact();
}

std::string TopologyConfigurations::name(int index) const { return fmt::format("{}-sample-{}", scene_.name, index); }

std::optional<std::vector<Verdict>> TopologyConfigurations::judge(int index, const std::vector<bool>& skip,
                                                                  std::vector<SampleResult>& notes,
                                                                  std::vector<double>& seconds) const {
  const TopologyDraw config = random_config(scene_, layout_, options_.seed, index, options_.coordinate_range);
  const auto name_of = [&] { return name(index); };
  return with_scalar_type(options_.arithmetic, [&]<class T>() {
    return configuration_verdicts<T>(scene_, layout_, config, name_of, claims_, skip, notes, seconds);
  });
}

bool TopologyConfigurations::is_replayable(int index) const { return is_readable(scene_, layout_, values(index)); }

MechanismCounterexample TopologyConfigurations::shrink(size_t claim, int index) const {
  return shrink_failure(claims_[claim], scene_, layout_, values(index), index, options_);
}

}  // namespace linkproof
