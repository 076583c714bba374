#include "symbolic/canonical_form.h"

#include <algorithm>
#include <sstream>

#include "ex_text.h"
#include "linkproof/core/error.h"
#include "symbolic/canonical_order.h"
#include "structure_hash.h"

namespace linkproof {

using namespace GiNaC;
using structure_hash::mix;
using structure_hash::text_hash;

namespace {

std::string numeric_text(const numeric& x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

}  // namespace

CanonicalForm::CanonicalForm(const std::vector<ex>& inputs) : CanonicalForm(std::vector<std::string>{}) {
  for (size_t i = 0; i < inputs.size(); ++i) {
    if (!is_a<symbol>(inputs[i])) throw InternalError("canonical form: input " + ex_text(inputs[i]) + " is not a symbol");
    input_index_[inputs[i]] = static_cast<std::uint32_t>(i);
    input_names_.push_back(ex_to<symbol>(inputs[i]).get_name());
  }
}

CanonicalForm::CanonicalForm(std::vector<std::string> input_names) : input_names_(std::move(input_names)) {
  Node unit;
  unit.key = text_hash("1");
  nodes_.push_back(std::move(unit));
  interned_.emplace("1", one);
}

CanonicalForm CanonicalForm::with_atoms() {
  CanonicalForm f(std::vector<ex>{});
  f.atoms_ = true;
  return f;
}

int CanonicalForm::compare(Id a, Id b) const {
  if (a == b) return 0;
  const Node& x = nodes_[a];
  const Node& y = nodes_[b];
  if (x.key != y.key) return x.key < y.key ? -1 : 1;
  // A key collision (or two symbols of one name): decide by structure.
  if (x.kind != y.kind) return x.kind < y.kind ? -1 : 1;
  switch (x.kind) {
    case Kind::One: return 0;
    case Kind::Symbol: return x.input < y.input ? -1 : (x.input > y.input ? 1 : 0);
    case Kind::Sum:
      if (x.terms.size() != y.terms.size()) return x.terms.size() < y.terms.size() ? -1 : 1;
      for (size_t i = 0; i < x.terms.size(); ++i) {
        if (const int c = compare(x.terms[i].first, y.terms[i].first)) return c;
        if (const int c = x.terms[i].second.compare(y.terms[i].second)) return c;
      }
      return 0;
    case Kind::Product:
      if (x.factors.size() != y.factors.size()) return x.factors.size() < y.factors.size() ? -1 : 1;
      for (size_t i = 0; i < x.factors.size(); ++i) {
        if (const int c = compare(x.factors[i].first, y.factors[i].first)) return c;
        if (x.factors[i].second != y.factors[i].second) return x.factors[i].second < y.factors[i].second ? -1 : 1;
      }
      return 0;
    case Kind::Atom: {
      // Rare (a key collision): the full text, then (distinct symbols of one name) creation order.
      const std::string tx = CanonicalOrder::text(x.atom), ty = CanonicalOrder::text(y.atom);
      if (tx != ty) return tx < ty ? -1 : 1;
      return a < b ? -1 : 1;
    }
  }
  return 0;
}

CanonicalForm::Id CanonicalForm::intern(Node n) {
  // The signature names children by id: ids identify structures exactly within this object.
  std::string sig;
  switch (n.kind) {
    case Kind::One:
    case Kind::Atom: return one;  // not interned here (atom())
    case Kind::Symbol: sig = "s" + std::to_string(n.input); break;
    case Kind::Sum: {
      auto t = n.terms;
      std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      sig = "+";
      for (const auto& [id, c] : t) sig += std::to_string(id) + ":" + numeric_text(c) + ";";
      break;
    }
    case Kind::Product: {
      auto f = n.factors;
      std::sort(f.begin(), f.end());
      sig = "*";
      for (const auto& [id, k] : f) sig += std::to_string(id) + "^" + std::to_string(k) + ";";
      break;
    }
  }
  if (auto it = interned_.find(sig); it != interned_.end()) return it->second;

  // Key: symbols by name and input index; sums and products as multisets of their children.
  std::vector<std::uint64_t> parts;
  switch (n.kind) {
    case Kind::One:
    case Kind::Atom: break;
    case Kind::Symbol: n.key = mix(mix(text_hash("symbol"), text_hash(input_names_[n.input])), n.input); break;
    case Kind::Sum:
      for (const auto& [id, c] : n.terms) parts.push_back(mix(nodes_[id].key, text_hash(numeric_text(c))));
      std::sort(parts.begin(), parts.end());
      n.key = text_hash("+");
      for (std::uint64_t p : parts) n.key = mix(n.key, p);
      std::sort(n.terms.begin(), n.terms.end(), [&](const auto& a, const auto& b) { return compare(a.first, b.first) < 0; });
      break;
    case Kind::Product:
      for (const auto& [id, k] : n.factors) parts.push_back(mix(nodes_[id].key, static_cast<std::uint64_t>(static_cast<std::int64_t>(k))));
      std::sort(parts.begin(), parts.end());
      n.key = text_hash("*");
      for (std::uint64_t p : parts) n.key = mix(n.key, p);
      std::sort(n.factors.begin(), n.factors.end(), [&](const auto& a, const auto& b) { return compare(a.first, b.first) < 0; });
      break;
  }
  const auto id = static_cast<Id>(nodes_.size());
  nodes_.push_back(std::move(n));
  interned_.emplace(std::move(sig), id);
  return id;
}

CanonicalForm::Id CanonicalForm::product_of(std::vector<std::pair<Id, int>> factors) {
  // Merge equal bases (GiNaC merges equal trees; canonically equal ones may still come apart).
  std::sort(factors.begin(), factors.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<Id, int>> merged;
  for (const auto& f : factors) {
    if (!merged.empty() && merged.back().first == f.first)
      merged.back().second += f.second;
    else
      merged.push_back(f);
  }
  std::erase_if(merged, [](const auto& f) { return f.second == 0; });
  if (merged.empty()) return one;
  if (merged.size() == 1 && merged[0].second == 1) return merged[0].first;
  Node n;
  n.kind = Kind::Product;
  n.factors = std::move(merged);
  return intern(std::move(n));
}

CanonicalForm::Id CanonicalForm::sum_of(std::vector<std::pair<Id, numeric>> terms, numeric& content) {
  std::sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<Id, numeric>> merged;
  for (const auto& t : terms) {
    if (!merged.empty() && merged.back().first == t.first)
      merged.back().second = merged.back().second + t.second;
    else
      merged.push_back(t);
  }
  std::erase_if(merged, [](const auto& t) { return t.second.is_zero(); });
  if (merged.empty()) {
    content = 0;
    return one;
  }
  if (merged.size() == 1) {
    content = merged[0].second;
    return merged[0].first;
  }
  // Content: the sign of the canonically first term times gcd(numerators) / lcm(denominators).
  size_t lead = 0;
  numeric g = merged[0].second.numer(), l = merged[0].second.denom();
  for (size_t i = 1; i < merged.size(); ++i) {
    if (compare(merged[i].first, merged[lead].first) < 0) lead = i;
    g = gcd(g, merged[i].second.numer());
    l = lcm(l, merged[i].second.denom());
  }
  content = abs(g) / l;
  if (merged[lead].second.is_negative()) content = -content;
  for (auto& t : merged) t.second = t.second / content;
  Node n;
  n.kind = Kind::Sum;
  n.terms = std::move(merged);
  return intern(std::move(n));
}

CanonicalForm::Split CanonicalForm::split(const ex& e) {
  if (auto it = memo_.find(e); it != memo_.end()) return it->second;
  Split s = split_uncached(e);
  memo_.emplace(e, s);
  return s;
}

namespace {

/// The primitive part p of a factor, raised to k, as (base, exponent) pairs.
void append_factors(const CanonicalForm& form, CanonicalForm::Id p, int k,
                    std::vector<std::pair<CanonicalForm::Id, int>>& out) {
  if (p == CanonicalForm::one) return;
  if (form.node(p).kind == CanonicalForm::Kind::Product) {
    for (const auto& [b, x] : form.node(p).factors) out.emplace_back(b, x * k);
  } else {
    out.emplace_back(p, k);
  }
}

}  // namespace

CanonicalForm::Split CanonicalForm::number(const numeric& value) const { return {value, one}; }

CanonicalForm::Split CanonicalForm::input(std::uint32_t index) {
  LINKPROOF_ASSERT(index < input_names_.size(), "canonical form: input index out of range");
  Node n;
  n.kind = Kind::Symbol;
  n.input = index;
  return {numeric(1), intern(std::move(n))};
}

CanonicalForm::Split CanonicalForm::sum(const std::vector<Split>& terms) {
  std::vector<std::pair<Id, numeric>> parts;
  parts.reserve(terms.size());
  for (const Split& t : terms)
    if (!t.content.is_zero()) parts.emplace_back(t.primitive, t.content);
  Split s{numeric(0), one};
  s.primitive = sum_of(std::move(parts), s.content);
  return s;
}

CanonicalForm::Split CanonicalForm::product(const std::vector<Split>& factors) {
  numeric content = 1;
  std::vector<std::pair<Id, int>> parts;
  for (const Split& f : factors) {
    content = content * f.content;
    append_factors(*this, f.primitive, 1, parts);
  }
  if (content.is_zero()) return {numeric(0), one};
  return {content, product_of(std::move(parts))};
}

CanonicalForm::Split CanonicalForm::power(const Split& base, int exponent) {
  if (exponent == 0) return {numeric(1), one};
  if (base.content.is_zero()) {
    if (exponent < 0) throw InternalError("tape: a power of zero with a negative exponent");
    return {numeric(0), one};
  }
  std::vector<std::pair<Id, int>> parts;
  append_factors(*this, base.primitive, exponent, parts);
  return {base.content.power(exponent), product_of(std::move(parts))};
}

CanonicalForm::Split CanonicalForm::split_uncached(const ex& e) {
  if (is_a<numeric>(e)) {
    const numeric& num = ex_to<numeric>(e);
    if (!num.is_rational() && atoms_) return atom(e);
    if (!num.is_rational()) throw InternalError("tape: non-rational constant " + ex_text(e));
    return number(num);
  }
  if (is_a<symbol>(e)) {
    auto it = input_index_.find(e);
    if (it == input_index_.end() && atoms_) return atom(e);
    if (it == input_index_.end()) throw InternalError("tape: symbol " + ex_text(e) + " is not an input");
    return input(it->second);
  }
  if (is_a<add>(e) || is_a<mul>(e)) {
    std::vector<Split> operands;
    operands.reserve(e.nops());
    for (size_t i = 0; i < e.nops(); ++i) operands.push_back(split(e.op(i)));
    return is_a<add>(e) ? sum(operands) : product(operands);
  }
  if (is_a<GiNaC::power>(e)) {
    const ex& expo = e.op(1);
    if ((!is_a<numeric>(expo) || !ex_to<numeric>(expo).is_integer()) && atoms_) return atom(e);
    if (!is_a<numeric>(expo) || !ex_to<numeric>(expo).is_integer())
      throw InternalError("tape: non-integer power " + ex_text(e));
    const int k = ex_to<numeric>(expo).to_int();
    if (k == 0) return {numeric(1), one};
    const Split b = split(e.op(0));
    if (b.content.is_zero() && k < 0) throw InternalError("tape: a power of zero with negative exponent " + ex_text(e));
    return power(b, k);
  }
  if (atoms_) return atom(e);
  throw InternalError("tape: cannot compile " + ex_text(e));
}

CanonicalForm::Split CanonicalForm::atom(const ex& e) {
  if (auto it = atom_ids_.find(e); it != atom_ids_.end()) return {numeric(1), it->second};
  Node n;
  n.kind = Kind::Atom;
  n.atom = e;
  if (is_a<symbol>(e)) {
    n.key = mix(text_hash("atom"), text_hash(ex_to<symbol>(e).get_name()));
  } else if (is_a<function>(e) || is_a<GiNaC::power>(e)) {
    // By name and the canonical form of the arguments: GiNaC's form of an argument (a sum in
    // a product, say) is no more canonical than anywhere else.
    n.key = text_hash(is_a<function>(e) ? ex_to<function>(e).get_name() : std::string("^"));
    for (size_t i = 0; i < e.nops(); ++i) {
      const Split a = split(e.op(i));
      n.key = mix(n.key, mix(text_hash(numeric_text(a.content)), nodes_[a.primitive].key));
    }
  } else {
    n.key = text_hash(CanonicalOrder::text(e));
  }
  const auto id = static_cast<Id>(nodes_.size());
  nodes_.push_back(std::move(n));
  atom_ids_.emplace(e, id);
  return {numeric(1), id};
}

}  // namespace linkproof
