// bench's progress bar counted two units of step 3 where it does four (three adaptive requests
// on the random pentagons, one on the extreme families): it printed 207/206 and 208/206.
#include <gtest/gtest.h>

#include "numerics/bench_study.h"

namespace linkproof {
namespace {

TEST(BenchProgress, CountsEveryUnitOfWorkAndEndsAtItsTotal) {
  BenchOptions o;
  o.families = {"omega_scale"};
  o.random_cases = 1;
  o.adaptive_cases = 2;
  o.time_budget_seconds = 1e-5;
  int calls = 0, last_done = 0, last_total = 0;
  o.progress = [&](int done, int total) {
    ++calls;
    EXPECT_LE(done, total);
    EXPECT_EQ(done, last_done + 1);
    if (last_total) {
      EXPECT_EQ(total, last_total);
    }
    last_done = done;
    last_total = total;
  };
  (void)run_bench(o);
  EXPECT_GT(calls, 5);
  EXPECT_EQ(last_done, last_total);
}

}  // namespace
}  // namespace linkproof
