// Numbers in the reports of `linkproof report` (report/document.h): every exact value with its
// decimal beside it, typeset as math, the way number_text.h writes them in the text reports.
//
//   an integer          22                                   (math)
//   a short fraction    \frac{3755}{1331} \approx 2.821187077 (math; "=" where the decimal is the value)
//   a long fraction     ≈ 157.0796327 (exact: 116 digits)    (a folded span: HTML opens to the
//                                                             fraction; Markdown and LaTeX show
//                                                             the line; --json has every digit)
//   a float             its own text (number_text.h)
//
// Only digits, signs and the program's own TeX go into math: any text is safe here.
#pragma once

#include <string>

#include "linkproof/geometry/vec2.h"
#include "report/document.h"
#include "report/number_text.h"

namespace linkproof::report {

/// An exact rational as TeX: "-7/3" -> "-\frac{7}{3}".
std::string rational_tex(const Rational& q);

/// A decimal as TeX: "1.5e-40" -> "1.5 \times 10^{-40}".
std::string decimal_tex(const std::string& decimal);

/// An exact value as one TeX formula with its decimal: "22", "\frac{3755}{1331} \approx
/// 2.821187077", "\frac{7}{20} = 0.35"; a long fraction "\approx 157.0796327\ (\text{exact: 116
/// digits})".
std::string number_tex(const Rational& q, int digits = kReadableDigits);

/// An exact value as TeX with its decimal (the table above); a long fraction and a float give
/// the spans of their rows. `digits` significant digits of the decimal.
Rich number_rich(const ResultNumber& x, int digits = kReadableDigits);

/// A point "(x, y)" of exact coordinates, each as number_rich.
Rich point_rich(const Vec2<Rational>& p, int digits = kReadableDigits);

/// Text made by the program that may be an exact number ("3755/1331", "-2") or a point of two
/// ("(-9/2, -27/8)"): as number_rich / point_rich; any other text as plain text.
Rich value_rich(const std::string& value, int digits = kReadableDigits);

}  // namespace linkproof::report
