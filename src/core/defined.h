// Defined<V>: a value, or the name of the quantity that does not exist and why.
// Used where a geometric construction can break (a point at infinity, a null ray) while the
// rest of the evaluation goes on; get() throws UndefinedQuantity, which a claim runner turns
// into the verdict `undefined` naming the quantity.
#pragma once

#include <memory>
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
    // The names live on the heap, and only when there is something to say: a defined value
    // (the hot path of the construction) carries one null pointer, not two strings.
    if (!quantity.empty() || !reason.empty())
      d.why_ = std::make_shared<const Why>(Why{std::move(quantity), std::move(reason)});
    return d;
  }
  /// No value and nothing said yet: a placeholder to be assigned (costs no string).
  static Defined pending() { return Defined(); }
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
    if (!value_) throw UndefinedQuantity(quantity(), reason());
    return *value_;
  }
  const std::string& quantity() const { return why_ ? why_->quantity : empty(); }
  const std::string& reason() const { return why_ ? why_->reason : empty(); }

 private:
  struct Why {
    std::string quantity, reason;
  };
  static const std::string& empty() {
    static const std::string e;
    return e;
  }
  Defined() = default;
  std::optional<V> value_;
  std::shared_ptr<const Why> why_;
};

}  // namespace linkproof
