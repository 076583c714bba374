// The paper's graphic construction for side j of the n-side polygon (Dijksman 1966, sec. 2;
// SPEC.md A3), generic over the scalar type.
//
// Four-bar j is K'_j K_{n-2} K_{n-1} K_n: input r_j moved parallel so that it ends in K_{n-2},
// coupler r_{n-2}, output r_{n-1}, fixed pivots K'_j and K_n.
//   K'_j   = K_{n-2} - r_j                         (K'_{n-3} = K_{n-3})
//   Q_j    = line(K_{n-2}, K_{n-1}) ^ line(K_n, K'_j)   relative pole of input and output
//   P'_j   = line(K_{n-1}, K_n) ^ line(K'_j, K_{n-2})   instant centre of the coupler
//   i_{n-1,j} = Q_jK'_j / Q_jK_n       directed segments            eq. (4)
//   i_{n-2,j} = K_{n-2}K'_j / K_{n-2}P'_j  directed segments         eq. (6)
//   beta_j  angle at Q_j from ray Q_j->K_{n-1} ... > 0 iff P'_j -> Q_j -> K_{n-1} is ccw;
//           cot beta_j = (QK . QP) / (QK x QP), QK = K_{n-1} - Q_j, QP = P'_j - Q_j
//   lambda_j = i_{n-1,j} (1 - i_{n-1,j}) cot beta_j                  eq. (9a)
//   gamma_j angle at P'_j in triangle Q_j P'_j K_{n-1}, > 0 iff Q_j -> P'_j -> K_{n-1} is ccw
//   mu_j    = i_{n-2,j} (1 - i_{n-2,j}) cot gamma_j                  (companion formula)
// Each quantity is Defined<>: where the construction breaks (Q_j or P'_j at infinity, a null
// ray, beta_j = 0) it names the quantity and the reason (SPEC A6), and the rest goes on.
//
// ConstructionReading selects the erratum readings of SPEC A5 (the seed's printed forms and
// tempting misreadings), so that each can be evaluated by the same code and shown to fail.
#pragma once

#include <string>

#include "linkproof/core/defined.h"
#include "linkproof/geometry/polygon.h"

namespace linkproof {

/// How the construction is read. The default is the correct reading of SPEC A3.
struct ConstructionReading {
  /// false: the seed's printed K_j instead of the displaced K'_j (A5.1): the whole four-bar is
  /// built on the undisplaced joint, i.e. Q_j on line K_nK_j and P_j on line K_jK_{n-2}.
  bool displaced_start = true;
  /// false: beta_j measured towards P_j = line(K_{n-1}, K_n) ^ line(K_j, K_{j+1}) (the
  /// undisplaced side) instead of P'_j, as printed in (9a) (A5.2).
  bool beta_towards_p_prime = true;
  /// false: beta_j > 0 iff the triangle is clockwise (the reversed sign rule, A5.6).
  bool beta_ccw_positive = true;
  /// false: unsigned segment ratios |QK'|/|QK_n| (A5.6).
  bool signed_ratios = true;
};

template <class T>
struct FourBarConstruction {
  int j = 0;                   ///< which input side (1..n-3)
  Vec2<T> k_prime;             ///< K'_j (or K_j in the undisplaced reading)
  Defined<Vec2<T>> q;          ///< Q_j
  Defined<Vec2<T>> p_prime;    ///< P'_j
  Defined<T> i_out;            ///< i_{n-1,j}, eq. (4)
  Defined<T> i_cpl;            ///< i_{n-2,j}, eq. (6)
  Defined<T> cot_beta;         ///< cot beta_j, eq. (9a)
  Defined<T> cot_gamma;        ///< cot gamma_j (companion)
  Defined<T> lambda;           ///< lambda_j = i_{n-1,j}(1 - i_{n-1,j}) cot beta_j, eq. (9a)
  Defined<T> mu;               ///< mu_j = i_{n-2,j}(1 - i_{n-2,j}) cot gamma_j
};

/// Names of undefined quantities are built only when a quantity is undefined: on the regular
/// path the construction makes no strings (they were ~45 % of its cost). The `_lazy` forms take
/// callables returning the name and the description; the string forms call them.

/// Intersection of line(p, p + u) and line(q, q + v). Throws UndefinedQuantity(name(), ...) if
/// a direction is null or the lines are parallel (the point is at infinity).
template <class T, class NameFn, class LinesFn>
Vec2<T> construct_line_intersection_lazy(const Vec2<T>& p, const Vec2<T>& u, const Vec2<T>& q, const Vec2<T>& v,
                                         const NameFn& name, const LinesFn& lines) {
  if (is_zero_vector(u) || is_zero_vector(v))
    throw UndefinedQuantity(name(), "a line through " + lines() + " has coincident points");
  const T den = cross(u, v);
  if (linkproof::is_zero(den)) throw UndefinedQuantity(name(), "lines " + lines() + " are parallel: the point is at infinity");
  const T t = cross(q - p, v) / den;
  return p + t * u;
}

template <class T>
Vec2<T> construct_line_intersection(const Vec2<T>& p, const Vec2<T>& u, const Vec2<T>& q,
                                    const Vec2<T>& v, const std::string& name,
                                    const std::string& lines) {
  return construct_line_intersection_lazy(p, u, q, v, [&] { return name; }, [&] { return lines; });
}

/// Directed ratio XA / XB of segments on one line through X (A, B collinear with X):
/// positive iff A and B lie on the same side of X. Undefined if B = X.
template <class T, class NameFn>
T compute_directed_ratio_lazy(const Vec2<T>& x, const Vec2<T>& a, const Vec2<T>& b, const NameFn& name) {
  const Vec2<T> xb = b - x;
  const T den = norm2(xb);
  if (linkproof::is_zero(den)) throw UndefinedQuantity(name(), "the reference segment has zero length");
  return dot(a - x, xb) / den;
}

template <class T>
T compute_directed_ratio(const Vec2<T>& x, const Vec2<T>& a, const Vec2<T>& b, const std::string& name) {
  return compute_directed_ratio_lazy(x, a, b, [&] { return name; });
}

/// cot of the signed angle at a vertex V between the rays VA and VB: (VA . VB) / (VA x VB).
/// The angle is positive iff VA x VB > 0, i.e. iff the triangle B -> V -> A is counter-clockwise.
template <class T, class NameFn, class RaysFn>
T compute_cot_signed_angle_lazy(const Vec2<T>& va, const Vec2<T>& vb, const NameFn& name, const RaysFn& rays) {
  if (is_zero_vector(va) || is_zero_vector(vb))
    throw UndefinedQuantity(name(), "a ray of " + rays() + " is null (its end coincides with the vertex)");
  const T s = cross(va, vb);
  if (linkproof::is_zero(s)) throw UndefinedQuantity(name(), rays() + " are collinear: the angle is 0 or pi, its cotangent infinite");
  return dot(va, vb) / s;
}

template <class T>
T compute_cot_signed_angle(const Vec2<T>& va, const Vec2<T>& vb, const std::string& name,
                           const std::string& rays) {
  return compute_cot_signed_angle_lazy(va, vb, [&] { return name; }, [&] { return rays; });
}

/// Builds the construction for input side j (1 <= j <= n-3) of polygon `poly`.
template <class T>
FourBarConstruction<T> construct_four_bar(const Polygon<T>& poly, int j,
                                          const ConstructionReading& reading = {}) {
  const int n = poly.n();
  const auto sj = [j] { return std::to_string(j); };
  const Vec2<T>& k_n2 = poly.joint(n - 2);
  const Vec2<T>& k_n1 = poly.joint(n - 1);
  const Vec2<T>& k_n = poly.joint(n);
  const Vec2<T> r_j = poly.side(j);

  FourBarConstruction<T> c{j, reading.displaced_start ? k_n2 - r_j : poly.joint(j),
                           Defined<Vec2<T>>::pending(), Defined<Vec2<T>>::pending(),
                           Defined<T>::pending(), Defined<T>::pending(),
                           Defined<T>::pending(), Defined<T>::pending(),
                           Defined<T>::pending(), Defined<T>::pending()};
  const Vec2<T> kp = c.k_prime;
  const auto kp_name = [&] { return reading.displaced_start ? "K'_" + sj() : "K_" + sj(); };

  c.q = Defined<Vec2<T>>::attempt([&] {
    if (is_zero_vector(kp - k_n))
      throw UndefinedQuantity("Q_" + sj(), kp_name() + " coincides with K_n: the ground line K_n" + kp_name() + " is undefined");
    return construct_line_intersection_lazy(k_n2, k_n1 - k_n2, k_n, kp - k_n, [&] { return "Q_" + sj(); },
                                            [&] { return "K_{n-2}K_{n-1} and K_n" + kp_name(); });
  });
  c.p_prime = Defined<Vec2<T>>::attempt([&] {
    return construct_line_intersection_lazy(k_n1, k_n - k_n1, kp, k_n2 - kp, [&] { return "P'_" + sj(); },
                                            [&] { return "K_{n-1}K_n and " + kp_name() + "K_{n-2}"; });
  });
  const auto ratio = [&](const Vec2<T>& x, const Vec2<T>& a, const Vec2<T>& b, const auto& name) {
    T r = compute_directed_ratio_lazy(x, a, b, name);
    return reading.signed_ratios ? r : abs_value(r);
  };
  c.i_out = Defined<T>::attempt([&] { return ratio(c.q.get(), kp, k_n, [&] { return "i_{n-1," + sj() + "}"; }); });
  c.i_cpl = Defined<T>::attempt([&] { return ratio(k_n2, kp, c.p_prime.get(), [&] { return "i_{n-2," + sj() + "}"; }); });

  c.cot_beta = Defined<T>::attempt([&] {
    Vec2<T> p = c.p_prime.get();
    if (!reading.beta_towards_p_prime)
      p = construct_line_intersection_lazy(k_n1, k_n - k_n1, poly.joint(j), r_j, [&] { return "P_" + sj(); },
                                           [&] { return "K_{n-1}K_n and K_" + sj() + "K_" + std::to_string(j + 1); });
    const Vec2<T> q = c.q.get();
    // beta_j > 0 iff P -> Q -> K_{n-1} is ccw, i.e. iff QK x QP > 0.
    T cot = compute_cot_signed_angle_lazy(k_n1 - q, p - q, [&] { return "beta_" + sj(); },
                                          [&] { return "rays Q_" + sj() + "K_{n-1} and Q_" + sj() + "P'_" + sj(); });
    return reading.beta_ccw_positive ? cot : -cot;
  });
  c.cot_gamma = Defined<T>::attempt([&] {
    const Vec2<T> p = c.p_prime.get();
    // gamma_j > 0 iff Q -> P' -> K_{n-1} is ccw, i.e. iff P'K x P'Q > 0.
    return compute_cot_signed_angle_lazy(k_n1 - p, c.q.get() - p, [&] { return "gamma_" + sj(); },
                                         [&] { return "rays P'_" + sj() + "K_{n-1} and P'_" + sj() + "Q_" + sj(); });
  });
  const T one = from_int<T>(1);
  c.lambda = Defined<T>::attempt([&] { const T& i = c.i_out.get(); return i * (one - i) * c.cot_beta.get(); });
  c.mu = Defined<T>::attempt([&] { const T& i = c.i_cpl.get(); return i * (one - i) * c.cot_gamma.get(); });
  return c;
}

}  // namespace linkproof
