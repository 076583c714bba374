#include "core/large_blocks.h"

#include <climits>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace linkproof {

bool keep_large_blocks_for_reuse() {
#if defined(__GLIBC__)
  // Both calls return 1 when glibc takes the setting; an interposed allocator (ASan's) does not.
  const int no_mmap = mallopt(M_MMAP_MAX, 0);
  const int no_trim = mallopt(M_TRIM_THRESHOLD, INT_MAX);
  return no_mmap == 1 && no_trim == 1;
#else
  return false;
#endif
}

}  // namespace linkproof
