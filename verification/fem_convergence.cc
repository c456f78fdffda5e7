// fem_convergence: mesh (and penalty) convergence study of the FEM reference.
//
// Runs fem::solve on levels L = 0..max on PROBLEM.json and prints deal.II ConvergenceTables:
//  * no die (Lame cylinder): the r-weighted L2 stress error against the exact solution
//    (verification/lame_exact.h) and the energy error, with observed rates (h halves per row);
//  * die: P (consistent reaction), P from the traces, c/a, the differences between levels with
//    their observed rates and a Richardson extrapolation of P from the last three levels;
//    for the unilateral methods also a penalty study at the finest level (kappa factors).
//
// Sample run:
//   build/bin/fem_convergence verification/problems/die_unilateral.json --max-refinements 4
//
// Outline problems (DESIGN.md 7.1) are refused (exit 2): run fem_solve per level for them.
//
// Exit status: 0 success, 2 bad input, 3 numerical failure (the study so far is written).
#include "fem_reference/axisymmetric_fem.h"
#include "problem/problem.h"
#include "problem/json_io.h"
#include "verification/lame_exact.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cmath>
#include <iostream>

namespace
{
  struct Extrapolation
  {
    double value = NAN, rate = NAN, error_estimate = NAN;
  };

  /// Richardson from the last three values of a sequence on meshes halved each step:
  /// rate = log2(|d_{L-1}| / |d_L|), value = x_L + d_L / (2^rate - 1); error estimate
  /// |value - x_L|. With two values only the difference |d_L| is the estimate.
  Extrapolation richardson(const std::vector<double> &x)
  {
    Extrapolation e;
    const std::size_t n = x.size();
    if (n < 2)
      return e;
    const double d2 = x[n - 1] - x[n - 2];
    e.error_estimate = std::abs(d2);
    if (n < 3)
      return e;
    const double d1 = x[n - 2] - x[n - 3];
    if (d1 == 0 || d2 == 0 || d1 * d2 < 0)
      return e;
    e.rate = std::log2(std::abs(d1 / d2));
    if (e.rate > 0.1)
      {
        e.value = x[n - 1] + d2 / (std::pow(2.0, e.rate) - 1);
        e.error_estimate = std::abs(e.value - x[n - 1]);
      }
    return e;
  }

  std::vector<double> differences(const std::vector<double> &x)
  {
    std::vector<double> d;
    for (std::size_t i = 1; i < x.size(); ++i)
      d.push_back(std::abs(x[i] - x[i - 1]));
    return d;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      // 1. Command line and input.
      CLI::App app{"Convergence study of the deal.II FEM reference"};
      std::string problem_path, output_path;
      int max_level = 4, degree = -1;
      std::vector<double> penalty_factors{1e1, 1e2, 1e3, 1e4};
      app.add_option("problem", problem_path, "problem file (JSON, SI units)")->required();
      app.add_option("--max-refinements", max_level, "finest level L")
        ->check(CLI::Range(1, axisym::ranges::fem_refinements.hi));
      app.add_option("--degree", degree, "element degree p (default fem.degree)")
        ->check(CLI::Range(axisym::ranges::fem_degree.lo, axisym::ranges::fem_degree.hi));
      app.add_option("--penalty-factors", penalty_factors,
                     "kappa factors of the penalty study at the finest level (comma list)")
        ->delimiter(',');
      app.add_option("--output", output_path, "study as JSON");
      try
        {
          app.parse(argc, argv);
        }
      catch (const CLI::ParseError &e)
        {
          const int status = app.exit(e);
          return status == 0 ? 0 : 2;
        }
      const axisym::Problem problem = axisym::read_problem_file(problem_path);
      // The study compares with the Lame solution or studies the die: the hollow-cylinder form.
      // (An outline problem used to run against a Lame solution built from absent pressures.)
      if (!problem.legacy_cylinder)
        throw axisym::InputError("problem file " + problem_path +
                                 ": fem_convergence studies the hollow-cylinder form only "
                                 "(geometry.inner_radius, ...); for an outline section run "
                                 "fem_solve --refinements L");
      fem::FemOptions base = fem::options_from_problem(problem);
      if (degree > 0)
        base.degree = degree;
      base.progress = false;
      for (const double f : penalty_factors)
        if (!(f > 0) || !std::isfinite(f))
          throw axisym::InputError("--penalty-factors: " + std::to_string(f) + " must be > 0");
      if (!output_path.empty())
        axisym::check_output_path("--output", output_path);
      const double a = problem.geometry.half_length();
      const bool unilateral = problem.die && problem.contact.method != "fixed";

      std::optional<verification::LameCylinder> exact;
      fem::StressFunction exact_stress;
      if (!problem.die)
        {
          exact = verification::LameCylinder{
            problem.geometry.inner_radius,  problem.geometry.outer_radius,
            problem.geometry.length,        problem.material.youngs_modulus,
            problem.material.poisson_ratio, problem.loading->inner_pressure,
            problem.loading->outer_pressure};
          exact_stress = [&](double r, double z) { return exact->stress(r, z); };
        }
      fmt::print("fem_convergence: Q{} elements, levels 0..{}, {}\n", base.degree, max_level,
                 problem.die ? "die, contact.method = " + problem.contact.method
                             : std::string("Lame cylinder (exact solution known)"));

      // 2. Mesh study.
      nlohmann::json study;
      study["problem"] = problem.source;
      study["degree"] = base.degree;
      study["levels"] = nlohmann::json::array();
      std::vector<double> level_col, cells, dofs, seconds, force, trace, ratio, ratio_gap, error, max_error,
        energy_error,
        lagrange, iterations;
      bool failed = false;
      for (int level = 0; level <= max_level && !failed; ++level)
        {
          fem::FemOptions o = base;
          o.refinements = level;
          const fem::FemResult r = fem::solve(problem, o, exact_stress);
          if (!r.success)
            {
              fmt::print(stderr, "fem_convergence: level {}: {}\n", level, r.message);
              failed = true;
            }
          level_col.push_back(level);
          cells.push_back(static_cast<double>(r.n_cells));
          dofs.push_back(static_cast<double>(r.n_dofs));
          seconds.push_back(r.total_seconds);
          lagrange.push_back(r.functionals.lagrange);
          nlohmann::json row = {{"level", level},
                                {"cells", r.n_cells},
                                {"dofs", r.n_dofs},
                                {"success", r.success},
                                {"lagrange", r.functionals.lagrange},
                                {"castigliano", r.functionals.castigliano},
                                {"reissner", r.functionals.reissner},
                                {"seconds", r.total_seconds}};
          if (exact && r.success)
            {
              error.push_back(*r.stress_l2_error / *r.stress_l2_norm);
              const double u = -exact->strain_energy();
              energy_error.push_back(std::abs(r.functionals.lagrange - u) / std::abs(u));
              row["stress_l2_relative_error"] = error.back();
              max_error.push_back(*r.stress_max_error / *r.stress_max_norm);
              row["stress_max_relative_error"] = max_error.back();
              row["lagrange_relative_error"] = energy_error.back();
            }
          if (r.contact)
            {
              force.push_back(r.contact->force);
              trace.push_back(r.contact->force_trace);
              ratio.push_back(r.contact->half_width / a);
              ratio_gap.push_back(r.contact->half_width_gap / a);
              row["half_width_gap_ratio"] = ratio_gap.back();
              iterations.push_back(r.contact->active_set_iterations);
              row["force"] = r.contact->force;
              row["force_trace"] = r.contact->force_trace;
              row["half_width_ratio"] = ratio.back();
              row["active_set_iterations"] = r.contact->active_set_iterations;
              row["penalty"] = r.contact->penalty;
            }
          study["levels"].push_back(row);
          fmt::print(stderr, "fem_convergence: level {} done ({} dofs, {:.2f} s)\n", level,
                     r.n_dofs, r.total_seconds);
        }

      std::vector<fem::TableColumn> cols{{"L", level_col, 0, false, false},
                                         {"cells", cells, 0, false, false},
                                         {"dofs", dofs, 0, false, false}};
      if (exact)
        {
          cols.push_back({"|s-s_h|/|s|", error, 3, true, true});
          cols.push_back({"max|s-s_h|/max|s|", max_error, 3, true, true});
          cols.push_back({"|Phi_L+U|/U", energy_error, 3, true, true});
          cols.push_back({"Phi_L [J/rad]", lagrange, 8, true, false});
        }
      else
        {
          cols.push_back({"P [N]", force, 7, true, false});
          cols.push_back({"P_trace [N]", trace, 7, true, false});
          cols.push_back({"c/a", ratio, 5, false, false});
          if (unilateral)
            cols.push_back({"c_gap/a", ratio_gap, 5, false, false});
          cols.push_back({"Phi_L [J/rad]", lagrange, 6, true, false});
          // Differences start at L = 1 (rates need consecutive entries).
          std::vector<fem::TableColumn> dcols{
            {"L", std::vector<double>(level_col.begin() + 1, level_col.end()), 0, false, false},
            {"|P_L-P_L-1| [N]", differences(force), 3, true, true},
            {"|PhiL_L-PhiL_L-1|", differences(lagrange), 3, true, true}};
          if (unilateral)
            dcols.push_back({"|c_L-c_L-1|/a", differences(ratio), 3, true, true});
          if (level_col.size() > 1)
            {
              cols.push_back({"time [s]", seconds, 2, false, false});
              fmt::print("{}\n", fem::format_convergence_table(cols));
              fmt::print("Differences between levels (rates = observed orders in h):\n{}\n",
                         fem::format_convergence_table(dcols));
              cols.pop_back();
            }
          const Extrapolation ep = richardson(force), ec = richardson(ratio),
                              el = richardson(lagrange);
          study["extrapolation"] = {{"force", ep.value},
                                    {"force_rate", ep.rate},
                                    {"force_error_estimate", ep.error_estimate},
                                    {"half_width_ratio", ec.value},
                                    {"half_width_ratio_rate", ec.rate},
                                    {"half_width_ratio_error_estimate", ec.error_estimate},
                                    {"lagrange", el.value},
                                    {"lagrange_rate", el.rate}};
          fmt::print("Richardson (last three levels; nan: differences not monotone): P = {:.7g} N "
                     "(rate {:.2f}, est. error {:.2g} N = {:.2g} %), Phi_L = {:.7g} J/rad "
                     "(rate {:.2f})\n",
                     ep.value, ep.rate, ep.error_estimate, 100 * ep.error_estimate / force.back(),
                     el.value, el.rate);
          if (unilateral)
            fmt::print("  c/a = {:.5f} (rate {:.2f}, est. error {:.2g}; last level {:.5f})\n",
                       ec.value, ec.rate, ec.error_estimate, ratio.back());
        }
      if (exact)
        {
          cols.push_back({"time [s]", seconds, 2, false, false});
          fmt::print("{}\n", fem::format_convergence_table(cols));
        }

      // 3. Penalty study at the finest level (unilateral only).
      if (unilateral && !failed)
        {
          std::vector<double> factor_col, kappa_col, p_col, c_col, cg_col, pen_col, it_col, t_col;
          study["penalty_study"] = nlohmann::json::array();
          for (const double factor : penalty_factors)
            {
              fem::FemOptions o = base;
              o.refinements = max_level;
              o.penalty_factor = factor;
              const fem::FemResult r = fem::solve(problem, o);
              if (!r.success)
                {
                  fmt::print(stderr, "fem_convergence: penalty factor {}: {}\n", factor, r.message);
                  failed = true;
                }
              factor_col.push_back(factor);
              kappa_col.push_back(r.contact->penalty);
              p_col.push_back(r.contact->force);
              c_col.push_back(r.contact->half_width / a);
              cg_col.push_back(r.contact->half_width_gap / a);
              pen_col.push_back(r.contact->max_penetration);
              it_col.push_back(r.contact->active_set_iterations);
              t_col.push_back(r.total_seconds);
              study["penalty_study"].push_back({{"penalty_factor", factor},
                                                {"penalty", r.contact->penalty},
                                                {"success", r.success},
                                                {"force", r.contact->force},
                                                {"force_trace", r.contact->force_trace},
                                                {"half_width_ratio", c_col.back()},
                                                {"half_width_gap_ratio", cg_col.back()},
                                                {"max_penetration", pen_col.back()},
                                                {"active_set_iterations", it_col.back()},
                                                {"seconds", r.total_seconds}});
              fmt::print(stderr, "fem_convergence: penalty factor {:g} done ({:.2f} s)\n", factor,
                         r.total_seconds);
            }
          std::vector<double> dp;
          for (const double p : p_col)
            dp.push_back(std::abs(p - p_col.back()));
          fmt::print("Penalty study at L = {} (kappa = factor * E / h_min):\n{}\n", max_level,
                     fem::format_convergence_table({{"factor", factor_col, 1, true, false},
                                                    {"kappa [Pa/m]", kappa_col, 3, true, false},
                                                    {"P [N]", p_col, 7, true, false},
                                                    {"|P-P_last| [N]", dp, 3, true, false},
                                                    {"c/a", c_col, 5, false, false},
                                                    {"c_gap/a", cg_col, 5, false, false},
                                                    {"max pen. [m]", pen_col, 3, true, false},
                                                    {"iters", it_col, 0, false, false},
                                                    {"time [s]", t_col, 2, false, false}}));
        }
      study["success"] = !failed;
      if (!output_path.empty())
        axisym::write_json_atomically(output_path, study);
      return failed ? 3 : 0;
    }
  catch (const axisym::InputError &e)
    {
      std::cerr << "fem_convergence: error: " << e.what() << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "fem_convergence: error: " << e.what() << '\n';
      return 3;
    }
}
