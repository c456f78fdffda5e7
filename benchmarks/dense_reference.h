// The dense reference of the benchmarks, and the host's caches: what the RFM kernels are
// compared with in the same run (rfm_benchmark.cc).
#pragma once

#include "rfm/hardware.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace benchmarks
{
  /// A well-conditioned SPD matrix R R^T + n I.
  inline Eigen::MatrixXd spd_matrix(Eigen::Index n)
  {
    const Eigen::MatrixXd r = Eigen::MatrixXd::Random(n, n);
    Eigen::MatrixXd a = r * r.transpose();
    a.diagonal().array() += static_cast<double>(n);
    return a;
  }

  /// Best rate of `run` (flops per call) over repetitions lasting at least 0.3 s in all.
  template <typename Run>
  double best_rate(double flops, Run run)
  {
    using clock = std::chrono::steady_clock;
    double best = 1e300, total = 0.0;
    for (int k = 0; k < 3 || total < 0.3; ++k)
      {
        const clock::time_point start = clock::now();
        run();
        const double s = std::chrono::duration<double>(clock::now() - start).count();
        best = std::min(best, s);
        total += s;
      }
    return flops / best;
  }

  /// GEMM C = A^T B with A, B of n_q x n: the shape of one assembly block.
  inline double gemm_flops_per_second(Eigen::Index n, Eigen::Index n_q)
  {
    const rfm::BlasThreadsOn all_threads; // the reference: what n_threads() cores can do
    const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n_q, n), b = Eigen::MatrixXd::Random(n_q, n);
    Eigen::MatrixXd c(n, n);
    return best_rate(2.0 * n * n * n_q, [&] { c.noalias() = a.transpose() * b; });
  }

  /// LLT of an SPD n x n matrix (a fresh factor each time, as the benchmark does).
  inline double cholesky_flops_per_second(Eigen::Index n)
  {
    const rfm::BlasThreadsOn all_threads;
    const Eigen::MatrixXd a = spd_matrix(n);
    return best_rate(n * n * n / 3.0, [&] {
      const Eigen::LLT<Eigen::MatrixXd> llt(a);
      if (llt.info() != Eigen::Success)
        throw std::runtime_error("reference Cholesky failed");
    });
  }

  struct CacheLevel
  {
    std::string name;
    long bytes;
  };

  /// Data caches of cpu0: sysconf where the C library knows them, else
  /// /sys/devices/system/cpu/cpu0/cache.
  std::vector<CacheLevel> host_caches();
} // namespace benchmarks
