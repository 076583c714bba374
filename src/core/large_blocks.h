// Process setting of the executables (the CLI, linkproof_mpi, the benchmarks): large freed
// blocks are kept for reuse instead of being returned to the kernel.
//
// glibc serves every block above its mmap threshold (which it raises to at most 32 MB) with a
// mapping of its own and unmaps it on free. A check at n = 1000 builds and drops rate
// polynomials of about a million terms (32 MB and more) over and over, and every new mapping
// is faulted in page by page with the kernel clearing each page (perf: page faults 10 % of a
// double check, system time about 2 s of 13-18 s; docs/performance.md). With no mmap for
// blocks and the heap's top never trimmed, a freed block is reused by the next allocation.
// The cost is that the memory of a run's peak stays with the process until it exits, which is
// what a command-line run wants; a program that links the library decides for itself (the
// library never calls this).
#pragma once

namespace linkproof {

/// Applies the setting (glibc's mallopt: M_MMAP_MAX 0, M_TRIM_THRESHOLD INT_MAX). Returns
/// whether the allocator took it: false where malloc is not glibc's (a sanitizer's allocator).
bool keep_large_blocks_for_reuse();

}  // namespace linkproof
