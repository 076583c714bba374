// Defined<V>: a value, or the name of the quantity that does not exist and why.
// Used where a geometric construction can break (a point at infinity, a null ray) while the
// rest of the evaluation goes on; get() throws UndefinedQuantity, which a claim runner turns
// into the verdict `undefined` naming the quantity.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "linkproof/core/error.h"

namespace linkproof {

template <class V>
class Defined {
 public:
  Defined(V value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  static Defined undefined(std::string quantity, std::string reason) {
    Defined d;
    d.quantity_ = std::move(quantity);
    d.reason_ = std::move(reason);
    return d;
  }
  /// Runs f(); a thrown UndefinedQuantity becomes an undefined result.
  template <class F>
  static Defined attempt(F&& f) {
    try {
      return Defined(f());
    } catch (const UndefinedQuantity& u) {
      return undefined(u.quantity(), u.reason());
    }
  }

  bool has_value() const { return value_.has_value(); }
  const V& get() const {
    if (!value_) throw UndefinedQuantity(quantity_, reason_);
    return *value_;
  }
  const std::string& quantity() const { return quantity_; }
  const std::string& reason() const { return reason_; }

 private:
  Defined() = default;
  std::optional<V> value_;
  std::string quantity_, reason_;
};

}  // namespace linkproof
