#include "claims/vocabulary.h"

#include "linkproof/core/error.h"

namespace linkproof {

const std::vector<Word>& vocabulary() {
  using K = ClaimKind;
  using E = Evaluation;
  constexpr Languages P = Languages::Polygon, M = Languages::Mechanism, B = Languages::Both;
  const std::vector<ClaimKind> none, input{K::InputIndex}, side{K::SideIndex}, body{K::SumBody};
  // The polygon words come first in the order of their codes (word_code): a new polygon word goes
  // after the last one (l), a mechanism word anywhere after them.
  static const std::vector<Word> words = {
      // Polygon. Ground truth (symbolic engine, conventions §A2), relative to the fixed side n.
      {"omega_out", P, none, K::Number, E::OmegaOut, "omega_out", "omega_{n-1,n}: exact angular velocity of side n-1 (engine)"},
      {"omega_cpl", P, none, K::Number, E::OmegaCpl, "omega_cpl", "omega_{n-2,n}: exact angular velocity of side n-2 (engine)"},
      {"omega_dot_out", P, none, K::Number, E::OmegaDotOut, "omega_dot_out", "omega-dot_{n-1,n}: exact angular acceleration of side n-1 (engine)"},
      {"omega_dot_cpl", P, none, K::Number, E::OmegaDotCpl, "omega_dot_cpl", "omega-dot_{n-2,n}: exact angular acceleration of side n-2 (engine)"},
      {"side_omega", P, side, K::Number, E::SideOmega, "side_omega[k]", "side_omega[k] = omega_{k,n} for every side k (inputs, engine truth for n-2, n-1; 0 for n)"},
      {"side_omega_dot", P, side, K::Number, E::SideOmegaDot, "side_omega_dot[k]", "side_omega_dot[k] = omega-dot_{k,n} likewise"},
      {"acc", P, side, K::Vector, E::JointAcc, "acc[k]", "acc[k]: acceleration of joint K_k, sum_{i<k} (omega-dot_i J r_i - omega_i^2 r_i) (eqs. 8, 12)"},
      // Inputs.
      {"omega", P, input, K::Number, E::InputOmega, "omega[j]", "omega[j] = omega_{j,n}, input angular velocity"},
      {"omega_dot", P, input, K::Number, E::InputOmegaDot, "omega_dot[j]", "omega_dot[j] = omega-dot_{j,n}, input angular acceleration"},
      // The paper's construction for four-bar j (conventions §A3), under the claim's reading.
      {"i_out", P, input, K::Number, E::IOut, "i_out[j]", "i_{n-1,j} = Q_jK'_j / Q_jK_n, directed (eq. 4)"},
      {"i_cpl", P, input, K::Number, E::ICpl, "i_cpl[j]", "i_{n-2,j} = K_{n-2}K'_j / K_{n-2}P'_j, directed (eq. 6)"},
      {"cot_beta", P, input, K::Number, E::CotBeta, "cot_beta[j]", "cot beta_j, beta_j at Q_j from ray Q_jK_{n-1} to Q_jP'_j, > 0 iff ccw (eq. 9a)"},
      {"cot_gamma", P, input, K::Number, E::CotGamma, "cot_gamma[j]", "cot gamma_j, gamma_j at P'_j in triangle Q_j P'_j K_{n-1} (companion)"},
      {"lambda", P, input, K::Number, E::Lambda, "lambda[j]", "lambda_j = i_{n-1,j}(1 - i_{n-1,j}) cot beta_j by the construction (eq. 9a)"},
      {"mu", P, input, K::Number, E::Mu, "mu[j]", "mu_j = i_{n-2,j}(1 - i_{n-2,j}) cot gamma_j by the construction (companion)"},
      {"Kp", P, input, K::Vector, E::Kp, "Kp[j]", "K'_j = K_{n-2} - r_j (the displaced start of r_j)"},
      {"Q", P, input, K::Vector, E::Q, "Q[j]", "Q_j = line(K_{n-2},K_{n-1}) ^ line(K_n,K'_j)"},
      {"Pp", P, input, K::Vector, E::Pp, "Pp[j]", "P'_j = line(K_{n-1},K_n) ^ line(K'_j,K_{n-2})"},
      // Closed forms (conventions §A3), independent of the construction.
      {"i_out_closed", P, input, K::Number, E::IOutClosed, "i_out_closed[j]", "(r_j x r_{n-2}) / D"},
      {"i_cpl_closed", P, input, K::Number, E::ICplClosed, "i_cpl_closed[j]", "(r_{n-1} x r_j) / D"},
      {"lambda_closed", P, input, K::Number, E::LambdaClosed, "lambda_closed[j]", "-[r_{n-2}.r_j + i_{n-2,j}^2 |r_{n-2}|^2 + i_{n-1,j}^2 r_{n-2}.r_{n-1}] / D"},
      {"mu_closed", P, input, K::Number, E::MuClosed, "mu_closed[j]", "[r_{n-1}.r_j + i_{n-2,j}^2 r_{n-2}.r_{n-1} + i_{n-1,j}^2 |r_{n-1}|^2] / D"},
      // Four-bar j solved on its own by the engine (n = 4), independent of the construction.
      {"fourbar_ratio_out", P, input, K::Number, E::FourbarRatioOut, "fourbar_ratio_out[j]", "omega_out / omega_in of four-bar j (engine)"},
      {"fourbar_ratio_cpl", P, input, K::Number, E::FourbarRatioCpl, "fourbar_ratio_cpl[j]", "omega_coupler / omega_in of four-bar j (engine)"},
      {"fourbar_omega_out", P, input, K::Number, E::FourbarOmegaOut, "fourbar_omega_out[j]", "_j omega_{n-1,n}: output of four-bar j driven by omega_j (engine)"},
      {"fourbar_omega_cpl", P, input, K::Number, E::FourbarOmegaCpl, "fourbar_omega_cpl[j]", "_j omega_{n-2,n}: coupler of four-bar j driven by omega_j (engine)"},
      {"fourbar_omega_dot_out", P, input, K::Number, E::FourbarOmegaDotOut, "fourbar_omega_dot_out[j]", "_j omega-dot_{n-1,n}: four-bar j driven by omega_j, omega-dot_j (engine)"},
      {"fourbar_omega_dot_cpl", P, input, K::Number, E::FourbarOmegaDotCpl, "fourbar_omega_dot_cpl[j]", "_j omega-dot_{n-2,n} likewise"},
      // The angle phi between r_{n-2} and r_{n-1} (conventions §A3), signed unless the claim reads it unsigned.
      {"D", P, none, K::Number, E::D, "D", "D = r_{n-2} x r_{n-1} (0 at the dead centre)"},
      {"cot_phi", P, none, K::Number, E::CotPhi, "cot_phi", "cot phi = r_{n-2}.r_{n-1} / D, phi signed ccw from r_{n-2} to r_{n-1}"},
      {"rho", P, none, K::Number, E::Rho, "rho", "r_{n-2} / (r_{n-1} sin phi) = |r_{n-2}|^2 / D"},
      {"rho_companion", P, none, K::Number, E::RhoCompanion, "rho_companion", "r_{n-1} / (r_{n-2} sin phi) = |r_{n-1}|^2 / D"},
      // Geometry.
      {"r", P, side, K::Vector, E::R, "r[k]", "r[k] = K_{k+1} - K_k, side vector (K_{n+1} = K_1)"},
      {"K", P, side, K::Vector, E::K, "K[k]", "K[k]: joint k"},

      // Mechanism: rates of links, motion of points, constructed points (docs/claims.md).
      {"omega", M, {K::Link}, K::Number, E::Omega, "omega(L)", "angular velocity of link L relative to the ground (ground: 0)"},
      {"omega", M, {K::Link, K::Link}, K::Number, E::OmegaRelative, "omega(L, M)", "omega(L) - omega(M): L relative to M"},
      {"alpha", M, {K::Link}, K::Number, E::Alpha, "alpha(L)", "angular acceleration of link L relative to the ground (ground: 0)"},
      {"alpha", M, {K::Link, K::Link}, K::Number, E::AlphaRelative, "alpha(L, M)", "alpha(L) - alpha(M): L relative to M"},
      {"pos", M, {K::Point}, K::Vector, E::Position, "pos(P)", "position of joint or tracer point P (a vector)"},
      {"vel", M, {K::Point, K::Link}, K::Vector, E::Velocity, "vel(P, L)", "velocity of the point of link L now at P"},
      {"vel", M, {K::Point, K::Link, K::Link}, K::Vector, E::VelocityRelative, "vel(P, L, M)",
       "the same seen from link M: vel(P, L) - vel(P, M)"},
      {"acc", M, {K::Point, K::Link}, K::Vector, E::Acceleration, "acc(P, L)", "acceleration of the point of link L now at P"},
      {"acc", M, {K::Point, K::Link, K::Link}, K::Vector, E::AccelerationRelative, "acc(P, L, M)",
       "the same seen from link M: acc(P, L) - acc(P, M) - 2 omega(M) perp(vel(P, L, M)) (Coriolis)"},
      {"pole", M, {K::Link, K::Link}, K::Vector, E::Pole, "pole(L, M)",
       "instant centre of L and M (undefined at infinity, omega(L) = omega(M), or with no relative motion)"},
      {"centre", M, {K::Point, K::Link, K::Link}, K::Vector, E::Centre, "centre(P, L, M)",
       "centre of curvature of the path of the point of L at P seen from M (undefined where v = 0 or v x a = 0)"},
      {"centre_at", M, {K::Vector, K::Link, K::Link}, K::Vector, E::CentreAt, "centre_at(X, L, M)",
       "the same for the point of L at the position X (a vector, e.g. a meet): centre(P, L, M) with X for pos(P)"},
      {"sliding_v", M, {K::Slider}, K::Number, E::SlidingV, "sliding_v(J)",
       "sliding velocity of prismatic joint J along its unit axis (slider relative to guide)"},
      {"sliding_a", M, {K::Slider}, K::Number, E::SlidingA, "sliding_a(J)",
       "sliding acceleration of prismatic joint J along its unit axis (slider relative to guide)"},
      {"axis", M, {K::Slider}, K::Vector, E::Axis, "axis(J)",
       "the unit axis u of prismatic joint J, the direction of its guide (undefined if |u| is irrational)"},

      // Both languages: vector algebra.
      {"dot", B, {K::Vector, K::Vector}, K::Number, E::Dot, "dot(a, b)", "a . b"},
      {"cross", B, {K::Vector, K::Vector}, K::Number, E::Cross, "cross(a, b)", "a x b = ax by - ay bx"},
      {"norm2", B, {K::Vector}, K::Number, E::Norm2, "norm2(a)", "a . a"},
      {"perp", B, {K::Vector}, K::Vector, E::Perp, "perp(a)", "a turned by +90 degrees: (-ay, ax)"},
      {"vx", B, {K::Vector}, K::Number, E::Vx, "vx(a)", "x component of a"},
      {"vy", B, {K::Vector}, K::Number, E::Vy, "vy(a)", "y component of a"},

      // Polygon: sums and the index symbols.
      {"sum_j", P, body, K::Number, E::SumJ, "sum_j(e)", "sum over inputs j = 1..n-3"},
      {"sum_pairs", P, body, K::Number, E::SumPairs, "sum_pairs(e)", "sum over ordered pairs j != l of inputs"},
      {"sum_pairs_lt", P, body, K::Number, E::SumPairsLt, "sum_pairs_lt(e)", "sum over pairs j < l of inputs"},
      {"n", P, none, K::Index, E::IndexN, "n", "the number of sides (only inside an index: r[n-1])"},
      {"j", P, none, K::Index, E::IndexJ, "j", "input index bound by sum_j, sum_pairs or for_each"},
      {"l", P, none, K::Index, E::IndexL, "l", "second input index bound by sum_pairs"},

      // Mechanism: vectors made of numbers and of points.
      {"vec", M, {K::Number, K::Number}, K::Vector, E::Vec, "vec(x, y)", "the vector (x, y)"},
      {"meet", M, {K::Vector, K::Vector, K::Vector, K::Vector}, K::Vector, E::Meet, "meet(A, B, C, D)",
       "intersection of lines AB and CD (undefined for parallel lines or A = B, C = D)"},
  };
  return words;
}

namespace {

// The polygon words in the order of vocabulary(): code -> word.
const std::vector<const Word*>& polygon_words() {
  static const std::vector<const Word*> words = [] {
    std::vector<const Word*> out;
    for (const Word& w : vocabulary())
      if (w.belongs_to(Language::Polygon)) out.push_back(&w);
    return out;
  }();
  return words;
}

}  // namespace

const Word* find_word(Language language, const std::string& name, int arity) {
  for (const Word& w : vocabulary())
    if (w.belongs_to(language) && w.name == name && w.arity() == arity) return &w;
  return nullptr;
}

const Word& polygon_word(Evaluation evaluation) {
  for (const Word* w : polygon_words())
    if (w->evaluation == evaluation) return *w;
  throw InternalError("no polygon word evaluates as code " + std::to_string(static_cast<int>(evaluation)));
}

std::string word_signatures(Language language, const std::string& name) {
  std::string out;
  for (const Word& w : vocabulary())
    if (w.belongs_to(language) && w.name == name) out += (out.empty() ? "" : ", ") + w.signature;
  return out;
}

int word_code(const Word& w) {
  const auto& words = polygon_words();
  for (size_t k = 0; k < words.size(); ++k)
    if (words[k] == &w) return static_cast<int>(k);
  throw InternalError("'" + w.signature + "' is not a word of the polygon language");
}

const Word& word_of_code(int code) { return *polygon_words().at(static_cast<size_t>(code)); }

std::string describe(ClaimKind kind) {
  switch (kind) {
    case ClaimKind::Number: return "a number";
    case ClaimKind::Vector: return "a vector";
    case ClaimKind::Link: return "a link name";
    case ClaimKind::Point: return "a joint or point name";
    case ClaimKind::Slider: return "a prismatic joint name";
    case ClaimKind::InputIndex: return "an input index";
    case ClaimKind::SideIndex: return "a side index";
    case ClaimKind::SumBody: return "a number summed over inputs";
    case ClaimKind::Index: return "an index symbol";
  }
  return "?";
}

}  // namespace linkproof
