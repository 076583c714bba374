#include "proof/packed_normalizer.h"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cstdlib>

namespace linkproof::proof_detail {

namespace {

using GiNaC::ex;

cln::cl_RA rational(const GiNaC::numeric& n) { return cln::the<cln::cl_RA>(n.to_cl_N()); }

using Powers = std::vector<std::pair<int, int>>;

// visit(atom, e, f) for every atom of a or b (both sorted by atom), in order, with its
// exponent in each (0 where it is absent).
template <class Visit>
void for_each_atom(const Powers& a, const Powers& b, Visit visit) {
  size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    const int atom_a = i < a.size() ? a[i].first : INT_MAX;
    const int atom_b = j < b.size() ? b[j].first : INT_MAX;
    const int atom = std::min(atom_a, atom_b);
    const int e = atom_a == atom ? a[i++].second : 0;
    const int f = atom_b == atom ? b[j++].second : 0;
    visit(atom, e, f);
  }
}

}  // namespace

int PackedNormalizer::variable(const ex& s) {
  const auto it = index_.find(s);
  if (it != index_.end()) return it->second;
  if (symbols_.size() >= static_cast<size_t>(kMaxPackedVariables))
    throw PackedUnsupported{fmt::format("more than {} symbols", kMaxPackedVariables)};
  symbols_.push_back(s);
  return index_.emplace(s, static_cast<int>(symbols_.size() - 1)).first->second;
}

NormalizerOutOfTime PackedNormalizer::out_of_limits(const PackedTooLarge& t) const {
  if (t.products != 0)
    return {fmt::format("a product of {:.3g} partial products exceeds the limit of {:.3g}", static_cast<double>(t.products),
                        static_cast<double>(limits_.products))};
  return {fmt::format("a product of more than {:.3g} terms exceeds the limit of {:.3g}", static_cast<double>(t.terms),
                      static_cast<double>(limits_.terms))};
}

void PackedNormalizer::hold(const PackedPolynomial& p) {
  held_ += p.terms();
  if (held_ > limits_.held)
    throw NormalizerOutOfTime{fmt::format("the normal form's parts hold more than {:.3g} terms, the limit",
                                          static_cast<double>(limits_.held))};
}

void PackedNormalizer::check_deadline() const {
  if (deadline_ && std::chrono::steady_clock::now() > *deadline_) throw NormalizerOutOfTime{"the time budget ran out", true};
}

PackedPolynomial PackedNormalizer::multiply(const PackedPolynomial& a, const PackedPolynomial& b) {
  try {
    return proof_detail::multiply(a, b, [this] { check_deadline(); }, limits_);
  } catch (const PackedTooLarge& t) {
    throw out_of_limits(t);
  } catch (const PackedOverflow&) {
    throw PackedUnsupported{"exponents that need more than 127 bits"};
  }
}

const PackedNormalizer::Factored& PackedNormalizer::normal(const ex& e) {
  const auto it = memo_.find(e);
  if (it != memo_.end()) return it->second;
  check_deadline();
  Factored f = compute(e);
  hold(f.core);
  return memo_.emplace(e, std::move(f)).first->second;
}

PackedPolynomial PackedNormalizer::numerator(const ex& e) {
  const Factored& f = normal(e);
  return multiply(f.core, atom_product(f.powers, 1));
}

PackedPolynomial PackedNormalizer::denominator(const ex& e) { return atom_product(normal(e).powers, -1); }

std::pair<int, cln::cl_RA> PackedNormalizer::atom_of(const PackedPolynomial& p) {
  const cln::cl_RA lead = p.coefficients().back();
  const PackedPolynomial monic = cln::equal(lead, 1) ? p : multiply(p, PackedPolynomial::constant(1 / lead));
  // A hash that does not depend on the layout: the term count and the leading exponents.
  size_t hash = monic.terms();
  for (int v = 0; v < monic.layout().variables; ++v)
    hash = hash * 1000003u + monic.layout().exponent(monic.keys().back(), v);
  const auto [first, last] = atom_index_.equal_range(hash);
  for (auto it = first; it != last; ++it)
    if (atoms_[static_cast<size_t>(it->second)] == monic) return {it->second, lead};
  hold(monic);
  atoms_.push_back(monic);
  const int id = static_cast<int>(atoms_.size() - 1);
  atom_index_.emplace(hash, id);
  return {id, lead};
}

const PackedPolynomial& PackedNormalizer::atom_power(int atom, int k) {
  if (k == 1) return atoms_[static_cast<size_t>(atom)];
  if (const auto it = atom_powers_.find({atom, k}); it != atom_powers_.end()) return it->second;
  PackedPolynomial p = multiply(atom_power(atom, k - 1), atoms_[static_cast<size_t>(atom)]);
  hold(p);
  return atom_powers_.emplace(std::pair{atom, k}, std::move(p)).first->second;
}

PackedPolynomial PackedNormalizer::atom_product(const std::vector<std::pair<int, int>>& powers, int sign) {
  PackedPolynomial out = PackedPolynomial::constant(1);
  for (const auto& [atom, e] : powers)
    if (e * sign > 0) out = multiply(out, atom_power(atom, e * sign));
  return out;
}

int PackedNormalizer::variable_atom(int v) {
  if (variable_atoms_.size() <= static_cast<size_t>(v)) variable_atoms_.resize(static_cast<size_t>(v) + 1, -1);
  int& atom = variable_atoms_[static_cast<size_t>(v)];
  if (atom < 0) atom = atom_of(PackedPolynomial::variable(v)).first;
  return atom;
}

PackedNormalizer::Factored PackedNormalizer::without_content(Factored f) {
  const std::array<uint32_t, kMaxPackedVariables> least = f.core.least_exponents();
  Factored content{PackedPolynomial::constant(1), {}};
  for (int v = 0; v < f.core.layout().variables; ++v)
    if (least[v] != 0) content.powers.emplace_back(variable_atom(v), static_cast<int>(least[v]));
  if (content.powers.empty()) return f;
  std::sort(content.powers.begin(), content.powers.end());
  f.core = f.core.divided_by_monomial(least);
  return product(f, content);
}

PackedNormalizer::Factored PackedNormalizer::sum(const Factored& a, const Factored& b) {
  if (b.core.is_zero()) return a;
  if (a.core.is_zero()) return b;
  try {
    // The common power of each atom, min(e, f), and each core times the powers the other side
    // has more of (none when both have the same powers).
    Factored out;
    PackedPolynomial x = a.core, y = b.core;
    for_each_atom(a.powers, b.powers, [&](int atom, int e, int f) {
      const int common = std::min(e, f);
      if (common != 0) out.powers.emplace_back(atom, common);
      if (e > common) x = multiply(x, atom_power(atom, e - common));
      if (f > common) y = multiply(y, atom_power(atom, f - common));
    });
    out.core = x + y;
    if (out.core.is_zero()) out.powers.clear();
    return without_content(std::move(out));
  } catch (const PackedOverflow&) {
    throw PackedUnsupported{"exponents that need more than 127 bits"};
  }
}

PackedNormalizer::Factored PackedNormalizer::product(const Factored& a, const Factored& b) {
  if (a.core.is_zero() || b.core.is_zero()) return {};
  Factored out{multiply(a.core, b.core), {}};
  for_each_atom(a.powers, b.powers, [&out](int atom, int e, int f) {
    if (e + f != 0) out.powers.emplace_back(atom, e + f);  // a divisor times itself cancels here
  });
  return out;
}

PackedNormalizer::Factored PackedNormalizer::inverse(const Factored& a) {
  if (a.core.is_zero()) throw GiNaC::pole_error("PackedNormalizer: division by an identically zero expression", 1);
  const Factored whole = without_content(a);  // sums take the content out already: cheap
  Factored out;
  for (const auto& [atom, e] : whole.powers) out.powers.emplace_back(atom, -e);
  if (whole.core.terms() == 1 && whole.core.keys().front() == 0) {  // a number
    out.core = PackedPolynomial::constant(1 / whole.core.coefficients().front());
    return out;
  }
  const auto [atom, lead] = atom_of(whole.core);
  out.core = PackedPolynomial::constant(1 / lead);
  return product(out, Factored{PackedPolynomial::constant(1), {{atom, -1}}});
}

PackedNormalizer::Factored PackedNormalizer::power(const Factored& a, int k) {
  if (k == 0) return {PackedPolynomial::constant(1), {}};
  const Factored base = k > 0 ? a : inverse(a);
  Factored out{PackedPolynomial::constant(1), {}};
  for (int i = 0; i < std::abs(k); ++i) out = product(out, base);
  return out;
}

PackedNormalizer::Factored PackedNormalizer::compute(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    if (const auto inverse_of = inverses_.find(e); inverse_of != inverses_.end()) return inverse(normal(inverse_of->second));
    return {PackedPolynomial::constant(1), {{variable_atom(variable(e)), 1}}};
  }
  if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_rational()) throw PackedUnsupported{"a number that is not rational"};
    return {PackedPolynomial::constant(rational(n)), {}};
  }
  if (GiNaC::is_exactly_a<GiNaC::add>(e)) {
    Factored acc;
    for (size_t i = 0; i < e.nops(); ++i) {
      const Factored& term = normal(e.op(i));
      check_deadline();
      acc = sum(acc, term);
    }
    return acc;
  }
  if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    Factored acc{PackedPolynomial::constant(1), {}};
    for (size_t i = 0; i < e.nops(); ++i) {
      const Factored& factor = normal(e.op(i));
      check_deadline();
      acc = product(acc, factor);
    }
    return acc;
  }
  if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
    const Factored& b = normal(e.op(0));
    check_deadline();
    return power(b, GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int());
  }
  throw PackedUnsupported{"an operation that is not rational"};
}

GiNaC::ex PackedNormalizer::to_ex(const PackedPolynomial& p) const {
  GiNaC::exvector terms;
  for (size_t i = 0; i < p.terms(); ++i) {
    ex t = GiNaC::numeric(cln::cl_N(p.coefficients()[i]));
    for (int v = 0; v < p.layout().variables; ++v)
      if (const uint32_t e = p.layout().exponent(p.keys()[i], v)) t *= GiNaC::pow(symbols_[static_cast<size_t>(v)], e);
    terms.push_back(t);
  }
  return GiNaC::dynallocate<GiNaC::add>(terms);
}

PackedPolynomial reduce_on_circles(PackedPolynomial p, const std::vector<std::pair<ex, ex>>& axes, PackedNormalizer& n) {
  for (const auto& [c, s] : axes) {
    const std::vector<PackedPolynomial> by_s = p.coefficients_in(n.variable(s));
    if (by_s.size() < 2) continue;
    const PackedPolynomial one_minus_c2 = n.numerator(1 - c * c);
    const PackedPolynomial s1 = PackedPolynomial::variable(n.variable(s));
    PackedPolynomial out, factor = PackedPolynomial::constant(1);  // (1 - c^2)^(k/2)
    for (size_t k = 0; k < by_s.size(); ++k) {
      if (k >= 2 && k % 2 == 0) factor = n.multiply(factor, one_minus_c2);
      if (by_s[k].is_zero()) continue;
      out = out + n.multiply(by_s[k], k % 2 == 1 ? n.multiply(factor, s1) : factor);
    }
    p = std::move(out);
  }
  return p;
}

}  // namespace linkproof::proof_detail
