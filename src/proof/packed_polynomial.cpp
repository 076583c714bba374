#include "proof/packed_polynomial.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace linkproof::proof_detail {

PackedLayout PackedLayout::for_bounds(const std::array<uint32_t, kMaxPackedVariables>& bound) {
  PackedLayout l;
  l.bound = bound;
  int offset = 0;
  for (int v = 0; v < kMaxPackedVariables; ++v) {
    l.width[v] = static_cast<uint8_t>(std::bit_width(bound[v]));
    l.shift[v] = static_cast<uint8_t>(std::min(offset, 127));
    offset += l.width[v];
    if (bound[v] != 0) l.variables = v + 1;
  }
  if (offset > 127) throw PackedOverflow{};  // the top bit marks an empty slot of a TermTable
  return l;
}

namespace {

// Products with at most this many terms in the shorter factor merge rows instead of hashing.
constexpr size_t kMergeRows = 24;
// Hashed products of more partial products than this are split into output buckets, with at
// most kMaxRunPairs pairs of runs to sort.
constexpr size_t kBucketedProducts = 1 << 16;
constexpr size_t kMaxRunPairs = 1 << 18;

std::array<uint32_t, kMaxPackedVariables> max_bounds(const PackedLayout& a, const PackedLayout& b) {
  std::array<uint32_t, kMaxPackedVariables> m{};
  for (int v = 0; v < kMaxPackedVariables; ++v) m[v] = std::max(a.bound[v], b.bound[v]);
  return m;
}

/// Open addressing with linear probing: the partial products of one output bucket of a
/// multiplication. A key never has its top bit set (PackedLayout keeps to 127 bits), so that
/// marks an empty slot.
class TermTable {
 public:
  explicit TermTable(size_t expected) { resize(std::bit_ceil(std::max<size_t>(16, 2 * expected))); }
  void add(PackedKey k, const cln::cl_RA& c) {
    if (2 * (occupied_.size() + 1) > slots_.size()) resize(2 * slots_.size());
    const size_t i = slot(k);
    Slot& s = slots_[i];
    if (s.key == kEmpty) {
      s.key = k;
      s.value = c;
      occupied_.push_back(i);
    } else {
      s.value = s.value + c;
    }
  }
  size_t size() const { return occupied_.size(); }
  /// Appends the non-zero terms, sorted by key (sorting keys and slot numbers, then gathering),
  /// and empties the table.
  void drain_sorted(std::vector<PackedKey>& keys, std::vector<cln::cl_RA>& values) {
    std::vector<std::pair<PackedKey, size_t>> order;
    order.reserve(occupied_.size());
    for (const size_t i : occupied_)
      if (!cln::zerop(slots_[i].value)) order.emplace_back(slots_[i].key, i);
    std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [key, i] : order) {
      keys.push_back(key);
      values.push_back(slots_[i].value);
    }
    for (const size_t i : occupied_) slots_[i] = Slot{};
    occupied_.clear();
  }

 private:
  static constexpr PackedKey kEmpty = PackedKey{1} << 127;
  struct Slot {
    PackedKey key = kEmpty;
    cln::cl_RA value;
  };
  size_t slot(PackedKey k) const {
    const uint64_t mixed = (static_cast<uint64_t>(k) ^ (static_cast<uint64_t>(k >> 64) * 0x9E3779B97F4A7C15ull)) *
                           0xD6E8FEB86659FD93ull;
    size_t i = static_cast<size_t>(mixed >> 20) & (slots_.size() - 1);
    while (slots_[i].key != kEmpty && slots_[i].key != k) i = (i + 1) & (slots_.size() - 1);
    return i;
  }
  void resize(size_t capacity) {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    for (size_t& i : occupied_) {
      const size_t j = slot(old[i].key);
      slots_[j] = std::move(old[i]);
      i = j;
    }
  }
  std::vector<Slot> slots_;
  std::vector<size_t> occupied_;
};

/// Runs of terms of a sorted polynomial with the same bits from `shift` up (the same exponents
/// of the variables whose fields start there or above).
struct Run {
  size_t begin, end;
  PackedKey high;
};
std::vector<Run> runs_above(const std::vector<PackedKey>& keys, int shift) {
  std::vector<Run> out;
  for (size_t i = 0; i < keys.size(); ++i) {
    const PackedKey h = shift >= 128 ? 0 : keys[i] >> shift;
    if (out.empty() || out.back().high != h)
      out.push_back({i, i + 1, h});
    else
      out.back().end = i + 1;
  }
  return out;
}
size_t count_runs_above(const std::vector<PackedKey>& keys, int shift) {
  size_t n = 0;
  for (size_t i = 0; i < keys.size(); ++i) n += i == 0 || (keys[i] >> shift) != (keys[i - 1] >> shift);
  return n;
}

}  // namespace

// Builds polynomials from sorted terms (the friend through which the free functions fill one).
class PackedPolynomialBuilder {
 public:
  static PackedPolynomial make(const PackedLayout& l, std::vector<PackedKey> keys, std::vector<cln::cl_RA> coefficients) {
    PackedPolynomial p;
    p.layout_ = l;
    p.keys_ = std::move(keys);
    p.coefficients_ = std::move(coefficients);
    return p;
  }
  /// p (in the product's layout) times the term c x^k: shifted keys stay sorted.
  static PackedPolynomial times_term(const PackedPolynomial& p, PackedKey k, const cln::cl_RA& c) {
    PackedPolynomial out;
    out.layout_ = p.layout_;
    out.keys_.resize(p.terms());
    for (size_t i = 0; i < p.terms(); ++i) out.keys_[i] = p.keys_[i] + k;
    if (c == 1) {
      out.coefficients_ = p.coefficients_;
    } else {
      out.coefficients_.resize(p.terms());
      for (size_t i = 0; i < p.terms(); ++i) out.coefficients_[i] = p.coefficients_[i] * c;
    }
    return out;
  }
  /// a and b with the same fields, merged (b's coefficients times `sign`).
  static PackedPolynomial merge(const PackedPolynomial& a, const PackedPolynomial& b, int sign) {
    PackedPolynomial out;
    out.layout_ = a.layout_;
    out.keys_.reserve(a.terms() + b.terms());
    out.coefficients_.reserve(a.terms() + b.terms());
    size_t i = 0, j = 0;
    const auto push = [&out](PackedKey k, cln::cl_RA c) {
      if (cln::zerop(c)) return;
      out.keys_.push_back(k);
      out.coefficients_.push_back(std::move(c));
    };
    while (i < a.terms() || j < b.terms()) {
      if (j == b.terms() || (i < a.terms() && a.keys_[i] < b.keys_[j])) {
        push(a.keys_[i], a.coefficients_[i]);
        ++i;
      } else if (i == a.terms() || b.keys_[j] < a.keys_[i]) {
        push(b.keys_[j], sign > 0 ? b.coefficients_[j] : -b.coefficients_[j]);
        ++j;
      } else {
        push(a.keys_[i], sign > 0 ? a.coefficients_[i] + b.coefficients_[j] : a.coefficients_[i] - b.coefficients_[j]);
        ++i;
        ++j;
      }
    }
    return out;
  }
};

PackedPolynomial PackedPolynomial::constant(const cln::cl_RA& c) {
  if (cln::zerop(c)) return {};
  return PackedPolynomialBuilder::make(PackedLayout{}, {0}, {c});
}

PackedPolynomial PackedPolynomial::variable(int v) {
  if (v < 0 || v >= kMaxPackedVariables) throw PackedOverflow{};
  std::array<uint32_t, kMaxPackedVariables> bound{};
  bound[v] = 1;
  const PackedLayout l = PackedLayout::for_bounds(bound);
  return PackedPolynomialBuilder::make(l, {l.unit(v)}, {1});
}

uint32_t PackedPolynomial::degree(int v) const {
  uint32_t d = 0;
  for (const PackedKey k : keys_) d = std::max(d, layout_.exponent(k, v));
  return d;
}

std::array<uint32_t, kMaxPackedVariables> PackedPolynomial::least_exponents() const {
  std::array<uint32_t, kMaxPackedVariables> least{};
  if (keys_.empty()) return least;
  std::vector<int> open;  // the variables whose least exponent is not 0 yet
  for (int v = 0; v < layout_.variables; ++v)
    if ((least[v] = layout_.exponent(keys_.front(), v)) != 0) open.push_back(v);
  for (size_t i = 1; i < keys_.size() && !open.empty(); ++i) {
    for (size_t j = 0; j < open.size();) {
      const int v = open[j];
      least[v] = std::min(least[v], layout_.exponent(keys_[i], v));
      if (least[v] == 0) open[j] = open.back(), open.pop_back();
      else ++j;
    }
  }
  return least;
}

PackedPolynomial PackedPolynomial::divided_by_monomial(const std::array<uint32_t, kMaxPackedVariables>& by) const {
  PackedKey k = 0;
  for (int v = 0; v < layout_.variables; ++v) k += static_cast<PackedKey>(by[v]) << layout_.shift[v];
  if (k == 0) return *this;
  // Every field of every key holds at least `by`'s: no borrows, and the order is kept.
  PackedPolynomial out = *this;
  for (PackedKey& key : out.keys_) key -= k;
  return out;
}

PackedPolynomial PackedPolynomial::repacked(const PackedLayout& to) const {
  if (layout_.same_fields(to)) return PackedPolynomialBuilder::make(to, keys_, coefficients_);
  // `to` widens fields only, so each field moves up by its shift's growth; runs of adjacent
  // fields that move by the same amount move as one masked segment.
  struct Segment {
    PackedKey mask;
    int up;
  };
  std::vector<Segment> segments;
  for (int v = 0; v < layout_.variables; ++v) {
    if (layout_.width[v] == 0) continue;
    const int up = to.shift[v] - layout_.shift[v];
    const PackedKey mask = ((PackedKey{1} << layout_.width[v]) - 1) << layout_.shift[v];
    if (!segments.empty() && segments.back().up == up)
      segments.back().mask |= mask;
    else
      segments.push_back({mask, up});
  }
  std::vector<PackedKey> keys(keys_.size());
  for (size_t i = 0; i < keys_.size(); ++i) {
    PackedKey k = 0;
    for (const Segment& g : segments) k |= (keys_[i] & g.mask) << g.up;
    keys[i] = k;
  }
  return PackedPolynomialBuilder::make(to, std::move(keys), coefficients_);
}

bool PackedPolynomial::operator==(const PackedPolynomial& o) const {
  if (terms() != o.terms()) return false;
  if (layout_.same_fields(o.layout_)) return keys_ == o.keys_ && coefficients_ == o.coefficients_;
  const PackedLayout l = PackedLayout::for_bounds(max_bounds(layout_, o.layout_));
  return repacked(l) == o.repacked(l);
}

std::vector<PackedPolynomial> PackedPolynomial::coefficients_in(int v) const {
  std::vector<std::vector<PackedKey>> keys(degree(v) + 1);
  std::vector<std::vector<cln::cl_RA>> coefficients(keys.size());
  for (size_t i = 0; i < keys_.size(); ++i) {
    const uint32_t e = layout_.exponent(keys_[i], v);
    keys[e].push_back(keys_[i] - static_cast<PackedKey>(e) * layout_.unit(v));
    coefficients[e].push_back(coefficients_[i]);
  }
  std::vector<PackedPolynomial> out;
  for (size_t e = 0; e < keys.size(); ++e)
    out.push_back(PackedPolynomialBuilder::make(layout_, std::move(keys[e]), std::move(coefficients[e])));
  return out;
}

namespace {

PackedPolynomial combine(const PackedPolynomial& a, const PackedPolynomial& b, int sign) {
  const PackedLayout l = PackedLayout::for_bounds(max_bounds(a.layout(), b.layout()));
  return PackedPolynomialBuilder::merge(a.repacked(l), b.repacked(l), sign);
}

/// The bounds of a product; if they overflow, the factors' true degrees are tried instead.
PackedLayout product_layout(const PackedPolynomial& a, const PackedPolynomial& b) {
  std::array<uint32_t, kMaxPackedVariables> sum{};
  for (int v = 0; v < kMaxPackedVariables; ++v) sum[v] = a.layout().bound[v] + b.layout().bound[v];
  try {
    return PackedLayout::for_bounds(sum);
  } catch (const PackedOverflow&) {
    for (int v = 0; v < kMaxPackedVariables; ++v)
      sum[v] = (a.layout().bound[v] == 0 ? 0 : a.degree(v)) + (b.layout().bound[v] == 0 ? 0 : b.degree(v));
    return PackedLayout::for_bounds(sum);
  }
}

}  // namespace

PackedPolynomial operator+(const PackedPolynomial& a, const PackedPolynomial& b) { return combine(a, b, 1); }
PackedPolynomial operator-(const PackedPolynomial& a, const PackedPolynomial& b) { return combine(a, b, -1); }

PackedPolynomial multiply(const PackedPolynomial& a, const PackedPolynomial& b, const std::function<void()>& tick,
                          const PackedLimits& limits) {
  if (a.is_zero() || b.is_zero()) return {};
  const PackedLayout l = product_layout(a, b);
  const PackedPolynomial x = a.repacked(l), y = b.repacked(l);
  const PackedPolynomial& outer = x.terms() <= y.terms() ? x : y;
  const PackedPolynomial& inner = x.terms() <= y.terms() ? y : x;
  if (outer.terms() * inner.terms() > limits.products) throw PackedTooLarge{0, outer.terms() * inner.terms()};
  // Few outer terms (a monomial, a short sum times a long one, most products of a proof): each
  // row, a term times the inner polynomial, is already sorted; merge them pairwise.
  if (outer.terms() <= kMergeRows) {
    // As in a bottom-up merge sort: a stack of partial sums, two of the same level merged into
    // one of the next, so at most about twice the result's terms are held at a time.
    std::vector<std::pair<int, PackedPolynomial>> stack;
    const auto merge_top = [&] {
      PackedPolynomial top = std::move(stack.back().second);
      stack.pop_back();
      if (stack.back().second.terms() + top.terms() > limits.terms)
        throw PackedTooLarge{stack.back().second.terms() + top.terms(), 0};
      stack.back().second = PackedPolynomialBuilder::merge(stack.back().second, top, 1);
      ++stack.back().first;
      if (tick) tick();
    };
    for (size_t i = 0; i < outer.terms(); ++i) {
      stack.emplace_back(0, PackedPolynomialBuilder::times_term(inner, outer.keys()[i], outer.coefficients()[i]));
      while (stack.size() > 1 && stack[stack.size() - 2].first == stack.back().first) merge_top();
    }
    while (stack.size() > 1) merge_top();
    return std::move(stack.front().second);
  }
  // Output buckets: a product's bits from a field boundary s up are the sum of its factors'
  // (fields never carry), so the terms whose high parts sum to h make the product's terms with
  // high part h, and the buckets come out in key order. Each bucket is accumulated in a hash
  // table of its own size: a table of the whole product's size is a cache miss per partial
  // product. s is the lowest boundary with at most kMaxRunPairs pairs of runs.
  int split = 128;
  if (outer.terms() * inner.terms() > kBucketedProducts) {
    for (int v = l.variables - 1; v >= 0; --v) {
      if (l.width[v] == 0) continue;
      if (count_runs_above(outer.keys(), l.shift[v]) * count_runs_above(inner.keys(), l.shift[v]) > kMaxRunPairs) break;
      split = l.shift[v];
    }
  }
  const std::vector<Run> outer_runs = runs_above(outer.keys(), split), inner_runs = runs_above(inner.keys(), split);
  struct Pair {
    PackedKey high;
    uint32_t outer, inner;
  };
  std::vector<Pair> pairs;
  pairs.reserve(outer_runs.size() * inner_runs.size());
  for (size_t i = 0; i < outer_runs.size(); ++i)
    for (size_t j = 0; j < inner_runs.size(); ++j)
      pairs.push_back({outer_runs[i].high + inner_runs[j].high, static_cast<uint32_t>(i), static_cast<uint32_t>(j)});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& first, const Pair& second) { return first.high < second.high; });
  TermTable table(std::min(outer.terms() * inner.terms(), size_t{1} << 16));
  std::vector<PackedKey> keys;
  std::vector<cln::cl_RA> coefficients;
  size_t since_tick = 0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    const Run& ro = outer_runs[pairs[p].outer];
    const Run& ri = inner_runs[pairs[p].inner];
    for (size_t i = ro.begin; i < ro.end; ++i) {
      const PackedKey k = outer.keys()[i];
      const cln::cl_RA& c = outer.coefficients()[i];
      for (size_t j = ri.begin; j < ri.end; ++j) table.add(k + inner.keys()[j], c * inner.coefficients()[j]);
    }
    since_tick += (ro.end - ro.begin) * (ri.end - ri.begin);
    if (since_tick >= 65536) {
      since_tick = 0;
      if (tick) tick();
      if (keys.size() + table.size() > limits.terms) throw PackedTooLarge{keys.size() + table.size(), 0};
    }
    if (p + 1 == pairs.size() || pairs[p + 1].high != pairs[p].high) table.drain_sorted(keys, coefficients);
  }
  return PackedPolynomialBuilder::make(l, std::move(keys), std::move(coefficients));
}


}  // namespace linkproof::proof_detail
