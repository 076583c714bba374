// The sentences of a comparison's evidence (check/judge.h): how a floating-point tolerance was
// derived, why a comparison was not decided, which side to distrust and what decides instead,
// and the verdict rule of each arithmetic. Every report format takes them from here.
#pragma once

#include <string>

#include "linkproof/check/arithmetic.h"
#include "check/judge.h"
#include "report/number_text.h"

namespace linkproof {

/// How a value is written (report/number_text.h): `Exact` as the arithmetic prints it ("p/q",
/// every digit: the JSON's spelling); `Readable` an exact value with its decimal beside it, a
/// long fraction by its decimal and size (readable_number); `Compact` for a table cell, a long
/// fraction by its decimal and kLongFractionMark (compact_number: put long_fraction_note under
/// the table). Floats are written as they are in every style.
enum class NumberStyle { Exact, Readable, Compact };

/// The text of a comparison's values ("" where there is none).
std::string lhs_text(const ComparisonOutcome& c, NumberStyle style = NumberStyle::Exact, int digits = kReadableDigits);
std::string rhs_text(const ComparisonOutcome& c, NumberStyle style = NumberStyle::Exact, int digits = kReadableDigits);
std::string residual_text(const ComparisonOutcome& c, NumberStyle style = NumberStyle::Exact,
                          int digits = kReadableDigits);
/// One value in a style.
std::string styled_number(const ResultNumber& x, NumberStyle style, int digits = kReadableDigits);
/// The derived tolerance of a floating-point comparison; "" in exact arithmetic.
std::string tolerance_text(const ComparisonOutcome& c);

/// The rule by which verdicts are drawn in arithmetic `a`.
std::string tolerance_rule(Arithmetic a);

/// "tolerance 3.1e-15 = bound(lhs) 1.2e-15 + bound(rhs) 1.9e-15 + ..."; empty in exact arithmetic.
std::string tolerance_derivation_text(const ComparisonOutcome& c);

/// Why the comparison has no decided verdict (the outcome's own reason, or the judge's for an
/// undecided floating-point comparison); empty if it has one.
std::string reason_text(const ComparisonOutcome& c);

/// For an undecided floating-point comparison: the side whose bound is the wider, the quantity
/// behind it when known, and what decides instead; empty otherwise.
std::string trust_route_text(const ComparisonOutcome& c);

/// The quantity of the cause when it is one the claim reads (not the claim's own arithmetic);
/// empty otherwise (the JSON's `inconclusive_quantity`).
std::string inconclusive_quantity(const ComparisonOutcome& c);

/// One sentence: the cause's quantity and what decides instead.
std::string cause_text(const InconclusiveCause& cause);

}  // namespace linkproof
