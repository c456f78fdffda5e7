#include "rfm/allocator.h"

#include <cstdlib> // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#  include <malloc.h>
#endif

namespace rfm
{
  void keep_freed_matrices_in_heap()
  {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
#endif
  }
} // namespace rfm
