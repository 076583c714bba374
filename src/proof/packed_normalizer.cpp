#include "proof/packed_normalizer.h"

#include <fmt/format.h>

namespace linkproof::proof_detail {

namespace {

using GiNaC::ex;

cln::cl_RA rational(const GiNaC::numeric& n) { return cln::the<cln::cl_RA>(n.to_cl_N()); }

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

void PackedNormalizer::check_deadline() const {
  if (deadline_ && std::chrono::steady_clock::now() > *deadline_) throw NormalizerOutOfTime{"the time budget ran out"};
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

const PackedNormalizer::Fraction& PackedNormalizer::normal(const ex& e) {
  const auto it = memo_.find(e);
  if (it != memo_.end()) return it->second;
  check_deadline();
  Fraction f = compute(e);
  return memo_.emplace(e, std::move(f)).first->second;
}

PackedNormalizer::Fraction PackedNormalizer::sum(const Fraction& a, const Fraction& b) {
  if (b.num.is_zero()) return a;
  if (a.num.is_zero()) return b;
  try {
    if (a.den == b.den) return {a.num + b.num, a.den};
    return {multiply(a.num, b.den) + multiply(b.num, a.den), multiply(a.den, b.den)};
  } catch (const PackedOverflow&) {
    throw PackedUnsupported{"exponents that need more than 127 bits"};
  }
}

PackedNormalizer::Fraction PackedNormalizer::product(const Fraction& a, const Fraction& b) {
  if (a.num.is_zero() || b.num.is_zero()) return {PackedPolynomial{}, PackedPolynomial::constant(1)};
  return {multiply(a.num, b.num), multiply(a.den, b.den)};
}

PackedNormalizer::Fraction PackedNormalizer::compute(const ex& e) {
  const PackedPolynomial one = PackedPolynomial::constant(1);
  if (GiNaC::is_a<GiNaC::symbol>(e)) return {PackedPolynomial::variable(variable(e)), one};
  if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_rational()) throw PackedUnsupported{"a number that is not rational"};
    return {PackedPolynomial::constant(rational(n)), one};
  }
  if (GiNaC::is_exactly_a<GiNaC::add>(e)) {
    Fraction acc{PackedPolynomial{}, one};
    for (size_t i = 0; i < e.nops(); ++i) {
      const Fraction& term = normal(e.op(i));
      check_deadline();
      acc = sum(acc, term);
    }
    if (acc.num.is_zero()) acc.den = one;
    return acc;
  }
  if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    Fraction acc{one, one};
    for (size_t i = 0; i < e.nops(); ++i) {
      const Fraction& factor = normal(e.op(i));
      check_deadline();
      acc = product(acc, factor);
    }
    return acc;
  }
  if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
    const Fraction& b = normal(e.op(0));
    const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
    if (k.is_zero()) return {one, one};
    const unsigned exponent = static_cast<unsigned>(k.is_positive() ? k.to_int() : -k.to_int());
    check_deadline();
    const auto power = [&](const PackedPolynomial& p) {
      PackedPolynomial out = one;
      for (unsigned i = 0; i < exponent; ++i) out = multiply(out, p);
      return out;
    };
    if (k.is_positive()) return {power(b.num), power(b.den)};
    if (b.num.is_zero()) throw GiNaC::pole_error("PackedNormalizer: division by an identically zero expression", 1);
    return {power(b.den), power(b.num)};
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

PackedPolynomial clear_inverses(PackedPolynomial p, const std::vector<std::pair<ex, ex>>& inverses, PackedNormalizer& n) {
  for (const auto& [delta, det] : inverses) {
    const std::vector<PackedPolynomial> c = p.coefficients_in(n.variable(delta));
    if (c.size() < 2) continue;
    const PackedPolynomial& d = n.numerator(det);
    size_t i = 0;
    while (c[i].is_zero()) ++i;
    PackedPolynomial out = c[i];
    for (++i; i < c.size(); ++i) out = n.multiply(out, d) + c[i];
    p = std::move(out);
  }
  return p;
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
