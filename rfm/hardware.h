// What the dense kernels know of the host: the thread count they use and the L2 cache
// size that the assembly's chunks of quadrature points are fitted to.
//
// Threads: the OpenMP default (OMP_NUM_THREADS, else all cores) when the library is built
// with RFM_OPENMP=ON, else 1; set_n_threads overrides it (rfm_solve --threads, the
// benchmark's --threads=N). Results are bitwise identical between runs with the same
// thread count.
#pragma once

namespace rfm
{
  /// Threads the dense kernels use.
  int n_threads();
  /// Sets them; throws std::invalid_argument unless n >= 1. No effect without threading.
  void set_n_threads(int n);
  /// "none" or the parallel route compiled in.
  const char *threading_backend();

  /// Per-core L2 data cache of cpu0 in bytes: sysconf, else
  /// /sys/devices/system/cpu/cpu0/cache, else default_l2_bytes.
  long l2_cache_bytes();
  inline constexpr long default_l2_bytes = 512 * 1024;
} // namespace rfm
