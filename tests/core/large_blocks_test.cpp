// keep_large_blocks_for_reuse: after it, a block far above glibc's mmap threshold comes from
// the heap (no mapping of its own), and a freed one is reused by the next allocation of its
// size instead of being unmapped and faulted in again.
#include "core/large_blocks.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace linkproof {
namespace {

TEST(LargeBlocks, AreServedFromTheHeapAndReusedOnceTheSettingIsMade) {
#if defined(__GLIBC__)
  if (!keep_large_blocks_for_reuse()) GTEST_SKIP() << "malloc is not glibc's here (a sanitizer's allocator)";
  const size_t size = size_t{64} << 20;  // twice the ceiling of glibc's dynamic mmap threshold
  const size_t mapped_before = mallinfo2().hblks;
  void* first = std::malloc(size);
  ASSERT_NE(first, nullptr);
  std::memset(first, 1, size);
  EXPECT_EQ(mallinfo2().hblks, mapped_before) << "the block was given a mapping of its own";
  std::free(first);
  void* second = std::malloc(size);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(second, first) << "the freed block was not reused";
  std::free(second);
#else
  GTEST_SKIP() << "not glibc";
#endif
}

}  // namespace
}  // namespace linkproof
