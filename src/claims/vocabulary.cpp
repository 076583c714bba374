#include "claims/vocabulary.h"

namespace linkproof {

const std::vector<Word>& vocabulary() {
  using K = WordKind;
  static const std::vector<Word> words = {
      // Ground truth (symbolic engine, conventions §A2), relative to the fixed side n.
      {"omega_out", K::GlobalScalar, 0, "omega_{n-1,n}: exact angular velocity of side n-1 (engine)"},
      {"omega_cpl", K::GlobalScalar, 0, "omega_{n-2,n}: exact angular velocity of side n-2 (engine)"},
      {"omega_dot_out", K::GlobalScalar, 0, "omega-dot_{n-1,n}: exact angular acceleration of side n-1 (engine)"},
      {"omega_dot_cpl", K::GlobalScalar, 0, "omega-dot_{n-2,n}: exact angular acceleration of side n-2 (engine)"},
      {"side_omega", K::SideScalar, 1, "side_omega[k] = omega_{k,n} for every side k (inputs, engine truth for n-2, n-1; 0 for n)"},
      {"side_omega_dot", K::SideScalar, 1, "side_omega_dot[k] = omega-dot_{k,n} likewise"},
      {"acc", K::SideVector, 1, "acc[k]: acceleration of joint K_k, sum_{i<k} (omega-dot_i J r_i - omega_i^2 r_i) (eqs. 8, 12)"},
      // Inputs.
      {"omega", K::InputScalar, 1, "omega[j] = omega_{j,n}, input angular velocity"},
      {"omega_dot", K::InputScalar, 1, "omega_dot[j] = omega-dot_{j,n}, input angular acceleration"},
      // The paper's construction for four-bar j (conventions §A3), under the claim's reading.
      {"i_out", K::InputScalar, 1, "i_{n-1,j} = Q_jK'_j / Q_jK_n, directed (eq. 4)"},
      {"i_cpl", K::InputScalar, 1, "i_{n-2,j} = K_{n-2}K'_j / K_{n-2}P'_j, directed (eq. 6)"},
      {"cot_beta", K::InputScalar, 1, "cot beta_j, beta_j at Q_j from ray Q_jK_{n-1} to Q_jP'_j, > 0 iff ccw (eq. 9a)"},
      {"cot_gamma", K::InputScalar, 1, "cot gamma_j, gamma_j at P'_j in triangle Q_j P'_j K_{n-1} (companion)"},
      {"lambda", K::InputScalar, 1, "lambda_j = i_{n-1,j}(1 - i_{n-1,j}) cot beta_j by the construction (eq. 9a)"},
      {"mu", K::InputScalar, 1, "mu_j = i_{n-2,j}(1 - i_{n-2,j}) cot gamma_j by the construction (companion)"},
      {"Kp", K::InputVector, 1, "K'_j = K_{n-2} - r_j (the displaced start of r_j)"},
      {"Q", K::InputVector, 1, "Q_j = line(K_{n-2},K_{n-1}) ^ line(K_n,K'_j)"},
      {"Pp", K::InputVector, 1, "P'_j = line(K_{n-1},K_n) ^ line(K'_j,K_{n-2})"},
      // Closed forms (conventions §A3), independent of the construction.
      {"i_out_closed", K::InputScalar, 1, "(r_j x r_{n-2}) / D"},
      {"i_cpl_closed", K::InputScalar, 1, "(r_{n-1} x r_j) / D"},
      {"lambda_closed", K::InputScalar, 1, "-[r_{n-2}.r_j + i_{n-2,j}^2 |r_{n-2}|^2 + i_{n-1,j}^2 r_{n-2}.r_{n-1}] / D"},
      {"mu_closed", K::InputScalar, 1, "[r_{n-1}.r_j + i_{n-2,j}^2 r_{n-2}.r_{n-1} + i_{n-1,j}^2 |r_{n-1}|^2] / D"},
      // Four-bar j solved on its own by the engine (n = 4), independent of the construction.
      {"fourbar_ratio_out", K::InputScalar, 1, "omega_out / omega_in of four-bar j (engine)"},
      {"fourbar_ratio_cpl", K::InputScalar, 1, "omega_coupler / omega_in of four-bar j (engine)"},
      {"fourbar_omega_out", K::InputScalar, 1, "_j omega_{n-1,n}: output of four-bar j driven by omega_j (engine)"},
      {"fourbar_omega_cpl", K::InputScalar, 1, "_j omega_{n-2,n}: coupler of four-bar j driven by omega_j (engine)"},
      {"fourbar_omega_dot_out", K::InputScalar, 1, "_j omega-dot_{n-1,n}: four-bar j driven by omega_j, omega-dot_j (engine)"},
      {"fourbar_omega_dot_cpl", K::InputScalar, 1, "_j omega-dot_{n-2,n} likewise"},
      // The angle phi between r_{n-2} and r_{n-1} (conventions §A3), signed unless the claim reads it unsigned.
      {"D", K::GlobalScalar, 0, "D = r_{n-2} x r_{n-1} (0 at the dead centre)"},
      {"cot_phi", K::GlobalScalar, 0, "cot phi = r_{n-2}.r_{n-1} / D, phi signed ccw from r_{n-2} to r_{n-1}"},
      {"rho", K::GlobalScalar, 0, "r_{n-2} / (r_{n-1} sin phi) = |r_{n-2}|^2 / D"},
      {"rho_companion", K::GlobalScalar, 0, "r_{n-1} / (r_{n-2} sin phi) = |r_{n-1}|^2 / D"},
      // Geometry.
      {"r", K::SideVector, 1, "r[k] = K_{k+1} - K_k, side vector (K_{n+1} = K_1)"},
      {"K", K::SideVector, 1, "K[k]: joint k"},
      {"dot", K::VectorFunction, 2, "dot(a, b) = a.b"},
      {"cross", K::VectorFunction, 2, "cross(a, b) = a_x b_y - a_y b_x"},
      {"norm2", K::VectorFunction, 1, "norm2(a) = |a|^2"},
      {"perp", K::VectorFunction, 1, "perp(a) = J a = (-a_y, a_x)"},
      {"vx", K::VectorFunction, 1, "vx(a) = a_x"},
      {"vy", K::VectorFunction, 1, "vy(a) = a_y"},
      // Sums.
      {"sum_j", K::Sum, 1, "sum over inputs j = 1..n-3"},
      {"sum_pairs", K::Sum, 1, "sum over ordered pairs j != l of inputs"},
      {"sum_pairs_lt", K::Sum, 1, "sum over pairs j < l of inputs"},
      // Index symbols.
      {"n", K::Index, 0, "the number of sides (only inside an index: r[n-1])"},
      {"j", K::Index, 0, "input index bound by sum_j, sum_pairs or for_each"},
      {"l", K::Index, 0, "second input index bound by sum_pairs"},
  };
  return words;
}

const Word* find_word(const std::string& name, int arity) {
  for (const Word& w : vocabulary())
    if (w.name == name && w.arity == arity) return &w;
  return nullptr;
}

int word_code(const Word& w) { return static_cast<int>(&w - vocabulary().data()); }

}  // namespace linkproof
