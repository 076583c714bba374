// The paper's graphic construction for side j of the n-side polygon (Dijksman 1966, sec. 2;
// docs/conventions.md §A3), generic over the scalar type.
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
//
// The construction is written once, in construct_four_bar_steps: plain values and a status per
// step (geometry/construction_steps.h), no exception, string or allocation, so that the
// construction route (numerics/routes.h) can run it for every j of a large polygon. The points and
// lines shared by every four-bar j of a polygon (K_{n-2}, K_{n-1}, K_n) form a FourBarFrame,
// built once per polygon.
//
// construct_four_bar names what the steps found: each quantity is Defined<>, and where the
// construction breaks (Q_j or P'_j at infinity, a null ray, beta_j = 0) it names the quantity
// and the reason (docs/conventions.md §A6), and the rest goes on.
//
// ConstructionReading selects the erratum readings of docs/conventions.md §A5 (the paper's printed forms and
// tempting misreadings), so that each can be evaluated by the same code and shown to fail.
#pragma once

#include <string>

#include "core/scalar.h"
#include "core/defined.h"
#include "geometry/construction_steps.h"
#include "linkproof/geometry/polygon.h"
#include "geometry/zero_vector.h"

namespace linkproof {

/// How the construction is read. The default is the correct reading of docs/conventions.md §A3.
struct ConstructionReading {
  /// false: the paper's printed K_j instead of the displaced K'_j (§A5.1): the whole four-bar is
  /// built on the undisplaced joint, i.e. Q_j on line K_nK_j and P_j on line K_jK_{n-2}.
  bool displaced_start = true;
  /// false: beta_j measured towards P_j = line(K_{n-1}, K_n) ^ line(K_j, K_{j+1}) (the
  /// undisplaced side) instead of P'_j, as printed in (9a) (§A5.2).
  bool beta_towards_p_prime = true;
  /// false: beta_j > 0 iff the triangle is clockwise (the reversed sign rule, §A5.6).
  bool beta_ccw_positive = true;
  /// false: unsigned segment ratios |QK'|/|QK_n| (§A5.6).
  bool signed_ratios = true;
};

/// What every four-bar j of one polygon shares: the coupler and output joints, the ground
/// pivot K_n, and the lines K_{n-2}K_{n-1} (on which Q_j lies) and K_{n-1}K_n (on which P'_j
/// lies). Built once per polygon by make_four_bar_frame.
template <class T>
struct FourBarFrame {
  Vec2<T> k_n2;         ///< K_{n-2}
  Vec2<T> k_n1;         ///< K_{n-1}
  Vec2<T> k_n;          ///< K_n
  Vec2<T> coupler_dir;  ///< K_{n-1} - K_{n-2} (= r_{n-2}): direction of line K_{n-2}K_{n-1}
  Vec2<T> output_dir;   ///< K_n - K_{n-1} (= r_{n-1}): direction of line K_{n-1}K_n
  T one;                ///< 1 in T, for i (1 - i) in eq. (9a)
};

template <class T>
FourBarFrame<T> make_four_bar_frame(const Polygon<T>& poly) {
  const int n = poly.n();
  const Vec2<T>& k_n2 = poly.joint(n - 2);
  const Vec2<T>& k_n1 = poly.joint(n - 1);
  const Vec2<T>& k_n = poly.joint(n);
  return {k_n2, k_n1, k_n, k_n1 - k_n2, k_n - k_n1, from_int<T>(1)};
}

/// lambda_j = i_{n-1,j}(1 - i_{n-1,j}) cot beta_j (eq. 9a, after Freudenstein); with i_{n-2,j} and
/// cot gamma_j it gives mu_j of the companion formula. `one` is 1 in T.
template <class T>
T freudenstein_coefficient(const T& i, const T& cot, const T& one) {
  return i * (one - i) * cot;
}

/// Every point and number of the construction of one four-bar, as plain values, with the
/// status of each step. A value is meaningful only where its status is `defined`; a step whose
/// input is undefined is not run (status `not_reached`).
template <class T>
struct FourBarSteps {
  Vec2<T> k_prime;  ///< K'_j (K_j in the undisplaced reading)
  Vec2<T> q;        ///< Q_j
  Vec2<T> p_prime;  ///< P'_j
  T i_out{};        ///< i_{n-1,j}, eq. (4)
  T i_cpl{};        ///< i_{n-2,j}, eq. (6)
  T cot_beta{};     ///< cot beta_j, eq. (9a)
  T cot_gamma{};    ///< cot gamma_j (companion)
  T lambda{};       ///< lambda_j = i_{n-1,j}(1 - i_{n-1,j}) cot beta_j, eq. (9a)
  T mu{};           ///< mu_j = i_{n-2,j}(1 - i_{n-2,j}) cot gamma_j
  StepStatus q_status = StepStatus::not_reached;
  StepStatus p_prime_status = StepStatus::not_reached;
  StepStatus p_undisplaced_status = StepStatus::not_reached;  ///< P_j, reading §A5.2 only
  StepStatus i_out_status = StepStatus::not_reached;
  StepStatus i_cpl_status = StepStatus::not_reached;
  StepStatus beta_status = StepStatus::not_reached;
  StepStatus gamma_status = StepStatus::not_reached;
  /// i_{n-1,j}, i_{n-2,j}, lambda_j and mu_j all exist (then so do Q_j, P'_j, beta_j, gamma_j).
  bool coefficients_defined = false;
};

/// The construction of the four-bar with input side r_j starting at K_j, in `f`'s polygon
/// (docs/conventions.md §A3), step by step: the one implementation of the construction. construct_four_bar
/// names its undefined quantities; the construction route reads its coefficients directly.
/// Of `reading`, only the misreadings that move a point are applied here (§A5.1 K_j for K'_j,
/// §A5.2 beta_j towards P_j); ratios are directed and beta_j is ccw-positive, and lambda_j, mu_j
/// are formed from those (construct_four_bar applies the §A5.6 misreadings of the values).
///
/// Written for a loop over j in double (numerics/routes.h): always inlined, the statuses kept in
/// locals and stored once, so that the result lives in registers. (Through memory, GCC merges
/// tests of adjacent one-byte statuses into one wide load, which stalls on the byte stores.)
template <class T>
[[gnu::always_inline]] inline FourBarSteps<T> construct_four_bar_steps(const FourBarFrame<T>& f, const Vec2<T>& k_j,
                                                                       const Vec2<T>& r_j,
                                                                       const ConstructionReading& reading = {}) {
  constexpr StepStatus ok = StepStatus::defined, skipped = StepStatus::not_reached;
  FourBarSteps<T> s;
  // K'_j = K_{n-2} - r_j (docs/conventions.md §A3; §A5.1: the paper's printed K_j).
  s.k_prime = reading.displaced_start ? f.k_n2 - r_j : k_j;
  const Vec2<T>& kp = s.k_prime;

  // Q_j = line(K_{n-2}, K_{n-1}) ^ line(K_n, K'_j); the ground line needs K'_j != K_n (docs/conventions.md §A6).
  const Vec2<T> ground_dir = kp - f.k_n;
  const StepStatus q = is_zero_vector(ground_dir) ? StepStatus::pivots_coincide
                                                  : intersect_lines(f.k_n2, f.coupler_dir, f.k_n, ground_dir, s.q);
  // P'_j = line(K_{n-1}, K_n) ^ line(K'_j, K_{n-2}).
  const StepStatus p = intersect_lines(f.k_n1, f.output_dir, kp, f.k_n2 - kp, s.p_prime);

  // i_{n-1,j} = Q_jK'_j / Q_jK_n (eq. 4), i_{n-2,j} = K_{n-2}K'_j / K_{n-2}P'_j (eq. 6), directed.
  const StepStatus i_out = q == ok ? directed_ratio(s.q, kp, f.k_n, s.i_out) : skipped;
  const StepStatus i_cpl = p == ok ? directed_ratio(f.k_n2, kp, s.p_prime, s.i_cpl) : skipped;

  // cot beta_j = (QK . QP) / (QK x QP), QK = K_{n-1} - Q_j, QP = P'_j - Q_j: beta_j > 0 iff
  // P'_j -> Q_j -> K_{n-1} is ccw (eq. 9a). §A5.2 measures towards P_j = line(K_{n-1}, K_n) ^
  // line(K_j, K_{j+1}) instead (after P'_j, as the named construction reports P'_j first).
  StepStatus p_undisplaced = skipped, beta = skipped;
  if (p == ok) {
    Vec2<T> towards = s.p_prime;
    if (!reading.beta_towards_p_prime) p_undisplaced = intersect_lines(f.k_n1, f.output_dir, k_j, r_j, towards);
    if ((reading.beta_towards_p_prime || p_undisplaced == ok) && q == ok)
      beta = cot_signed_angle(f.k_n1 - s.q, towards - s.q, s.cot_beta);
  }
  // cot gamma_j = (P'K . P'Q) / (P'K x P'Q): gamma_j > 0 iff Q_j -> P'_j -> K_{n-1} is ccw.
  const StepStatus gamma = p == ok && q == ok ? cot_signed_angle(f.k_n1 - s.p_prime, s.q - s.p_prime, s.cot_gamma) : skipped;

  // lambda_j (eq. 9a) and mu_j (companion).
  if (i_out == ok && beta == ok) s.lambda = freudenstein_coefficient(s.i_out, s.cot_beta, f.one);
  if (i_cpl == ok && gamma == ok) s.mu = freudenstein_coefficient(s.i_cpl, s.cot_gamma, f.one);

  s.q_status = q;
  s.p_prime_status = p;
  s.p_undisplaced_status = p_undisplaced;
  s.i_out_status = i_out;
  s.i_cpl_status = i_cpl;
  s.beta_status = beta;
  s.gamma_status = gamma;
  s.coefficients_defined = i_out == ok && i_cpl == ok && beta == ok && gamma == ok;
  return s;
}

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

/// Which points a reading moves (§A5.1, §A5.2): readings of one key get the same steps from
/// construct_four_bar_steps and differ at most in how the values are read (§A5.6).
inline int construction_steps_key(const ConstructionReading& r) {
  return static_cast<int>(r.displaced_start) | static_cast<int>(r.beta_towards_p_prime) << 1;
}

/// The construction of four-bar j under `reading` from its steps `s`, which
/// construct_four_bar_steps made under a reading of the same construction_steps_key: every
/// quantity named where it does not exist.
template <class T>
FourBarConstruction<T> construction_from_steps(const FourBarSteps<T>& s, int j, const ConstructionReading& reading) {
  const T one = from_int<T>(1);
  const auto sj = [j] { return std::to_string(j); };
  const auto kp_name = [&] { return reading.displaced_start ? "K'_" + sj() : "K_" + sj(); };
  // §A5.6: unsigned segment ratios (abs_value throws for a symbolic value: that, too, is named).
  const auto ratio = [&](const T& r) { return reading.signed_ratios ? r : abs_value(r); };

  FourBarConstruction<T> c{j, s.k_prime,
                           Defined<Vec2<T>>::pending(), Defined<Vec2<T>>::pending(),
                           Defined<T>::pending(), Defined<T>::pending(),
                           Defined<T>::pending(), Defined<T>::pending(),
                           Defined<T>::pending(), Defined<T>::pending()};
  c.q = Defined<Vec2<T>>::attempt([&] {
    if (s.q_status == StepStatus::pivots_coincide)
      throw UndefinedQuantity("Q_" + sj(), kp_name() + " coincides with K_n: the ground line K_n" + kp_name() + " is undefined");
    require_intersection(s.q_status, [&] { return "Q_" + sj(); }, [&] { return "K_{n-2}K_{n-1} and K_n" + kp_name(); });
    return s.q;
  });
  c.p_prime = Defined<Vec2<T>>::attempt([&] {
    require_intersection(s.p_prime_status, [&] { return "P'_" + sj(); },
                         [&] { return "K_{n-1}K_n and " + kp_name() + "K_{n-2}"; });
    return s.p_prime;
  });
  c.i_out = Defined<T>::attempt([&] {
    (void)c.q.get();
    require_ratio(s.i_out_status, [&] { return "i_{n-1," + sj() + "}"; });
    return ratio(s.i_out);
  });
  c.i_cpl = Defined<T>::attempt([&] {
    (void)c.p_prime.get();
    require_ratio(s.i_cpl_status, [&] { return "i_{n-2," + sj() + "}"; });
    return ratio(s.i_cpl);
  });
  c.cot_beta = Defined<T>::attempt([&] {
    (void)c.p_prime.get();
    if (!reading.beta_towards_p_prime)
      require_intersection(s.p_undisplaced_status, [&] { return "P_" + sj(); },
                           [&] { return "K_{n-1}K_n and K_" + sj() + "K_" + std::to_string(j + 1); });
    (void)c.q.get();
    require_angle(s.beta_status, [&] { return "beta_" + sj(); },
                  [&] { return "rays Q_" + sj() + "K_{n-1} and Q_" + sj() + "P'_" + sj(); });
    return reading.beta_ccw_positive ? s.cot_beta : -s.cot_beta;  // §A5.6: the reversed sign rule
  });
  c.cot_gamma = Defined<T>::attempt([&] {
    (void)c.p_prime.get();
    (void)c.q.get();
    require_angle(s.gamma_status, [&] { return "gamma_" + sj(); },
                  [&] { return "rays P'_" + sj() + "K_{n-1} and P'_" + sj() + "Q_" + sj(); });
    return s.cot_gamma;
  });
  // From the values as read (equal to s.lambda, s.mu in the correct reading).
  c.lambda = Defined<T>::attempt([&] {
    const T& i = c.i_out.get();  // named before beta_j
    return freudenstein_coefficient(i, c.cot_beta.get(), one);
  });
  c.mu = Defined<T>::attempt([&] {
    const T& i = c.i_cpl.get();  // named before gamma_j
    return freudenstein_coefficient(i, c.cot_gamma.get(), one);
  });
  return c;
}

/// Builds the construction for input side j (1 <= j <= n-3) of polygon `poly`, every quantity
/// named where it does not exist. A quantity built from an undefined one carries that one's
/// name (i_{n-1,j} without Q_j says "Q_j"); beta_j reports P'_j before Q_j.
template <class T>
FourBarConstruction<T> construct_four_bar(const Polygon<T>& poly, int j, const ConstructionReading& reading = {}) {
  const FourBarSteps<T> s = construct_four_bar_steps(make_four_bar_frame(poly), poly.joint(j), poly.side(j), reading);
  return construction_from_steps(s, j, reading);
}

/// Throws the UndefinedQuantity that reading i_{n-1,j}, i_{n-2,j}, lambda_j, mu_j (in this
/// order) of construct_four_bar(poly, j) throws first. For a caller whose construct_four_bar_steps
/// found !coefficients_defined: the names are made only here, on the rare undefined path.
template <class T>
[[noreturn]] void throw_first_undefined_coefficient(const Polygon<T>& poly, int j) {
  const FourBarConstruction<T> c = construct_four_bar(poly, j);
  (void)c.i_out.get();
  (void)c.i_cpl.get();
  (void)c.lambda.get();
  (void)c.mu.get();
  throw InternalError("construction of four-bar " + std::to_string(j) + ": every coefficient is defined");
}

}  // namespace linkproof
