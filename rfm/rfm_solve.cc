// rfm_solve: the R-function method with Reissner's mixed principle on one problem file.
//
// Solves the axisymmetric elastic problem of PROBLEM.json (DESIGN.md section 7) with
// N = (p + 1)^2 coordinate functions per unknown component and writes the result JSON:
// discretization, the Lagrange/Castigliano/Reissner functionals (J per radian), the
// contact half-width and force when the problem has a die, fields at the sample points,
// solver diagnostics and timings.
//
// Sample run:
//   build/bin/rfm_solve verification/problems/lame_paper.json --degree 7 --output lame.json
//
// Exit status: 0 success, 2 bad input (nothing written), 3 numerical failure.
#include "rfm/model.h"
#include "rfm/problem.h"
#include "rfm/result_io.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <iostream>

namespace
{
  nlohmann::json fields_to_json(const rfm::Problem &problem, const rfm::RfmModel &model)
  {
    nlohmann::json out = nlohmann::json::array();
    if (problem.samples.empty())
      return out;
    const Eigen::Index n = static_cast<Eigen::Index>(problem.samples.size());
    Eigen::VectorXd r(n), z(n);
    for (Eigen::Index k = 0; k < n; ++k)
      r[k] = problem.samples[k][0], z[k] = problem.samples[k][1];
    const rfm::FieldValues f = model.evaluate(r, z);
    for (Eigen::Index k = 0; k < n; ++k)
      out.push_back({{"r", r[k]},
                     {"z", z[k]},
                     {"u_r", f.u(k, 0)},
                     {"u_z", f.u(k, 1)},
                     {"sigma_rr", f.sigma(k, rfm::rr)},
                     {"sigma_zz", f.sigma(k, rfm::zz)},
                     {"sigma_tt", f.sigma(k, rfm::tt)},
                     {"sigma_rz", f.sigma(k, rfm::rz)}});
    return out;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      // 1. Command line.
      CLI::App app{"R-function method with Reissner's mixed principle (axisymmetric elasticity)"};
      std::string problem_path, output_path;
      int degree = -1;
      app.add_option("problem", problem_path, "problem file (JSON, SI units)")->required();
      app.add_option("--degree", degree, "polynomial degree p per variable: N = (p+1)^2")
        ->check(CLI::Range(0, 40));
      app.add_option("--output", output_path, "result file (JSON); default: stdout summary only");
      try
        {
          app.parse(argc, argv);
        }
      catch (const CLI::ParseError &e)
        {
          const int status = app.exit(e);
          return status == 0 ? 0 : 2;
        }

      // 2. Input: everything is checked before any work or output.
      rfm::Problem problem = rfm::read_problem_file(problem_path);
      if (degree >= 0)
        problem.rfm.degree = degree;
      if (!output_path.empty())
        rfm::check_output_path("--output", output_path);
      if (problem.die && problem.contact.method != "fixed")
        throw rfm::InputError("problem file: contact.method = \"" + problem.contact.method +
                              "\": rfm_solve implements \"fixed\" only so far (the "
                              "iterative and max-force searches are not built yet)");
      const std::optional<double> half_width =
        problem.die ? std::optional<double>(problem.contact.half_width.value_or(
                        problem.geometry.half_length()))
                    : std::nullopt;

      // 3. Solve.
      const int p = problem.rfm.degree;
      fmt::print(stderr, "rfm_solve: degree p = {}, N = {} per component\n", p, (p + 1) * (p + 1));
      const rfm::RfmModel model(problem, problem.rfm, half_width);
      const rfm::SolveSummary &s = model.summary();

      nlohmann::json result;
      result["solver"] = "rfm";
      result["problem"] = problem.source;
      const auto n_basis = model.space().n_basis_functions();
      result["discretization"] = {
        {"degree", p},
        {"N", n_basis},
        {"unknowns", 6 * n_basis},
        {"stress_unknowns", 4 * n_basis},
        {"displacement_unknowns", 2 * n_basis},
        {"quadrature_points", model.space().quadrature().n_points()},
        {"gauss_points_per_cell", p + problem.rfm.extra_gauss_points},
        {"n_graded_layers", problem.rfm.n_graded_layers},
        {"grading_ratio", problem.rfm.grading_ratio},
        {"section", "upper half z in [0, length/2], symmetry plane z = 0"}};
      result["diagnostics"] = {{"status", s.success ? "ok" : "failed"},
                               {"message", s.message},
                               {"rcond_stress_block", s.rcond_stress},
                               {"rcond_schur_complement", s.rcond_schur},
                               {"cond_stress_block", s.cond_stress},
                               {"cond_schur_complement", s.cond_schur},
                               {"inf_sup_indicator", s.inf_sup}};
      result["timing"] = {{"assembly_s", model.assembly_seconds()},
                          {"solve_s", model.solve_seconds()}};
      if (!s.success)
        {
          if (!output_path.empty())
            rfm::write_json_atomically(output_path, result);
          fmt::print(stderr, "rfm_solve: numerical failure: {}\n", s.message);
          return 3;
        }

      // 4. Post-processing.
      const rfm::Functionals phi = model.solution().functionals();
      result["functionals"] = {{"lagrange", phi.lagrange},
                               {"castigliano", phi.castigliano},
                               {"reissner", phi.reissner},
                               {"indicator", phi.indicator()},
                               {"units", "J per radian"}};
      if (half_width)
        {
          const rfm::ContactForce force = model.contact_force();
          result["contact"] = {{"method", problem.contact.method},
                               {"half_width", *half_width},
                               {"half_width_ratio", *half_width / problem.geometry.half_length()},
                               {"force", force.domain},
                               {"force_trace", force.trace}};
        }
      result["samples"] = fields_to_json(problem, model);

      bool finite = std::isfinite(phi.lagrange) && std::isfinite(phi.castigliano) &&
                    std::isfinite(phi.reissner);
      if (!finite)
        {
          result["diagnostics"]["status"] = "failed";
          result["diagnostics"]["message"] = "non-finite functional";
        }
      if (!output_path.empty())
        rfm::write_json_atomically(output_path, result);
      fmt::print(stderr, "rfm_solve: Phi_L = {:.6e}, Phi_C = {:.6e}, Phi_R = {:.6e} J/rad; "
                         "assembly {:.3f} s, solve {:.3f} s\n",
                 phi.lagrange, phi.castigliano, phi.reissner, model.assembly_seconds(),
                 model.solve_seconds());
      if (!finite)
        {
          fmt::print(stderr, "rfm_solve: numerical failure: non-finite functional\n");
          return 3;
        }
      if (output_path.empty())
        std::cout << result.dump(2) << '\n';
      return 0;
    }
  catch (const rfm::InputError &e)
    {
      std::cerr << "rfm_solve: error: " << e.what() << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "rfm_solve: error: " << e.what() << '\n';
      return 3;
    }
}
