#include "proof/symbolic_motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "core/block_triangular.h"
#include "core/symbolic_scalar.h"
#include "mechanism/mechanism_vector_route.h"
#include "mechanism/poles.h"
#include "proof/topology_layout.h"

namespace linkproof {

namespace {

using GiNaC::ex;

class SymbolNames {
 public:
  ex make(const std::string& prefix, const std::string& name) {
    std::string base = prefix + "_";
    for (char ch : name) base += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    std::string unique = base;
    for (int k = 2; !used_.insert(unique).second; ++k) unique = fmt::format("{}_{}", base, k);
    names.push_back(unique);
    return GiNaC::symbol(unique);
  }
  std::vector<std::string> names;

 private:
  std::set<std::string> used_;
};

// det of `rows` restricted to `keep_rows` x `keep_cols`, expanded.
ex determinant(const DenseMatrix<ex>& rows, const std::vector<int>& keep_rows, const std::vector<int>& keep_cols) {
  const auto n = static_cast<unsigned>(keep_rows.size());
  if (n == 0) return 1;
  GiNaC::matrix m(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned k = 0; k < n; ++k) m(i, k) = rows[static_cast<size_t>(keep_rows[i])][static_cast<size_t>(keep_cols[k])];
  return GiNaC::expand(m.determinant());
}

std::vector<int> without(const std::vector<int>& v, size_t skip) {
  std::vector<int> out;
  for (size_t i = 0; i < v.size(); ++i)
    if (i != skip) out.push_back(v[i]);
  return out;
}

std::vector<int> all_of(size_t n) {
  std::vector<int> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = static_cast<int>(i);
  return v;
}

std::vector<std::vector<bool>> pattern_of(const DenseMatrix<ex>& A) {
  std::vector<std::vector<bool>> p;
  for (const auto row : A) {
    p.emplace_back();
    for (const ex& e : row) p.back().push_back(!e.is_zero());
  }
  return p;
}

// The velocity system's matrix with `inputs` as the input rows (right-hand side in b).
DenseMatrix<ex> velocity_matrix(const MechanismScene& s, const JointGeometry<ex>& geo, const std::vector<MechanismInput>& inputs,
                                std::vector<ex>& b, const std::vector<InputValue<ex>>* values) {
  DenseMatrix<ex> A = rigid_body_constraint_matrix<ex>(s.linkage, geo);
  b.assign(A.size(), ex(0));
  append_input_rows<ex>(s.linkage, inputs, A, b, false, s.source, values);
  return A;
}

// One group of the block solve: its rows and columns, adj of its block and 1/det.
struct SolvedBlock {
  MatrixBlock block;
  std::vector<std::vector<ex>> adj;  // adj[i][k]: column block.cols[i], row block.rows[k]
  ex inverse;                        // 1/det: a delta symbol or a number
};

}  // namespace

SymbolicConfiguration symbolic_configuration(const MechanismScene& s) {
  const TopologyLayout layout = topology_layout(s);
  const Linkage& g = s.linkage;
  SymbolNames names;
  SymbolicConfiguration c;
  std::vector<Vec2<ex>> group;
  for (const std::string& n : layout.group_name) {
    const ex x = names.make("x", n), y = names.make("y", n);
    group.push_back({x, y});
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    c.joint_at.push_back(group[static_cast<size_t>(layout.joint_group[static_cast<size_t>(j)])]);
    if (g.joint(j).type != JointType::Prismatic) {
      c.axis.push_back({0, 0});
      continue;
    }
    const ex cj = names.make("c", g.joint(j).name), sj = names.make("s", g.joint(j).name);
    c.axis.push_back({cj, sj});
    c.unit_axes.emplace_back(cj, sj);
    c.relations.push_back(fmt::format("{}^2 + {}^2 = 1", to_text(cj), to_text(sj)));
  }
  for (size_t p = 0; p < s.points.size(); ++p) c.point_at.push_back(group[static_cast<size_t>(layout.point_group[p])]);
  for (const MechanismInput& in : s.inputs) {
    const bool link = in.kind == MechanismInput::Kind::Link;
    const std::string who = link ? g.link_names()[static_cast<size_t>(in.index)] : g.joint(in.index).name;
    const ex rate = names.make(link ? "w" : "v", who), rate_dot = names.make(link ? "wd" : "vd", who);
    c.inputs.push_back({rate, rate_dot});
  }
  c.names = names.names;
  return c;
}

bool SymbolicMotion::has_inverse(const ex& e) const {
  return std::any_of(inverses.begin(), inverses.end(), [&](const InverseDeterminant& d) { return e.has(d.delta); });
}

SymbolicMotion solve_symbolically(const MechanismScene& s, const SymbolicConfiguration& c,
                                  const std::vector<MechanismInput>& inputs, const std::vector<InputValue<ex>>& values) {
  SymbolicMotion out;
  out.inputs = inputs;
  out.input_values = values;
  const Linkage& g = s.linkage;
  const JointGeometry<ex> geo{&c.joint_at, &c.axis};
  const size_t N = static_cast<size_t>(g.unknown_count());
  out.unknowns = static_cast<int>(N);
  std::vector<ex> b;
  const DenseMatrix<ex> A = velocity_matrix(s, geo, inputs, b, &values);
  if (A.size() != N) {
    out.note = fmt::format("the velocity system has {} equations for {} unknowns (redundant constraints): the "
                           "symbolic solution needs a square system", A.size(), N);
    return out;
  }
  const std::optional<std::vector<MatrixBlock>> blocks = block_triangular_form(pattern_of(A));
  out.det = blocks ? determinant(A, all_of(N), all_of(N)) : ex(0);
  if (out.det.is_zero()) {
    out.singular_everywhere = true;
    out.note = "the velocity system is singular on every configuration of the topology (det A = 0 identically)";
    return out;
  }
  // adj of each block: adj_{ik} = (-1)^{i+k} det(block without row k and column i).
  std::vector<SolvedBlock> solved;
  for (const MatrixBlock& block : *blocks) {
    SolvedBlock sb{block, {}, 0};
    const size_t k = block.cols.size();
    sb.adj.assign(k, std::vector<ex>(k));
    for (size_t r = 0; r < k; ++r)
      for (size_t i = 0; i < k; ++i)
        sb.adj[i][r] = ((i + r) % 2 ? -1 : 1) * determinant(A, without(block.rows, r), without(block.cols, i));
    const ex det = determinant(A, block.rows, block.cols);
    if (GiNaC::is_exactly_a<GiNaC::numeric>(det)) {
      sb.inverse = 1 / det;  // not 0: det A, their product up to sign, is not
    } else {
      out.inverses.push_back({GiNaC::symbol(fmt::format("delta{}", out.inverses.size() + 1)), det});
      sb.inverse = out.inverses.back().delta;
    }
    out.block_sizes.push_back(static_cast<int>(k));
    solved.push_back(std::move(sb));
  }
  // Group by group: the columns of earlier groups are known and move to the right-hand side.
  const auto solve = [&](const std::vector<ex>& rhs) {
    std::vector<ex> x(N, ex(0));
    std::vector<bool> known(N, false);
    for (const SolvedBlock& sb : solved) {
      std::vector<ex> local;
      for (int r : sb.block.rows) {
        ex v = rhs[static_cast<size_t>(r)];
        for (size_t col = 0; col < N; ++col)
          if (known[col] && !A[static_cast<size_t>(r)][col].is_zero()) v -= A[static_cast<size_t>(r)][col] * x[col];
        local.push_back(v);
      }
      for (size_t i = 0; i < sb.block.cols.size(); ++i) {
        ex sum = 0;
        for (size_t k = 0; k < local.size(); ++k)
          if (!sb.adj[i][k].is_zero() && !local[k].is_zero()) sum += sb.adj[i][k] * local[k];
        x[static_cast<size_t>(sb.block.cols[i])] = sum * sb.inverse;
      }
      for (int col : sb.block.cols) known[static_cast<size_t>(col)] = true;
    }
    return x;
  };
  const std::vector<ex> qdot = solve(b);
  std::vector<ex> h = rigid_body_acceleration_rhs<ex>(g, qdot, true, geo);
  DenseMatrix<ex> scratch;
  append_input_rows<ex>(g, inputs, scratch, h, true, s.source, &values);
  const std::vector<ex> qddot = solve(h);
  MechanismMotion<ex>& m = out.motion;
  for (int l = 0; l < g.link_count(); ++l) {
    const int col = g.unknown_of_link(l);
    m.omega.push_back(col < 0 ? ex(0) : qdot[static_cast<size_t>(col)]);
    m.omega_dot.push_back(col < 0 ? ex(0) : qddot[static_cast<size_t>(col)]);
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    const int col = g.unknown_of_joint(j);
    m.slide.push_back(col < 0 ? ex(0) : qdot[static_cast<size_t>(col)]);
    m.slide_dot.push_back(col < 0 ? ex(0) : qddot[static_cast<size_t>(col)]);
  }
  complete_joint_motion(g, m, geo);
  m.fields = link_fields_from_joints(g, m, geo);  // the form the proof's cancellations need (mechanism/poles.h)
  MechanismMotion<ex>& f = out.free_rates;
  const auto free_rate = [&](const std::string& name, int col, const std::vector<ex>& solved_rates) {
    if (col < 0) return ex(0);
    const GiNaC::symbol r(name);
    out.solved_rates[r] = solved_rates[static_cast<size_t>(col)];
    return ex(r);
  };
  for (int l = 0; l < g.link_count(); ++l) {
    const std::string link = g.link_names()[static_cast<size_t>(l)];
    f.omega.push_back(free_rate("omega_" + link, g.unknown_of_link(l), qdot));
    f.omega_dot.push_back(free_rate("alpha_" + link, g.unknown_of_link(l), qddot));
  }
  for (int j = 0; j < g.joint_count(); ++j) {
    f.slide.push_back(free_rate("sd_" + g.joint(j).name, g.unknown_of_joint(j), qdot));
    f.slide_dot.push_back(free_rate("sdd_" + g.joint(j).name, g.unknown_of_joint(j), qddot));
  }
  complete_joint_motion(g, f, geo);
  f.fields = link_fields_from_joints(g, f, geo);
  return out;
}

std::optional<std::vector<int>> group_sizes(const MechanismScene& s, const std::vector<MechanismInput>& inputs) {
  // The pattern needs no coordinates: the symbolic matrix's zeros are structural.
  const SymbolicConfiguration c = symbolic_configuration(s);
  const JointGeometry<ex> geo{&c.joint_at, &c.axis};
  std::vector<ex> b;
  const DenseMatrix<ex> A = velocity_matrix(s, geo, inputs, b, nullptr);
  if (A.size() != static_cast<size_t>(s.linkage.unknown_count())) return std::nullopt;
  const auto blocks = block_triangular_form(pattern_of(A));
  if (!blocks) return std::nullopt;
  std::vector<int> sizes;
  for (const MatrixBlock& block : *blocks) sizes.push_back(static_cast<int>(block.cols.size()));
  std::sort(sizes.rbegin(), sizes.rend());
  return sizes;
}

std::vector<MechanismInput> better_proof_drivers(const MechanismScene& s) {
  if (s.inputs.size() != 1) return {};
  const std::optional<std::vector<int>> own = group_sizes(s, s.inputs);
  if (!own) return {};
  std::vector<std::pair<std::vector<int>, MechanismInput>> better;
  for (int l = 0; l < s.linkage.link_count(); ++l) {
    if (s.linkage.unknown_of_link(l) < 0) continue;
    const MechanismInput in{MechanismInput::Kind::Link, l, Rational(1), Rational(0)};
    if (s.inputs[0].kind == in.kind && s.inputs[0].index == l) continue;
    const std::optional<std::vector<int>> sizes = group_sizes(s, {in});
    if (sizes && *sizes < *own) better.emplace_back(*sizes, in);
  }
  std::stable_sort(better.begin(), better.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<MechanismInput> out;
  for (const auto& [sizes, in] : better) out.push_back(in);
  return out;
}

}  // namespace linkproof
