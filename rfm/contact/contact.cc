#include "rfm/contact/contact.h"

#include "rfm/contact/contact_methods.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rfm
{
  using axisym::Die;
  using axisym::Geometry;
  using axisym::InputError;
  using axisym::Loading;
  using axisym::Problem;

  namespace
  {
    // Linear interpolation of the zero of f between (z0, f0) and (z1, f1), f0 f1 <= 0.
    double zero_between(double z0, double f0, double z1, double f1)
    {
      return f0 == f1 ? z0 : z0 + (z1 - z0) * f0 / (f0 - f1);
    }
  } // namespace

  std::unique_ptr<OutlineModel> solve_cylinder_zone(const Problem &problem,
                                                    const DiscretizationOptions &discretization,
                                                    const double c, const SolverOptions &solver)
  {
    // The body from the legacy fields, which callers may have changed after parsing.
    axisym::Problem q = problem;
    q.body = axisym::legacy_body(problem);
    return std::make_unique<OutlineModel>(q, discretization, solver,
                                          std::vector<DieZone>{{"outer", 0.0, c, problem.die->indentation}});
  }

  double zone_half_width(const OutlineModel &model)
  {
    return model.zones().at(0).s_hi;
  }

  std::vector<std::pair<double, double>> contact_pressure(const OutlineModel &model, const double c,
                                                          const int n)
  {
    const double r2 = model.body().outline.bounding_box().r_max;
    const Eigen::VectorXd z = Eigen::VectorXd::LinSpaced(n, 0.0, c);
    const FieldValues f = model.evaluate(Eigen::VectorXd::Constant(n, r2), z);
    std::vector<std::pair<double, double>> out;
    for (int k = 0; k < n; ++k)
      out.emplace_back(z[k], -f.sigma(k, rr));
    return out;
  }

  double edge_intensity_reciprocal_work(const OutlineModel &model, const Problem &problem,
                                        const double c, const double rho_1)
  {
    const double r2 = problem.geometry.outer_radius;
    const Material &m = problem.material;
    const double u_edge = die_u_r(*problem.die, problem.geometry, c);
    // J(rho) for a field given at points of the half circle (meridian components).
    const GaussRule1D gt = gauss_on_cells({0.0, 0.5 * M_PI, M_PI}, 32);
    const Eigen::Index n_t = gt.nodes.size();
    Eigen::VectorXd r(n_t), z(n_t);
    for (Eigen::Index k = 0; k < n_t; ++k)
      r[k] = r2 - rho_1 * std::sin(gt.nodes[k]), z[k] = c - rho_1 * std::cos(gt.nodes[k]);
    auto interaction = [&](auto field_at) {
      double j = 0.0;
      for (Eigen::Index k = 0; k < n_t; ++k)
        {
          // e_rho = (cos t) e_x + (sin t) e_y, e_x = -e_z, e_y = -e_r.
          const double n_r = -std::sin(gt.nodes[k]), n_z = -std::cos(gt.nodes[k]);
          const auto [s, u] = field_at(k);   // s = (rr, zz, tt, rz), u = (u_r, u_z)
          const EdgeModeValue a = edge_mode(-1, r[k], z[k], r2, c, m);
          const double t_r = s[rr] * n_r + s[rz] * n_z, t_z = s[rz] * n_r + s[zz] * n_z;
          const double ta_r = a.sigma[rr] * n_r + a.sigma[rz] * n_z;
          const double ta_z = a.sigma[rz] * n_r + a.sigma[zz] * n_z;
          j += gt.weights[k] * rho_1 * (t_r * a.u_r + t_z * a.u_z - ta_r * u[0] - ta_z * u[1]);
        }
      return j;
    };
    // 1. The n = 1 mode with itself: C.
    const double c1 = interaction([&](Eigen::Index k) {
      const EdgeModeValue v = edge_mode(1, r[k], z[k], r2, c, m);
      return std::pair{v.sigma, Eigen::Vector2d(v.u_r, v.u_z)};
    });
    // 2. The RFM field, translated so that u_r = 0 at the edge.
    const FieldValues f = model.evaluate(r, z);
    const double j_h = interaction([&](Eigen::Index k) {
      return std::pair{Eigen::Vector4d(f.sigma.row(k).transpose()),
                       Eigen::Vector2d(f.u(k, 0) - u_edge, f.u(k, 1))};
    });
    // 3. The contact face x in (0, rho_1): outward normal -e_y = +e_r; the aux traction there
    //    is s*_rr e_r (s*_rz = 0) and u~_r = u_r* - u_r*(c) is prescribed.
    const GaussRule1D gx = gauss_on_cells({0.0, rho_1}, 24, {0.0});
    double face = 0.0;
    for (Eigen::Index k = 0; k < gx.nodes.size(); ++k)
      {
        const double zk = c - gx.nodes[k];
        const EdgeModeValue a = edge_mode(-1, r2, zk, r2, c, m);
        face += gx.weights[k] * a.sigma[rr] * (die_u_r(*problem.die, problem.geometry, zk) - u_edge);
      }
    // Betti on the region between the half circle and the edge: J(rho_1) = J(0+) + face,
    // with the face term's sign from t* . u~ = s*_rr u~_r on the contact face.
    const double a_1 = (j_h - face) / c1;
    return std::sqrt(2.0 * M_PI) * a_1;
  }

  double interaction_radius(const Geometry &g, const double c)
  {
    return 0.9 * std::min({c, g.half_length() - c, g.outer_radius - g.inner_radius});
  }

  Quadrature2D interaction_quadrature(const Geometry &g, const double c, const double rho_1)
  {
    return interaction_quadrature(EdgeFrame::outer_side(g.outer_radius, c), rho_1);
  }

  double edge_intensity_interaction(const OutlineModel &model, const Problem &problem,
                                    const double c, const double rho_1)
  {
    return edge_intensity_interaction(
      [&model](const Eigen::Ref<const Eigen::VectorXd> &r,
               const Eigen::Ref<const Eigen::VectorXd> &z) { return model.evaluate(r, z); },
      problem, c, rho_1);
  }

  double edge_intensity_interaction(const FieldEvaluator &field, const Problem &problem,
                                    const double c, const double rho_1)
  {
    const double p_out = problem.loading ? problem.loading->outer_pressure : 0.0;
    return edge_intensity_interaction(
      field, EdgeFrame::outer_side(problem.geometry.outer_radius, c), problem.material, rho_1,
      [&](double x) { return die_u_r(*problem.die, problem.geometry, c - x); }, p_out);
  }



  std::vector<std::pair<double, double>> consistent_contact_pressure(const OutlineModel &model,
                                                                     const Problem &problem,
                                                                     const double c, const int n,
                                                                     const int n_moments)
  {
    const double r1 = problem.geometry.inner_radius, r2 = problem.geometry.outer_radius;
    // U_m(x) and U_m'(x) for m = 0..2 (n_moments - 1) by the recurrence
    // U_{m+1} = 2 x U_m - U_{m-1} (and its derivative).
    const int m_max = 2 * (n_moments - 1);
    // Beyond the zone (|x| > 1) the test functions are continued by their end value U_m(1):
    // the polynomial continuation grows like (2x)^m and amplifies the stress error on the
    // free part in the high moments (measured: p(0) off by 450 % with 7 moments at p = 8).
    auto chebyshev_u = [m_max](double x, std::vector<double> &u, std::vector<double> &du) {
      u.assign(m_max + 1, 0.0), du.assign(m_max + 1, 0.0);
      if (x > 1.0)
        {
          for (int m = 0; m <= m_max; ++m)
            u[m] = m + 1.0; // U_m(1), constant beyond the zone
          return;
        }
      u[0] = 1.0;
      if (m_max >= 1)
        u[1] = 2.0 * x, du[1] = 2.0;
      for (int m = 1; m < m_max; ++m)
        {
          u[m + 1] = 2.0 * x * u[m] - u[m - 1];
          du[m + 1] = 2.0 * u[m] + 2.0 * x * du[m] - du[m - 1];
        }
    };
    std::vector<double> u, du;

    // 1. Domain part: int s_h . e(V_k) for all k at once, on the assembly's rules.
    Eigen::VectorXd moments = -model.integrate(
      [&](const FieldValues &f, const Eigen::VectorXd &r, const Eigen::VectorXd &z) -> Eigen::MatrixXd {
        Eigen::MatrixXd g(r.size(), n_moments);
        for (Eigen::Index q = 0; q < r.size(); ++q)
          {
            chebyshev_u(z[q] / c, u, du);
            const double psi = (r[q] - r1) / (r2 - r1), dpsi = 1.0 / (r2 - r1);
            for (int k = 0; k < n_moments; ++k)
              g(q, k) = f.sigma(q, rr) * u[2 * k] * dpsi + f.sigma(q, tt) * u[2 * k] * psi / r[q] +
                        f.sigma(q, rz) * du[2 * k] / c * psi;
          }
        return g;
      });
    // 2. Work of the prescribed tractions on V_k.
    moments += model.traction_work([&](const Eigen::VectorXd &r, const Eigen::VectorXd &z) {
      Eigen::MatrixXd v = Eigen::MatrixXd::Zero(r.size(), 2 * n_moments);
      for (Eigen::Index q = 0; q < r.size(); ++q)
        {
          chebyshev_u(z[q] / c, u, du);
          for (int k = 0; k < n_moments; ++k)
            v(q, 2 * k) = u[2 * k] * (r[q] - r1) / (r2 - r1);
        }
      return v;
    });
    // 3. p(z) from the orthogonal expansion.
    std::vector<std::pair<double, double>> out;
    for (int i = 0; i < n; ++i)
      {
        const double z = c * i / (n - 1.0), x = z / c;
        chebyshev_u(x, u, du);
        double p = 0.0;
        for (int k = 0; k < n_moments; ++k)
          p += 2.0 * moments[k] / (M_PI * r2 * c) * u[2 * k];
        out.emplace_back(z, std::sqrt(std::max(0.0, 1.0 - x * x)) * p);
      }
    return out;
  }

  nlohmann::json to_json(const ContactIterate &it, const Problem &problem)
  {
    // The iterate's own a and delta (check_die_conditions); the legacy fields before a check.
    const double a = it.extent > 0.0 ? it.extent : problem.geometry.half_length();
    const double delta =
      it.indentation > 0.0 ? it.indentation : (problem.die ? problem.die->indentation : 1.0);
    return {{"phase", it.phase},
            {"half_width", it.half_width},
            {"half_width_ratio", it.half_width / a},
            {"indentation", it.indentation},
            {"force", it.force},
            {"force_trace", it.force_trace},
            {"edge_intensity", std::isfinite(it.edge_intensity) ? nlohmann::json(it.edge_intensity)
                                                                 : nlohmann::json(nullptr)},
            {"edge_intensity_reciprocal_work",
             std::isfinite(it.edge_intensity_reciprocal_work)
               ? nlohmann::json(it.edge_intensity_reciprocal_work)
               : nlohmann::json(nullptr)},
            {"edge_intensity_coefficient",
             std::isfinite(it.edge_intensity_coefficient)
               ? nlohmann::json(it.edge_intensity_coefficient)
               : nlohmann::json(nullptr)},
            {"lagrange", it.lagrange},
            {"castigliano", it.castigliano},
            {"reissner", it.reissner},
            {"max_tension", it.max_tension},
            {"max_penetration", it.max_penetration},
            {"max_tension_relative", it.max_tension / std::max(it.peak_pressure, 1e-300)},
            {"max_penetration_relative", it.max_penetration / delta},
            {"condition_1_2_holds", !it.tension},
            {"condition_1_3_holds", !it.penetration},
            {"conditions_hold", it.conditions_hold()},
            {"seconds", it.assembly_s + it.solve_s}};
  }

  nlohmann::json to_json(const ContactResult &result, const Problem &problem,
                         const int pressure_points)
  {
    const double a = problem.geometry.half_length();
    nlohmann::json out = {{"method", result.method}, {"message", result.message}};
    nlohmann::json iterations = nlohmann::json::array();
    for (const ContactIterate &it : result.history)
      iterations.push_back(to_json(it, problem));
    out["iterations"] = iterations;
    if (!result.success)
      return out;
    const ContactIterate &f = result.final;
    out["half_width"] = f.half_width;
    out["half_width_ratio"] = f.half_width / a;
    out["force"] = f.force;
    out["force_trace"] = f.force_trace;
    out["edge_intensity"] = std::isfinite(f.edge_intensity) ? nlohmann::json(f.edge_intensity)
                                                            : nlohmann::json(nullptr);
    if (result.half_width_range)
      out["half_width_range"] = {result.half_width_range->first, result.half_width_range->second};
    if (result.edge_intensity_root)
      out["edge_intensity_root"] = *result.edge_intensity_root;
    out["conditions"] = to_json(f, problem);
    if (pressure_points <= 0)
      return out;
    // p: the trace -sigma_rr(R2, z); p_consistent: the consistent reactions.
    nlohmann::json pressure = nlohmann::json::array();
    const double c = f.half_width;
    const auto trace = contact_pressure(*result.model, c, pressure_points);
    const auto consistent =
      c < a ? consistent_contact_pressure(*result.model, problem, c, pressure_points,
                                          default_pressure_moments)
            : decltype(trace){};
    for (std::size_t i = 0; i < trace.size(); ++i)
      {
        nlohmann::json e = {{"z", trace[i].first}, {"p", trace[i].second}};
        if (!consistent.empty())
          e["p_consistent"] = consistent[i].second;
        pressure.push_back(e);
      }
    out["pressure"] = pressure;
    return out;
  }

  ContactIterate check_contact(const Problem &problem, const OutlineModel &model,
                               const ContactOptions &options)
  {
    const double a = problem.geometry.half_length();
    const double c = zone_half_width(model);
    ContactIterate it;
    it.half_width = c;
    const OutlineModel::DieForce force = model.die_force("outer");
    it.force = force.domain;
    it.force_trace = force.trace;
    const Functionals phi = model.functionals();
    it.lagrange = phi.lagrange, it.castigliano = phi.castigliano, it.reissner = phi.reissner;
    it.assembly_s = model.assembly_seconds(), it.solve_s = model.solve_seconds();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const EdgeEnrichment *e = model.n_zone_edges() > 0 ? &model.zone_edge_enrichment(0) : nullptr;
    it.edge_intensity_coefficient =
      c < a && e && e->singular_column() >= 0
        ? std::sqrt(2.0 * M_PI) * model.edge_column_coefficients(0, e->singular_column())[0]
        : nan;
    const bool unloaded_free_part =
      !problem.loading || problem.loading->outer_pressure == 0.0;
    it.edge_intensity_reciprocal_work =
      (c < a && e && unloaded_free_part)
        ? edge_intensity_reciprocal_work(model, problem, c, 0.05 * e->cutoff_radius())
        : nan;
    it.edge_intensity =
      (c < a && e) ? edge_intensity_interaction(model, problem, c,
                                                interaction_radius(problem.geometry, c))
                   : nan;
    check_die_conditions(model, axisym::legacy_body(problem), it.edge_intensity, options, it);
    return it;
  }

  void check_die_conditions(const OutlineModel &model, const axisym::Body &body, const double k_edge,
                            const ContactOptions &options, ContactIterate &it)
  {
    const DieZone &zone = model.zones().at(0);
    const axisym::DieFrame frame = axisym::die_frame(body, zone.part);
    const axisym::DieProfile &profile = body.conditions.at(zone.part).die.profile;
    // The free side: s > 0 for a zone [0, c], s < 0 for [-c, 0]; t = |s| from the centre.
    const double sign = zone.s_hi > 0.0 ? 1.0 : -1.0;
    const double c = sign > 0 ? zone.s_hi : -zone.s_lo;
    const double a = sign > 0 ? frame.s_max : -frame.s_min;
    const double delta = zone.indentation;
    it.indentation = delta, it.extent = a;

    // Grid along the free side with c itself as a node,
    const int n = options.n_check_points;
    std::vector<double> ts;
    for (int k = 0; k < n; ++k)
      ts.push_back(a * k / (n - 1.0));
    ts.push_back(c);
    // and points graded toward c beyond it, c (1 + 10^-k): a zone too short shows first
    // there (its penetration grows like sqrt(t - c), the die's gap like t - c). A zone too
    // long shows inside it, where the edge term's tension grows like (c - t)^(-1/2) against a
    // smooth pressure that falls to zero: the uniform grid resolves that when its spacing is
    // at most c / 1000 (the hollow cylinder, c about a / 2); a zone small against its part
    // (a Hertz zone 1/23 of its face: c / 90) gets points c (1 - 10^-k) as well.
    const bool grade_inside = a / (n - 1.0) > 1e-3 * c;
    for (int k = 2; k <= 6; ++k)
      {
        if (const double tk = c * (1.0 + std::pow(10.0, -k)); tk < a)
          ts.push_back(tk);
        if (grade_inside)
          ts.push_back(c * (1.0 - std::pow(10.0, -k)));
      }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    const auto n_t = static_cast<Eigen::Index>(ts.size());
    const Eigen::Map<const Eigen::VectorXd> t(ts.data(), n_t);
    Eigen::VectorXd r(n_t), z(n_t);
    for (Eigen::Index k = 0; k < n_t; ++k)
      {
        const axisym::Point x = frame.point_at(sign * t[k]);
        r[k] = x.r, z[k] = x.z;
      }
    FieldValues f = model.evaluate(r, z);
    // The edge term: the n = 1 amplitude of both spaces replaced by the given K. The discrete
    // coefficients carry the unresolved edge field (on the hollow cylinder their root lies
    // 0.4-0.8 % above the FEM's c at p = 8-16), and the traces' sign near the edge, which
    // decides conditions 1.2 and 1.3 there, is that amplitude's.
    const EdgeEnrichment *e = model.n_zone_edges() > 0 ? &model.zone_edge_enrichment(0) : nullptr;
    if (e && std::isfinite(k_edge) && e->singular_column() >= 0)
      {
        const Eigen::Index j = e->singular_column();
        const double a_1 = k_edge / std::sqrt(2.0 * M_PI);
        const auto [q_s, q_u] = model.edge_column_coefficients(0, j);
        // Only the points in the columns' support |t - c| < rho_0 (t is sorted).
        const double rho_0 = e->cutoff_radius();
        const auto first = std::lower_bound(ts.begin(), ts.end(), c - rho_0) - ts.begin();
        const auto last = std::upper_bound(ts.begin(), ts.end(), c + rho_0) - ts.begin();
        if (last > first)
          {
            const Eigen::Index n_near = last - first;
            const EdgeColumns cols = e->evaluate(r.segment(first, n_near), z.segment(first, n_near));
            for (int i = 0; i < 4; ++i)
              f.sigma.col(i).segment(first, n_near) += (a_1 - q_s) * cols.stress[i].col(j);
            for (int i = 0; i < 2; ++i)
              f.u.col(i).segment(first, n_near) += (a_1 - q_u) * cols.u[i].col(j);
          }
      }
    const double nr = frame.normal.r, nz = frame.normal.z;
    auto pressure = [&](const Eigen::Index k) {
      return -(f.sigma(k, rr) * nr * nr + 2.0 * f.sigma(k, rz) * nr * nz + f.sigma(k, zz) * nz * nz);
    };
    // How far the part enters the die: (delta - g0) + u . n (> 0: penetration).
    auto penetration = [&](const Eigen::Index k) {
      return (delta - profile.gap(t[k])) + (f.u(k, 0) * nr + f.u(k, 1) * nz);
    };

    // Condition 1.2 inside the zone: p = -sigma_nn >= 0.
    double p_peak = 0.0;
    for (Eigen::Index k = 0; k < n_t && t[k] <= c; ++k)
      p_peak = std::max(p_peak, pressure(k));
    it.peak_pressure = p_peak;
    const double tol_p = options.violation_tolerance * std::max(p_peak, 1e-300);
    it.first_tension_z = c;
    it.max_tension = 0.0, it.tension = false;
    for (Eigen::Index k = 0; k < n_t && t[k] <= c; ++k)
      {
        const double p = pressure(k);
        it.max_tension = std::max(it.max_tension, -p);
        if (p < -tol_p && !it.tension)
          {
            it.tension = true;
            // Walk back to the last non-negative pressure: the zero where it turns tensile.
            Eigen::Index j = k;
            while (j > 0 && pressure(j - 1) < 0.0)
              --j;
            it.first_tension_z = j == 0 ? 0.0
                                        : zero_between(t[j - 1], pressure(j - 1), t[j], pressure(j));
          }
      }

    // Condition 1.3 outside the zone: no penetration.
    const double tol_u = options.penetration_tolerance * delta;
    it.penetration_end_z = c;
    it.max_penetration = 0.0, it.penetration = false;
    bool in_run = false, run_done = false;
    for (Eigen::Index k = 0; k < n_t; ++k)
      {
        if (t[k] <= c)
          continue;
        const double pen = penetration(k);
        it.max_penetration = std::max(it.max_penetration, pen);
        if (pen > tol_u)
          {
            it.penetration = true;
            if (!run_done)
              in_run = true;
          }
        if (in_run && !run_done && pen <= 0.0)
          {
            it.penetration_end_z = zero_between(t[k - 1], penetration(k - 1), t[k], pen);
            run_done = true;
          }
      }
    if (in_run && !run_done)
      it.penetration_end_z = a;
  }

  bool contact_methods::ZoneTrials::solve(const double c, ContactIterate &it, const char *phase)
  {
    std::unique_ptr<OutlineModel> model;
    try
      {
        model = model_at(c);
      }
    catch (const InputError &)
      {
        throw; // bad input, not a numerical failure
      }
    catch (const std::runtime_error &e)
      {
        result.message = e.what();
        return false;
      }
    if (!model->ok())
      {
        std::ostringstream msg;
        msg << "solve at c = " << c << " m failed: " << model->summary().message;
        result.message = msg.str();
        return false;
      }
    it = check(*model);
    it.phase = phase;
    result.history.push_back(it);
    result.model = std::move(model);
    result.final = it;
    if (on_step)
      on_step(it);
    return true;
  }

  ContactResult solve_contact(const Problem &problem, const DiscretizationOptions &discretization,
                              const ContactOptions &options)
  {
    ContactResult result;
    result.method = problem.contact.method;
    contact_methods::ZoneTrials s{
      problem, discretization, options, result, problem.geometry.half_length(),
      [&](const double c) { return solve_cylinder_zone(problem, discretization, c); },
      [&](const OutlineModel &model) { return check_contact(problem, model, options); },
      false, false, 0.05 * problem.geometry.half_length()};
    if (problem.contact.method == "fixed")
      {
        ContactIterate it;
        result.success = s.solve(problem.contact.half_width.value_or(problem.geometry.half_length()),
                                 it, "fixed");
        if (result.success)
          result.message = it.conditions_hold() ? "fixed zone; conditions 1.2 and 1.3 hold"
                                                : "fixed zone; conditions 1.2/1.3 violated "
                                                  "(expected unless c is the true half-width)";
      }
    else if (problem.contact.method == "edge-intensity")
      contact_methods::edge_intensity(s);
    else if (problem.contact.method == "iterate")
      contact_methods::iterate(s);
    else
      contact_methods::max_force(s);
    return result;
  }
} // namespace rfm
