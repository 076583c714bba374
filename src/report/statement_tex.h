// A claim's statement as a report typesets it. Statements are written in ASCII by the claim
// catalogues ("omega_{n-1,n} = sum_j i_{n-1,j} omega_{j,n}"); a report shows their formulas as
// math ($\omega_{n-1,n} = \sum_j i_{n-1,j} \omega_{j,n}$) and their words as text.
//
// A statement is data (a claim file can be anyone's), so it is typeset only when it is made of
// the characters of such formulas: letters, digits, spaces and _ ^ { } ( ) [ ] + - * / = , . ; :
// ' | < > !; braces balanced; no "^^" (TeX's character code notation); no double subscript or
// superscript. Then no backslash, $, %, #, & or ~ of the input reaches the TeX: every command
// in it is one this translation writes (Greek letters, \dot, \sum, \cot, \sin, \cos, \neq,
// \mathrm, and \lt, \gt, \vert for < > |, which Markdown would read). Any other statement is plain text, escaped by the renderer as before.
#pragma once

#include <string>

#include "report/document.h"

namespace linkproof::report {

/// The statement as spans: runs of formula tokens as math, runs of words as text; the whole
/// statement as plain text when it is not made of formula characters alone (see above).
Rich statement_rich(const std::string& statement);

/// One run of formula tokens as TeX ("omega-dot_{j,n}" -> "\dot\omega_{j,n}"); "" when the run
/// is not safe to typeset (see above).
std::string formula_tex(const std::string& formula);

/// A term's label as the engine writes it ("omega[1]*omega[2]", "omega_dot[2]", "j=1:
/// omega[1]^2") as TeX ("\omega_{1}\omega_{2}", "\dot\omega_{2}", "j=1:\ \omega_{1}^2"); any
/// other label ("total") as plain text.
Rich term_label_rich(const std::string& label);

}  // namespace linkproof::report
