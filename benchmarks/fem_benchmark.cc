// Google Benchmark: the deal.II FEM reference against DoFs (Q2, refinement levels), for
// the Lame cylinder and the die problem at a fixed contact zone (bilateral, the same
// problems as rfm_benchmark). Reported times are per solve; the counters split them into
// assembly and linear solve as measured inside fem::solve.
#include "fem_reference/axisymmetric_fem.h"
#include "rfm/problem.h"

#include <benchmark/benchmark.h>

namespace
{
  rfm::Problem make_problem(bool die)
  {
    nlohmann::json j = {
      {"geometry", {{"inner_radius", 0.1}, {"outer_radius", 0.2}, {"length", 0.4}}},
      {"material", {{"youngs_modulus", 2.1e11}, {"poisson_ratio", 0.3}}}};
    if (die)
      j["die"] = {{"indentation", 1e-6}}, j["contact"] = {{"method", "fixed"}, {"half_width", 0.106}};
    else
      j["loading"] = {{"inner_pressure", 1e7}};
    return rfm::parse_problem(j);
  }

  void fem_solve(benchmark::State &state, bool die)
  {
    const rfm::Problem problem = make_problem(die);
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
