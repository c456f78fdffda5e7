// Google Benchmark: the deal.II FEM reference against DoFs (Q2, refinement levels), for
// the Lame cylinder and the die problem at a fixed contact zone (bilateral, the same
// problems as rfm_benchmark). Reported times are per solve; the counters split them into
// assembly and linear solve as measured inside fem::solve.
#include "fem_reference/axisymmetric_fem.h"

#include "benchmarks/benchmark_problems.h"

#include <benchmark/benchmark.h>

namespace
{
  using benchmarks::make_problem;

  void fem_solve(benchmark::State &state, bool die)
  {
    const axisym::Problem problem = make_problem(die);
    fem::FemOptions o = fem::options_from_problem(problem);
    o.refinements = static_cast<int>(state.range(0));
    o.progress = false;
    fem::FemResult r;
    for (auto _ : state)
      {
        r = fem::solve(problem, o);
        if (!r.success)
          state.SkipWithError(r.message.c_str());
      }
    state.counters["dofs"] = static_cast<double>(r.n_dofs);
    state.counters["assembly_s"] = r.assembly_seconds;
    state.counters["solve_s"] = r.solve_seconds;
    state.SetComplexityN(static_cast<benchmark::IterationCount>(r.n_dofs));
  }

  void BM_FemLame(benchmark::State &s) { fem_solve(s, false); }
  void BM_FemDie(benchmark::State &s) { fem_solve(s, true); }

  void levels(benchmark::internal::Benchmark *b)
  {
    b->ArgNames({"L"})->DenseRange(0, 5)->Unit(benchmark::kMillisecond)->Complexity();
  }
} // namespace

BENCHMARK(BM_FemLame)->Apply(levels);
BENCHMARK(BM_FemDie)->Apply(levels);

BENCHMARK_MAIN();
