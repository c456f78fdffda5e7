#include "rfm/hardware.h"

#include <Eigen/Core>

#include <sched.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <vector>
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
    return "OpenBLAS kernels (EIGEN_USE_BLAS), one thread each, on the solver's own threads "
           "(assembly by columns, solve by tiles)";
#else
    return "Eigen kernels, one thread each, on the solver's own threads (assembly by columns, "
           "solve by tiles)";
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

  namespace
  {
    // f(t) on threads started for this call (the fallback of run_on_threads). The parts
    // start together once every thread exists: if starting one fails, none has run (a
    // part may wait at a barrier for the others), the started ones are released and
    // joined, and the error is rethrown.
    void run_on_new_threads(const int n, const std::function<void(int)> &f)
    {
      std::vector<std::exception_ptr> errors(n);
      std::atomic<int> gate{0}; // 0: wait, 1: run, 2: abandon
      auto guarded = [&](int t) {
        while (gate.load(std::memory_order_acquire) == 0)
          std::this_thread::yield();
        if (gate.load(std::memory_order_acquire) != 1)
          return;
        try
          {
            f(t);
          }
        catch (...)
          {
            errors[t] = std::current_exception();
          }
      };
      std::vector<std::thread> threads;
      try
        {
          for (int t = 1; t < n; ++t)
            threads.emplace_back(guarded, t);
        }
      catch (...)
        {
          gate.store(2, std::memory_order_release);
          for (std::thread &t : threads)
            t.join();
          throw;
        }
      gate.store(1, std::memory_order_release);
      guarded(0);
      for (std::thread &t : threads)
        t.join();
      for (const std::exception_ptr &e : errors)
        if (e)
          std::rethrow_exception(e);
    }

    // Never destroyed (see run_on_threads): its workers stay parked until the process ends.
    class WorkerPool
    {
    public:
      // False if the pool is busy (nested or concurrent use) or cannot start a worker:
      // the caller falls back to threads of its own.
      bool try_run(const int n, const std::function<void(int)> &f)
      {
        if (busy_.exchange(true))
          return false;
        try
          {
            const std::lock_guard<std::mutex> lock(mutex_);
            while (static_cast<int>(workers_.size()) < n - 1)
              {
                const int index = static_cast<int>(workers_.size()) + 1;
                const unsigned now = generation_.load();
                workers_.emplace_back([this, index, now] { work(index, now); });
              }
            errors_.assign(n, nullptr);
            job_ = &f;
            job_threads_ = n;
            remaining_.store(n - 1);
            generation_.fetch_add(1);
          }
        catch (...)
          {
            busy_.store(false);
            return false;
          }
        wake_.notify_all();
        try
          {
            f(0);
          }
        catch (...)
          {
            errors_[0] = std::current_exception();
          }
        while (remaining_.load(std::memory_order_acquire) > 0)
          std::this_thread::yield();
        std::exception_ptr first;
        for (const std::exception_ptr &e : errors_)
          if (e && !first)
            first = e;
        busy_.store(false);
        if (first)
          std::rethrow_exception(first);
        return true;
      }

    private:
      // `seen`: the generation when the worker was created (its first job is the next).
      void work(const int index, unsigned seen)
      {
        bool spin = true;
        while (true)
          {
            // After a part, spin a little: the next section usually follows at once. A
            // worker the last section did not need sleeps at once (it would only take a
            // core from the threads that work).
            const auto spin_until =
              std::chrono::steady_clock::now() + std::chrono::microseconds(spin ? 200 : 0);
            while (generation_.load(std::memory_order_acquire) == seen &&
                   std::chrono::steady_clock::now() < spin_until)
              std::this_thread::yield();
            const std::function<void(int)> *job = nullptr;
            {
              std::unique_lock<std::mutex> lock(mutex_);
              wake_.wait(lock, [&] { return generation_.load() != seen; });
              seen = generation_.load();
              if (index < job_threads_)
                job = job_;
            }
            spin = job != nullptr;
            if (!job)
              continue;
            try
              {
                (*job)(index);
              }
            catch (...)
              {
                errors_[index] = std::current_exception();
              }
            remaining_.fetch_sub(1, std::memory_order_release);
          }
      }

      std::vector<std::thread> workers_;
      std::mutex mutex_;
      std::condition_variable wake_;
      std::atomic<unsigned> generation_{0};
      std::atomic<int> remaining_{0};
      std::atomic<bool> busy_{false};
      const std::function<void(int)> *job_ = nullptr;
      int job_threads_ = 0;
      std::vector<std::exception_ptr> errors_;
    };
  } // namespace

  void run_on_threads(const int n, const std::function<void(int)> &f)
  {
    if (n <= 1)
      {
        f(0);
        return;
      }
    // Deliberately never destroyed: joining the workers at exit would hang if exit() ran
    // inside a section (a worker parked at a barrier), and throw if called from a worker.
    static WorkerPool &pool = *new WorkerPool;
    if (!pool.try_run(n, f))
      run_on_new_threads(n, f);
  }
} // namespace rfm
