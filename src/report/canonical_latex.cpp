#include "canonical_latex.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "symbolic/canonical_order.h"

namespace linkproof::report {

namespace {

using namespace GiNaC;

std::string ginac_latex(const ex& e) {
  std::ostringstream o;
  o << latex << e;
  return o.str();
}

std::string print(const ex& e);

// An operand of a product or the base of a power: parenthesised when it is a sum or product.
std::string operand_text(const std::string& text, const ex& e) {
  return is_exactly_a<add>(e) || is_exactly_a<mul>(e) ? "\\left(" + text + "\\right)" : text;
}

std::string power_text(const std::string& base_text, const ex& base, const ex& exponent) {
  if (exponent.is_equal(1)) return operand_text(base_text, base);
  if (exponent.is_equal(numeric(1, 2))) return "\\sqrt{" + base_text + "}";
  return operand_text(base_text, base) + "^{" + print(exponent) + "}";
}

// The text of a sum's terms sorted by their text without a leading minus (so a sum and its
// negation list their terms in the same order), joined by their signs.
std::string sum_text(const ex& e) {
  std::vector<std::pair<std::string, std::string>> terms;
  for (size_t i = 0; i < e.nops(); ++i) {
    std::string t = print(e.op(i));
    terms.emplace_back(t.rfind('-', 0) == 0 ? t.substr(1) : t, t);
  }
  std::sort(terms.begin(), terms.end());
  std::string out;
  for (const auto& [key, t] : terms) out += out.empty() || t.rfind('-', 0) == 0 ? t : "+" + t;
  return out;
}

// A product as [sign]coefficient numerator / denominator. A sum among its factors (or an
// integer power of one) is printed with a positive first term, its sign moved to the
// coefficient: GiNaC's normal() chooses the signs of a numerator and denominator by an order
// that differs between runs. Factors are sorted by their text.
std::string product_text(const std::vector<ex>& factors) {
  numeric coefficient = 1;
  std::vector<std::string> top, bottom;
  for (const ex& f : factors) {
    if (is_exactly_a<numeric>(f)) {
      coefficient *= ex_to<numeric>(f);
      continue;
    }
    ex base = is_exactly_a<power>(f) ? f.op(0) : f, exponent = is_exactly_a<power>(f) ? f.op(1) : ex(1);
    std::string base_text = print(base);
    if (is_exactly_a<add>(base) && is_exactly_a<numeric>(exponent) && ex_to<numeric>(exponent).is_integer() &&
        base_text.rfind('-', 0) == 0) {
      base = -base;
      base_text = print(base);
      if (ex_to<numeric>(exponent).is_odd()) coefficient = -coefficient;
    }
    if (is_exactly_a<numeric>(exponent) && ex_to<numeric>(exponent).is_negative())
      bottom.push_back(power_text(base_text, base, -exponent));
    else
      top.push_back(power_text(base_text, base, exponent));
  }
  std::sort(top.begin(), top.end());
  std::sort(bottom.begin(), bottom.end());
  // A lone parenthesised sum needs no parentheses inside \frac{}{}.
  const auto bare = [](std::vector<std::string>& v) {
    const std::string open = "\\left(", close = "\\right)";
    if (v.size() == 1 && v[0].rfind(open, 0) == 0 && v[0].size() > open.size() + close.size() &&
        v[0].compare(v[0].size() - close.size(), close.size(), close) == 0)
      v[0] = v[0].substr(open.size(), v[0].size() - open.size() - close.size());
  };
  const bool negative = coefficient.is_negative();
  const numeric c = abs(coefficient);
  if (!c.denom().is_equal(1)) bottom.insert(bottom.begin(), ginac_latex(c.denom()));
  std::string num;
  if (!c.numer().is_equal(1) || top.empty()) num = ginac_latex(c.numer());
  for (const auto& t : top) num += (num.empty() ? "" : " ") + t;
  const std::string sign = negative ? "-" : "";
  if (bottom.empty()) return sign + num;
  if (c.numer().is_equal(1)) bare(top);
  bare(bottom);
  num.clear();
  if (!c.numer().is_equal(1) || top.empty()) num = ginac_latex(c.numer());
  for (const auto& t : top) num += (num.empty() ? "" : " ") + t;
  std::string den;
  for (const auto& b : bottom) den += (den.empty() ? "" : " ") + b;
  return sign + "\\frac{" + num + "}{" + den + "}";
}

std::string print(const ex& e) {
  if (is_exactly_a<add>(e)) return sum_text(e);
  if (is_exactly_a<mul>(e)) {
    std::vector<ex> factors;
    for (size_t i = 0; i < e.nops(); ++i) factors.push_back(e.op(i));
    return product_text(factors);
  }
  if (is_exactly_a<power>(e) && is_exactly_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_negative())
    return product_text({e});
  if (is_exactly_a<power>(e)) return power_text(print(e.op(0)), e.op(0), e.op(1));
  if (is_exactly_a<function>(e)) {
    std::string args;
    for (size_t i = 0; i < e.nops(); ++i) args += (i ? ", " : "") + print(e.op(i));
    std::string name = ex_to<function>(e).get_name();
    if (name == "sin" || name == "cos" || name == "tan") name = "\\" + name;
    return name + "(" + args + ")";
  }
  return ginac_latex(e);  // numbers and symbols: GiNaC's own, which does not depend on order
}

}  // namespace

std::string canonical_latex(const ex& e) { return print(e); }

}  // namespace linkproof::report
