// lame_cylinder: verification of the RFM solver on the Lame cylinder.
//
// For each problem file of the Lame family (verification/problems/lame_*.json) and each
// polynomial degree p (N = (p+1)^2 coordinate functions per component), the driver
//   1. solves with rfm (half section, symmetry plane z = 0),
//   2. compares the stresses with the exact solution (verification/lame_exact.h):
//      relative L2 error of the stress tensor (Frobenius, weight r) on a quadrature
//      independent of the assembly rule, and the max error on a 41 x 41 grid,
//   3. reports the three functionals next to the exact value -U (the analog of the
//      paper's Table 1), the a-posteriori indicator |Phi_L - Phi_C| / |Phi_R| against
//      the true energy error, the inf-sup indicator, condition numbers and timings,
//   4. samples sigma_rr(r) at z = 0 for several N (the analog of the paper's Fig. 1)
//      and all stresses along the end z = a,
//   5. fits the exponential rate log10(error) ~ -k p, and
//   6. checks verification/tolerances.json (exit status 1 on a violated tolerance).
//
// Sample run:
//   build/bin/lame_cylinder --mode quick --output-dir build/verification
#include "problem/json_io.h"
#include "problem/problem.h"
#include "rfm/outline_model.h"
#include "verification/driver.h"
#include "verification/lame_errors.h"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace
{
  struct CaseFile
  {
    std::string name, file;
  };

  nlohmann::json profile(const rfm::OutlineModel &model, double z, int n, double r1, double r2,
                         const verification::LameCylinder &exact)
  {
    const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, r1, r2);
    const rfm::FieldValues f = model.evaluate(r, Eigen::VectorXd::Constant(n, z));
    nlohmann::json out = {{"z", z}, {"r", std::vector<double>(r.data(), r.data() + n)}};
    const char *names[] = {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"};
    for (int c = 0; c < 4; ++c)
      {
        std::vector<double> v(n), e(n);
        for (int k = 0; k < n; ++k)
          v[k] = f.sigma(k, c), e[k] = exact.stress(r[k], z)[c];
        out[names[c]] = v;
        out[std::string(names[c]) + "_exact"] = e;
      }
    return out;
  }

  // Least-squares slope of log10(error) against p over the points above the floor.
  double decades_per_degree(const std::vector<int> &p, const std::vector<double> &err,
                            int p_min, double floor)
  {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p[i] >= p_min && err[i] > floor)
        {
          const double x = p[i], y = std::log10(err[i]);
          sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
        }
    if (n < 2)
      return std::nan("");
    return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
  }
} // namespace

nlohmann::json run(const verification::DriverContext &context)
{
  const std::string &mode = context.mode, &source_dir = context.source_dir;
  const std::vector<CaseFile> cases = {
    {"paper", "lame_paper.json"},
    {"two_pressures", "lame_two_pressures.json"},
    {"nearly_incompressible", "lame_nearly_incompressible.json"},
    {"thick_wall", "lame_thick_wall.json"}};
  const int p_max = context.full() ? 20 : 14;
  const std::vector<int> fig1_degrees = {0, 1, 2, 3, 5, 7};

  nlohmann::json results = {{"driver", "lame_cylinder"}, {"mode", mode}};
  for (const CaseFile &cf : cases)
    {
      // 2. One case: the problem file, its exact solution, a sweep over p.
      const std::string path = source_dir + "/verification/problems/" + cf.file;
      const axisym::Problem problem = axisym::read_problem_file(path);
      const verification::LameCylinder exact = verification::exact_of(problem);
      const double phi_exact = -exact.strain_energy();
      nlohmann::json c = {{"problem_file", "verification/problems/" + cf.file},
                          {"problem", problem.source},
                          {"exact_functional", phi_exact}};
      fmt::print("\n== Lame cylinder, case {} ({}) ==\n", cf.name, cf.file);
      fmt::print("{:>3} {:>5} {:>13} {:>13} {:>13} {:>10} {:>10} {:>10} {:>9} {:>9} "
                 "{:>9} {:>9}\n",
                 "p", "N", "Phi_C [J]", "Phi_R [J]", "Phi_L [J]", "L2 err", "max err",
                 "indicator", "inf-sup", "cond K", "asm [s]", "solve [s]");
      std::vector<int> ps;
      std::vector<double> errs;
      for (int p = 0; p <= p_max; ++p)
        {
          rfm::DiscretizationOptions options = problem.rfm;
          options.degree = p;
          const rfm::OutlineModel model(problem, options);
          if (!model.ok())
            throw verification::NumericalFailure("case " + cf.name + ", p = " +
                                                 std::to_string(p) + ": " +
                                                 model.summary().message);
          const rfm::Functionals phi = model.functionals();
          const auto [l2, mx] = verification::stress_errors(model, exact);
          const rfm::SolveSummary &s = model.summary();
          const int n = (p + 1) * (p + 1);
          fmt::print("{:>3} {:>5} {:>13.8f} {:>13.8f} {:>13.8f} {:>10.3e} {:>10.3e} "
                     "{:>10.3e} {:>9.2e} {:>9.2e} {:>9.4f} {:>9.4f}\n",
                     p, n, phi.castigliano, phi.reissner, phi.lagrange, l2, mx,
                     phi.indicator(), s.inf_sup, s.cond_schur, model.assembly_seconds(),
                     model.solve_seconds());
          c["degrees"]["p" + std::to_string(p)] = {
            {"degree", p},
            {"N", n},
            {"stress_l2_relative", l2},
            {"stress_max_relative", mx},
            {"lagrange", phi.lagrange},
            {"castigliano", phi.castigliano},
            {"reissner", phi.reissner},
            {"castigliano_minus_reissner_relative",
             std::abs(phi.castigliano - phi.reissner) / std::abs(phi_exact)},
            {"lagrange_minus_exact_relative", (phi.lagrange - phi_exact) / std::abs(phi_exact)},
            {"reissner_error_relative", std::abs(phi.reissner - phi_exact) / std::abs(phi_exact)},
            {"indicator", phi.indicator()},
            {"inf_sup", s.inf_sup},
            {"cond_stress_block", s.cond_stress},
            {"cond_schur", s.cond_schur},
            {"assembly_s", model.assembly_seconds()},
            {"solve_s", model.solve_seconds()}};
          ps.push_back(p);
          errs.push_back(l2);

          // Fig. 1 analog: sigma_rr(r) at z = 0; stresses along the end at the top p.
          if (std::find(fig1_degrees.begin(), fig1_degrees.end(), p) != fig1_degrees.end())
            c["profiles_mid"].push_back(
              {{"degree", p}, {"N", n},
               {"profile", profile(model, 0.0, 61, exact.inner_radius, exact.outer_radius, exact)}});
          if (p == 7)
            c["profile_end_p7"] = profile(model, 0.5 * exact.length, 61, exact.inner_radius,
                                          exact.outer_radius, exact);
        }
      fmt::print("exact: Phi = -U = {:.8f} J per radian\n", phi_exact);
      c["decades_per_degree"] = decades_per_degree(ps, errs, 2, 1e-11);
      fmt::print("observed rate: stress L2 error falls by {:.2f} decades per degree\n",
                 c["decades_per_degree"].get<double>());
      results["cases"][cf.name] = c;
    }

  return results;
}

int main(int argc, char **argv)
{
  return verification::run_driver(argc, argv, "lame_cylinder", "Lame cylinder: RFM against the exact solution", run);
}
