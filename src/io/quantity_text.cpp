#include "quantity_text.h"

#include <cln/integer.h>
#include <fmt/format.h>

#include <array>
#include <cctype>
#include <stdexcept>

#include "io/input_limits.h"

namespace linkproof {

namespace {

// |log2| of a coefficient: about 10^+-4000, the range of one exact number (core/exact.h).
constexpr long kMaxCoefficientBits = 13300;

struct Unit {
  std::string_view suffix;
  QuantityKind kind;
  Rational factor;  // times pi
};

const std::array<Unit, 4>& units() {
  static const std::array<Unit, 4> all = {Unit{"rpm/s", QuantityKind::AngularAcceleration, Rational(1) / 30},
                                          Unit{"rpm", QuantityKind::AngularVelocity, Rational(1) / 30},
                                          Unit{"deg", QuantityKind::Angle, Rational(1) / 180},
                                          Unit{"rad", QuantityKind::Angle, 0}};
  return all;
}

std::string allowed_units(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::Angle: return "`deg`, `rad` or no unit (radians)";
    case QuantityKind::AngularVelocity: return "`rpm` or no unit (rad/s)";
    case QuantityKind::AngularAcceleration: return "`rpm/s` or no unit (rad/s^2)";
    case QuantityKind::Sliding: return "no unit (lengths per second, per second squared)";
  }
  return "";
}

[[noreturn]] void refuse(const std::string& problem) { throw std::invalid_argument(problem); }

// Recursive descent over the product (the unit already removed).
class ProductReader {
 public:
  explicit ProductReader(std::string_view text) : text_(text) {}

  PiMultiple read() {
    PiMultiple value = factor();
    for (;;) {
      skip_spaces();
      if (at_end()) return value;
      const char op = text_[pos_];
      if (is_letter(op)) {
        const std::size_t start = pos_;
        const std::string_view name = identifier();
        if (name == "pi") refuse(fmt::format("a missing `*` before `pi` at character {} (write 2*pi, not 2pi)", start + 1));
        refuse(fmt::format("unknown name `{}` at character {} (units: deg, rad, rpm, rpm/s)", name, start + 1));
      }
      if (op == '+' || op == '-')
        refuse(fmt::format("`{}` at character {}: an angle or a rate is a product (numbers, `pi`, `*`, `/`, a minus "
                           "sign in front and a unit), not a sum",
                           op, pos_ + 1));
      if (op != '*' && op != '/') refuse(fmt::format("expected `*`, `/` or the end at character {}, got `{}`", pos_ + 1, op));
      ++pos_;
      const std::size_t where = pos_;
      const PiMultiple rhs = factor();
      if (op == '*') {
        value.coefficient = value.coefficient * rhs.coefficient;
        value.pi_power += rhs.pi_power;
      } else {
        if (cln::zerop(rhs.coefficient)) refuse(fmt::format("division by zero at character {}", where + 1));
        value.coefficient = value.coefficient / rhs.coefficient;
        value.pi_power -= rhs.pi_power;
      }
    }
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  void skip_spaces() {
    while (!at_end() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  static bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
  static bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }

  PiMultiple factor() {
    skip_spaces();
    if (at_end()) refuse(fmt::format("expected a number or `pi` at character {}, got the end", pos_ + 1));
    const char c = text_[pos_];
    if (c == '-' || c == '+') {
      if (++signs_ > 8) refuse("more than 8 signs in a row");
      ++pos_;
      PiMultiple inner = factor();
      if (c == '-') inner.coefficient = -inner.coefficient;
      return inner;
    }
    signs_ = 0;
    if (is_digit(c) || c == '.') return number();
    if (is_letter(c)) {
      const std::size_t start = pos_;
      const std::string_view name = identifier();
      if (name == "pi") return {1, 1};
      refuse(fmt::format("unknown name `{}` at character {} (an angle or a rate is numbers, `pi`, `*`, `/`, a "
                         "minus sign and a unit)",
                         name, start + 1));
    }
    refuse(fmt::format("expected a number or `pi` at character {}, got `{}`", pos_ + 1, c));
  }

  std::string_view identifier() {
    const std::size_t start = pos_;
    while (!at_end() && (is_letter(text_[pos_]) || is_digit(text_[pos_]))) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  // digits [. digits] [e [sign] digits], read exactly by parse_rational.
  PiMultiple number() {
    const std::size_t start = pos_;
    while (!at_end() && (is_digit(text_[pos_]) || text_[pos_] == '.')) ++pos_;
    if (!at_end() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t k = pos_ + 1;
      if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
      if (k < text_.size() && is_digit(text_[k])) {
        pos_ = k;
        while (!at_end() && is_digit(text_[pos_])) ++pos_;
      }
    }
    const std::string_view token = text_.substr(start, pos_ - start);
    try {
      return {parse_rational(token), 0};
    } catch (const std::invalid_argument& e) {
      refuse(fmt::format("the number `{}` at character {}: {}", token, start + 1, e.what()));
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int signs_ = 0;
};

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

bool PiMultiple::is_rational() const { return pi_power == 0 || cln::zerop(coefficient); }

std::string quantity_kind_name(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::Angle: return "an angle";
    case QuantityKind::AngularVelocity: return "an angular velocity";
    case QuantityKind::AngularAcceleration: return "an angular acceleration";
    case QuantityKind::Sliding: return "a sliding rate";
  }
  return "";
}

bool looks_like_quantity_expression(std::string_view text) {
  for (char c : text)
    if (c == '*' || (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E')) return true;
  return false;
}

PiMultiple parse_quantity(std::string_view text, QuantityKind kind) {
  if (text.size() > kMaxNumberCharacters)
    refuse(fmt::format("{} characters; the limit is {} (docs/limits.md)", text.size(), kMaxNumberCharacters));
  std::string_view body = trimmed(text);
  if (body.empty()) refuse("empty text");
  const Unit* unit = nullptr;
  for (const Unit& u : units()) {
    if (body.size() >= u.suffix.size() && body.substr(body.size() - u.suffix.size()) == u.suffix) {
      unit = &u;
      body = trimmed(body.substr(0, body.size() - u.suffix.size()));
      break;
    }
  }
  if (unit && unit->kind != kind)
    refuse(fmt::format("the unit `{}` is for {}; {} takes {}", unit->suffix, quantity_kind_name(unit->kind),
                       quantity_kind_name(kind), allowed_units(kind)));
  if (unit && body.empty()) refuse(fmt::format("a unit `{}` without a number", unit->suffix));
  PiMultiple value = ProductReader(body).read();
  if (unit && !cln::zerop(unit->factor)) {
    value.coefficient = value.coefficient * unit->factor;
    value.pi_power += 1;
  }
  if (cln::zerop(value.coefficient)) value.pi_power = 0;
  const auto bits_of = [](const cln::cl_I& n) { return static_cast<long>(cln::integer_length(cln::abs(n))); };
  if (bits_of(cln::numerator(value.coefficient)) > kMaxCoefficientBits ||
      bits_of(cln::denominator(value.coefficient)) > kMaxCoefficientBits)
    refuse("the value is beyond 10^4000 in size or precision (docs/limits.md)");
  if (value.pi_power > 64 || value.pi_power < -64) refuse("pi to a power beyond 64");
  return value;
}

}  // namespace linkproof
