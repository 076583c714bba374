// Angles and rates written as short expressions in a mechanism scene ("30deg", "pi/6", "1.2rad",
// "-2000rpm"), read exactly as c * pi^k. Private to src/io (mechanism_scene.cpp).
//
// Grammar (spaces allowed between tokens):
//   quantity := product [unit]
//   product  := factor { ("*" | "/") factor }
//   factor   := ("-" | "+") factor | number | "pi"
//   number   := an exact number as in core/exact.h: "12", "0.5", "2.5e-3" (a fraction is a product)
//   unit     := "deg" | "rad" | "rpm" | "rpm/s", as the quantity allows
// Units: an angle takes deg (pi/180 rad) or rad; without a unit it is in radians. An input's
// omega takes rpm (revolutions per minute: 2 pi / 60 rad/s, signed: -2000rpm turns clockwise);
// omega_dot takes rpm/s (2 pi / 60 rad/s^2); without a unit they are in rad/s and rad/s^2.
// Sliding rates v, a take no unit (lengths per second). Without `+` there is no sum, so every
// value is exactly c * pi^k with c rational: exact, whatever enclosure is later made of it.
#pragma once

#include <string>
#include <string_view>

#include "linkproof/core/exact.h"

namespace linkproof {

/// c * pi^k.
struct PiMultiple {
  Rational coefficient = 0;
  int pi_power = 0;
  /// True when the value is a rational number as written (no pi, or a zero coefficient).
  bool is_rational() const;
};

enum class QuantityKind {
  Angle,                ///< radians; deg, rad
  AngularVelocity,      ///< rad/s; rpm
  AngularAcceleration,  ///< rad/s^2; rpm/s
  Sliding,              ///< a sliding velocity or acceleration (lengths per second): no unit
};

/// The quantity in SI units (rad, rad/s, rad/s^2). Throws std::invalid_argument with what is
/// wrong and where ("unknown name `degrees` at character 4"); the caller adds file and field.
PiMultiple parse_quantity(std::string_view text, QuantityKind kind);

/// True when `text` is meant as an expression rather than a plain number: it holds a letter
/// other than an exponent's e, or `*`. Plain numbers keep the exact-number reader and its messages.
bool looks_like_quantity_expression(std::string_view text);

/// How the quantity kind is spelled in messages: "an angle", "an angular velocity", ...
std::string quantity_kind_name(QuantityKind kind);

}  // namespace linkproof
