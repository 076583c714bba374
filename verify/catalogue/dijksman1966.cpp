// The catalogue of Dijksman (1966): every equation of sec. 2-3 and the erratum readings of
// SPEC.md A5, each evaluated on the polygon context by the paper's own construction and
// compared with the engine's exact truth.
#include "dijksman1966.h"

#include "dijksman1966_parts.h"

namespace linkproof::dijksman1966 {

using namespace parts;

namespace {

// --- Velocities: eqs. (4), (5), (6) --------------------------------------------------------

/// (4): i_{n-1,j} = Q_jK'_j / Q_jK_n equals omega_out/omega_in of four-bar j, for every j.
template <class T>
ClaimSides<T> eq4(const PolygonContext<T>& c, const ConstructionReading& r) {
  const auto cons = constructions(c, r);
  ClaimSides<T> s;
  for (int j = 1; j <= c.inputs(); ++j)
    s.instances.push_back(compare<T>(label_j(j), [&] { return cons[j - 1].i_out.get(); },
                                     [&] { return c.four_bars[j - 1].ratio_out.get(); }));
  return s;
}

/// (5): omega_{n-1,n} = sum_j i_{n-1,j} omega_j.
template <class T>
ClaimSides<T> eq5(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  s.instances.push_back(compare<T>("total", [&] { return c.truth.get().omega[c.n - 2]; }, [&] {
    T sum = from_int<T>(0);
    for (int j = 1; j <= c.inputs(); ++j) sum += c.construction[j - 1].i_out.get() * c.omega_in(j);
    return sum;
  }));
  return s;
}

/// (6): i_{n-2,j} = K_{n-2}K'_j / K_{n-2}P'_j equals omega_coupler/omega_in of four-bar j, and
/// omega_{n-2,n} = sum_j i_{n-2,j} omega_j.
template <class T>
ClaimSides<T> eq6(const PolygonContext<T>& c, const ConstructionReading& r) {
  const auto cons = constructions(c, r);
  ClaimSides<T> s;
  for (int j = 1; j <= c.inputs(); ++j)
    s.instances.push_back(compare<T>(label_j(j), [&] { return cons[j - 1].i_cpl.get(); },
                                     [&] { return c.four_bars[j - 1].ratio_cpl.get(); }));
  s.instances.push_back(compare<T>("total", [&] { return c.truth.get().omega[c.n - 3]; }, [&] {
    T sum = from_int<T>(0);
    for (int j = 1; j <= c.inputs(); ++j) sum += cons[j - 1].i_cpl.get() * c.omega_in(j);
    return sum;
  }));
  return s;
}

// --- Four-bar accelerations: eqs. (9), (9a) --------------------------------------------------

/// (9): _j omega-dot_{n-1,n} of four-bar j = lambda_j omega_j^2 + i_{n-1,j} omega-dot_j.
template <class T>
ClaimSides<T> eq9(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  for (int j = 1; j <= c.inputs(); ++j)
    s.instances.push_back(compare<T>(label_j(j), [&] { return c.four_bars[j - 1].omega_dot_out.get(); }, [&] {
      const auto& k = c.construction[j - 1];
      const T& w = c.omega_in(j);
      return k.lambda.get() * w * w + k.i_out.get() * c.omega_dot_in(j);
    }));
  return s;
}

/// (9a): lambda_j (closed form, SPEC A3) = i_{n-1,j} (1 - i_{n-1,j}) cot beta_j (construction).
template <class T>
ClaimSides<T> eq9a(const PolygonContext<T>& c, const ConstructionReading& r) {
  const auto cons = constructions(c, r);
  ClaimSides<T> s;
  for (int j = 1; j <= c.inputs(); ++j)
    s.instances.push_back(compare<T>(label_j(j), [&] { return c.closed.get().lambda[j - 1]; },
                                     [&] { return cons[j - 1].lambda.get(); }));
  return s;
}

// --- Mixed terms: eqs. (10), (11), (13), (14), (18)-(21) ------------------------------------

/// Delta omega-dot as the paper defines it in (10)/(11): the truth minus the sum of the
/// four-bar contributions (each four-bar solved exactly by the engine).
template <class T>
T mixed_term_out(const PolygonContext<T>& c) {
  T d = c.truth.get().omega_dot[c.n - 2];
  for (const auto& fb : c.four_bars) d = d - fb.omega_dot_out.get();
  return d;
}
template <class T>
T mixed_term_cpl(const PolygonContext<T>& c) {
  T d = c.truth.get().omega_dot[c.n - 3];
  for (const auto& fb : c.four_bars) d = d - fb.omega_dot_cpl.get();
  return d;
}

/// S_1, S_2 of SPEC A3 from the four-bars' own velocities _j omega (engine), used by (18)-(20).
template <class T>
std::pair<T, T> mixed_sums_from_four_bars(const PolygonContext<T>& c) {
  std::vector<T> out, cpl;
  for (const auto& fb : c.four_bars) {
    out.push_back(fb.omega_out.get());
    cpl.push_back(fb.omega_cpl.get());
  }
  return {ordered_pair_sum(out), ordered_pair_sum(cpl)};
}

/// S_1, S_2 from the construction's ratios: _j omega = i omega_j, as substituted in (21).
template <class T>
std::pair<T, T> mixed_sums_from_construction(const PolygonContext<T>& c, const ConstructionReading& r) {
  const auto cons = constructions(c, r);
  return {ordered_pair_sum(contributions<T>(c, [&](int j) { return cons[j - 1].i_out.get(); })),
          ordered_pair_sum(contributions<T>(c, [&](int j) { return cons[j - 1].i_cpl.get(); }))};
}

/// (21) right side: -(pair/2) [cot phi S_1 + r_{n-2}/(r_{n-1} sin phi) S_2], construction ratios.
template <class T>
T eq21_rhs(const PolygonContext<T>& c, const FormulaReading& rd) {
  const auto [s1, s2] = mixed_sums_from_construction(c, rd.construction);
  const PhiTerms<T> phi = phi_terms(c, rd.signed_phi);
  const T half_pair = rd.ordered_pairs ? from_int<T>(1) : from_int<T>(1) / from_int<T>(2);
  return -half_pair * (phi.cot_phi * s1 + phi.rho * s2);
}

/// (10): omega-dot_{n-1,n} - Delta omega-dot_{n-1,n} [by (21)] = sum_j _j omega-dot_{n-1,n}.
template <class T>
ClaimSides<T> eq10(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  s.instances.push_back(compare<T>("total", [&] { return c.truth.get().omega_dot[c.n - 2] - eq21_rhs(c, {}); }, [&] {
    T sum = from_int<T>(0);
    for (const auto& fb : c.four_bars) sum += fb.omega_dot_out.get();
    return sum;
  }));
  return s;
}

/// (11): omega-dot_{n-2,n} - Delta omega-dot_{n-2,n} [by (19)] = sum_j _j omega-dot_{n-2,n}.
template <class T>
ClaimSides<T> eq11(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  s.instances.push_back(compare<T>("total", [&] {
    const auto [s1, s2] = mixed_sums_from_construction(c, {});
    const Vec2<T> a = c.r(c.n - 2), b = c.r(c.n - 1);
    const T delta = (norm2(b) * s1 + dot(a, b) * s2) / c.closed.get().D;
    return c.truth.get().omega_dot[c.n - 3] - delta;
  }, [&] {
    T sum = from_int<T>(0);
    for (const auto& fb : c.four_bars) sum += fb.omega_dot_cpl.get();
    return sum;
  }));
  return s;
}

/// Acceleration of K_{n-1} by (8) and (12): b = sum_j (omega-dot_j J r_j - omega_j^2 r_j)
/// + omega-dot_{n-2} J r_{n-2} - omega_{n-2}^2 r_{n-2}.
template <class T>
Vec2<T> acceleration_k_n1(const PolygonContext<T>& c) {
  const PolygonMotion<T>& m = c.truth.get();
  Vec2<T> b{from_int<T>(0), from_int<T>(0)};
  for (int j = 1; j <= c.n - 2; ++j) {
    const Vec2<T> r = c.r(j);
    b = b + m.omega_dot[j - 1] * perp(r) - (m.omega[j - 1] * m.omega[j - 1]) * r;
  }
  return b;
}

/// (13): tangential component in the frame at K_{n-1}, +X = -J r_{n-1}/|r_{n-1}|, both sides
/// multiplied by |r_{n-1}| to stay rational: omega-dot_{n-1} |r_{n-1}|^2 = b . (-J r_{n-1}).
template <class T>
ClaimSides<T> eq13(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  const Vec2<T> r = c.r(c.n - 1);
  s.instances.push_back(compare<T>("X", [&] { return c.truth.get().omega_dot[c.n - 2] * norm2(r); },
                                   [&] { return dot(acceleration_k_n1(c), -perp(r)); }));
  return s;
}

/// (14): normal component, +Y = r_{n-1}/|r_{n-1}|: omega_{n-1}^2 |r_{n-1}|^2 = b . r_{n-1}.
template <class T>
ClaimSides<T> eq14(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  const Vec2<T> r = c.r(c.n - 1);
  s.instances.push_back(compare<T>("Y", [&] {
    const T& w = c.truth.get().omega[c.n - 2];
    return w * w * norm2(r);
  }, [&] { return dot(acceleration_k_n1(c), r); }));
  return s;
}

/// (18): Delta_{n-1} |r_{n-1}|^2 = -Delta_{n-2} r_{n-2}.r_{n-1} - D S_2.
template <class T>
ClaimSides<T> eq18(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  const Vec2<T> a = c.r(c.n - 2), b = c.r(c.n - 1);
  s.instances.push_back(compare<T>("total", [&] { return mixed_term_out(c) * norm2(b); }, [&] {
    return -mixed_term_cpl(c) * dot(a, b) - c.closed.get().D * mixed_sums_from_four_bars(c).second;
  }));
  return s;
}

/// (19): Delta_{n-2} D = |r_{n-1}|^2 S_1 + r_{n-2}.r_{n-1} S_2.
template <class T>
ClaimSides<T> eq19(const PolygonContext<T>& c) {
  ClaimSides<T> s;
  const Vec2<T> a = c.r(c.n - 2), b = c.r(c.n - 1);
  s.instances.push_back(compare<T>("total", [&] { return mixed_term_cpl(c) * c.closed.get().D; }, [&] {
    const auto [s1, s2] = mixed_sums_from_four_bars(c);
    return norm2(b) * s1 + dot(a, b) * s2;
  }));
  return s;
}

/// (20): Delta_{n-1} = -cot phi S_1 - (r_{n-2}/(r_{n-1} sin phi)) S_2.
template <class T>
ClaimSides<T> eq20(const PolygonContext<T>& c, bool signed_phi) {
  ClaimSides<T> s;
  s.instances.push_back(compare<T>("total", [&] { return mixed_term_out(c); }, [&] {
    const auto [s1, s2] = mixed_sums_from_four_bars(c);
    const PhiTerms<T> phi = phi_terms(c, signed_phi);
    return -phi.cot_phi * s1 - phi.rho * s2;
  }));
  return s;
}

/// (21): Delta_{n-1} = -sum_{j!=l} [i_{n-1,j} i_{n-1,l} cot phi + i_{n-2,j} i_{n-2,l} r_{n-2}/(r_{n-1} sin phi)] omega_j omega_l.
template <class T>
ClaimSides<T> eq21(const PolygonContext<T>& c, const FormulaReading& rd) {
  ClaimSides<T> s;
  s.instances.push_back(compare<T>("total", [&] { return mixed_term_out(c); }, [&] { return eq21_rhs(c, rd); }));
  return s;
}

// --- The catalogue ---------------------------------------------------------------------------

const std::string kPaper = "Dijksman (1966), J. Mechanisms 1:73-81";

ClaimInfo info(std::string id, std::string where, std::string statement, int min_n = 4, int max_n = 0) {
  return ClaimInfo{"dijksman1966." + std::move(id), kPaper + ", " + std::move(where), std::move(statement),
                   Expectation::Holds, "", min_n, max_n};
}
ClaimInfo erratum(std::string id, std::string where, std::string statement, std::string note, int min_n = 4,
                  int max_n = 0) {
  ClaimInfo i = info(std::move(id), std::move(where), std::move(statement), min_n, max_n);
  i.expected = Expectation::Fails;
  i.note = std::move(note);
  return i;
}

ConstructionReading undisplaced() { ConstructionReading r; r.displaced_start = false; return r; }
ConstructionReading unsigned_ratios() { ConstructionReading r; r.signed_ratios = false; return r; }
ConstructionReading beta_towards_p() { ConstructionReading r; r.beta_towards_p_prime = false; return r; }
ConstructionReading reversed_beta() { ConstructionReading r; r.beta_ccw_positive = false; return r; }
FormulaReading unsigned_phi() { FormulaReading f; f.signed_phi = false; return f; }
FormulaReading j_lt_l() { FormulaReading f; f.ordered_pairs = false; return f; }

std::vector<Claim> make_catalogue() {
  std::vector<Claim> v;
  const auto add = [&v](ClaimInfo i, auto f) { v.push_back(Claim::make(std::move(i), f)); };

  add(info("eq4", "sec. 2.1, eq. (4)", "i_{n-1,j} = Q_jK'_j / Q_jK_n (directed) equals omega_out/omega_in of four-bar j"),
      [](const auto& c) { return eq4(c, {}); });
  add(info("eq5", "sec. 2.1, eq. (5)", "omega_{n-1,n} = sum_j i_{n-1,j} omega_{j,n}"),
      [](const auto& c) { return eq5(c); });
  add(info("eq6", "sec. 2.1, eq. (6)",
           "i_{n-2,j} = K_{n-2}K'_j / K_{n-2}P'_j (directed) equals omega_coupler/omega_in of four-bar j; "
           "omega_{n-2,n} = sum_j i_{n-2,j} omega_{j,n}"),
      [](const auto& c) { return eq6(c, {}); });
  add(info("eq9", "sec. 2.2, eq. (9)", "_j omega-dot_{n-1,n} of four-bar j = lambda_j omega_{j,n}^2 + i_{n-1,j} omega-dot_{j,n}"),
      [](const auto& c) { return eq9(c); });
  add(info("eq9a", "sec. 2.2, eq. (9a)",
           "lambda_j = i_{n-1,j}(1 - i_{n-1,j}) cot beta_j, beta_j = angle P'_j Q_j K_{n-1}, > 0 iff ccw"),
      [](const auto& c) { return eq9a(c, {}); });
  add(info("eq10", "sec. 2.2, eq. (10)",
           "omega-dot_{n-1,n} - Delta omega-dot_{n-1,n} = sum_j _j omega-dot_{n-1,n} (Delta by (21))"),
      [](const auto& c) { return eq10(c); });
  add(info("eq11", "sec. 2.2, eq. (11)",
           "omega-dot_{n-2,n} - Delta omega-dot_{n-2,n} = sum_j _j omega-dot_{n-2,n} (Delta by (19))"),
      [](const auto& c) { return eq11(c); });
  add(info("eq13", "sec. 2.2.1, eq. (13)",
           "omega-dot_{n-1,n} r_{n-1} = (b_{K_{n-2}} + omega-dot_{n-2,n} x r_{n-2} - omega_{n-2,n}^2 r_{n-2})_X, "
           "+X = -J r_{n-1}/|r_{n-1}| (both sides times |r_{n-1}|)"),
      [](const auto& c) { return eq13(c); });
  add(info("eq14", "sec. 2.2.1, eq. (14)",
           "omega_{n-1,n}^2 r_{n-1} = (b_{K_{n-2}} + omega-dot_{n-2,n} x r_{n-2} - omega_{n-2,n}^2 r_{n-2})_Y, "
           "+Y = r_{n-1}/|r_{n-1}| (both sides times |r_{n-1}|)"),
      [](const auto& c) { return eq14(c); });
  add(info("eq18", "sec. 2.2.1, eq. (18)",
           "Delta omega-dot_{n-1,n} |r_{n-1}|^2 = -Delta omega-dot_{n-2,n} r_{n-2}.r_{n-1} - D S_2"),
      [](const auto& c) { return eq18(c); });
  add(info("eq19", "sec. 2.2.1, eq. (19)", "Delta omega-dot_{n-2,n} D = |r_{n-1}|^2 S_1 + r_{n-2}.r_{n-1} S_2"),
      [](const auto& c) { return eq19(c); });
  add(info("eq20", "sec. 2.2.1, eq. (20)",
           "Delta omega-dot_{n-1,n} = -cot phi S_1 - (r_{n-2}/(r_{n-1} sin phi)) S_2, phi signed (ccw)"),
      [](const auto& c) { return eq20(c, true); });
  add(info("eq21", "sec. 2.2.1, eq. (21)",
           "Delta omega-dot_{n-1,n} = -sum_{j!=l} [i_{n-1,j} i_{n-1,l} cot phi + i_{n-2,j} i_{n-2,l} "
           "r_{n-2}/(r_{n-1} sin phi)] omega_j omega_l"),
      [](const auto& c) { return eq21(c, FormulaReading{}); });
  add(info("eq22", "sec. 2.2.1, eq. (22)",
           "omega-dot_{n-1,n} = sum_j (lambda_j omega_j^2 + i_{n-1,j} omega-dot_j) - cot phi sum_{j!=l} "
           "i_{n-1,j} i_{n-1,l} omega_j omega_l - (r_{n-2}/(r_{n-1} sin phi)) sum_{j!=l} i_{n-2,j} i_{n-2,l} omega_j omega_l"),
      [](const auto& c) { return eq22_sides(c, FormulaReading{}); });
  add(info("sec3", "sec. 3, pentagon formula",
           "omega-dot_{4,5} = sum_{j=1,2} [i_{4,j}(1 - i_{4,j}) omega_j^2 cot beta_j + i_{4,j} omega-dot_j] "
           "- 2 i_{4,1} i_{4,2} omega_1 omega_2 cot phi - 2 i_{3,1} i_{3,2} omega_1 omega_2 r_3/(r_4 sin phi)",
           5, 5),
      [](const auto& c) { return eq22_sides(c, FormulaReading{}); });
  add(info("companion", "sec. 2.2 (mentioned, not printed); SPEC A4",
           "omega-dot_{n-2,n} = sum_j (mu_j omega_j^2 + i_{n-2,j} omega-dot_j) + cot phi S_2' + (|r_{n-1}|^2/D) S_1'"),
      [](const auto& c) { return companion_sides(c, FormulaReading{}); });

  // Erratum readings (SPEC A5): expected to fail on generic configurations.
  add(erratum("eq4.printed", "sec. 2.1, eq. (4) as printed",
              "i_{n-1,j} = Q_jK_j / Q_jK_n with the undisplaced K_j",
              "A5.1: the OCR dropped the prime of K'_j; only j = n-3 has K'_j = K_j", 5),
      [](const auto& c) { return eq4(c, undisplaced()); });
  add(erratum("eq4.unsigned_ratio", "sec. 2.1, eq. (4), unsigned",
              "i_{n-1,j} = |Q_jK'_j| / |Q_jK_n| (lengths, not directed segments)",
              "A5.6: the ratio is negative when K'_j and K_n lie on opposite sides of Q_j"),
      [](const auto& c) { return eq4(c, unsigned_ratios()); });
  add(erratum("eq6.printed", "sec. 2.1, eq. (6) as printed",
              "i_{n-2,j} = K_{n-2}K_j / K_{n-2}P_j with the undisplaced K_j (four-bar K_j K_{n-2} K_{n-1} K_n)",
              "A5.1: the OCR dropped the prime of K'_j", 5),
      [](const auto& c) { return eq6(c, undisplaced()); });
  add(erratum("eq6.unsigned_ratio", "sec. 2.1, eq. (6), unsigned",
              "i_{n-2,j} = |K_{n-2}K'_j| / |K_{n-2}P'_j| (lengths)", "A5.6: directed segments are needed"),
      [](const auto& c) { return eq6(c, unsigned_ratios()); });
  add(erratum("eq9a.printed", "sec. 2.2, eq. (9a) as printed",
              "beta_j = angle P_j Q_j K_{n-1} with P_j on the undisplaced side r_j",
              "A5.2: P_j must be P'_j (intersection of r_{n-1} with the displaced r_j)", 5),
      [](const auto& c) { return eq9a(c, beta_towards_p()); });
  add(erratum("eq9a.reversed_beta", "sec. 2.2, eq. (9a), sign rule reversed",
              "beta_j > 0 iff the triangle P'_j Q_j K_{n-1} is clockwise",
              "A5.6: the printed rule (ccw positive) is the right one"),
      [](const auto& c) { return eq9a(c, reversed_beta()); });
  add(erratum("eq20.unsigned_phi", "sec. 2.2.1, eq. (20), unsigned phi",
              "eq. (20) with phi the unsigned drawn angle between r_{n-2} and r_{n-1}",
              "A3/A5.6: phi is signed; with the paper's clockwise numbering of a convex polygon D < 0 and phi < 0"),
      [](const auto& c) { return eq20(c, false); });
  add(erratum("eq21.unsigned_phi", "sec. 2.2.1, eq. (21), unsigned phi", "eq. (21) with the unsigned phi",
              "A3/A5.6: phi is signed"),
      [](const auto& c) { return eq21(c, unsigned_phi()); });
  add(erratum("eq21.j_lt_l", "sec. 2.2.1, eq. (21), j < l", "eq. (21) summed over j < l only",
              "A3/A5.6: the sums run over ordered pairs j != l (each unordered pair twice)", 5),
      [](const auto& c) { return eq21(c, j_lt_l()); });
  add(erratum("eq22.unsigned_phi", "sec. 2.2.1, eq. (22), unsigned phi", "eq. (22) with the unsigned phi",
              "A3/A5.6: phi is signed"),
      [](const auto& c) { return eq22_sides(c, unsigned_phi()); });
  add(erratum("eq22.j_lt_l", "sec. 2.2.1, eq. (22), j < l", "eq. (22) summed over j < l only (no factor 2 in sec. 3)",
              "A3/A5.6: ordered pairs", 5),
      [](const auto& c) { return eq22_sides(c, j_lt_l()); });
  add(erratum("eq22.reversed_beta", "sec. 2.2.1, eq. (22), reversed beta sign",
              "eq. (22) with beta_j > 0 iff clockwise", "A5.6: the sign rule of (9a) is ccw positive"),
      [](const auto& c) {
        FormulaReading f;
        f.construction = reversed_beta();
        return eq22_sides(c, f);
      });
  add(erratum("sec3.printed", "sec. 3 as printed",
              "the pentagon formula with i_{4,1} = Q_1K_1/Q_1K_5, i_{3,1} = K_3K_1/K_3P_1 (undisplaced K_1)",
              "A5.3: K_1 must be K'_1 (sec. 3 even prints K'_2 = K_2, the one joint that needs no prime)", 5, 5),
      [](const auto& c) {
        FormulaReading f;
        f.construction = undisplaced();
        return eq22_sides(c, f);
      });
  return v;
}

}  // namespace

const std::vector<Claim>& catalogue() {
  static const std::vector<Claim> claims = make_catalogue();
  return claims;
}

}  // namespace linkproof::dijksman1966
