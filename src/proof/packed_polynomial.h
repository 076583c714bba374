// Sparse multivariate polynomials with exact rational coefficients and packed exponents: the
// arithmetic of the mechanism proofs' zero tests when GiNaC's expansion is too slow for them.
// Private to src/proof.
//
// Why not GiNaC: a proof's residual numerator has millions of terms (Koshel's class-III
// mechanism: 1.5-3 million). GiNaC's expand of a product of two sums adds each partial product
// to the running result (quadratic in the result's size) inside one call that no deadline can
// stop, and keeps every term as a tree of symbols and powers. Here a monomial is one 128-bit
// integer, the exponent of variable v in its own bit field (127 bits in all: the top bit marks
// an empty slot of a product's hash table), so the product of two monomials is the sum of their
// keys. A product with a short factor merges its sorted rows (a term times the long factor);
// any other accumulates in a hash table and is sorted once. Coefficients are CLN rationals (a small integer is an immediate value: no allocation).
//
// Bit fields: each polynomial carries an upper bound of its degree in every variable, and the
// field of v is just wide enough for that bound. A product's bounds are the sums of its
// factors', so the sum of two keys never carries from one field into the next. Fields are laid
// out in variable order, lowest variable in the lowest bits, so keys compare as exponent vectors
// compare (lexicographically from the highest variable down) in every layout: repacking a
// sorted polynomial into wider fields keeps it sorted. A polynomial whose fields need more than
// 127 bits throws PackedOverflow (the caller falls back to GiNaC).
#pragma once

#include <cln/rational.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace linkproof::proof_detail {

__extension__ typedef unsigned __int128 PackedKey;  // __extension__: a GCC/Clang type
constexpr int kMaxPackedVariables = 64;

/// The exponents of a polynomial do not fit in 127 bits (or it has too many variables).
struct PackedOverflow {};
/// What one product may cost: the terms it may hold (memory), and its partial products (time:
/// n x m for factors of n and m terms, however few terms they leave).
struct PackedLimits {
  size_t terms = 16'000'000;  // about 0.8 GB at the peak of a product
  size_t products = 50'000'000;  // seconds
  size_t held = 25'000'000;  // terms a normal form's memo and caches hold at once: about 1.2 GB
};
/// A product was about to pass a limit: the terms it held, or the partial products it needs.
struct PackedTooLarge {
  size_t terms = 0, products = 0;
};

/// Where each variable's exponent lives in a key: bounds, and the fields they need.
struct PackedLayout {
  std::array<uint32_t, kMaxPackedVariables> bound{};  ///< the degree in v is at most bound[v]
  std::array<uint8_t, kMaxPackedVariables> shift{}, width{};
  int variables = 0;  ///< 1 + the highest variable with a non-zero bound

  /// The layout for these bounds (throws PackedOverflow past 127 bits).
  static PackedLayout for_bounds(const std::array<uint32_t, kMaxPackedVariables>& bound);
  /// Same fields: keys of one are keys of the other.
  bool same_fields(const PackedLayout& o) const { return width == o.width; }
  uint32_t exponent(PackedKey k, int v) const {
    return width[v] == 0 ? 0 : static_cast<uint32_t>((k >> shift[v]) & ((PackedKey{1} << width[v]) - 1));
  }
  PackedKey unit(int v) const { return PackedKey{1} << shift[v]; }
};

/// A polynomial: terms sorted by key, no zero coefficient.
class PackedPolynomial {
 public:
  PackedPolynomial() = default;
  static PackedPolynomial constant(const cln::cl_RA& c);
  static PackedPolynomial variable(int v);

  bool is_zero() const { return keys_.empty(); }
  size_t terms() const { return keys_.size(); }
  const PackedLayout& layout() const { return layout_; }
  const std::vector<PackedKey>& keys() const { return keys_; }
  const std::vector<cln::cl_RA>& coefficients() const { return coefficients_; }
  /// The true degree in v (0 for the zero polynomial).
  uint32_t degree(int v) const;
  bool operator==(const PackedPolynomial& o) const;

  /// The same polynomial in the layout `to`, whose fields are nowhere narrower than this one's;
  /// sorted order is kept.
  PackedPolynomial repacked(const PackedLayout& to) const;

  /// The monomial content: per variable, the least exponent among the terms (all 0 for the
  /// zero polynomial).
  std::array<uint32_t, kMaxPackedVariables> least_exponents() const;
  /// This divided by the monomial of exponents `by` (at most least_exponents(), per variable).
  PackedPolynomial divided_by_monomial(const std::array<uint32_t, kMaxPackedVariables>& by) const;

  /// The polynomials c_k with this = sum_k c_k v^k (c_k free of v), k = 0 .. degree(v).
  std::vector<PackedPolynomial> coefficients_in(int v) const;

  friend PackedPolynomial operator+(const PackedPolynomial& a, const PackedPolynomial& b);
  friend PackedPolynomial operator-(const PackedPolynomial& a, const PackedPolynomial& b);
  /// `tick` is called every few thousand partial products (a deadline throws from it); past
  /// `limits`, PackedTooLarge.
  friend PackedPolynomial multiply(const PackedPolynomial& a, const PackedPolynomial& b, const std::function<void()>& tick,
                                   const PackedLimits& limits);

 private:
  PackedLayout layout_;
  std::vector<PackedKey> keys_;
  std::vector<cln::cl_RA> coefficients_;
  friend class PackedPolynomialBuilder;
};

PackedPolynomial multiply(const PackedPolynomial& a, const PackedPolynomial& b, const std::function<void()>& tick,
                          const PackedLimits& limits);

}  // namespace linkproof::proof_detail
