#include "rfm/model.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace rfm
{
  using axisym::Die;
  using axisym::Geometry;
  using axisym::InputError;
  using axisym::Loading;
  using axisym::Problem;

  Section build_section(const Problem &problem, const std::optional<double> half_width)
  {
    if (!problem.legacy_cylinder)
      throw InputError("geometry.outline: RfmModel is the hollow-cylinder model (with the "
                       "die); an outline section is solved by OutlineModel (outline_model.h)");
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
    // Enrichment: a near-edge rule of 2 n_e^2 points where ~20 matrices of all columns
    // are formed, and n_edge more unknowns in each space.
    const bool edge = !contact_edges(s).empty() && options.edge_modes > 0;
    const double n_edge_pts = n_gauss + options.edge_extra_points;
    const double n_eq = edge ? 2.0 * n_edge_pts * n_edge_pts : 0.0;
    const double n_edge_columns =
      edge ? options.edge_modes * (options.edge_mode_degree + 1.0) *
               (options.edge_mode_degree + 2.0) / 2.0
           : 0.0;
    const double n_s = 4 * n + n_edge_columns;
    const double n_u = 2 * n + n_edge_columns;
    return 8.0 * (14.0 * n_q * n + 20.0 * n_eq * n_s + 2.0 * n_s * n_s + 3.0 * n_s * n_u +
                  2.0 * n_u * n_u);
  }

  RfmModel::RfmModel(const Problem &problem, const DiscretizationOptions &options,
                     const std::optional<double> half_width, const SolverOptions &solver_options)
    : half_width_(half_width)
  {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const Structures structures(build_section(problem, half_width));
    space_ = std::make_unique<DiscreteSpace>(structures, options, problem.material);
    AssemblyOptions assembly;
    assembly.full_r11 = false; // the solver reads R11's lower triangle only
    const ReissnerSystem system = assemble_reissner_system(*space_, problem.material, assembly);
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

  double RfmModel::edge_intensity() const
  {
    const EdgeEnrichment *e = space_->enrichment();
    if (!e || e->singular_column() < 0)
      return std::numeric_limits<double>::quiet_NaN();
    const Eigen::VectorXd &q = solution_->stress_coefficients();
    return std::sqrt(2.0 * M_PI) * q[4 * space_->n_basis_functions() + e->singular_column()];
  }

  FieldValues RfmModel::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                 const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    return mirrored_fields(r, z, [this](const auto &rr_, const auto &zz_) {
      return solution_->evaluate(rr_, zz_);
    });
  }

  ContactForce RfmModel::contact_force() const
  {
    ContactForce p;
    const Section &s = space_->structures().section();
    const double r1 = s.r_min(), r2 = s.r_max();

    // Domain integral with the test field v = (psi, 0), psi = (r - R1)/(R2 - R1):
    // e(v) = (1/(R2 - R1), 0, psi/r, 0), on the assembly's rules.
    const double integral = solution_->integrate(
      [&](const FieldValues &f, const Eigen::VectorXd &r, const auto &) -> Eigen::MatrixXd {
        return f.sigma.col(rr) / (r2 - r1) +
               f.sigma.col(tt).cwiseProduct((r.array() - r1).matrix().cwiseQuotient(r)) /
                 (r2 - r1);
      })[0];
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

  ToleranceSolve solve_to_tolerance(const Problem &problem, const DiscretizationOptions &options,
                                    const double tolerance)
  {
    return solve_degree_sequence<RfmModel>(
      options, tolerance,
      [&](const DiscretizationOptions &o) {
        return std::make_unique<RfmModel>(problem, o, std::nullopt);
      },
      [](const RfmModel &m) { return m.solution().functionals().indicator(); });
  }
} // namespace rfm
