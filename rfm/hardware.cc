#include "rfm/hardware.h"

#include <Eigen/Core>

#include <sched.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#if defined(RFM_OPENBLAS)
extern "C"
{
  void openblas_set_num_threads(int);
  int openblas_get_num_threads(void);
}
#endif

namespace rfm
{
  namespace
  {
    // OPENBLAS_NUM_THREADS, else OMP_NUM_THREADS (OpenBLAS's own order), else the cores
    // this process may run on (taskset), as OpenBLAS counts them.
    int threads_from_environment()
    {
      for (const char *name : {"OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"})
        if (const char *v = std::getenv(name))
          {
            const int n = std::atoi(v);
            if (n >= 1)
              return n;
          }
      cpu_set_t set;
      if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0)
        return CPU_COUNT(&set);
      const unsigned cores = std::thread::hardware_concurrency();
      return cores > 0 ? static_cast<int>(cores) : 1;
    }

    int &thread_count()
    {
      static int n = threads_from_environment();
      return n;
    }
  } // namespace

  int n_threads() { return thread_count(); }

  namespace
  {
    // Scopes alive: OpenBLAS runs on n_threads() threads when some BlasThreadsOn scope is
    // and no BlasThreadsOff scope is, else on one.
    std::atomic<int> blas_on_depth{0}, blas_off_depth{0};

    void apply_blas_threads()
    {
#if defined(RFM_OPENBLAS)
      const int n = blas_on_depth > 0 && blas_off_depth == 0 ? thread_count() : 1;
      if (openblas_get_num_threads() != n)
        openblas_set_num_threads(n);
#endif
    }

    // OpenBLAS starts on all cores: one thread until a BlasThreadsOn scope asks for more.
    [[maybe_unused]] const bool blas_single_at_start = (apply_blas_threads(), true);
  } // namespace

  void set_n_threads(int n)
  {
    if (n < 1)
      throw std::invalid_argument("thread count: " + std::to_string(n) + " (must be >= 1)");
    thread_count() = n;
    apply_blas_threads();
  }

  const char *threading_backend()
  {
#if defined(RFM_OPENBLAS)
    return "OpenBLAS (EIGEN_USE_BLAS) + assembly threads";
#else
    return "assembly threads only (Eigen kernels single-threaded)";
#endif
  }

  BlasThreadsOn::BlasThreadsOn(const bool enable) : enabled_(enable)
  {
    if (enabled_)
      ++blas_on_depth, apply_blas_threads();
  }

  BlasThreadsOn::~BlasThreadsOn()
  {
    if (enabled_)
      --blas_on_depth, apply_blas_threads();
  }

  BlasThreadsOff::BlasThreadsOff() { ++blas_off_depth, apply_blas_threads(); }

  BlasThreadsOff::~BlasThreadsOff() { --blas_off_depth, apply_blas_threads(); }

  namespace
  {
    long l2_from_sysfs()
    {
      for (int index = 0; index < 8; ++index)
        {
          const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index);
          std::ifstream level_file(dir + "/level"), size_file(dir + "/size");
          int level = 0;
          long size = 0;
          char unit = 0;
          if (!(level_file >> level))
            return 0;
          if (level != 2 || !(size_file >> size))
            continue;
          size_file >> unit;
          return unit == 'M' ? size << 20 : unit == 'K' ? size << 10 : size;
        }
      return 0;
    }
  } // namespace

  long l2_cache_bytes()
  {
    static const long bytes = [] {
#if defined(_SC_LEVEL2_CACHE_SIZE)
      const long s = sysconf(_SC_LEVEL2_CACHE_SIZE);
      if (s > 0)
        return s;
#endif
      const long f = l2_from_sysfs();
      return f > 0 ? f : default_l2_bytes;
    }();
    return bytes;
  }
} // namespace rfm
