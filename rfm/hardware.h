// What the dense kernels know of the host: the thread count they use and the L2 cache
// size that the assembly's chunks of quadrature points are fitted to.
//
// Threads: Eigen's products go to OpenBLAS (RFM_OPENBLAS=ON, EIGEN_USE_BLAS), which runs
// them on n_threads() threads; the assembly splits its block products between
// n_threads() threads of its own and runs OpenBLAS single-threaded meanwhile. Default:
// OPENBLAS_NUM_THREADS, else OMP_NUM_THREADS, else all cores; set_n_threads overrides it
// (rfm_benchmark --threads=N). Results are bitwise identical
// between runs with the same thread count (each output entry is computed by one thread
// in a fixed order; the assembly's column ranges and OpenBLAS's partitions depend on the
// thread count only). Different thread counts differ by rounding.
#pragma once

namespace rfm
{
  /// Threads the dense kernels and the assembly use.
  int n_threads();
  /// Sets them; throws std::invalid_argument unless n >= 1.
  void set_n_threads(int n);
  /// The parallel route compiled in.
  const char *threading_backend();

  /// While alive, OpenBLAS runs on the calling thread only (inside the assembly's own
  /// threads); the last one alive restores n_threads() at its end (they nest).
  class BlasThreadsOff
  {
  public:
    BlasThreadsOff();
    ~BlasThreadsOff();
    BlasThreadsOff(const BlasThreadsOff &) = delete;
    BlasThreadsOff &operator=(const BlasThreadsOff &) = delete;
  };

  /// Per-core L2 data cache of cpu0 in bytes: sysconf, else
  /// /sys/devices/system/cpu/cpu0/cache, else default_l2_bytes.
  long l2_cache_bytes();
  inline constexpr long default_l2_bytes = 512 * 1024;
} // namespace rfm
