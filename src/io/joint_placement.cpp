#include "joint_placement.h"

#include <cln/integer.h>
#include <cln/rational.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "enclosure.h"
#include "linkproof/core/exact.h"
#include "linkproof/core/error.h"
#include "yaml_document.h"

namespace linkproof::placement {

namespace {

using yaml_io::backticked;
using EVec = Vec2<Enclosure>;

Enclosure exact(const Rational& q) { return Enclosure::exact(q); }

// A sign the enclosure could not decide at this precision: the placement is tried again at a
// higher one, and refused with this message at the last.
struct Undecided {
  std::string field, problem;
};

// c pi^k.
Enclosure value_of(const PiMultiple& a, int bits) {
  Enclosure v = exact(a.coefficient);
  if (a.is_rational()) return v;
  const Enclosure pi = pi_enclosure(bits);
  for (int i = 0; i < std::abs(a.pi_power); ++i) v = a.pi_power > 0 ? v * pi : divide(v, pi);
  return v;
}

// Niven's theorem: at t pi (t rational, reduced to [0, 2)) cos and sin are rational only at
// these t, where they are 0, +-1/2 or +-1; everywhere else they are irrational.
std::optional<Rational> rational_value_at(const Rational& t, const std::array<std::pair<Rational, Rational>, 8>& table) {
  for (const auto& [at, value] : table)
    if (at == t) return value;
  return std::nullopt;
}
const std::array<std::pair<Rational, Rational>, 8>& rational_cos_table() {
  static const std::array<std::pair<Rational, Rational>, 8> t = {
      std::pair<Rational, Rational>{0, 1}, {Rational(1) / 3, Rational(1) / 2}, {Rational(1) / 2, 0},
      {Rational(2) / 3, Rational(-1) / 2}, {1, -1}, {Rational(4) / 3, Rational(-1) / 2}, {Rational(3) / 2, 0},
      {Rational(5) / 3, Rational(1) / 2}};
  return t;
}
const std::array<std::pair<Rational, Rational>, 8>& rational_sin_table() {
  static const std::array<std::pair<Rational, Rational>, 8> t = {
      std::pair<Rational, Rational>{0, 0}, {Rational(1) / 6, Rational(1) / 2}, {Rational(1) / 2, 1},
      {Rational(5) / 6, Rational(1) / 2}, {1, 0}, {Rational(7) / 6, Rational(-1) / 2}, {Rational(3) / 2, -1},
      {Rational(11) / 6, Rational(-1) / 2}};
  return t;
}

// cos A, sin A: exact where they are rational (A = 0; the angles of Niven's table), else
// enclosures. (cos and sin of a non-zero rational number of radians are transcendental.)
CosSin cos_sin_of_angle(const PiMultiple& a, int bits) {
  if (a.pi_power != 1) return cos_sin_of(value_of(a, bits), bits);
  const Rational t = a.coefficient - 2 * Rational(cln::floor1(a.coefficient / 2));  // A = t pi (mod 2 pi)
  const std::optional<Rational> c = rational_value_at(t, rational_cos_table());
  const std::optional<Rational> s = rational_value_at(t, rational_sin_table());
  CosSin cs;
  if (!c || !s) cs = cos_sin_of(exact(t) * pi_enclosure(bits), bits);
  if (c) cs.cos = exact(*c);
  if (s) cs.sin = exact(*s);
  return cs;
}

// For messages: the value to 6 significant digits (exact values exactly when integers).
std::string approx(const Enclosure& e) { return format_decimal(e.mid, 6); }

// 10^(e - digits) where 10^e <= magnitude < 10^(e + 1).
Rational decimal_grid(const Rational& magnitude, int digits) {
  long e = static_cast<long>(std::floor(static_cast<double>(binary_exponent(magnitude) - 1) * 0.30102999566398120));
  while (cln::expt(Rational(10), e) > magnitude) --e;
  while (cln::expt(Rational(10), e + 1) <= magnitude) ++e;
  return cln::expt(Rational(10), e - digits);
}

class Placer {
 public:
  Placer(const std::vector<JointSpec>& specs, std::string source) : specs_(specs), source_(std::move(source)) {
    for (std::size_t i = 0; i < specs_.size(); ++i) index_.emplace(specs_[i].name, static_cast<int>(i));
  }

  // Every joint after the joints it is placed from; unknown references and cycles refused.
  std::vector<int> order() {
    for (const JointSpec& s : specs_)
      for (const auto& [name, field] : s.from)
        if (!index_.count(name))
          throw InputError(source_, field,
                           fmt::format("unknown joint {}: joint {} is placed from it, but the scene has no joint of "
                                       "that name",
                                       backticked(name), backticked(s.name)));
    state_.assign(specs_.size(), 0);
    for (std::size_t i = 0; i < specs_.size(); ++i) visit(static_cast<int>(i));
    return order_;
  }

  // The enclosures of every joint at `bits`, in `order`. Throws Undecided, or InputError for
  // a dimension set that does not assemble.
  std::vector<EVec> construct_all(const std::vector<int>& order, int bits) const {
    std::vector<EVec> at(specs_.size());
    for (int i : order) at[static_cast<std::size_t>(i)] = construct(specs_[static_cast<std::size_t>(i)], at, bits);
    return at;
  }

 private:
  void visit(int i) {
    auto& st = state_[static_cast<std::size_t>(i)];
    if (st == 2) return;
    if (st == 1) {
      // `path` holds the joints being placed; the cycle runs from i's entry to its end.
      std::vector<std::string> cycle;
      bool in = false;
      for (int k : path_) {
        in = in || k == i;
        if (in) cycle.push_back(specs_[static_cast<std::size_t>(k)].name);
      }
      cycle.push_back(specs_[static_cast<std::size_t>(i)].name);
      const JointSpec& s = specs_[static_cast<std::size_t>(i)];
      throw InputError(source_, s.field,
                       fmt::format("joint {} cannot be placed from placed joints: its position depends on itself "
                                   "({}); give one of them a position `at: [x, y]`",
                                   backticked(s.name), fmt::join(cycle, " -> ")));
    }
    st = 1;
    path_.push_back(i);
    for (const auto& ref : specs_[static_cast<std::size_t>(i)].from) visit(index_.at(ref.first));
    path_.pop_back();
    st = 2;
    order_.push_back(i);
  }

  const EVec& placed(const std::vector<EVec>& at, const JointSpec& s, std::size_t k) const {
    return at[static_cast<std::size_t>(index_.at(s.from[k].first))];
  }
  std::string ref(const JointSpec& s, std::size_t k) const { return backticked(s.from[k].first); }

  EVec construct(const JointSpec& s, const std::vector<EVec>& at, int bits) const {
    switch (s.kind) {
      case JointSpec::Kind::Point: return {exact(s.point.x), exact(s.point.y)};
      case JointSpec::Kind::AtJoint: return placed(at, s, 0);
      case JointSpec::Kind::Polar: {
        const CosSin e = cos_sin_of_angle(s.angle, bits);
        return placed(at, s, 0) + exact(s.length) * EVec{e.cos, e.sin};
      }
      case JointSpec::Kind::Dyad: return construct_dyad(s, placed(at, s, 0), placed(at, s, 1), bits);
      case JointSpec::Kind::Slide: return construct_slide(s, placed(at, s, 0), placed(at, s, 1), bits);
    }
    throw InternalError("unknown placement kind");
  }

  EVec construct_dyad(const JointSpec& s, const EVec& p1, const EVec& p2, int bits) const {
    const Enclosure l1 = exact(s.length), l2 = exact(s.length2);
    const EVec d = p2 - p1;
    const Enclosure d2 = norm2(d);
    const std::optional<int> d2_sign = decided_sign(d2);
    if (d2_sign == 0)
      throw InputError(source_, s.field,
                       fmt::format("joint {} cannot be placed: {} and {} are at the same point, so the two circles "
                                   "are concentric",
                                   backticked(s.name), ref(s, 0), ref(s, 1)));
    if (!d2_sign)
      throw Undecided{s.field, fmt::format("joint {}: cannot decide whether {} and {} are apart (they coincide to "
                                           "within 10^-1500)",
                                           backticked(s.name), ref(s, 0), ref(s, 1))};
    const Enclosure k = d2 + l1 * l1 - l2 * l2;
    const Enclosure delta = exact(4) * d2 * l1 * l1 - k * k;
    const std::optional<int> delta_sign = decided_sign(delta);
    if (!delta_sign)
      throw Undecided{s.field, fmt::format("joint {}: cannot decide whether the circles about {} and {} meet: they "
                                           "touch to within 10^-1500 (a dead-centre position)",
                                           backticked(s.name), ref(s, 0), ref(s, 1))};
    if (*delta_sign < 0) refuse_dyad(s, d2, bits);
    const Enclosure two_d2 = exact(2) * d2;
    const Enclosure along = divide(k, two_d2), across = divide(sqrt_of(delta, bits), two_d2);
    return p1 + along * d + (exact(s.side) * across) * perp(d);
  }

  [[noreturn]] void refuse_dyad(const JointSpec& s, const Enclosure& d2, int bits) const {
    const Enclosure d = sqrt_of(d2, bits);
    const Rational sum = s.length + s.length2, difference = cln::abs(s.length - s.length2);
    const std::string circles = fmt::format("the circle about {} (radius {}) and the circle about {} (radius {})",
                                            ref(s, 0), format_rational(s.length), ref(s, 1), format_rational(s.length2));
    if (d2.mid > sum * sum)
      throw InputError(source_, s.field,
                       fmt::format("joint {} cannot be placed: {} do not meet: their centres are {} apart, more than "
                                   "{} + {} = {}; the dyad misses by {}",
                                   backticked(s.name), circles, approx(d), format_rational(s.length),
                                   format_rational(s.length2), format_rational(sum), approx(d - exact(sum))));
    throw InputError(source_, s.field,
                     fmt::format("joint {} cannot be placed: {} do not meet: one lies inside the other, their centres "
                                 "are {} apart, less than |{} - {}| = {}; the dyad misses by {}",
                                 backticked(s.name), circles, approx(d), format_rational(s.length),
                                 format_rational(s.length2), format_rational(difference), approx(exact(difference) - d)));
  }

  EVec construct_slide(const JointSpec& s, const EVec& on_line, const EVec& centre, int bits) const {
    const CosSin cs = cos_sin_of_angle(s.angle, bits);
    const EVec e{cs.cos, cs.sin};
    const EVec w = on_line - centre;
    const Enclosure b = dot(w, e), l = exact(s.length);
    // |e| = 1 for the true e, so Disc = b^2 - |W|^2 + L^2 holds for the true values, which the
    // enclosures contain.
    const Enclosure disc = b * b - norm2(w) + l * l;
    const std::optional<int> sign = decided_sign(disc);
    if (!sign)
      throw Undecided{s.field, fmt::format("joint {}: cannot decide whether the line through {} meets the circle about "
                                           "{}: it touches it to within 10^-1500",
                                           backticked(s.name), ref(s, 0), ref(s, 1))};
    if (*sign < 0) {
      const Enclosure h = cross(e, w), miss_by = (decided_sign(h).value_or(1) < 0 ? -h : h) - l;
      throw InputError(source_, s.field,
                       fmt::format("joint {} cannot be placed: the line through {} at the angle {} passes {} from {}, "
                                   "farther than the length {}: it misses the circle by {}",
                                   backticked(s.name), ref(s, 0), s.angle_text,
                                   approx(decided_sign(h).value_or(1) < 0 ? -h : h), ref(s, 1),
                                   format_rational(s.length), approx(miss_by)));
    }
    const Enclosure t = -b + exact(s.side) * sqrt_of(disc, bits);
    return on_line + t * e;
  }

  const std::vector<JointSpec>& specs_;
  std::string source_;
  std::map<std::string, int> index_;
  std::vector<int> state_, path_, order_;
};

// The coordinate as a rational on `grid`, and the distance bound it adds.
Rational rationalised(const Enclosure& x, const Rational& grid, Rational& bound) {
  if (x.is_exact()) return x.mid;
  const Rational q = nearest_on_grid(x.mid, grid);
  bound = cln::max(bound, cln::abs(q - x.mid) + x.rad);
  return q;
}

// The first continued-fraction convergent p/q of x with |x - p/q| <= eps (x itself at worst).
Rational nearest_convergent(const Rational& x, const Rational& eps) {
  cln::cl_I p_prev = 1, q_prev = 0, p = cln::floor1(x), q = 1;
  Rational rest = x - Rational(p);
  while (cln::abs(x - Rational(p) / Rational(q)) > eps && !cln::zerop(rest)) {
    const Rational inverse = 1 / rest;
    const cln::cl_I a = cln::floor1(inverse);
    rest = inverse - Rational(a);
    const cln::cl_I p_next = a * p + p_prev, q_next = a * q + q_prev;
    p_prev = p, q_prev = q, p = p_next, q = q_next;
  }
  return Rational(p) / Rational(q);
}

}  // namespace

Placement place_joints(const std::vector<JointSpec>& specs, const Rational& scale, const std::string& source) {
  LINKPROOF_ASSERT(cln::plusp(scale), "the scene's scale must be positive");
  Placer placer(specs, source);
  const std::vector<int> order = placer.order();
  const Rational grid = decimal_grid(scale, kRationalisedDigits);
  for (int bits = kFirstWorkingBits;; bits *= 2) {
    const bool last = bits >= kMaxWorkingBits;
    std::vector<EVec> at;
    try {
      at = placer.construct_all(order, bits);
    } catch (const Undecided& u) {
      if (last) throw InputError(source, u.field, u.problem);
      continue;
    }
    // Rounding to the grid adds at most grid/2; an enclosure wider than grid/8 (cancellation
    // near a dead centre) is computed again at a higher precision.
    const bool sharp = std::all_of(at.begin(), at.end(), [&](const EVec& p) {
      return p.x.rad <= grid / 8 && p.y.rad <= grid / 8;
    });
    if (!sharp && !last) continue;
    Placement out;
    out.working_bits = bits;
    for (const EVec& p : at) {
      PlacedJoint j;
      j.at = {rationalised(p.x, grid, j.bound), rationalised(p.y, grid, j.bound)};
      j.exact = p.x.is_exact() && p.y.is_exact();
      out.joints.push_back(std::move(j));
    }
    return out;
  }
}

RationalisedNumber rationalise_number(const PiMultiple& x) {
  if (x.is_rational()) return {x.coefficient, true, 0};
  for (int bits = kFirstWorkingBits;; bits *= 2) {
    const Enclosure v = value_of(x, bits);
    const Rational grid = decimal_grid(cln::abs(v.mid), kRationalisedDigits);
    if (v.rad > grid / 8 && bits < kMaxWorkingBits) continue;
    RationalisedNumber r;
    r.exact = false;
    r.value = rationalised(v, grid, r.bound);
    return r;
  }
}

RationalisedDirection rationalise_direction(const PiMultiple& angle) {
  const int bits = kFirstWorkingBits;
  const CosSin cs = cos_sin_of_angle(angle, bits);
  if (cs.cos.is_exact() && cs.sin.is_exact()) return {{cs.cos.mid, cs.sin.mid}, true, 0};
  // t = tan(A/2) = sin / (1 + cos), or for cos < 0 the same of A + pi, whose direction is the
  // opposite: the denominator is then at least 1.
  const bool flip = cln::minusp(cs.cos.mid);
  const Enclosure t = flip ? divide(-cs.sin, exact(1) - cs.cos) : divide(cs.sin, exact(1) + cs.cos);
  RationalisedDirection r;
  r.exact = false;
  // The convergent of t's midpoint with the smallest denominator within 10^-(digits + 2) (about
  // 10^31 then): the direction's coordinates stay short enough to be written back in a scene.
  const Rational tq = nearest_convergent(t.mid, cln::expt(Rational(10), -(kRationalisedDigits + 2)));
  const Rational t_bound = cln::abs(tq - t.mid) + t.rad;
  const Rational n = 1 + tq * tq;
  r.unit = {(1 - tq * tq) / n, 2 * tq / n};
  if (flip) r.unit = {-r.unit.x, -r.unit.y};
  // The angle 2 atan t moves by at most 2 |t - t*| (|atan'| <= 1), each coordinate of a unit
  // vector by at most the angle.
  r.bound = 2 * t_bound;
  return r;
}

bool is_angle_within_limit(const PiMultiple& angle) {
  const Enclosure v = value_of(angle, 64);
  return cln::abs(v.mid) + v.rad <= Rational(kMaxAngleRadians);
}

}  // namespace linkproof::placement
