// Exit codes and the --strict policy are the command line's (cli/exit_status.h): the library's
// results carry facts (verdicts, counts, how a run ended) and no exit code; report/ prints the
// CLI's decisions as given.
#include <gtest/gtest.h>

#include <string>

#include "exit_status.h"
#include "linkproof/mechanism/mechanism_check.h"

// Detection, outside namespace linkproof so that only argument-dependent lookup can find a
// library function named exit_status (cli::exit_status is not found from here).
namespace detect {
template <class R>
concept HasFreeExitStatus = requires(const R& r) { exit_status(r); };
template <class R>
concept HasMemberExitStatus = requires(const R& r) { r.exit_status(); };
template <class R>
concept HasStrictMember = requires(const R& r) { r.strict; };
template <class R>
concept TakesAStrictFlag = requires(const R& r) { r.is_as_expected(true); } || requires(const R& r) { r.as_expected(true); };
}  // namespace detect

namespace linkproof {
namespace {

ClaimOutcome outcome(Expectation expected, Verdict verdict) {
  ClaimOutcome o;
  o.info.id = "c";
  o.info.expected = expected;
  o.verdict = verdict;
  return o;
}

TEST(LibraryResults, CarryNoExitCodeAndNoStrictPolicy) {
  EXPECT_FALSE(detect::HasFreeExitStatus<PolygonCheck>);
  EXPECT_FALSE(detect::HasFreeExitStatus<MechanismCheck>);
  EXPECT_FALSE(detect::HasFreeExitStatus<DataCheck>);
  EXPECT_FALSE(detect::HasFreeExitStatus<std::vector<ClaimOutcome>>);
  EXPECT_FALSE(detect::HasMemberExitStatus<SweepReport>);
  EXPECT_FALSE(detect::HasMemberExitStatus<BatchSweepResult>);
  EXPECT_FALSE(detect::HasMemberExitStatus<CountReport>);
  EXPECT_FALSE(detect::HasStrictMember<PolygonCheck>);
  EXPECT_FALSE(detect::HasStrictMember<MechanismCheck>);
  EXPECT_FALSE(detect::HasStrictMember<CountReport>);
  EXPECT_FALSE(detect::TakesAStrictFlag<ClaimOutcome>);
  EXPECT_FALSE(detect::TakesAStrictFlag<ProofResult>);
  EXPECT_FALSE(detect::TakesAStrictFlag<CountClaim>);
  // The detection itself works: the CLI's function is found where it is.
  EXPECT_TRUE((requires(const SweepReport& r) { cli::exit_status(r); }));
}

TEST(ExitStatus, StrictCountsUndefinedOrInconclusiveTrueClaimsAsNotAsExpected) {
  for (Verdict v : {Verdict::Undefined, Verdict::Inconclusive}) {
    const std::vector<ClaimOutcome> claims{outcome(Expectation::Holds, Verdict::Holds), outcome(Expectation::Holds, v)};
    EXPECT_EQ(cli::exit_status(claims), 0) << to_string(v);
    const ClaimsStatus strict = cli::claims_status(claims, /*strict=*/true);
    EXPECT_EQ(strict.exit_status, 1) << to_string(v);
    EXPECT_TRUE(strict.strict);
    EXPECT_EQ(strict.as_expected, (std::vector<bool>{true, false})) << to_string(v);
    // An erratum reading left undecided says nothing against it, strict or not.
    EXPECT_TRUE(cli::is_as_expected(outcome(Expectation::Fails, v), true)) << to_string(v);
  }
  // An erratum reading that holds here is no failure; a true claim that fails is one.
  EXPECT_EQ(cli::exit_status({outcome(Expectation::Fails, Verdict::Holds)}, true), 0);
  EXPECT_EQ(cli::exit_status({outcome(Expectation::Holds, Verdict::Fails)}), 1);
  // An error wins over everything (exit 3), and is never as expected.
  const ClaimsStatus error = cli::claims_status(
      {outcome(Expectation::Holds, Verdict::Fails), outcome(Expectation::Fails, Verdict::Error)});
  EXPECT_EQ(error.exit_status, 3);
  EXPECT_EQ(error.as_expected, (std::vector<bool>{false, false}));
}

TEST(ExitStatus, StrictProofsAndCountsNeedTheWholeRangeOrTheStatedVerdict) {
  ProofResult p;
  p.expected = Expectation::Holds;
  p.verdict = ProofVerdict::ProvedFor;
  const ClaimsStatus lenient = cli::proofs_status({p});
  EXPECT_EQ(lenient.exit_status, 0);
  const ClaimsStatus strict = cli::proofs_status({p}, true);
  EXPECT_EQ(strict.exit_status, 1);
  EXPECT_EQ(strict.as_expected, std::vector<bool>{false});
  p.verdict = ProofVerdict::Error;
  EXPECT_EQ(cli::exit_status(std::vector<ProofResult>{p}), 3);

  CountReport r;
  r.claims.resize(1);
  r.claims[0].expected = CountVerdict::Proved;
  r.claims[0].verdict = CountVerdict::HoldsOnSamples;
  EXPECT_EQ(cli::count_status(r).exit_status, 0);
  EXPECT_EQ(cli::count_status(r, true).exit_status, 1);
  r.claims[0].verdict = CountVerdict::Proved;
  EXPECT_EQ(cli::count_status(r, true).exit_status, 0);
}

TEST(ExitStatus, SweepAndBatchSweepAreDecidedFromTheirFacts) {
  SweepReport s;
  s.tallies.resize(2);
  s.tallies[0].id = "a", s.tallies[0].expected = Expectation::Holds;
  s.tallies[1].id = "b", s.tallies[1].expected = Expectation::Fails;
  s.tallies[1].fails = 7;  // an erratum reading failing is its disproof
  EXPECT_EQ(s.unexpected_failures(), 0);
  EXPECT_EQ(cli::exit_status(s), 0);
  s.tallies[0].fails = 2;
  EXPECT_EQ(s.unexpected_failures(), 2);
  EXPECT_EQ(cli::exit_status(s), 1);
  s.tallies[1].error = 1;
  EXPECT_EQ(s.errors(), 1);
  EXPECT_EQ(cli::exit_status(s), 3);

  BatchSweepResult r;
  r.report = s;
  EXPECT_EQ(cli::exit_status(r), 3);
  r.status = BatchSweepResult::Status::Interrupted, r.signal = 15;
  EXPECT_EQ(cli::exit_status(r), 143);
  r.status = BatchSweepResult::Status::OutOfTime;
  EXPECT_EQ(cli::exit_status(r), 2);
  r.status = BatchSweepResult::Status::WorkerFailed;
  EXPECT_EQ(cli::exit_status(r), 3);
}

}  // namespace
}  // namespace linkproof

namespace linkproof {
namespace {

// Claims on random configurations of a topology: samples are evidence, not a proof, so under
// --strict a true claim that holds on them is not as expected; an erratum must be disproved.
TEST(ExitStatus, SamplingStrictNeverAcceptsSamplesForATrueClaim) {
  TopologySampleRun run;
  SampleResult holds;
  holds.info.expected = Expectation::Holds;
  holds.verdict = TopologyVerdict::HoldsOnSamples;
  SampleResult erratum;
  erratum.info.expected = Expectation::Fails;
  erratum.verdict = TopologyVerdict::Disproved;
  run.claims = {holds, erratum};
  const ClaimsStatus lenient = cli::sampling_status(run, false);
  EXPECT_EQ(lenient.exit_status, 0);
  EXPECT_EQ(lenient.as_expected, (std::vector<bool>{true, true}));
  const ClaimsStatus strict = cli::sampling_status(run, true);
  EXPECT_EQ(strict.exit_status, 1);
  EXPECT_EQ(strict.as_expected, (std::vector<bool>{false, true}));
  run.claims[1].verdict = TopologyVerdict::HoldsOnSamples;  // the erratum not found wrong
  EXPECT_EQ(cli::sampling_status(run, false).exit_status, 1);
}

}  // namespace
}  // namespace linkproof
