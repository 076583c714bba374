#include "count/count_claim.h"

#include <algorithm>

namespace linkproof {

std::string_view to_string(CountVerdict v) {
  switch (v) {
    case CountVerdict::Proved: return "proved";
    case CountVerdict::HoldsOnSamples: return "holds_on_samples";
    case CountVerdict::Disproved: return "disproved";
    case CountVerdict::Error: return "error";
  }
  return "error";
}

CountClaim judge_rank(std::string id, std::string statement, int expected_rank, int rank, int augmented_rank,
                      const RankResult& evidence) {
  CountClaim c;
  c.id = std::move(id);
  c.statement = std::move(statement);
  c.expected_value = std::to_string(expected_rank);
  c.observed_value = std::to_string(rank);
  c.rank = evidence;
  const bool consistent = rank == augmented_rank;
  c.verdict = rank == expected_rank && consistent ? CountVerdict::Proved : CountVerdict::Disproved;
  c.reason = "rank " + std::to_string(rank) + (consistent ? ", consistent"
                                                           : ", inconsistent: augmented rank " +
                                                                 std::to_string(augmented_rank));
  return c;
}

CountClaim judge_value(std::string id, std::string statement, const std::string& expected,
                       const std::string& observed) {
  CountClaim c;
  c.id = std::move(id);
  c.statement = std::move(statement);
  c.expected_value = expected;
  c.observed_value = observed;
  c.verdict = expected == observed ? CountVerdict::Proved : CountVerdict::Disproved;
  return c;
}

CountClaim count_error(std::string id, std::string statement, std::string reason) {
  CountClaim c;
  c.id = std::move(id);
  c.statement = std::move(statement);
  c.verdict = CountVerdict::Error;
  c.reason = std::move(reason);
  return c;
}

}  // namespace linkproof
