#include "linkproof/testing/generators.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

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
  if (cls != GrashofClass::ChangePoint) {
    if (bias == Bias::NearDeadCentre) {
      const int k = draw_exponent(12);
      b = near_line(a, o4 - a, Rational(1) / pow10(k));
      suffix = fmt::format("/near-toggle-1e-{}", k);
    } else if (bias == Bias::ExtremeRatio) {
      const int k = draw_exponent(8);
      const bool shorter = *rc::gen::arbitrary<bool>();
      a = extreme_ratio(o2, a, k, shorter);
      suffix = ratio_suffix(k, shorter);
    }
  }
  return with_suffix(make_fourbar(o2, a, b, o4, *gen_rate(), *gen_rate()), suffix);
}

template <size_t N, class Make>
MechanismCase draw_multi(Bias bias, int bound, Make make) {
  const int den = *rc::gen::inRange(1, 4);
  std::array<Point, N> p;
  for (auto& x : p) x = draw_point(bound, den);
  std::string suffix;
  if (bias == Bias::ExtremeRatio) {  // joints 0 and 1 are the input link's (AB; 12 and 01 in Fig. 5)
    const int k = draw_exponent(8);
    const bool shorter = *rc::gen::arbitrary<bool>();
    p[1] = extreme_ratio(p[0], p[1], k, shorter);
    suffix = ratio_suffix(k, shorter);
  }
  return with_suffix(make(p, *gen_rate(), *gen_rate()), suffix);
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
  if (inverted) return with_suffix(make_inverted_slider_crank(o, a, b, *gen_rate(), *gen_rate()), suffix);
  Point axis = draw_offset(3, 1);
  if (bias == Bias::NearDeadCentre) {  // the rod nearly perpendicular to the guide: v_B undetermined
    const int k = draw_exponent(12);
    axis = jturn(b - a) + (Rational(1) / pow10(k)) * (b - a);
    suffix = fmt::format("/near-toggle-1e-{}", k);
  }
  return with_suffix(make_slider_crank(o, a, b, axis, *gen_rate(), *gen_rate()), suffix);
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
  return well_posed(rc::gen::exec([=] { return draw_multi<7>(resolve(bias), bound, make_watt_sixbar); }));
}

rc::Gen<MechanismCase> gen_stephenson_sixbar(Bias bias, int bound) {
  return well_posed(rc::gen::exec([=] { return draw_multi<7>(resolve(bias), bound, make_stephenson_sixbar); }));
}

rc::Gen<MechanismCase> gen_fig5_eightbar(Bias bias, int bound) {
  return well_posed(rc::gen::exec([=] { return draw_multi<10>(resolve(bias), bound, make_fig5_eightbar); }));
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
