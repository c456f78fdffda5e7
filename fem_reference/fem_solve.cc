// fem_solve: the deal.II finite-element reference on one problem file.
//
// Solves the axisymmetric elastic problem of PROBLEM.json with Q_p elements (p = fem.degree)
// on the gmsh mesh of level L (fem.refinements or --refinements) of the section's outline:
// the hollow cylinder of DESIGN.md section 7 as its half section z in [0, a] (mirrored), or
// any section given by its outline (DESIGN.md 7.1) as given, curved edges represented at the
// element degree, with its body
// loads (rotation, gravity, temperature; stresses reported are total stresses) and the
// reactions of its support parts. Writes the result
// JSON with the same keys as rfm_solve: discretization, the Lagrange/Castigliano/Reissner
// functionals (J per radian), the contact half-width, force and pressure profile when the
// problem has a die, fields at the sample points, timings. The conventions are in
// fem_reference/axisymmetric_fem.h. --vtu DIR (created with its parents when missing) writes
// DIR/fem_solution.vtu: u_r, u_z, the four stresses and the vector `displacement`.
//
// Sample run:
//   build/bin/fem_solve verification/problems/die_unilateral.json --refinements 3
//       --output die.json --vtu out/vtu
//
// Exit status: 0 success, 2 bad input (nothing written), 3 numerical failure (the result
// with the history so far is still written).
//
// Distributed (issue 25): `mpirun -np N build/bin/fem_solve PROBLEM.json ...` runs the same
// solver on a p4est mesh shared by N processes (fem_reference/axisymmetric_fem.h, "MPI");
// the result is the same file, with discretization.processes = N, and --vtu writes
// DIR/fem_solution.pvtu with one piece per process.
#include "fem_reference/axisymmetric_fem.h"
#include "fem_reference/fem_result_json.h"
#include "problem/problem.h"
#include "problem/json_io.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <filesystem>
#include <iostream>

int main(int argc, char **argv)
{
  // Under mpirun every rank runs this program on its share of the mesh; rank 0 prints and
  // writes (axisymmetric_fem.h, "MPI"). Started without a launcher, nothing changes.
  const fem::MpiSession mpi(argc, argv);
  const bool root = mpi.rank() == 0;
  try
    {
      // 1. Command line.
      CLI::App app{"deal.II FEM reference (axisymmetric elasticity, die contact)"};
      std::string problem_path, output_path, vtu_directory, solver = "direct";
      int refinements = -1, edge_fitting_passes = -1, max_iterations = -1;
      double penalty_factor = -1, adaptive_tolerance = -1, max_dofs = -1;
      bool adaptive = false;
      std::string adaptive_goal;
      app.add_option("problem", problem_path, "problem file (JSON, SI units)")->required();
      app.add_option("--refinements", refinements,
                     "mesh level L: cells per line x 2^L (nested graded meshes)");
      app.add_flag("--adaptive", adaptive,
                   "adaptive refinement from the mesh of level L (fem.refinement.strategy = "
                   "\"adaptive\"): Kelly's estimate, cells carrying half its square refined, "
                   "until the estimate or the energy's change is below the tolerance");
      app.add_option("--adaptive-tolerance", adaptive_tolerance,
                     "adaptive: the relative estimate or energy change to stop at (default "
                     "fem.refinement.tolerance, 1e-6)");
      app.add_option("--adaptive-goal", adaptive_goal,
                     "adaptive: refine for the energy (default) or for the stresses at the "
                     "problem's samples (goal-oriented; fem.refinement.goal)")
        ->check(CLI::IsMember({"energy", "samples"}));
      app.add_option("--max-dofs", max_dofs,
                     "adaptive: no cycle beyond this many dofs (default fem.refinement.max_dofs, 1e6)");
      app.add_option("--output", output_path, "result file (JSON); default: stdout");
      app.add_option("--vtu", vtu_directory,
                     "write DIR/fem_solution.vtu (u_r, u_z, stresses, the vector displacement); "
                     "DIR is created when missing; under mpirun DIR/fem_solution.pvtu and one "
                     "piece per process");
      app.add_option("--linear-solver", solver,
                     fmt::format("direct (UMFPACK; under mpirun MUMPS up to {} dofs, CG + AMG "
                                 "beyond) or cg (CG + SSOR; under mpirun CG + AMG)",
                                 fem::FemOptions{}.mpi_direct_max_dofs))
        ->check(CLI::IsMember({"direct", "cg"}));
      app.add_option("--penalty-factor", penalty_factor,
                     "unilateral contact: kappa = factor * E / h_min (default 1e3)");
      app.add_option("--edge-fitting-passes", edge_fitting_passes,
                     "unilateral contact: remesh at the found contact edge this many times "
                     "(default 1)");
      app.add_option("--max-active-set-iterations", max_iterations,
                     "unilateral contact: iteration limit per pass (default 50); exceeding it "
                     "is a numerical failure (exit 3)");
      try
        {
          app.parse(argc, argv);
        }
      catch (const CLI::ParseError &e)
        {
          const int status = root ? app.exit(e) : e.get_exit_code();
          return status == 0 ? 0 : 2;
        }

      // 2. Input: everything is checked before any work or output.
      const axisym::Problem problem = axisym::read_problem_file(problem_path);
      fem::FemOptions options = fem::options_from_problem(problem);
      if (refinements != -1)
        {
          axisym::ranges::fem_refinements.check(refinements, "--refinements");
          options.refinements = refinements;
        }
      if (adaptive)
        options.adaptive = true;
      if (!adaptive_goal.empty())
        options.adaptive_goal = adaptive_goal == "samples" ? fem::FemOptions::AdaptiveGoal::samples
                                                           : fem::FemOptions::AdaptiveGoal::energy;
      if (adaptive_tolerance != -1)
        options.adaptive_tolerance = adaptive_tolerance;
      if (max_dofs != -1)
        options.adaptive_max_dofs = static_cast<long>(max_dofs);
      if (edge_fitting_passes != -1)
        options.edge_fitting_passes = edge_fitting_passes;
      if (max_iterations != -1)
        options.max_active_set_iterations = max_iterations;
      if (penalty_factor != -1)
        options.penalty_factor = penalty_factor;
      options.linear_solver = solver == "direct" ? fem::FemOptions::LinearSolver::direct
                                                 : fem::FemOptions::LinearSolver::cg;
      options.vtu_directory = vtu_directory;
      options.validate();
      fem::check_supported(problem, options);
      if (!output_path.empty())
        axisym::check_output_path("--output", output_path);
      if (!vtu_directory.empty())
        {
          std::error_code ec;
          std::filesystem::create_directories(vtu_directory, ec);
          if (ec || !std::filesystem::is_directory(vtu_directory))
            throw axisym::InputError("--vtu = " + vtu_directory +
                                     ": must be a directory or creatable as one" +
                                     (ec ? " (" + ec.message() + ")" : std::string()));
        }
      if (!root)
        {
          // The other ranks solve alongside rank 0 and stay silent.
          const fem::FemResult r = fem::solve(problem, options);
          return r.success ? 0 : 3;
        }
      if (mpi.active())
        fmt::print(stderr, "fem_solve: MPI, {} process{} sharing the mesh (p4est), Trilinos "
                           "matrices; MUMPS up to {} dofs, CG + ML AMG beyond\n",
                   mpi.size(), mpi.size() == 1 ? "" : "es", options.mpi_direct_max_dofs);
      fmt::print(stderr, "fem_solve: Q{} elements, level L = {}{}, gmsh mesh, {} solver{}{}\n",
                 options.degree, options.refinements,
                 options.adaptive ? fmt::format(" then adaptive (tolerance {:g}, at most {} dofs)",
                                                options.adaptive_tolerance, options.adaptive_max_dofs)
                                  : "",
                 solver,
                 problem.body->die_parts().empty()
                   ? ""
                   : ", contact.method = " + problem.contact.method,
                 problem.legacy_cylinder ? ", hollow cylinder (half section, mirrored)"
                                         : ", outline section");
      if (problem.body_loads.any())
        {
          const axisym::BodyLoads &l = problem.body_loads;
          fmt::print(stderr,
                     "fem_solve: body loads: angular_velocity = {} rad/s, gravity = {} m/s^2, "
                     "temperature.field = [{}, {}, {}] (K, K/m, K/m); density = {} kg/m^3, "
                     "thermal_expansion = {} 1/K; stresses reported are total stresses\n",
                     l.angular_velocity, l.gravity, l.temperature[0], l.temperature[1],
                     l.temperature[2],
                     problem.material.density ? fmt::format("{}", *problem.material.density)
                                              : std::string("-"),
                     problem.material.thermal_expansion
                       ? fmt::format("{}", *problem.material.thermal_expansion)
                       : std::string("-"));
        }

      // 3. Solve and write.
      const fem::FemResult r = fem::solve(problem, options);
      const nlohmann::json result = fem::result_to_json(problem, options, r);
      if (!output_path.empty())
        axisym::write_json_atomically(output_path, result);
      else
        std::cout << result.dump(2) << '\n';
      if (!r.success)
        {
          fmt::print(stderr, "fem_solve: numerical failure: {}\n", r.message);
          return 3;
        }
      if (result["diagnostics"]["status"] == "warning")
        fmt::print(stderr, "fem_solve: warning: {}\n", result["diagnostics"]["message"].get<std::string>());
      fmt::print(stderr, "fem_solve: Phi_L = {:.6e}, Phi_C = {:.6e}, Phi_R = {:.6e} J/rad; "
                         "assembly {:.3f} s, solve {:.3f} s\n",
                 r.functionals.lagrange, r.functionals.castigliano, r.functionals.reissner,
                 r.assembly_seconds, r.solve_seconds);
      if (!vtu_directory.empty())
        fmt::print(stderr, "fem_solve: wrote {}\n",
                   (std::filesystem::path(vtu_directory) /
                    (mpi.active() ? "fem_solution.pvtu" : "fem_solution.vtu"))
                     .string());
      if (r.contact && problem.legacy_cylinder)
        fmt::print(stderr, "fem_solve: c = {:.6g} m (c/a = {:.4f}), P = {:.6g} N (trace {:.6g} N)\n",
                   r.contact->half_width, r.contact->half_width / problem.geometry.half_length(),
                   r.contact->force, r.contact->force_trace);
      else if (r.contact)
        {
          std::vector<fem::ContactResult> dies{*r.contact};
          dies.insert(dies.end(), r.other_dies.begin(), r.other_dies.end());
          for (const fem::ContactResult &d : dies)
            fmt::print(stderr,
                       "fem_solve: die on {}: c = {:.6g} m{}, delta = {:.6g} m, P = {:.6g} N "
                       "(trace {:.6g} N)\n",
                       d.part, d.half_width,
                       d.zone ? fmt::format(" (zone [{:.6g}, {:.6g}] m along the part)",
                                            (*d.zone)[0], (*d.zone)[1])
                              : std::string(),
                       d.indentation, d.force, d.force_trace);
        }
      return 0;
    }
  catch (const axisym::InputError &e)
    {
      if (root) // every rank reads the same input and fails alike
        std::cerr << "fem_solve: error: " << e.what() << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "fem_solve: error" << (mpi.active() ? fmt::format(" (rank {})", mpi.rank()) : "")
                << ": " << e.what() << '\n';
      return 3;
    }
}
