// What the dense kernels know of the host: the thread count they use and the L2 cache
// size that the assembly's chunks of quadrature points are fitted to.
//
// Threads: Eigen's products go to OpenBLAS (RFM_OPENBLAS=ON, EIGEN_USE_BLAS), which runs
// the large saddle-point solves on n_threads() threads (BlasThreadsOn) and everything else
// on one; the assembly splits its block products between n_threads() threads of its own
// and runs OpenBLAS single-threaded meanwhile. Default:
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

  /// OpenBLAS runs on one thread except inside a BlasThreadsOn scope (and outside every
  /// BlasThreadsOff scope): most of the program's BLAS calls are small products (field
  /// evaluation, functionals, the contact check) that a second thread only slows down
  /// (measured: die_contact --mode full 58 s on one thread, 80 s with OpenBLAS on two
  /// threads everywhere). Both scopes nest.
  ///
  /// While alive (and enabled), OpenBLAS runs on n_threads() threads: the large dense
  /// factorizations and solves (solve_saddle_point above parallel_solve_unknowns).
  class BlasThreadsOn
  {
  public:
    explicit BlasThreadsOn(bool enable = true);
    ~BlasThreadsOn();
    BlasThreadsOn(const BlasThreadsOn &) = delete;
    BlasThreadsOn &operator=(const BlasThreadsOn &) = delete;

  private:
    bool enabled_;
  };

  /// While alive, OpenBLAS runs on the calling thread only (inside the assembly's own
  /// threads), whatever BlasThreadsOn scopes enclose it.
  class BlasThreadsOff
  {
  public:
    BlasThreadsOff();
    ~BlasThreadsOff();
    BlasThreadsOff(const BlasThreadsOff &) = delete;
    BlasThreadsOff &operator=(const BlasThreadsOff &) = delete;
  };

  /// Saddle-point systems with at least this many unknowns (stress + displacement) are
  /// factorized on n_threads() threads, smaller ones on one: measured two-thread over
  /// one-thread solve times 1.16x at 726 unknowns (Lame p = 10), 1.38x at 1014 (p = 12).
  inline constexpr long parallel_solve_unknowns = 1000;

  /// Per-core L2 data cache of cpu0 in bytes: sysconf, else
  /// /sys/devices/system/cpu/cpu0/cache, else default_l2_bytes.
  long l2_cache_bytes();
  inline constexpr long default_l2_bytes = 512 * 1024;
} // namespace rfm
