// What the dense kernels know of the host: the thread count they use and the L2 cache
// size that the assembly's chunks of quadrature points are fitted to.
//
// Threads: Eigen's products go to OpenBLAS (RFM_OPENBLAS=ON, EIGEN_USE_BLAS), which runs
// on one thread in the solver. The parallelism is the solver's own, on n_threads()
// threads of one persistent pool (run_on_threads): the assembly splits its block
// products between them, and the large saddle-point solves run as a task graph of tiles
// (rfm/solve/bordered_cholesky.h), each task a single-threaded OpenBLAS call. Default:
// OPENBLAS_NUM_THREADS, else OMP_NUM_THREADS, else all cores; set_n_threads overrides it
// (rfm_benchmark --threads=N). Results are bitwise identical between runs with the same
// thread count (each output entry is computed by one thread in a fixed order; the
// assembly's column ranges depend on the thread count only). The solve's factors are
// bitwise the same for every thread count; the assembly's differ by rounding.
#pragma once

#include <functional>

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
  /// While alive (and enabled), OpenBLAS runs on n_threads() threads (the benchmark's
  /// dense references).
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
  /// one-thread solve times (rfm/solve/bordered_cholesky.h) 1.25x at 510 unknowns (die p = 8),
  /// 1.45x at 726 (Lame p = 10), 1.65x at 1014 (p = 12); none at 486 (Lame p = 8).
  inline constexpr long parallel_solve_unknowns = 500;

  /// Runs f(0), ..., f(n - 1) at the same time on n threads: f(0) on the caller, the rest on
  /// workers kept for the whole process (started on first use), so that a parallel
  /// section costs no thread start (measured 0.15-0.3 ms per std::thread here, against
  /// a 4.5 ms two-thread assembly at Lame p = 14). The f(t) may wait for each other (a
  /// barrier). Returns when all have returned; the first exception (by t) is rethrown
  /// then. A worker spins for 0.2 ms after its part, then sleeps: back-to-back sections
  /// (assembly, then the solve) find it awake. A call from inside a section, or while
  /// another thread's section runs, gets threads of its own instead.
  void run_on_threads(int n, const std::function<void(int)> &f);

  /// Per-core L2 data cache of cpu0 in bytes: sysconf, else
  /// /sys/devices/system/cpu/cpu0/cache, else default_l2_bytes.
  long l2_cache_bytes();
  inline constexpr long default_l2_bytes = 512 * 1024;
} // namespace rfm
