// The outcome of a counting claim (a rank, a balance, a solved value), with its evidence.
//
// Counting claims are statements about exact integers and rationals, so there is no tolerance:
//  proved            the computed value equals the stated one exactly, and the computation
//                    covers every case the claim states (a rank of relations with constant
//                    coefficients, or of one stated configuration such as the Fig. 5 eight-bar);
//  holds_on_samples  a rank whose relations depend on the geometry, computed exactly on
//                    `samples` polygons and equal to the stated one on each: the generic rank is
//                    at least that, but no argument covers every configuration;
//  disproved         it does not; `observed` holds what was computed (e.g. the observed rank);
//  error             the count could not be made (a dead centre, an undetermined velocity, ...).
// An erratum reading of the paper is stated with `expected = Disproved`.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "count/counting.h"

namespace linkproof {

enum class CountVerdict { Proved, HoldsOnSamples, Disproved, Error };

/// "proved", "holds_on_samples", "disproved", "error" (the JSON spelling).
std::string_view to_string(CountVerdict v);

struct CountClaim {
  std::string id;
  std::string statement;           ///< what is claimed, in words, with the source
  CountVerdict verdict = CountVerdict::Error;
  CountVerdict expected = CountVerdict::Proved;
  std::string expected_value;      ///< the stated value ("1711", "171151479/318550130", ...)
  std::string observed_value;      ///< the computed value; empty on error
  std::string reason;              ///< why: the error, or what was compared
  std::optional<RankResult> rank;  ///< sizes, ranks and time when the claim is a rank
  int samples = 0;                 ///< holds_on_samples: the exact polygons it rests on
  /// The expected verdict; a stated "proved" is also met by holds_on_samples (the program's
  /// --strict, under which it is not, is the command line's policy).
  bool as_expected() const {
    return verdict == expected || (expected == CountVerdict::Proved && verdict == CountVerdict::HoldsOnSamples);
  }
};

/// Judges "the family has rank `expected_rank` and is consistent" against a computed rank.
/// `rank` and `augmented_rank` are those to compare (e.g. taken modulo the triangle relations);
/// `evidence` is the underlying system, kept for sizes and time.
CountClaim judge_rank(std::string id, std::string statement, int expected_rank, int rank, int augmented_rank,
                      const RankResult& evidence);

/// Judges an exact value: proved iff observed == expected.
CountClaim judge_value(std::string id, std::string statement, const std::string& expected,
                       const std::string& observed);

/// A claim that could not be evaluated.
CountClaim count_error(std::string id, std::string statement, std::string reason);

/// A list of counting claims, in the order they were made.
struct CountReport {
  std::string subject;              ///< "n = 3..60", "eight-bar of Fig. 5", ...
  std::vector<CountClaim> claims;
  std::vector<std::string> notes;   ///< statements for the reader (e.g. the docs/conventions.md §A5.5 erratum)
};

}  // namespace linkproof
