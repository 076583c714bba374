#include "linkproof/testing/generators.h"

#include <cln/integer.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "linkproof/core/error.h"

namespace linkproof::testing {

namespace {

Rational pow10(int k) { return cln::expt(Rational(10), k); }

Point jturn(const Point& v) { return perp(v); }

/// A point with numerators from gen_coordinate over the denominator `den`.
Point draw_point(int bound, int den) {
  const int x = *gen_coordinate(bound);
  const int y = *gen_coordinate(bound);
  return {Rational(x) / Rational(den), Rational(y) / Rational(den)};
}

/// A non-zero offset with numerators in [-bound, bound].
Point draw_offset(int bound, int den) {
  return *rc::gen::suchThat(rc::gen::exec([=] { return draw_point(bound, den); }),
                            [](const Point& p) { return !cln::zerop(p.x) || !cln::zerop(p.y); });
}

Bias resolve(Bias b) {
  if (b != Bias::Any) return b;
  return static_cast<Bias>(*rc::gen::inRange(0, 5));  // None first: shrinks to an ordinary case
}

/// The bias exponent k in [2, kmax] (shrinks toward 2) and the family suffix.
int draw_exponent(int kmax) { return *rc::gen::inRange(2, kmax + 1); }

/// A point ~eps off the line through `from` in direction v, at s v with s in {1/2, 2, 1/3, 3,
/// 2/3, 3/2} (never 1: the point would sit next to from + v, a short side at a right angle).
Point near_line(const Point& from, const Point& v, const Rational& eps) {
  static const int s[6][2] = {{1, 2}, {2, 1}, {1, 3}, {3, 1}, {2, 3}, {3, 2}};
  const auto& f = s[*rc::gen::inRange(0, 6)];
  return from + (Rational(f[0]) / Rational(f[1])) * v + eps * jturn(v);
}

/// `moved` scaled about `fixed` by 10^(+-k): one link much shorter or longer than the rest.
Point extreme_ratio(const Point& fixed, const Point& moved, int k, bool shorter) {
  return fixed + (shorter ? Rational(1) / pow10(k) : pow10(k)) * (moved - fixed);
}

std::string ratio_suffix(int k, bool shorter) { return fmt::format("/ratio-1e{}{}", shorter ? "-" : "", k); }

std::string_view bias_name(Bias b) {
  switch (b) {
    case Bias::NearDeadCentre: return "near-toggle";
    case Bias::QFar: return "q-far";
    case Bias::BetaSmall: return "beta-small";
    case Bias::ExtremeRatio: return "ratio";
    default: return "none";
  }
}

/// The label of a bias that the family cannot have (the header says why): the case is ordinary.
std::string does_not_apply(Bias b) { return fmt::format("/{}-does-not-apply", bias_name(b)); }

/// One loop of a mechanism read as Dijksman's polygon (conventions §A1): K_1..K_n point into the case's
/// joints, side n is fixed, sides 1..n-3 are the known ones.
struct LoopRef {
  std::vector<Point*> k;
  std::vector<std::string> names;
};

/// NearDeadCentre, QFar or BetaSmall on one loop, as bias_polygon does on a polygon: K_{n-1}
/// moves ~10^-k off a line through K_{n-2}, so that r_{n-2} is nearly parallel to
///   r_{n-1}          (NearDeadCentre: D = r_{n-2} x r_{n-1} ~ 0, the loop's toggle),
///   r_j + r_{n-1}    (QFar: Q_j far away),
///   r_j              (BetaSmall: beta_j small).
/// Returns the suffix, naming the loop by its joints and j ("/q-far-j2-loop-A.B.E.F.G-1e-6").
std::string bias_loop(const LoopRef& l, Bias bias) {
  const size_t n = l.k.size();
  const Point k_nm2 = *l.k[n - 3], k_n = *l.k[n - 1];
  const std::string loop = fmt::format("loop-{}", fmt::join(l.names, "."));
  const int k = draw_exponent(12);
  const Rational eps = Rational(1) / pow10(k);
  if (bias == Bias::NearDeadCentre) {
    *l.k[n - 2] = near_line(k_nm2, k_n - k_nm2, eps);
    return fmt::format("/near-toggle-{}-1e-{}", loop, k);
  }
  const int j = *rc::gen::inRange(1, static_cast<int>(n) - 2);  // 1..n-3, shrinking toward 1
  const Point r_j = *l.k[static_cast<size_t>(j)] - *l.k[static_cast<size_t>(j - 1)];
  if (bias == Bias::QFar) {  // r_{n-2} x (r_j + r_{n-1}) = r_{n-2} x (r_j + K_n - K_{n-2}) ~ 0
    *l.k[n - 2] = near_line(k_nm2, r_j + k_n - k_nm2, eps);
    return fmt::format("/q-far-j{}-{}-1e-{}", j, loop, k);
  }
  *l.k[n - 2] = near_line(k_nm2, r_j, eps);
  return fmt::format("/beta-small-j{}-{}-1e-{}", j, loop, k);
}

std::vector<Point> polygon_points(const PolygonOptions& o, int n, PolygonShape shape, int den) {
  std::vector<Point> pts;
  if (shape == PolygonShape::Scattered) {
    for (int i = 0; i < n; ++i) pts.push_back(draw_point(o.coordinate_bound, den));
    return pts;
  }
  // Convex / star: distinct parameters t on the rational circle ((1 - t^2), 2t) / (1 + t^2).
  auto ts = *rc::gen::unique<std::vector<int>>(static_cast<size_t>(n), rc::gen::inRange(-3 * n, 3 * n + 1));
  std::sort(ts.begin(), ts.end());
  const int radius = *rc::gen::inRange(2, std::max(3, o.coordinate_bound + 1));
  for (int k : ts) {
    const Rational t = Rational(k) / Rational(n);
    const Rational r = shape == PolygonShape::Star ? Rational(*rc::gen::inRange(1, radius + 1)) : Rational(radius);
    const Rational one(1), d(den);
    pts.push_back({r * (one - t * t) / (one + t * t) / d, r * Rational(2) * t / (one + t * t) / d});
  }
  if (*rc::gen::arbitrary<bool>()) std::reverse(pts.begin(), pts.end());  // the paper numbers clockwise
  return pts;
}

std::string_view shape_name(PolygonShape s) {
  switch (s) {
    case PolygonShape::Convex: return "convex";
    case PolygonShape::Star: return "star";
    default: return "scattered";
  }
}

/// Applies a polygon bias; returns the family suffix. Indices: K_j is pts[j-1].
std::string bias_polygon(std::vector<Point>& pts, Bias bias) {
  const size_t n = pts.size();
  const Point &k_n = pts[n - 1], &k_nm2 = pts[n - 3];
  const Point r1 = pts[1] - pts[0];
  switch (bias) {
    case Bias::NearDeadCentre: {
      const int k = draw_exponent(12);
      pts[n - 2] = near_line(k_nm2, k_n - k_nm2, Rational(1) / pow10(k));
      return fmt::format("/near-dead-centre-1e-{}", k);
    }
    case Bias::QFar: {  // r_{n-2} nearly parallel to r_1 + K_n - K_{n-2} (see the header)
      const int k = draw_exponent(12);
      pts[n - 2] = near_line(k_nm2, r1 + k_n - k_nm2, Rational(1) / pow10(k));
      return fmt::format("/q-far-1e-{}", k);
    }
    case Bias::BetaSmall: {  // r_{n-2} nearly parallel to r_1
      const int k = draw_exponent(12);
      pts[n - 2] = near_line(k_nm2, r1, Rational(1) / pow10(k));
      return fmt::format("/beta-small-1e-{}", k);
    }
    case Bias::ExtremeRatio: {
      const int k = draw_exponent(8);
      const bool shorter = *rc::gen::arbitrary<bool>();
      pts[1] = extreme_ratio(pts[0], pts[1], k, shorter);
      return ratio_suffix(k, shorter);
    }
    default: return "";
  }
}

bool polygon_ok(const PolygonCase& c) {
  return polygon_input_problem(c.polygon).empty() && !cln::zerop(c.polygon.dead_centre_determinant());
}

MechanismCase with_suffix(MechanismCase c, const std::string& suffix) {
  c.family += suffix;
  c.scene.name += suffix;
  std::replace(c.scene.name.begin(), c.scene.name.end(), '/', '-');
  return c;
}

MechanismCase draw_fourbar(std::optional<GrashofClass> cls, Bias bias, int bound) {
  const int den = *rc::gen::inRange(1, 4);
  Point o2 = draw_point(bound, den), a = draw_point(bound, den), b = draw_point(bound, den), o4 = draw_point(bound, den);
  // Make the wanted class likely: the shortest link is the crank, ground or coupler.
  if (cls == GrashofClass::CrankRocker) a = o2 + draw_offset(2, den);
  if (cls == GrashofClass::DoubleCrank) o4 = o2 + draw_offset(2, den);
  if (cls == GrashofClass::DoubleRocker) b = a + draw_offset(2, den);
  if (cls == GrashofClass::ChangePoint) b = a + (o4 - o2);  // a parallelogram: s + l = p + q
  std::string suffix;
  if (cls == GrashofClass::ChangePoint) {
    if (bias != Bias::None) suffix = does_not_apply(bias);  // s + l = p + q does not survive a move
  } else {
    if (bias == Bias::NearDeadCentre) {
      const int k = draw_exponent(12);
      b = near_line(a, o4 - a, Rational(1) / pow10(k));
      suffix = fmt::format("/near-toggle-1e-{}", k);
    } else if (bias == Bias::QFar || bias == Bias::BetaSmall) {
      suffix = bias_loop({{&o2, &a, &b, &o4}, {"O2", "A", "B", "O4"}}, bias);
    } else if (bias == Bias::ExtremeRatio) {
      const int k = draw_exponent(8);
      const bool shorter = *rc::gen::arbitrary<bool>();
      a = extreme_ratio(o2, a, k, shorter);
      suffix = ratio_suffix(k, shorter);
    }
  }
  return with_suffix(make_fourbar(o2, a, b, o4, *gen_rate(), *gen_rate()), suffix);
}

/// `biased_loop(p)`: the loop that NearDeadCentre, QFar and BetaSmall bend (bias_loop);
/// `toggle(p)`, if given, places NearDeadCentre instead.
template <size_t N, class Make, class Loop, class Toggle>
MechanismCase draw_multi(Bias bias, int bound, Make make, Loop biased_loop, Toggle toggle) {
  const int den = *rc::gen::inRange(1, 4);
  std::array<Point, N> p;
  for (auto& x : p) x = draw_point(bound, den);
  std::string suffix;
  if (bias == Bias::ExtremeRatio) {  // joints 0 and 1 are the input link's (AB; 12 and 01 in Fig. 5)
    const int k = draw_exponent(8);
    const bool shorter = *rc::gen::arbitrary<bool>();
    p[1] = extreme_ratio(p[0], p[1], k, shorter);
    suffix = ratio_suffix(k, shorter);
  } else if (bias == Bias::NearDeadCentre && toggle) {
    suffix = (*toggle)(p);
  } else if (bias == Bias::NearDeadCentre || bias == Bias::QFar || bias == Bias::BetaSmall) {
    suffix = bias_loop(biased_loop(p), bias);
  }
  const Rational omega = *gen_rate(), omega_dot = *gen_rate();
  return with_suffix(make(p, omega, omega_dot), suffix);
}

/// Watt I: the driven loop C, D, E, F (links BCD, DE, EF, CFG; side CFG fixed, BCD the known
/// side): the dyad DE, EF driven by BCD relative to CFG.
LoopRef watt_loop(std::array<Point, 7>& p) { return {{&p[2], &p[3], &p[4], &p[5]}, {"C", "D", "E", "F"}}; }
/// Stephenson III: the pentagon A, B, E, F, G (links AB, BCE, EF, FG, ground; AB and BCE known).
LoopRef stephenson_loop(std::array<Point, 7>& p) {
  return {{&p[0], &p[1], &p[4], &p[5], &p[6]}, {"A", "B", "E", "F", "G"}};
}
/// Fig. 5: the pentagon 1-2-3-4-0, K = J01, J12, J23, J34, J40 (sides links 1, 2, 3, 4, 0).
LoopRef fig5_loop(std::array<Point, 10>& p) {
  return {{&p[4], &p[0], &p[1], &p[2], &p[3]}, {"J01", "J12", "J23", "J34", "J40"}};
}

/// A real root of the quadratic det(t) = a t^2 + b t + c nearest 0 with |t| <= 8, to within
/// about 10^-digits (exact if the root is rational); nullopt if none.
std::optional<Rational> quadratic_root(const Rational& a, const Rational& b, const Rational& c, int digits) {
  std::vector<Rational> roots;
  if (cln::zerop(a)) {
    if (cln::zerop(b)) return std::nullopt;
    roots.push_back(-c / b);
  } else {
    const Rational disc = b * b - Rational(4) * a * c;
    if (cln::minusp(disc)) return std::nullopt;
    // sqrt(P/Q) = sqrt(P Q) / Q, its integer part at scale S = 10^digits.
    const cln::cl_I P = cln::numerator(disc), Q = cln::denominator(disc), S = cln::expt_pos(cln::cl_I(10), static_cast<unsigned long>(digits));
    cln::cl_I root;
    cln::isqrt(P * Q * S * S, &root);
    const Rational s = Rational(root) / Rational(Q * S);
    roots.push_back((-b + s) / (Rational(2) * a));
    roots.push_back((-b - s) / (Rational(2) * a));
  }
  std::optional<Rational> best;
  for (const Rational& r : roots)
    if (cln::abs(r) <= 8 && (!best || cln::abs(r) < cln::abs(*best))) best = r;
  return best;
}

/// NearDeadCentre for the Fig. 5 eight-bar, whose loops are coupled (no loop's D is the
/// mechanism's dead point): joint m moves along u to t ~10^-k past a root of the velocity
/// determinant det(p_m + t u), which is quadratic in t (p_m enters the columns of its two links).
/// Up to six (joint, direction) draws; kToggleNotFound if none has a usable root.
constexpr std::string_view kToggleNotFound = "/near-toggle-not-found";

std::string fig5_toggle(std::array<Point, 10>& p) {
  static const char* names[10] = {"J12", "J23", "J34", "J40", "J01", "J15", "J57", "J74", "J56", "J63"};
  const int k = draw_exponent(12);
  for (int attempt = 0; attempt < 6; ++attempt) {
    const size_t m = static_cast<size_t>(*rc::gen::inRange(0, 10));
    const Point u = draw_offset(2, 1);
    std::optional<Rational> failed;
    const auto det = [&](const Rational& t) -> Rational {
      auto q = p;
      q[m] = p[m] + t * u;
      try {
        return compute_velocity_determinant(make_fig5_eightbar(q, 1, 0).scene);
      } catch (const InputError&) {
        failed = t;
        return 0;
      }
    };
    const Rational f0 = det(0), f1 = det(1), fm1 = det(-1);
    const Rational a = (f1 + fm1) / Rational(2) - f0, b = (f1 - fm1) / Rational(2), c = f0;
    if (failed || det(2) != Rational(4) * a + Rational(2) * b + c || det(-2) != Rational(4) * a - Rational(2) * b + c)
      continue;  // not a quadratic: a builder refused a position
    const auto root = quadratic_root(a, b, c, k + 4);
    if (!root) continue;
    const Rational grid = pow10(k + 2), eps = Rational(1) / pow10(k);
    const Rational t = Rational(cln::round1(*root * grid)) / grid + eps;
    // The root lies between t - 2 eps and t: det changes sign there (checked, not assumed).
    const Rational at = det(t), before = det(t - Rational(2) * eps);
    if (failed || cln::zerop(at) || !cln::minusp(at * before)) continue;
    p[m] = p[m] + t * u;
    return fmt::format("/near-toggle-{}-1e-{}", names[m], k);
  }
  return std::string(kToggleNotFound);
}

/// kind 0 slider-crank, 1 inverted, -1 either.
MechanismCase draw_slider(Bias bias, int bound, int kind) {
  const int den = *rc::gen::inRange(1, 4);
  const bool inverted = (kind < 0 ? *rc::gen::inRange(0, 2) : kind) == 1;
  Point o = draw_point(bound, den), a = draw_point(bound, den), b = draw_point(bound, den);
  std::string suffix;
  if (bias == Bias::ExtremeRatio) {
    const int k = draw_exponent(8);
    const bool shorter = *rc::gen::arbitrary<bool>();
    a = extreme_ratio(o, a, k, shorter);
    suffix = ratio_suffix(k, shorter);
  }
  if (bias == Bias::QFar || bias == Bias::BetaSmall) suffix = does_not_apply(bias);
  if (inverted) {
    if (bias == Bias::NearDeadCentre) {  // A ~10^-k from the slot's pivot O4 (here b): omega ~ 1/|A O4|
      const int k = draw_exponent(12);
      a = b + (Rational(1) / pow10(k)) * draw_offset(2, 1);
      suffix = fmt::format("/near-toggle-1e-{}", k);
    }
    const Rational omega = *gen_rate(), omega_dot = *gen_rate();
    return with_suffix(make_inverted_slider_crank(o, a, b, omega, omega_dot), suffix);
  }
  Point axis = draw_offset(3, 1);
  if (bias == Bias::NearDeadCentre) {  // the rod nearly perpendicular to the guide: v_B undetermined
    const int k = draw_exponent(12);
    axis = jturn(b - a) + (Rational(1) / pow10(k)) * (b - a);
    suffix = fmt::format("/near-toggle-1e-{}", k);
  }
  const Rational omega = *gen_rate(), omega_dot = *gen_rate();
  return with_suffix(make_slider_crank(o, a, b, axis, omega, omega_dot), suffix);
}

rc::Gen<MechanismCase> well_posed(rc::Gen<MechanismCase> g) {
  return rc::gen::suchThat(std::move(g), [](const MechanismCase& c) { return is_well_posed(c.scene); });
}

}  // namespace

rc::Gen<int> gen_coordinate(int bound) {
  // 0, 1, -1, 2, -2, ...: the index shrinks toward 0, so |value| does.
  return rc::gen::map(rc::gen::inRange(0, 2 * bound + 1), [](int i) { return i % 2 == 1 ? (i + 1) / 2 : -(i / 2); });
}

rc::Gen<Rational> gen_rate() {
  return rc::gen::exec([] {
    const int num = *gen_coordinate(6);
    const int den = *rc::gen::inRange(1, 5);
    return Rational(num) / Rational(den);
  });
}

rc::Gen<PolygonCase> gen_polygon(PolygonOptions o) {
  return rc::gen::suchThat(rc::gen::exec([o] {
                             const int n = *rc::gen::inRange(o.n_min, o.n_max + 1);
                             const PolygonShape shape =
                                 o.shape == PolygonShape::Any ? static_cast<PolygonShape>(*rc::gen::inRange(0, 3)) : o.shape;
                             const int den = *rc::gen::inRange(1, 4);
                             std::vector<Point> pts = polygon_points(o, n, shape, den);
                             const std::string suffix = bias_polygon(pts, resolve(o.bias));
                             PolygonCase c;
                             c.family = fmt::format("polygon/{}/n={}{}", shape_name(shape), n, suffix);
                             c.polygon = Polygon<Rational>(std::move(pts));
                             for (int j = 0; j + 3 < n; ++j) {
                               c.rates.omega.push_back(*gen_rate());
                               c.rates.omega_dot.push_back(*gen_rate());
                             }
                             return c;
                           }),
                           polygon_ok);
}

rc::Gen<MechanismCase> gen_fourbar(std::optional<GrashofClass> grashof, Bias bias, int bound) {
  return rc::gen::suchThat(rc::gen::exec([=] { return draw_fourbar(grashof, resolve(bias), bound); }),
                           [grashof](const MechanismCase& c) {
                             return (!grashof || c.family.rfind(fmt::format("fourbar/{}", to_string(*grashof)), 0) == 0) &&
                                    is_well_posed(c.scene);
                           });
}

rc::Gen<MechanismCase> gen_watt_sixbar(Bias bias, int bound) {
  using Toggle = std::string (*)(std::array<Point, 7>&);
  return well_posed(rc::gen::exec(
      [=] { return draw_multi<7>(resolve(bias), bound, make_watt_sixbar, watt_loop, std::optional<Toggle>()); }));
}

rc::Gen<MechanismCase> gen_stephenson_sixbar(Bias bias, int bound) {
  using Toggle = std::string (*)(std::array<Point, 7>&);
  return well_posed(rc::gen::exec([=] {
    return draw_multi<7>(resolve(bias), bound, make_stephenson_sixbar, stephenson_loop, std::optional<Toggle>());
  }));
}

rc::Gen<MechanismCase> gen_fig5_eightbar(Bias bias, int bound) {
  using Toggle = std::string (*)(std::array<Point, 10>&);
  // A draw whose toggle search failed is drawn again, so NearDeadCentre always gives a toggle.
  return rc::gen::suchThat(rc::gen::exec([=] {
                             return draw_multi<10>(resolve(bias), bound, make_fig5_eightbar, fig5_loop,
                                                   std::optional<Toggle>(fig5_toggle));
                           }),
                           [](const MechanismCase& c) {
                             return c.family.find(kToggleNotFound) == std::string::npos && is_well_posed(c.scene);
                           });
}

rc::Gen<MechanismCase> gen_slider_mechanism(Bias bias, int bound) {
  return well_posed(rc::gen::exec([=] { return draw_slider(resolve(bias), bound, -1); }));
}

rc::Gen<MechanismCase> gen_mechanism(MechanismOptions o) {
  if (o.families.empty())
    o.families = {Family::FourBar,    Family::SliderCrank,      Family::InvertedSliderCrank, Family::WattSixBar,
                  Family::StephensonSixBar, Family::Fig5EightBar, Family::Polygon};
  return rc::gen::exec([o] {
    const Family f = o.families[static_cast<size_t>(*rc::gen::inRange(0, static_cast<int>(o.families.size())))];
    switch (f) {
      case Family::FourBar: return *gen_fourbar(o.grashof, o.bias, o.coordinate_bound);
      case Family::SliderCrank:
      case Family::InvertedSliderCrank: {
        const int kind = f == Family::SliderCrank ? 0 : 1;
        return *well_posed(rc::gen::exec([=] { return draw_slider(resolve(o.bias), o.coordinate_bound, kind); }));
      }
      case Family::WattSixBar: return *gen_watt_sixbar(o.bias, o.coordinate_bound);
      case Family::StephensonSixBar: return *gen_stephenson_sixbar(o.bias, o.coordinate_bound);
      case Family::Fig5EightBar: return *gen_fig5_eightbar(o.bias, o.coordinate_bound);
      case Family::Polygon: {
        PolygonOptions po = o.polygon;
        if (po.bias == Bias::None) po.bias = o.bias;
        return polygon_mechanism(*gen_polygon(po));
      }
    }
    return *gen_fourbar(o.grashof, o.bias, o.coordinate_bound);
  });
}

/// The family label without the bias exponent ("near-dead-centre-1e-7" -> "near-dead-centre"),
/// so that coverage counts cases per family and bias.
std::string coverage_label(std::string family) {
  for (auto p = family.find("-1e"); p != std::string::npos; p = family.find("-1e")) {
    auto end = family.find('/', p);
    family.erase(p, end == std::string::npos ? std::string::npos : end - p);
  }
  return family;
}

void classify_case(const MechanismCase& c) { RC_CLASSIFY(true, coverage_label(c.family)); }
void classify_case(const PolygonCase& c) { RC_CLASSIFY(true, coverage_label(c.family)); }

}  // namespace linkproof::testing
