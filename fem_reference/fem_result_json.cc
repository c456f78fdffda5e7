#include "fem_reference/fem_result_json.h"

#include "problem/sample_checks.h"

#include <cmath>
#include <string>
#include <vector>

namespace fem
{
  namespace
  {
    nlohmann::json functionals_to_json(const Functionals &f)
    {
      return {{"lagrange", f.lagrange},
              {"castigliano", f.castigliano},
              {"reissner", f.reissner},
              {"strain_energy", f.strain_energy},
              {"external_work", f.external_work},
              {"body_force_work", f.body_force_work},
              {"thermal_strain_work", f.thermal_strain_work},
              {"penalty_energy", f.penalty_energy},
              {"units", "J per radian"}};
    }

    nlohmann::json samples_to_json(const std::vector<FieldSample> &samples)
    {
      nlohmann::json out = nlohmann::json::array();
      for (const FieldSample &s : samples)
        out.push_back({{"r", s.r},
                       {"z", s.z},
                       {"u_r", s.u_r},
                       {"u_z", s.u_z},
                       {"sigma_rr", s.sigma[0]},
                       {"sigma_zz", s.sigma[1]},
                       {"sigma_tt", s.sigma[2]},
                       {"sigma_rz", s.sigma[3]}});
      return out;
    }
  } // namespace

  nlohmann::json result_to_json(const axisym::Problem &problem, const FemOptions &options,
                                const FemResult &r)
  {
    nlohmann::json j;
    j["solver"] = "fem";
    j["problem"] = problem.source;
    // The solver of the last solve: umfpack, cg-ssor (serial), mumps or cg-amg (MPI).
    const std::string linear_solver =
      !r.linear_solver.empty() ? r.linear_solver
      : options.linear_solver == FemOptions::LinearSolver::direct ? "umfpack" : "cg-ssor";
    j["discretization"] = {
      {"degree", r.degree},
      {"refinements", r.refinements},
      {"dofs", r.n_dofs},
      {"cells", r.n_cells},
      {"mesh", r.mesh_generator},
      {"refinement_rule", "L global refinements of the gmsh base mesh, new vertices on the "
                          "arcs (manifolds), MappingQ(degree); refined toward the dies' zones "
                          "and graded toward the singular vertices and the traction jumps (graded_vertices; lambda 1 at a jump)"},
      {"base_cells", r.n_base_cells},
      {"base_mesh_size", r.base_mesh_size},
      {"base_cells_on_shortest_edge", options.outline_cells_on_shortest_edge},
      {"base_mesh_subdivided", r.base_mesh_subdivided},
      {"base_mesh_flat_corners", r.base_mesh_flat_corners},
      {"grading", nullptr},
      {"linear_solver", linear_solver},
      {"linear_iterations", r.linear_iterations},
      {"processes", r.processes},
      {"section", problem.body && problem.body->mirrored
                    ? "upper half z in [0, length/2] as an outline, mirrored in z = 0 (the "
                      "functionals, forces and norms are the whole body's)"
                    : "the outline as given (geometry.outline), no mirroring"}};
    j["discretization"]["refinement_strategy"] = options.adaptive ? "adaptive" : "uniform";
    if (options.adaptive)
      {
        j["discretization"]["refinement_rule"] =
          "L global refinements of the gmsh base mesh (refined toward the dies' zones), then "
          "adaptive cycles: Kelly's estimate times sqrt(r) per cell, the cells carrying "
          "adaptive_fraction of its square refined (hanging nodes constrained), new vertices on "
          "the arcs, MappingQ(degree)";
        j["discretization"]["adaptive"] = {{"goal", options.adaptive_goal == FemOptions::AdaptiveGoal::samples
                                                      ? "samples"
                                                      : "energy"},
                                           {"tolerance", options.adaptive_tolerance},
                                           {"max_dofs", options.adaptive_max_dofs},
                                           {"fraction", options.adaptive_fraction},
                                           {"stopped", r.adaptive_stop},
                                           {"cycles", nlohmann::json::array()}};
        for (const FemResult::AdaptiveCycle &c : r.adaptive_cycles)
          j["discretization"]["adaptive"]["cycles"].push_back({{"dofs", c.n_dofs},
                                                               {"cells", c.n_cells},
                                                               {"estimate", c.estimate},
                                                               {"reissner", c.reissner},
                                                               {"change", std::isfinite(c.change)
                                                                            ? nlohmann::json(c.change)
                                                                            : nlohmann::json(nullptr)},
                                                               {"force", c.force},
                                                               {"samples", samples_to_json(c.samples)},
                                                               {"seconds", c.seconds}});
      }
    j["discretization"]["graded_vertices"] = nlohmann::json::array();
    for (const auto &g : r.graded_vertices)
      j["discretization"]["graded_vertices"].push_back(
        {{"r", g[0]}, {"z", g[1]}, {"lambda", g[2]}, {"halvings", static_cast<int>(g[3])}});
    j["diagnostics"] = {{"status", r.success ? "ok" : "failed"}, {"message", r.message}};
    // A sample at a vertex where the stress has no value (problem/sample_checks.h, the same
    // check as rfm_solve's): the mesh's value there is whichever cell's holds the point.
    if (const std::vector<axisym::SampleAtVertex> at = axisym::samples_at_vertices(problem); !at.empty())
      {
        j["diagnostics"]["samples_at_vertices"] = axisym::to_json(at);
        if (r.success)
          {
            j["diagnostics"]["status"] = "warning";
            j["diagnostics"]["message"] = axisym::samples_at_vertices_warning(at);
            // As rfm_solve's diagnostics.warnings: the check's key and its message.
            j["diagnostics"]["warnings"] = {{{"check", "samples_at_vertices"},
                                             {"message", j["diagnostics"]["message"]}}};
          }
      }
    if (r.stress_l2_error)
      {
        j["diagnostics"]["stress_l2_error"] = *r.stress_l2_error;
        j["diagnostics"]["stress_l2_norm"] = *r.stress_l2_norm;
      }
    if (r.displacement_l2_error)
      {
        j["diagnostics"]["displacement_l2_error"] = *r.displacement_l2_error;
        j["diagnostics"]["displacement_l2_norm"] = *r.displacement_l2_norm;
      }
    if (r.stress_max_error)
      {
        j["diagnostics"]["stress_max_error"] = *r.stress_max_error;
        j["diagnostics"]["stress_max_norm"] = *r.stress_max_norm;
      }
    j["timing"] = {{"assembly_s", r.assembly_seconds},
                   {"solve_s", r.solve_seconds},
                   {"total_s", r.total_seconds},
                   {"peak_memory_bytes", r.peak_memory_bytes},
                   {"peak_memory_bytes_all_processes", r.peak_memory_bytes_all_processes}};
    if (r.success || (r.contact && !r.contact->iterations.empty()))
      j["functionals"] = functionals_to_json(r.functionals);
    // One die in the form of DESIGN.md 7 (`contact` is the first die, `dies` lists them all).
    auto die_to_json = [&](const ContactResult &c) {
        nlohmann::json contact = {{"part", c.part},
                                  {"method", c.method},
                                  {"mode", c.unilateral ? "unilateral-penalty" : "bilateral"},
                                  {"half_width", c.half_width},
                                  {"indentation", c.indentation},
                                  {"force", c.force},
                                  {"force_trace", c.force_trace},
                                  {"edge_intensity", nullptr}, // not extracted by the FEM yet
                                  {"h_min", c.h_min},
                                  {"max_penetration", c.max_penetration}};
        if (problem.legacy_cylinder)
          contact["half_width_ratio"] = c.half_width / problem.geometry.half_length();
        if (c.zone)
          contact["zone"] = {(*c.zone)[0], (*c.zone)[1]};
        if (c.unilateral)
          {
            contact["half_width_gap"] = c.half_width_gap;
            contact["force_penalty"] = c.force_penalty;
            contact["penalty"] = c.penalty;
            contact["penalty_factor"] = c.penalty_factor;
            contact["active_set_iterations"] = c.active_set_iterations;
            contact["edge_fitting_passes"] = c.edge_fitting_passes;
          }
        nlohmann::json iterations = nlohmann::json::array();
        for (const ActiveSetStep &s : c.iterations)
          iterations.push_back({{"pass", s.pass},
                                {"iteration", s.iteration},
                                {"n_active", s.n_active},
                                {"n_changed", s.n_changed},
                                {"half_width", s.half_width},
                                {"force", s.force},
                                {"force_trace", s.force_trace},
                                {"force_penalty", s.force_penalty},
                                {"lagrange", s.functionals.lagrange},
                                {"castigliano", s.functionals.castigliano},
                                {"reissner", s.functionals.reissner}});
        contact["iterations"] = iterations;
        nlohmann::json pressure = nlohmann::json::array();
        for (const PressurePoint &p : c.pressure)
          pressure.push_back({{"s", p.s},
                              {"r", p.r},
                              {"z", p.z},
                              {"p", p.p},
                              {"p_trace", p.p_trace},
                              {"gap", std::isfinite(p.gap) ? nlohmann::json(p.gap) : nullptr}});
        contact["pressure"] = pressure;
        return contact;
    };
    if (r.contact)
      {
        j["contact"] = die_to_json(*r.contact);
        if (!problem.legacy_cylinder)
          {
            j["dies"] = nlohmann::json::array({j["contact"]});
            for (const ContactResult &c : r.other_dies)
              j["dies"].push_back(die_to_json(c));
          }
      }
    j["samples"] = samples_to_json(r.samples);
    if (!problem.legacy_cylinder)
      {
        // Support reactions [N, full 360 degree body] (axisymmetric_fem.h, PartReaction).
        nlohmann::json reactions = nlohmann::json::array();
        for (const PartReaction &p : r.reactions)
          reactions.push_back({{"part", p.part},
                               {"condition", p.condition},
                               {"force_r", p.force_r},
                               {"force_z", p.force_z}});
        j["reactions"] = reactions;
      }
    return j;
  }
} // namespace fem
