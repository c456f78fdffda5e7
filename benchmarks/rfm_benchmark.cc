// Google Benchmark: RFM assembly and solve against the basis size N = (p+1)^2, for the
// Lame cylinder and the die problem at a fixed contact zone, beside a dense reference
// (Eigen GEMM and Cholesky of comparable sizes) measured in the same run, so that
// assembly and solve are reported as fractions of this machine's dense peak.
//
// FLOP counts (counters "flops" as rates):
//   assembly: 12 blocks of B^T diag(w) B', each 2 N^2 n_q (7 of R11, 5 of R12);
//   solve: Cholesky of 4N ((4N)^3/3), L^-1 R12 ((4N)^2 2N), K = Y^T Y ((2N)^2 4N),
//          Cholesky of 2N ((2N)^3/3): about 72 N^3.
//
//   build/bin/rfm_benchmark --benchmark_out=reports/data/benchmark_rfm.json
//                           --benchmark_out_format=json     (or: cmake --build --preset benchmarks)
#include "benchmarks/benchmark_problems.h"
#include "rfm/assembly.h"
#include "rfm/model.h"
#include "rfm/saddle_point_solver.h"

#include <Eigen/Cholesky>

#include <benchmark/benchmark.h>

namespace
{
  using benchmarks::make_problem;

  std::optional<double> zone(const axisym::Problem &p)
  {
    return p.die ? p.contact.half_width : std::nullopt;
  }

  void assembly(benchmark::State &state, bool die)
  {
    const axisym::Problem problem = make_problem(die);
    rfm::DiscretizationOptions o;
    o.degree = static_cast<int>(state.range(0));
    const rfm::DiscreteSpace space(rfm::Structures(rfm::build_section(problem, zone(problem))), o, problem.material);
    const double n = static_cast<double>(space.n_basis_functions());
    const double n_q = static_cast<double>(space.quadrature().n_points());
    for (auto _ : state)
      benchmark::DoNotOptimize(rfm::assemble_reissner_system(space, problem.material));
    state.counters["N"] = n;
    state.counters["n_unknowns"] = 6 * n;
    state.counters["n_quadrature_points"] = n_q;
    state.counters["flops"] = benchmark::Counter(24.0 * n * n * n_q, benchmark::Counter::kIsIterationInvariantRate);
    state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
  }

  void solve(benchmark::State &state, bool die)
  {
    const axisym::Problem problem = make_problem(die);
    rfm::DiscretizationOptions o;
    o.degree = static_cast<int>(state.range(0));
    const rfm::DiscreteSpace space(rfm::Structures(rfm::build_section(problem, zone(problem))), o, problem.material);
    const rfm::ReissnerSystem system = rfm::assemble_reissner_system(space, problem.material);
    rfm::SolverOptions so;
    so.compute_diagnostics = false;
    const double n = static_cast<double>(space.n_basis_functions());
    for (auto _ : state)
      benchmark::DoNotOptimize(rfm::solve_saddle_point(system, so));
    state.counters["N"] = n;
    state.counters["n_unknowns"] = 6 * n;
    state.counters["flops"] = benchmark::Counter(72.0 * n * n * n, benchmark::Counter::kIsIterationInvariantRate);
    state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
  }

  void BM_RfmAssemblyLame(benchmark::State &s) { assembly(s, false); }
  void BM_RfmSolveLame(benchmark::State &s) { solve(s, false); }
  void BM_RfmAssemblyDie(benchmark::State &s) { assembly(s, true); }
  void BM_RfmSolveDie(benchmark::State &s) { solve(s, true); }

  // Dense reference: C = A^T B with A, B of n_q x n (the shape of an assembly block).
  void BM_DenseGemm(benchmark::State &state)
  {
    const Eigen::Index n = state.range(0), n_q = 4 * state.range(0);
    const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n_q, n), b = Eigen::MatrixXd::Random(n_q, n);
    Eigen::MatrixXd c(n, n);
    for (auto _ : state)
      {
        c.noalias() = a.transpose() * b;
        benchmark::DoNotOptimize(c.data());
      }
    state.counters["n"] = static_cast<double>(n);
    state.counters["flops"] = benchmark::Counter(2.0 * n * n * n_q, benchmark::Counter::kIsIterationInvariantRate);
    state.SetComplexityN(n);
  }

  // Dense reference: Cholesky (LLT) of an SPD n x n matrix.
  void BM_DenseCholesky(benchmark::State &state)
  {
    const Eigen::Index n = state.range(0);
    const Eigen::MatrixXd r = Eigen::MatrixXd::Random(n, n);
    const Eigen::MatrixXd a = r * r.transpose() + n * Eigen::MatrixXd::Identity(n, n);
    for (auto _ : state)
      {
        Eigen::LLT<Eigen::MatrixXd> llt(a);
        benchmark::DoNotOptimize(llt.matrixLLT().data());
      }
    state.counters["n"] = static_cast<double>(n);
    state.counters["flops"] = benchmark::Counter(n * n * n / 3.0, benchmark::Counter::kIsIterationInvariantRate);
    state.SetComplexityN(n);
  }

  // One size sweep for all RFM benchmarks: p = 0..20 (N = 1..441).
  void degrees(benchmark::internal::Benchmark *b)
  {
    b->ArgNames({"p"});
    for (int p = 0; p <= 20; p += (p < 4 ? 1 : 2))
      b->Arg(p);
    b->Unit(benchmark::kMillisecond)->Complexity();
  }
  void dense_sizes(benchmark::internal::Benchmark *b)
  {
    b->ArgNames({"n"});
    for (int n : {64, 128, 256, 512, 1024, 1764})
      b->Arg(n);
    b->Unit(benchmark::kMillisecond)->Complexity();
  }
} // namespace

BENCHMARK(BM_RfmAssemblyLame)->Apply(degrees);
BENCHMARK(BM_RfmSolveLame)->Apply(degrees);
BENCHMARK(BM_RfmAssemblyDie)->Apply(degrees);
BENCHMARK(BM_RfmSolveDie)->Apply(degrees);
BENCHMARK(BM_DenseGemm)->Apply(dense_sizes);
BENCHMARK(BM_DenseCholesky)->Apply(dense_sizes);

BENCHMARK_MAIN();
