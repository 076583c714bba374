// The benchmarks' main: Google Benchmark's, after the process setting the CLI makes
// (core/large_blocks.h), so that a benchmark costs what the command it measures costs.
#include <benchmark/benchmark.h>

#include "core/large_blocks.h"

int main(int argc, char** argv) {
  linkproof::keep_large_blocks_for_reuse();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
