#include "rfm/model.h"

#include <chrono>
#include <cmath>

namespace rfm
{
  Section build_section(const Problem &problem, const std::optional<double> half_width)
  {
    const Geometry &g = problem.geometry;
    const double a = g.half_length();
    const Loading loading = problem.loading.value_or(Loading{});
    Section s(g.inner_radius, g.outer_radius, 0.0, a);

    s.add_part({"inner", Side::inner, 0.0, a, Condition::traction, -loading.inner_pressure, {}, {}});
    s.add_part({"symmetry", Side::bottom, g.inner_radius, g.outer_radius, Condition::symmetry,
                0.0, {}, {}});
    s.add_part({"end", Side::top, g.inner_radius, g.outer_radius, Condition::traction, 0.0, {}, {}});
    if (!problem.die)
      {
        s.add_part({"outer", Side::outer, 0.0, a, Condition::traction, -loading.outer_pressure,
                    {}, {}});
        return s;
      }
    const double c = std::min(half_width.value_or(a), a);
    const Die die = *problem.die;
    BoundaryPart contact{"contact", Side::outer, 0.0, c, Condition::contact, 0.0, {}, {}};
    contact.normal_displacement = [die, g](double z) { return die_u_r(die, g, z); };
    contact.normal_displacement_derivative = [die, g](double z) {
      return die_u_r_derivative(die, g, z);
    };
    s.add_part(contact);
    if (c < a * (1 - 1e-12))
      s.add_part({"outer_free", Side::outer, c, a, Condition::traction, -loading.outer_pressure,
                  {}, {}});
    return s;
  }

  double estimate_memory_bytes(const Problem &problem, const DiscretizationOptions &options,
                               const std::optional<double> half_width)
  {
    const Section s = build_section(problem, half_width);
    const auto r_cells = section_cells(s.r_min(), s.r_max(), options.n_cells_r, s.r_breaks(),
                                       options.n_graded_layers, options.grading_ratio);
    const auto z_cells = section_cells(s.z_min(), s.z_max(), options.n_cells_z, s.z_breaks(),
                                       options.n_graded_layers, options.grading_ratio);
    const double n_gauss = options.degree + options.extra_gauss_points;
    const double n_q = (r_cells.size() - 1.0) * (z_cells.size() - 1.0) * n_gauss * n_gauss;
    const double n = (options.degree + 1.0) * (options.degree + 1.0);
    return 8.0 * (14.0 * n_q * n + 2.0 * (4 * n) * (4 * n) + 3.0 * (4 * n) * (2 * n) +
                  2.0 * (2 * n) * (2 * n));
  }

  RfmModel::RfmModel(const Problem &problem, const DiscretizationOptions &options,
                     const std::optional<double> half_width, const SolverOptions &solver_options)
    : half_width_(half_width)
  {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const Structures structures(build_section(problem, half_width));
    space_ = std::make_unique<DiscreteSpace>(structures, options);
    const ReissnerSystem system = assemble_reissner_system(*space_, problem.material);
    const auto t1 = clock::now();
    SaddlePointSolution s = solve_saddle_point(system, solver_options);
    const auto t2 = clock::now();
    assembly_s_ = std::chrono::duration<double>(t1 - t0).count();
    solve_s_ = std::chrono::duration<double>(t2 - t1).count();
    summary_ = s.summary;
    if (summary_.success)
      solution_ = std::make_unique<RfmSolution>(*space_, problem.material, std::move(s.q_s),
                                                std::move(s.q_u));
  }

  FieldValues RfmModel::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                 const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    FieldValues f = solution_->evaluate(r, z.cwiseAbs());
    // Mirror: u_z and sigma_rz (and gamma_rz) are odd in z.
    for (Eigen::Index k = 0; k < z.size(); ++k)
      if (z[k] < 0)
        {
          f.u(k, 1) = -f.u(k, 1);
          f.sigma(k, rz) = -f.sigma(k, rz);
          f.strain(k, rz) = -f.strain(k, rz);
        }
    return f;
  }

  ContactForce RfmModel::contact_force() const
  {
    ContactForce p;
    const Section &s = space_->structures().section();
    const double r1 = s.r_min(), r2 = s.r_max();

    // Domain integral with the test field v = (psi, 0), psi = (r - R1)/(R2 - R1):
    // e(v) = (1/(R2 - R1), 0, psi/r, 0).
    const Quadrature2D &q = space_->quadrature();
    const FieldValues f = solution_->evaluate(q.r, q.z);
    double integral = 0.0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      {
        const double psi = (q.r[k] - r1) / (r2 - r1);
        integral += space_->measure()[k] *
                    (f.sigma(k, rr) / (r2 - r1) + f.sigma(k, tt) * psi / q.r[k]);
      }
    p.domain = -2.0 * M_PI * integral;

    // Trace on r = R2 with the outer side's boundary points (weights carry r ds and
    // the mirror factor).
    const BoundaryQuadrature &bq = space_->boundary_quadrature();
    const FieldValues fb = solution_->evaluate(bq.r, bq.z);
    double trace = 0.0;
    for (Eigen::Index k = 0; k < bq.weights.size(); ++k)
      if (s.parts()[bq.part[k]].side == Side::outer)
        trace += bq.weights[k] * fb.sigma(k, rr);
    p.trace = -2.0 * M_PI * trace;
    return p;
  }
} // namespace rfm
