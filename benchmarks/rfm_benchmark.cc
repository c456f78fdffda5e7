// Google Benchmark: RFM assembly and solve against the basis size N = (p+1)^2, for the
// Lame cylinder and the die problem at a fixed contact zone, both on the outline model (the
// only RFM model; the rectangle's tensor rule and Legendre basis), beside a dense reference
// (Eigen GEMM and Cholesky) measured in the same run at the matching size, so that
// assembly and solve are reported as fractions of this machine's dense speed.
//
// FLOP counts (counters "flops" as rates; nominal, the same before and after the symmetric
// shortcuts of the assembly):
//   assembly: 12 blocks of B^T diag(w) B', each 2 N^2 n_q (7 of R11, 5 of R12);
//   solve: Cholesky of 4N ((4N)^3/3), L^-1 R12 ((4N)^2 2N), K = Y^T Y ((2N)^2 4N),
//          Cholesky of 2N ((2N)^3/3): about 72 N^3.
// Matching sizes: assembly against C = A^T B with A, B of n_q x N (one assembly block on
// the same quadrature); solve against the Cholesky of n = 4N (the stress block M).
//
// BM_SectionBasis: the section basis's evaluation in double, long double and double-double
// (points per second), on the thick sphere's quarter annulus.
//
// Counters per point: fraction_of_gemm / fraction_of_cholesky (this point's rate over the
// reference's rate, both measured in this process), working_set_bytes (the matrices the
// kernel reads and writes), threads. Context: the host's cache sizes and the thread count.
//
//   build/bin/rfm_benchmark --benchmark_out=reports/data/benchmark_rfm.json
//                           --benchmark_out_format=json     (or: cmake --build --preset benchmarks)
//   build/bin/rfm_benchmark --threads=2    (or OMP_NUM_THREADS=2; default: all cores)
#include "benchmarks/benchmark_problems.h"
#include "benchmarks/dense_reference.h"
#include "rfm/allocator.h"
#include "rfm/contact/contact.h"
#include "rfm/hardware.h"
#include "rfm/outline_model.h"
#include "rfm/quadrature/section_quadrature.h"
#include "rfm/spaces/section_basis.h"
#include "problem/problem.h"
#include "problem/test_problems.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>

namespace
{
  using benchmarks::make_problem;

  // The model a user's solve builds: the outline model of the problem's body, with the die's
  // zone [0, c] on `outer` (contact.h) for the die problem.
  std::unique_ptr<rfm::OutlineModel> solved_model(const axisym::Problem &p, const int degree)
  {
    rfm::DiscretizationOptions o = p.rfm;
    o.degree = degree;
    rfm::SolverOptions so;
    so.compute_diagnostics = false; // as a user's solve would not need them timed
    if (p.die)
      return rfm::solve_cylinder_zone(p, o, *p.contact.half_width, so);
    return std::make_unique<rfm::OutlineModel>(p, o, so);
  }

  // The interior rule's size without a solve: the tensor rule of the split rectangle.
  Eigen::Index quadrature_points(const axisym::Problem &p, const int degree)
  {
    std::vector<rfm::DieZone> zones;
    if (p.die)
      zones.push_back({"outer", 0.0, *p.contact.half_width, p.die->indentation});
    const rfm::OutlineStructures s(*p.body, degree, zones);
    return rfm::rectangle_gauss(s.body().outline, degree + p.rfm.extra_gauss_points).n_points();
  }

  // Reference rates, measured once per size in this process and shared by every point
  // that matches it.
  double gemm_rate(Eigen::Index n, Eigen::Index n_q)
  {
    static std::map<std::pair<Eigen::Index, Eigen::Index>, double> rates;
    auto it = rates.find({n, n_q});
    if (it == rates.end())
      it = rates.emplace(std::make_pair(n, n_q), benchmarks::gemm_flops_per_second(n, n_q)).first;
    return it->second;
  }
  double cholesky_rate(Eigen::Index n)
  {
    static std::map<Eigen::Index, double> rates;
    auto it = rates.find(n);
    if (it == rates.end())
      it = rates.emplace(n, benchmarks::cholesky_flops_per_second(n)).first;
    return it->second;
  }

  // Assembly (OutlineModel::assembly_seconds: the rules, the basis and structure values,
  // the system) and solve (solve_seconds) of the same model, timed by the model itself
  // (manual time): each iteration builds and solves one model.
  void assembly(benchmark::State &state, bool die)
  {
    const axisym::Problem problem = make_problem(die);
    const int p = static_cast<int>(state.range(0));
    // One untimed solve: the heap then holds the system's memory, as in a driver's second
    // solve (a single timed iteration of a large p would otherwise time the page faults).
    std::unique_ptr<rfm::OutlineModel> m = solved_model(problem, p);
    for (auto _ : state)
      {
        m = solved_model(problem, p);
        state.SetIterationTime(m->assembly_seconds());
      }
    const Eigen::Index n = m->n_basis_functions(), n_q = m->n_quadrature_points();
    const double flops = 24.0 * n * n * n_q;
    const double n_s = static_cast<double>(m->n_kept_unknowns()[0]);
    const double n_u = static_cast<double>(m->n_kept_unknowns()[1]);
    state.counters["N"] = static_cast<double>(n);
    state.counters["n_unknowns"] = n_s + n_u;
    state.counters["n_quadrature_points"] = static_cast<double>(n_q);
    state.counters["flops"] = benchmark::Counter(flops, benchmark::Counter::kIsIterationInvariantRate);
    // basis values and derivatives at the points (3 n_q N) and the system written.
    state.counters["working_set_bytes"] = 8.0 * (3.0 * n_q * n + n_s * n_s + n_s * n_u);
    state.counters["threads"] = rfm::n_threads();
    // Google Benchmark divides kIsIterationInvariantRate counters by the elapsed time; a
    // kIsIterationInvariantRate counter of flops / reference rate gives the fraction.
    state.counters["fraction_of_gemm"] =
      benchmark::Counter(flops / gemm_rate(n, n_q), benchmark::Counter::kIsIterationInvariantRate);
    state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
  }

  void solve(benchmark::State &state, bool die)
  {
    const axisym::Problem problem = make_problem(die);
    const int p = static_cast<int>(state.range(0));
    std::unique_ptr<rfm::OutlineModel> m = solved_model(problem, p); // untimed, as above
    for (auto _ : state)
      {
        m = solved_model(problem, p);
        state.SetIterationTime(m->solve_seconds());
      }
    const Eigen::Index n = m->n_basis_functions();
    const double flops = 72.0 * n * n * n;
    const double n_s = static_cast<double>(m->n_kept_unknowns()[0]);
    const double n_u = static_cast<double>(m->n_kept_unknowns()[1]);
    state.counters["N"] = static_cast<double>(n);
    state.counters["n_unknowns"] = n_s + n_u;
    state.counters["flops"] = benchmark::Counter(flops, benchmark::Counter::kIsIterationInvariantRate);
    // the system read (R11, R12), and the factors of M and K.
    state.counters["working_set_bytes"] = 8.0 * (2.0 * n_s * n_s + n_s * n_u + n_u * n_u);
    state.counters["threads"] = rfm::n_threads();
    state.counters["fraction_of_cholesky"] =
      benchmark::Counter(flops / cholesky_rate(4 * n), benchmark::Counter::kIsIterationInvariantRate);
    state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
  }

  void BM_RfmAssemblyLame(benchmark::State &s) { assembly(s, false); }
  void BM_RfmSolveLame(benchmark::State &s) { solve(s, false); }
  void BM_RfmAssemblyDie(benchmark::State &s) { assembly(s, true); }
  void BM_RfmSolveDie(benchmark::State &s) { solve(s, true); }

  // Dense reference: C = A^T B with A, B of n_q x n (the shape of an assembly block).
  void BM_DenseGemm(benchmark::State &state)
  {
    const Eigen::Index n = state.range(0), n_q = state.range(1);
    const rfm::BlasThreadsOn all_threads;
    const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n_q, n), b = Eigen::MatrixXd::Random(n_q, n);
    Eigen::MatrixXd c(n, n);
    for (auto _ : state)
      {
        c.noalias() = a.transpose() * b;
        benchmark::DoNotOptimize(c.data());
      }
    state.counters["n"] = static_cast<double>(n);
    state.counters["flops"] = benchmark::Counter(2.0 * n * n * n_q, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["threads"] = rfm::n_threads();
    state.SetComplexityN(n);
  }

  // Dense reference: Cholesky (LLT) of an SPD n x n matrix.
  void BM_DenseCholesky(benchmark::State &state)
  {
    const Eigen::Index n = state.range(0);
    const rfm::BlasThreadsOn all_threads;
    const Eigen::MatrixXd a = benchmarks::spd_matrix(n);
    for (auto _ : state)
      {
        Eigen::LLT<Eigen::MatrixXd> llt(a);
        benchmark::DoNotOptimize(llt.matrixLLT().data());
      }
    state.counters["n"] = static_cast<double>(n);
    state.counters["flops"] = benchmark::Counter(n * n * n / 3.0, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["threads"] = rfm::n_threads();
    state.SetComplexityN(n);
  }

  // The section-orthonormal basis's values and both derivatives (SectionPolynomialBasis::
  // evaluate) on the thick sphere's quarter annulus (59 % of its box), whose double
  // recurrence is noisy from p = 18 (section_basis.h): in double, in long double (the former
  // extended precision) and in double-double (the present one), at the points of the section
  // rule of p + 3 points a direction. items_per_second: points per second.
  void BM_SectionBasis(benchmark::State &state)
  {
    using Precision = rfm::SectionPolynomialBasis::Precision;
    const int p = static_cast<int>(state.range(0));
    const Precision precision = static_cast<Precision>(state.range(1));
    const axisym::Outline outline = axisym::parse_problem(axisym::testing::thick_sphere()).body->outline;
    const axisym::BoundingBox b = outline.bounding_box();
    rfm::SectionQuadratureOptions qo;
    qo.n_points = p + 2;
    const rfm::Quadrature2D samples = rfm::section_gauss(outline, qo);
    qo.n_points = p + 3;
    const rfm::Quadrature2D points = rfm::section_gauss(outline, qo);
    const rfm::SectionPolynomialBasis basis(p, p, b.r_min, b.r_max, b.z_min, b.z_max, samples.r, samples.z,
                                            samples.weights.cwiseProduct(samples.r));
    for (auto _ : state)
      benchmark::DoNotOptimize(basis.evaluate(points.r, points.z, true, precision));
    state.SetItemsProcessed(state.iterations() * points.n_points());
    state.counters["N"] = static_cast<double>(basis.n_basis_functions());
    state.counters["orthonormality_error"] = basis.orthonormality_error();
  }
  void section_basis_cases(benchmark::internal::Benchmark *b)
  {
    using Precision = rfm::SectionPolynomialBasis::Precision;
    b->ArgNames({"p", "precision"});
    for (const int p : {16, 20, 24})
      for (const Precision precision : {Precision::double_precision, Precision::long_double, Precision::double_double})
        b->Args({p, static_cast<long>(precision)});
    b->Unit(benchmark::kMillisecond);
  }

  // One size sweep for all RFM benchmarks: p = 0..20 (N = 1..441).
  void degrees(benchmark::internal::Benchmark *b)
  {
    b->ArgNames({"p"});
    for (int p = 0; p <= 20; p += (p < 4 ? 1 : 2))
      b->Arg(p);
    b->Unit(benchmark::kMillisecond)->UseManualTime()->Complexity();
  }
  // The references at the sizes of the sweep: GEMM on the quadratures of both problems,
  // Cholesky of n = 4N.
  void gemm_sizes(benchmark::internal::Benchmark *b)
  {
    b->ArgNames({"n", "n_q"});
    for (int p = 4; p <= 20; p += 2)
      for (bool die : {false, true})
        {
          const axisym::Problem problem = make_problem(die);
          b->Args({static_cast<long>((p + 1) * (p + 1)), quadrature_points(problem, p)});
        }
    b->Unit(benchmark::kMillisecond);
  }
  void cholesky_sizes(benchmark::internal::Benchmark *b)
  {
    b->ArgNames({"n"});
    for (int p = 4; p <= 20; p += 2)
      b->Arg(4 * (p + 1) * (p + 1));
    b->Unit(benchmark::kMillisecond)->Complexity();
  }

  std::string cache_context()
  {
    std::string s;
    for (const benchmarks::CacheLevel &c : benchmarks::host_caches())
      s += (s.empty() ? "" : ", ") + c.name + " " + std::to_string(c.bytes / 1024) + " KiB";
    return s;
  }
} // namespace

BENCHMARK(BM_RfmAssemblyLame)->Apply(degrees);
BENCHMARK(BM_RfmSolveLame)->Apply(degrees);
BENCHMARK(BM_RfmAssemblyDie)->Apply(degrees);
BENCHMARK(BM_RfmSolveDie)->Apply(degrees);
BENCHMARK(BM_DenseGemm)->Apply(gemm_sizes);
BENCHMARK(BM_DenseCholesky)->Apply(cholesky_sizes);
BENCHMARK(BM_SectionBasis)->Apply(section_basis_cases);

// Our own main: --threads=N (before Google Benchmark's flags), the allocator setting of
// the drivers, and the host description in the context.
int main(int argc, char **argv)
{
  int threads = 0;
  int kept = 1;
  for (int i = 1; i < argc; ++i)
    {
      if (std::strncmp(argv[i], "--threads=", 10) == 0)
        threads = std::stoi(argv[i] + 10);
      else
        argv[kept++] = argv[i];
    }
  argc = kept;
  if (threads > 0)
    rfm::set_n_threads(threads);
  rfm::keep_freed_matrices_in_heap();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::AddCustomContext("rfm_threads", std::to_string(rfm::n_threads()));
  benchmark::AddCustomContext("rfm_threading", rfm::threading_backend());
  benchmark::AddCustomContext("host_caches", cache_context());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
