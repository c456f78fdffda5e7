// body_loads: rotation, gravity and temperature in both solvers (DESIGN.md 7.1, issue 14).
//
//   1. Spinning hollow cylinder in plane strain (u_z = 0 on both ends), against the closed
//      form (verification/body_load_exact.h): the RFM's max stress error on a 41 x 11 grid,
//      its indicator |Phi_L - Phi_C| / |Phi_R| and Phi_R against -U, against p; the FEM's
//      (Q2) r-weighted L2 and max stress errors against the level and the observed order.
//   2. Spinning solid cylinder with the axis, plane strain (polynomial stress: both exact).
//   3. Hollow cylinder heated by T = T0 + T_r r, plane strain, as in 1 (Phi_R against +U).
//   4. Sections with arcs, heated, no closed form: a ring of circular section (T = T_r r)
//      and a thick sphere under inner pressure (T = T_z z): the FEM at each level against
//      the RFM at the largest p (max over the FEM's Gauss-Lobatto points of
//      |s_FEM - s_RFM|, relative to max |s_RFM|), and the RFM's indicator.
//   5. Hollow column on a frictionless plane under its own weight: the reaction on the plane
//      (domain-independent: rho g V) and the indicator, RFM and FEM.
//   6. Values on the axis (issue 24 item 5): a spinning solid cylinder with free ends (no
//      closed form), the RFM with and without the axis parity (rfm.axis_parity) against the
//      FEM's finest level at samples on the axis and off it.
//   7. The tolerance gate (verification/tolerances.json, entry "body_loads").
//
// Sample run:
//   build/bin/body_loads --mode quick --output-dir build/verification-output
#include "fem_reference/axisymmetric_fem.h"
#include "problem/problem.h"
#include "rfm/outline_model.h"
#include "rfm/quadrature/quadrature.h"
#include "verification/body_load_exact.h"
#include "verification/driver.h"
#include "verification/outline_errors.h"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

namespace
{
  using verification::max_stress_error;
  using verification::observed_order;

  using Stress = std::function<std::array<double, 4>(double, double)>;

  rfm::OutlineModel solve_rfm(const axisym::Problem &problem, const int p, const std::string &name)
  {
    rfm::DiscretizationOptions o = problem.rfm;
    o.degree = p;
    rfm::OutlineModel m(problem, o);
    if (!m.ok())
      throw verification::NumericalFailure(name + ", p = " + std::to_string(p) + ": " +
                                           m.summary().message);
    return m;
  }

  fem::FemResult solve_fem(const axisym::Problem &problem, const int level, const std::string &name,
                           const Stress &exact)
  {
    fem::FemOptions o = fem::options_from_problem(problem);
    o.refinements = level;
    o.progress = false;
    fem::FemResult f = fem::solve(problem, o, exact);
    if (!f.success)
      throw verification::NumericalFailure(name + " FEM, L = " + std::to_string(level) + ": " +
                                           f.message);
    return f;
  }


  // A grid of the rectangle [r0, r1] x [0, h] (r0 = 0 moved off the axis by 1e-9 m).
  std::pair<Eigen::VectorXd, Eigen::VectorXd> grid(double r0, double r1, double h, int nr, int nz)
  {
    Eigen::VectorXd r(nr * nz), z(nr * nz);
    for (int i = 0; i < nr; ++i)
      for (int j = 0; j < nz; ++j)
        r[i * nz + j] = std::max(r0 + (r1 - r0) * i / (nr - 1.0), 1e-9),
                   z[i * nz + j] = h * j / (nz - 1.0);
    return {r, z};
  }

  verification::PlaneStrainCylinder cylinder_of(const axisym::Problem &p, double a, double b)
  {
    verification::PlaneStrainCylinder c{a, b, p.material.youngs_modulus, p.material.poisson_ratio};
    c.density = p.material.density.value_or(0.0);
    c.angular_velocity = p.body_loads.angular_velocity;
    c.thermal_expansion = p.material.thermal_expansion.value_or(0.0);
    c.temperature_0 = p.body_loads.temperature[0];
    c.temperature_r = p.body_loads.temperature[1];
    return c;
  }


  // Cases 1-3: a plane-strain cylinder [a, 0.2] x [0, 0.1] against its closed form.
  nlohmann::json cylinder_case(const verification::DriverContext &context, const std::string &file,
                               const std::string &title, double a, const std::vector<int> &degrees,
                               const std::vector<int> &levels, double energy_sign)
  {
    const axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    const verification::PlaneStrainCylinder exact = cylinder_of(problem, a, 0.2);
    const Stress stress = [&](double r, double z) { return exact.stress(r, z); };
    const auto [r, z] = grid(a, 0.2, 0.1, 41, 11);
    const double phi_exact = energy_sign * exact.elastic_energy(0.1);
    nlohmann::json c = {{"problem_file", "verification/problems/" + file},
                        {"exact_functional", phi_exact}};
    fmt::print("\n== {} ==\n", title);
    fmt::print("RFM: {:>3} {:>5} {:>12} {:>11} {:>14} {:>9}\n", "p", "N", "max err", "indicator",
               "Phi_R error", "time [s]");
    for (const int p : degrees)
      {
        const rfm::OutlineModel m = solve_rfm(problem, p, title);
        const double err = max_stress_error(m, r, z, stress);
        const rfm::Functionals phi = m.functionals();
        const double phi_err = std::abs(phi.reissner - phi_exact) / std::abs(phi_exact);
        const double seconds = m.assembly_seconds() + m.solve_seconds();
        fmt::print("     {:>3} {:>5} {:>12.3e} {:>11.3e} {:>14.3e} {:>9.3f}\n", p,
                   m.n_basis_functions(), err, phi.indicator(), phi_err, seconds);
        c["rfm"]["p" + std::to_string(p)] = {
          {"N", m.n_basis_functions()}, {"max_error_relative", err},
          {"indicator", phi.indicator()}, {"lagrange", phi.lagrange},
          {"castigliano", phi.castigliano}, {"reissner", phi.reissner},
          {"functional_error_relative", phi_err}, {"seconds", seconds}};
      }
    fmt::print("FEM Q2: {:>2} {:>8} {:>12} {:>8} {:>12} {:>9}\n", "L", "dofs", "L2 err", "order",
               "max err", "time [s]");
    double previous = 0;
    for (std::size_t i = 0; i < levels.size(); ++i)
      {
        const fem::FemResult f = solve_fem(problem, levels[i], title, stress);
        const double l2 = *f.stress_l2_error / *f.stress_l2_norm;
        const double mx = *f.stress_max_error / *f.stress_max_norm;
        const double order = i > 0 ? observed_order(previous, l2) : 0.0;
        fmt::print("        {:>2} {:>8} {:>12.3e} {:>8.2f} {:>12.3e} {:>9.3f}\n", levels[i],
                   f.n_dofs, l2, order, mx, f.total_seconds);
        c["fem"]["L" + std::to_string(levels[i])] = {{"dofs", f.n_dofs},
                                                     {"l2_error_relative", l2},
                                                     {"max_error_relative", mx},
                                                     {"seconds", f.total_seconds}};
        if (i > 0)
          c["fem"]["observed_order_l2_last"] = order;
        previous = l2;
      }
    return c;
  }
  // A case without a closed form: the RFM over p (functionals), then the FEM at each level
  // against the RFM at the largest p (max over the FEM's Gauss-Lobatto points of
  // |s_FEM - s_RFM| relative to max |s_RFM|, and the r-weighted L2 difference).
  nlohmann::json rfm_against_fem(const verification::DriverContext &context,
                                 const std::string &file, const std::string &title, bool full,
                                 const std::vector<int> &levels)
  {
    const axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    nlohmann::json c = {{"problem_file", "verification/problems/" + file}};
    fmt::print("\n== {} ==\n", title);
    const std::vector<int> ps = full ? std::vector<int>{8, 12, 16} : std::vector<int>{8, 12};
    std::unique_ptr<rfm::OutlineModel> best;
    for (const int p : ps)
      {
        auto m = std::make_unique<rfm::OutlineModel>(solve_rfm(problem, p, title));
        const rfm::Functionals phi = m->functionals();
        fmt::print("RFM p = {:>2}: indicator {:.3e}, Phi_L {:.9e}, Phi_C {:.9e}, Phi_R {:.9e}\n", p,
                   phi.indicator(), phi.lagrange, phi.castigliano, phi.reissner);
        c["rfm"]["p" + std::to_string(p)] = {{"N", m->n_basis_functions()},
                                             {"indicator", phi.indicator()},
                                             {"lagrange", phi.lagrange},
                                             {"castigliano", phi.castigliano},
                                             {"reissner", phi.reissner}};
        best = std::move(m);
      }
    c["rfm_reference_degree"] = ps.back();
    const Stress rfm_stress = [&](double r, double z) {
      Eigen::VectorXd rr(1), zz(1);
      rr << std::max(r, 1e-12);
      zz << z;
      const rfm::FieldValues f = best->evaluate(rr, zz);
      return std::array<double, 4>{f.sigma(0, 0), f.sigma(0, 1), f.sigma(0, 2), f.sigma(0, 3)};
    };
    // A 41 x 41 grid of the bounding box, the points inside the section at least 1e-3 of
    // its size from the boundary (a mapped FEM cell can have a singular Jacobian at a
    // boundary vertex where two arcs meet smoothly: its stress there is not the field's).
    axisym::Problem with_grid = problem;
    with_grid.samples.clear();
    const axisym::Outline &outline = problem.body->outline;
    const axisym::BoundingBox box = outline.bounding_box();
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j)
        {
          const axisym::Point q{box.r_min + (box.r_max - box.r_min) * i / 40.0,
                                box.z_min + (box.z_max - box.z_min) * j / 40.0};
          if (outline.contains(q, 0.0) && outline.distance_to_boundary(q) >= 1e-3 * outline.size())
            with_grid.samples.push_back({q.r, q.z});
        }
    double previous = 0;
    for (std::size_t i = 0; i < levels.size(); ++i)
      {
        const fem::FemResult f = solve_fem(with_grid, levels[i], title, rfm_stress);
        const double l2 = *f.stress_l2_error / *f.stress_l2_norm;
        const double mx = *f.stress_max_error / *f.stress_max_norm;
        double grid_diff = 0, grid_max = 0;
        for (const fem::FieldSample &fs : f.samples)
          {
            const auto s_rfm = rfm_stress(fs.r, fs.z);
            for (int k = 0; k < 4; ++k)
              grid_diff = std::max(grid_diff, std::abs(fs.sigma[k] - s_rfm[k])),
              grid_max = std::max(grid_max, std::abs(s_rfm[k]));
          }
        grid_diff /= grid_max;
        fmt::print("FEM Q2 L = {}: {} dofs, |s_FEM - s_RFM| / max |s_RFM|: L2 {:.3e}, max on the grid "
                   "{:.3e} ({} points), max at the Gauss-Lobatto points {:.3e}; Phi_L {:.9e}\n",
                   levels[i], f.n_dofs, l2, grid_diff, f.samples.size(), mx,
                   f.functionals.lagrange);
        c["fem"]["L" + std::to_string(levels[i])] = {{"dofs", f.n_dofs},
                                                     {"l2_difference_to_rfm_relative", l2},
                                                     {"grid_max_difference_to_rfm_relative", grid_diff},
                                                     {"max_difference_to_rfm_relative", mx},
                                                     {"lagrange", f.functionals.lagrange}};
        if (i > 0)
          c["fem"]["observed_order_l2_last"] = observed_order(previous, l2);
        c["fem"]["grid_max_difference_to_rfm_finest"] = grid_diff;
        c["fem"]["max_difference_to_rfm_finest"] = mx;
        c["fem"]["l2_difference_to_rfm_finest"] = l2;
        c["grid_points"] = f.samples.size();
        previous = l2;
      }
    return c;
  }

  // Case 6: the RFM with and without the axis parity against the FEM's finest level at the
  // problem's samples, those on the axis (r = 0) and the others apart, each as the largest
  // stress component's difference relative to the largest |sigma| of the FEM's samples.
  nlohmann::json axis_case(const verification::DriverContext &context, const std::string &file,
                           const std::string &title, const std::vector<int> &degrees,
                           const std::vector<int> &levels)
  {
    const axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    nlohmann::json c = {{"problem_file", "verification/problems/" + file}};
    fmt::print("\n== {} ==\n", title);
    std::vector<std::array<double, 4>> reference, previous;
    for (const int level : levels)
      {
        const fem::FemResult f = solve_fem(problem, level, title, {});
        previous = reference;
        reference.clear();
        for (const fem::FieldSample &s : f.samples)
          reference.push_back(s.sigma);
        c["fem"]["L" + std::to_string(level)] = {{"dofs", f.n_dofs},
                                                 {"reissner", f.functionals.reissner},
                                                 {"seconds", f.total_seconds}};
        fmt::print("FEM Q2 L = {}: {} dofs, Phi_R {:.12e} J/rad ({:.1f} s)\n", level, f.n_dofs,
                   f.functionals.reissner, f.total_seconds);
      }
    const double scale = verification::largest_component(reference);
    const std::array<Eigen::VectorXd, 2> points = verification::sample_points(problem);
    const Eigen::VectorXd &r = points[0], &z = points[1];
    // Largest difference from the reference on the axis and off it, relative to scale.
    auto errors = [&](auto sigma) {
      auto e = verification::axis_and_off_axis_differences(r, reference, sigma);
      return std::array<double, 2>{e[0] / scale, e[1] / scale};
    };
    const auto fem_change = errors([&](Eigen::Index k, int m) { return previous[static_cast<std::size_t>(k)][m]; });
    c["fem"]["change_last_axis_relative"] = fem_change[0];
    c["fem"]["change_last_off_axis_relative"] = fem_change[1];
    fmt::print("FEM: change between the last two levels, on the axis {:.2e}, off it {:.2e} of max "
               "|sigma| = {:.4g} MPa\n", fem_change[0], fem_change[1], scale / 1e6);
    for (const bool parity : {true, false})
      {
        axisym::Problem pr = problem;
        pr.rfm.axis_parity = parity;
        const std::string key = parity ? "rfm" : "rfm_without_axis_parity";
        for (const int p : degrees)
          {
            const rfm::OutlineModel m = solve_rfm(pr, p, title);
            if (m.axis_parity() != parity)
              throw std::logic_error(title + ": the axis parity is " + (parity ? "off: " : "on") +
                                     m.axis_parity_obstacle());
            const rfm::FieldValues v = m.evaluate(r, z);
            const auto e = errors([&](Eigen::Index k, int comp) { return v.sigma(k, comp); });
            const rfm::Functionals phi = m.functionals();
            fmt::print("RFM{} p = {:>2}: samples on the axis {:.2e}, off it {:.2e} of max |sigma| "
                       "from the FEM's; indicator {:.2e} ({:.2f} s)\n",
                       parity ? "" : " without axis parity", p, e[0], e[1], phi.indicator(),
                       m.assembly_seconds() + m.solve_seconds());
            c[key]["p" + std::to_string(p)] = {{"axis_sample_error_relative", e[0]},
                                               {"sample_error_relative", e[1]},
                                               {"axis_to_off_axis_ratio", e[0] / e[1]},
                                               {"indicator", phi.indicator()},
                                               {"reissner", phi.reissner},
                                               {"seconds", m.assembly_seconds() + m.solve_seconds()}};
          }
      }
    return c;
  }
} // namespace

nlohmann::json run(const verification::DriverContext &context)
{
  const bool full = context.full();
  nlohmann::json results = {{"driver", "body_loads"}, {"mode", context.mode}};
  const std::vector<int> levels = full ? std::vector<int>{1, 2, 3, 4} : std::vector<int>{1, 2, 3};
  const std::vector<int> degrees =
    full ? std::vector<int>{4, 6, 8, 10, 12, 14} : std::vector<int>{4, 8, 12};

  results["spinning_cylinder"] =
    cylinder_case(context, "spinning_cylinder_plane_strain.json",
                  "Spinning hollow cylinder in plane strain (a = 0.1, b = 0.2 m, 500 rad/s)", 0.1,
                  degrees, levels, -1.0);
  results["spinning_solid_cylinder"] =
    cylinder_case(context, "spinning_solid_cylinder.json",
                  "Spinning solid cylinder in plane strain (b = 0.2 m, 500 rad/s, the axis)", 0.0,
                  {4, 8}, {1, 2}, -1.0);
  results["heated_cylinder"] =
    cylinder_case(context, "heated_cylinder_plane_strain.json",
                  "Hollow cylinder heated by T = 20 + 1000 r K, plane strain", 0.1, degrees, levels,
                  +1.0);

  // 4. Heated sections with arcs: FEM against the RFM at the largest p.
  results["heated_ring"] = rfm_against_fem(
    context, "heated_ring.json",
    "Ring of circular section (centre r = 0.15 m, radius 0.04 m) heated by T = 1000 r K", full,
    levels);
  // T linear in z on the sphere: smooth in the body (T = T_r r is not smooth on the axis:
  // it is the cone sqrt(x^2 + y^2) in 3D, and so is the stress it causes).
  results["heated_sphere"] = rfm_against_fem(
    context, "heated_sphere.json", "Thick sphere heated by T = 1000 z K, inner pressure 10 MPa",
    full, {1, 2, 3}); // L = 4 (109442 dofs) changed nothing but the report's time

  // 5. Self weight on a frictionless plane: the reaction -2 pi int sigma_zz(r, 0) r dr.
  {
    const std::string title = "Hollow column on a frictionless plane under its own weight";
    axisym::Problem problem =
      axisym::read_problem_file(context.problem_path("spinning_cylinder_plane_strain.json"));
    problem.body->conditions.at("top") = axisym::PartCondition{};
    problem.body_loads = axisym::BodyLoads{};
    problem.body_loads.gravity = 9.81;
    const double weight = problem.material.density.value() * 9.81 * M_PI * (0.04 - 0.01) * 0.1;
    const rfm::GaussRule1D g = rfm::gauss_on_cells({0.1, 0.2}, 24);
    nlohmann::json c = {{"weight", weight}};
    fmt::print("\n== {} (weight {:.6g} N) ==\n", title, weight);
    for (const int p : full ? std::vector<int>{8, 12, 16} : std::vector<int>{8, 12})
      {
        const rfm::OutlineModel m = solve_rfm(problem, p, title);
        const rfm::FieldValues f = m.evaluate(g.nodes, Eigen::VectorXd::Zero(g.nodes.size()));
        double reaction = 0;
        for (Eigen::Index i = 0; i < g.nodes.size(); ++i)
          reaction -= 2 * M_PI * g.weights[i] * g.nodes[i] * f.sigma(i, rfm::zz);
        const rfm::Functionals phi = m.functionals();
        fmt::print("RFM p = {:>2}: reaction / weight - 1 = {:.3e}, indicator {:.3e}\n", p,
                   reaction / weight - 1, phi.indicator());
        c["rfm"]["p" + std::to_string(p)] = {{"reaction_error_relative", std::abs(reaction / weight - 1)},
                                             {"indicator", phi.indicator()}};
      }
    results["self_weight"] = c;
  }

  // 6. Values on the axis.
  results["axis_values"] = axis_case(
    context, "spinning_solid_cylinder_free_ends.json",
    "Values on the axis: spinning solid cylinder with free ends (b = 0.2 m, h = 0.1 m, 500 rad/s)",
    full ? std::vector<int>{8, 12, 16} : std::vector<int>{8, 12},
    full ? std::vector<int>{3, 4, 5} : std::vector<int>{3, 4});
  return results;
}

int main(int argc, char **argv)
{
  return verification::run_driver(argc, argv, "body_loads",
                                  "rotation, gravity and temperature in both solvers", run);
}
