#include "rfm/fields/vertex_intensity.h"

#include "rfm/fields/interaction_integral.h"
#include "rfm/spaces/wedge_frame.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    using cd = std::complex<double>;

    /// Part `part` of a mode's field scaled by `scale` at (rho, theta) in meridian components.
    MeridianWedgeField real_field(const Wedge &wedge, const WedgeMode &mode, const cd scale, const int part,
                                  const double rho, const double theta, const double beta, const double mu,
                                  const double nu)
    {
      return meridian_wedge_field(wedge.evaluate(mode, rho, theta), scale, part, theta + beta, mu, nu);
    }

    /// The modes' real fields and their duals: field k is part parts[k] of modes[mode_of[k]].
    struct FieldList
    {
      std::vector<WedgeMode> modes;
      std::vector<cd> scales;
      std::vector<std::size_t> mode_of;
      std::vector<int> part;
      void add(const WedgeMode &m, const cd scale)
      {
        modes.push_back(m), scales.push_back(scale);
        for (int p = 0; p < (m.lambda.imag() == 0.0 ? 1 : 2); ++p)
          mode_of.push_back(modes.size() - 1), part.push_back(p);
      }
      std::size_t size() const { return part.size(); }
    };

    /// The outline's edges that arrive at (end at) and leave (start at) `at`.
    std::array<const axisym::OutlineEdge *, 2> faces_at(const axisym::Outline &outline, const axisym::Point at)
    {
      const auto [arriving, leaving] = outline.edges_at(at);
      if (!arriving || !leaving)
        throw std::invalid_argument("vertex_intensities: (" + std::to_string(at.r) + ", " + std::to_string(at.z) +
                                    ") is not a vertex of the outline");
      return {arriving, leaving};
    }

    /// A rule on [0, length] for integrands regular at 0 or ~ x^(-a) (plain length weights):
    /// 12 Gauss points on geometric cells of ratio 0.2, the innermost mapped by x = x_in s^2.
    GaussRule1D face_rule(const double length)
    {
      GaussRule1D g = polar_radial_rule(length, 12, 8);
      g.weights.array() /= g.nodes.array();
      return g;
    }

    /// The polar angle from the bisector `beta` of the point of face `e` at the distance rho from
    /// the vertex (`leaving`: e starts there; else it ends there), from the chord's turn from
    /// the tangent, half the arc's angle, without the cancellation of x - v at small rho.
    double chord_angle(const axisym::OutlineEdge &e, const bool leaving, const double rho, const double beta)
    {
      const axisym::Point t = leaving ? e.tangent_at(0.0) : e.tangent_at(1.0);
      double angle = leaving ? std::atan2(t.z, t.r) : std::atan2(-t.z, -t.r);
      if (e.kind == axisym::OutlineEdge::Kind::arc)
        {
          const double half = std::asin(std::min(1.0, 0.5 * rho / e.radius()));
          const double turn = e.sweep() > 0.0 ? 1.0 : -1.0;
          angle += (leaving ? turn : -turn) * half;
        }
      double theta = angle - beta;
      theta -= 2.0 * pi * std::round(theta / (2.0 * pi));
      return theta;
    }

    /// The rule of the interaction integral: the sector rho < rho_1 of the body about the
    /// vertex (area weights dr dz), and the points of the faces that are arcs within rho_1,
    /// by their distance rho from the vertex (weights ds = drho / cos(phi / 2), phi the arc's
    /// angle from the vertex), with rho and its weight drho, the polar angle, the arc's outward
    /// normal and edge and whether it leaves the vertex at each.
    struct InteractionRule
    {
      Quadrature2D area, arcs;
      std::vector<double> arc_rho, arc_drho, arc_theta;
      std::vector<axisym::Point> normal;
      std::vector<const axisym::OutlineEdge *> edge;
      std::vector<bool> leaving;
    };

    InteractionRule interaction_rule(const VertexEnrichment &frame, const axisym::Outline &outline,
                                     const double rho_1)
    {
      if (!(rho_1 > 0.0))
        throw std::invalid_argument("vertex_interaction_quadrature: rho_1 must be positive");
      const double alpha = frame.wedge().half_angle(), leaving = frame.bisector_angle() - alpha;
      VertexEnrichment sector(frame.vertex(), {std::cos(leaving), std::sin(leaving)}, frame.wedge(), {}, rho_1,
                              frame.material());
      const auto [arriving_edge, leaving_edge] = faces_at(outline, frame.vertex());
      InteractionRule rule;
      const GaussRule1D g = face_rule(rho_1);
      for (const axisym::OutlineEdge *e : {leaving_edge, arriving_edge})
        {
          if (e->kind != axisym::OutlineEdge::Kind::arc)
            continue;
          const double radius = e->radius(), sweep = std::abs(e->sweep());
          if (!(rho_1 < 2.0 * radius * std::sin(0.5 * sweep)))
            throw std::invalid_argument("vertex_intensities: rho_1 reaches beyond the end of part " + e->part);
          const bool from_start = e == leaving_edge;
          const Eigen::Index n0 = rule.arcs.weights.size(), n = g.nodes.size();
          rule.arcs.r.conservativeResize(n0 + n), rule.arcs.z.conservativeResize(n0 + n);
          rule.arcs.weights.conservativeResize(n0 + n);
          for (Eigen::Index k = 0; k < n; ++k)
            {
              const double rho = g.nodes[k], phi = 2.0 * std::asin(0.5 * rho / radius);
              const double t = from_start ? phi / sweep : 1.0 - phi / sweep;
              const axisym::Point x = e->point_at(t);
              rule.arcs.r[n0 + k] = x.r, rule.arcs.z[n0 + k] = x.z;
              rule.arcs.weights[n0 + k] = g.weights[k] / std::cos(0.5 * phi);
              rule.arc_rho.push_back(rho), rule.arc_drho.push_back(g.weights[k]);
              rule.arc_theta.push_back(chord_angle(*e, from_start, rho, frame.bisector_angle()));
              rule.normal.push_back(e->outward_normal_at(t));
              rule.edge.push_back(e);
              rule.leaving.push_back(from_start);
            }
        }
      if (rule.arcs.weights.size() > 0)
        sector.set_curved_faces(WedgeFrame(*arriving_edge, *leaving_edge));
      rule.area = sector.near_rule(8, 12);
      return rule;
    }

    /// int_0^rho_1 q(rho) rho^mu drho for q = 1 - 3 t^2 + 2 t^3, t = rho / rho_1 (Re mu > -1).
    cd weighted_power_integral(const cd mu, const double rho_1)
    {
      return std::pow(cd(rho_1), mu + 1.0) * (1.0 / (mu + 1.0) - 3.0 / (mu + 3.0) + 2.0 / (mu + 4.0));
    }

    /// The points at which the integral asks for the field: the area's, then the arcs'.
    Quadrature2D asked_points(const InteractionRule &rule)
    {
      const Eigen::Index na = rule.area.weights.size(), nf = rule.arcs.weights.size();
      Quadrature2D all;
      all.r.resize(na + nf), all.z.resize(na + nf), all.weights.resize(na + nf);
      all.r << rule.area.r, rule.arcs.r;
      all.z << rule.area.z, rule.arcs.z;
      all.weights << rule.area.weights, rule.arcs.weights;
      return all;
    }
  } // namespace

  Quadrature2D vertex_interaction_quadrature(const VertexEnrichment &frame, const axisym::Problem &problem,
                                             const double rho_1)
  {
    return asked_points(interaction_rule(frame, problem.body->outline, rho_1));
  }

  std::vector<VertexIntensity> vertex_intensities(const FieldEvaluator &field,
                                                  const VertexEnrichment &frame,
                                                  const axisym::Problem &problem, const double rho_1)
  {
    const Wedge &wedge = frame.wedge();
    const axisym::Point at = frame.vertex();
    const double alpha = wedge.half_angle(), beta = frame.bisector_angle();
    const Material &m = problem.material;
    const double nu = m.poisson_ratio, mu = m.youngs_modulus / (2.0 * (1.0 + nu));

    // The singular modes, each scaled to the notch normalization, and their duals.
    FieldList modes, duals;
    std::vector<VertexIntensity> out;
    for (const WedgeMode &mode : frame.modes())
      {
        if (!(mode.lambda.real() < 1.0))
          continue;
        const WedgeFieldValues b = wedge.evaluate(mode, 1.0, 0.0);
        const cd pivot = std::abs(b.s_tt) >= std::abs(b.s_rt) ? b.s_tt : b.s_rt;
        if (std::abs(pivot) == 0.0)
          throw std::logic_error("vertex_intensities: a mode without stress on its bisector");
        modes.add(mode, 1.0 / (std::sqrt(2.0 * pi) * pivot));
        out.push_back({mode.lambda, 0.0});
        // The duals at -lambda, once per exponent (a double root has two).
        if (modes.modes.size() >= 2 &&
            std::abs(modes.modes[modes.modes.size() - 2].lambda - mode.lambda) < 1e-12)
          continue;
        const std::vector<WedgeMode> d = wedge.modes_at(-mode.lambda);
        for (const WedgeMode &g : d)
          duals.add(g, 1.0);
      }
    const std::size_t n = modes.size();
    if (n == 0)
      return out;
    if (duals.size() != n)
      throw std::logic_error("vertex_intensities: " + std::to_string(duals.size()) +
                             " dual fields for " + std::to_string(n) + " modes");

    // B_ij: the plane Betti form of mode field i and dual j on the unit circle,
    // int (s_i e_rho . u*_j - s*_j e_rho . u_i) dtheta.
    std::vector<double> cells;
    const int pieces = static_cast<int>(std::ceil(2.0 * alpha / (0.25 * pi)));
    for (int k = 0; k <= pieces; ++k)
      cells.push_back(-alpha + 2.0 * alpha * k / pieces);
    const GaussRule1D gt = gauss_on_cells(cells, 16);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (Eigen::Index k = 0; k < gt.nodes.size(); ++k)
      {
        const double theta = gt.nodes[k], phi = theta + beta;
        const double e_r = std::cos(phi), e_z = std::sin(phi);
        for (std::size_t i = 0; i < n; ++i)
          {
            const MeridianWedgeField f = real_field(wedge, modes.modes[modes.mode_of[i]], modes.scales[modes.mode_of[i]],
                                           modes.part[i], 1.0, theta, beta, mu, nu);
            for (std::size_t j = 0; j < n; ++j)
              {
                const MeridianWedgeField g = real_field(wedge, duals.modes[duals.mode_of[j]], 1.0, duals.part[j],
                                               1.0, theta, beta, mu, nu);
                b(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) +=
                  gt.weights[k] *
                  ((f.s[rr] * e_r + f.s[rz] * e_z) * g.u[0] + (f.s[rz] * e_r + f.s[zz] * e_z) * g.u[1] -
                   (g.s[rr] * e_r + g.s[rz] * e_z) * f.u[0] - (g.s[rz] * e_r + g.s[zz] * e_z) * f.u[1]);
              }
          }
      }

    // The domain part on the sector, -int (q div W + W . grad q) dr dz, per dual.
    //
    // Its terms u_r s*_tt and - r alpha T tr s*, and the faces' t_h . u*, go like rho^(-a)
    // drho at the vertex (a = Re lambda of the dual's mode): for a near 1 a fixed share of
    // their integrals lies below any radius that points in (r, z) can resolve ((1e-14)^(1 - a)
    // of it below 1e-14 rho_1: 13 % at the 186-degree free wedge's a = 0.9375, where the plain
    // rule gave the mode's K 3.8 % low). So their parts with the vertex's values, u_r(v),
    // r_v alpha T(v) and r_v t_h(v), whose integrals are q rho^mu times a function of the
    // angle, are integrated in closed form in rho (weighted_power_integral) and by Gauss in the
    // angle over the straight wedge, plus the slivers between a face's tangent and its arc
    // (regular, by Gauss in rho); the rules take only the rest, regular at the vertex.
    const InteractionRule rule = interaction_rule(frame, problem.body->outline, rho_1);
    const Quadrature2D &qd = rule.area;
    const Quadrature2D asked = asked_points(rule);
    const FieldValues fh = field(asked.r, asked.z); // the area's points, then the arcs'
    const FieldValues fv = field(Eigen::VectorXd::Constant(1, at.r), Eigen::VectorXd::Constant(1, at.z));
    const axisym::BodyLoads &loads = problem.body_loads;
    const double u_rv = fv.u(0, 0);
    const double thermal_v = loads.thermal() ? at.r * axisym::thermal_strain(loads, m, at.r, at.z) : 0.0;
    // The vertex part of the area's integrand at a dual's stress: u_r(v) s*_tt - r_v alpha T(v) tr s*.
    const auto vertex_part = [&](const MeridianWedgeField &g) {
      return u_rv * g.s[tt] - thermal_v * (g.s[rr] + g.s[zz] + g.s[tt]);
    };
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    for (Eigen::Index k = 0; k < qd.weights.size(); ++k)
      {
        const double r = qd.r[k], z = qd.z[k];
        const double rho = std::hypot(r - at.r, z - at.z);
        if (!(rho > 0.0))
          continue;
        const double e_r = (r - at.r) / rho, e_z = (z - at.z) / rho;
        double theta = std::atan2(e_z, e_r) - beta;
        theta -= 2.0 * pi * std::round(theta / (2.0 * pi));
        const auto [q, dq] = interaction_weight(rho, rho_1);
        const double u_r = fh.u(k, 0), ut_r = u_r - fv.u(0, 0), ut_z = fh.u(k, 1) - fv.u(0, 1);
        const std::array<double, 2> f =
          loads.body_force() ? axisym::body_force(loads, m, r, z) : std::array<double, 2>{0.0, 0.0};
        const double alpha_t = loads.thermal() ? axisym::thermal_strain(loads, m, r, z) : 0.0;
        for (std::size_t j = 0; j < n; ++j)
          {
            const MeridianWedgeField g = real_field(wedge, duals.modes[duals.mode_of[j]], 1.0, duals.part[j], rho,
                                           theta, beta, mu, nu);
            const double w_r = r * (fh.sigma(k, rr) * g.u[0] + fh.sigma(k, rz) * g.u[1] -
                                    g.s[rr] * ut_r - g.s[rz] * ut_z);
            const double w_z = r * (fh.sigma(k, rz) * g.u[0] + fh.sigma(k, zz) * g.u[1] -
                                    g.s[rz] * ut_r - g.s[zz] * ut_z);
            const double div_w = g.u[0] * fh.sigma(k, tt) + u_r * g.s[tt] - g.s[rr] * ut_r -
                                 g.s[rz] * ut_z - r * (f[0] * g.u[0] + f[1] * g.u[1]) -
                                 r * alpha_t * (g.s[rr] + g.s[zz] + g.s[tt]);
            rhs[static_cast<Eigen::Index>(j)] -=
              qd.weights[k] * (q * (div_w - vertex_part(g)) + (w_r * e_r + w_z * e_z) * dq);
          }
      }

    // The vertex parts in closed form: - int q rho^mu rho drho int vertex_part(S*(theta)) dtheta
    // over the straight wedge (S* the dual's stress at rho = 1, mu + 1 = -a + i b its
    // exponent), then the slivers where a face is an arc: the sector's angles at rho run from
    // theta_0(rho) to theta_1(rho), not from -alpha to alpha.
    const auto faces = faces_at(problem.body->outline, at); // arriving, leaving
    const GaussRule1D gr = face_rule(rho_1), g3 = gauss_legendre(4);
    for (std::size_t j = 0; j < n; ++j)
      {
        const WedgeMode &dual = duals.modes[duals.mode_of[j]];
        const cd radial = weighted_power_integral(dual.lambda, rho_1); // s* ~ rho^(lambda - 1), times rho
        for (Eigen::Index k = 0; k < gt.nodes.size(); ++k)
          rhs[static_cast<Eigen::Index>(j)] -=
            gt.weights[k] *
            vertex_part(real_field(wedge, dual, radial, duals.part[j], 1.0, gt.nodes[k], beta, mu, nu));
        for (int f = 0; f < 2; ++f)
          {
            const axisym::OutlineEdge &e = *faces[static_cast<std::size_t>(f)];
            if (e.kind != axisym::OutlineEdge::Kind::arc)
              continue;
            const bool leaving = f == 1;
            const double edge_theta = leaving ? -alpha : alpha;
            for (Eigen::Index k = 0; k < gr.nodes.size(); ++k)
              {
                const double rho = gr.nodes[k], q = interaction_weight(rho, rho_1).first;
                // The sector's angles at rho gain [alpha, theta_1] and lose [-alpha, theta_0].
                const double to = chord_angle(e, leaving, rho, beta), sign = leaving ? -1.0 : 1.0;
                double sliver = 0.0;
                for (Eigen::Index l = 0; l < g3.nodes.size(); ++l)
                  {
                    const double theta = edge_theta + 0.5 * (g3.nodes[l] + 1.0) * (to - edge_theta);
                    sliver += 0.5 * g3.weights[l] * (to - edge_theta) *
                              vertex_part(real_field(wedge, dual, 1.0, duals.part[j], rho, theta, beta, mu, nu));
                  }
                rhs[static_cast<Eigen::Index>(j)] -= gr.weights[k] * q * rho * sign * sliver;
              }
          }
      }

    // The faces' part, int q W . n ds = int q r (t_h . u* - t* . u~) ds: t_h . u* where a face
    // carries a traction (on free faces it is 0; on clamped and symmetry lines both fields'
    // constrained parts vanish), and on an arc also - t* . u~, the dual's traction on it (the
    // dual is traction free on the straight wedge's face, the arc's tangent at the vertex, not
    // on the arc: t* ~ rho^(-lambda) / R there, integrable against u~). The part
    // q r_v t_h(v) . u*(rho, face angle), with the traction at the vertex, in closed form.
    using Kind = axisym::PartCondition::Kind;
    const auto prescribed = [](const axisym::PartCondition &c, const axisym::Point n_out) {
      return c.kind == Kind::pressure ? std::array<double, 2>{-c.pressure * n_out.r, -c.pressure * n_out.z}
             : c.kind == Kind::traction ? std::array<double, 2>{c.traction[0], c.traction[1]}
                                        : std::array<double, 2>{0.0, 0.0};
    };
    std::array<std::array<double, 2>, 2> t_vertex{}; // the faces' tractions at the vertex
    for (int f = 0; f < 2; ++f)
      {
        const axisym::OutlineEdge *e = faces[static_cast<std::size_t>(f)];
        const bool leaving = f == 1;
        const axisym::PartCondition &c = problem.body->conditions.at(e->part);
        if (e->kind != axisym::OutlineEdge::Kind::line &&
            c.kind != Kind::traction_free && c.kind != Kind::pressure && c.kind != Kind::traction)
          throw std::invalid_argument("vertex_intensities: part " + e->part +
                                      " is an arc with a prescribed displacement or a die (the dual modes "
                                      "meet such a condition on lines only)");
        if (c.kind != Kind::pressure && c.kind != Kind::traction)
          continue;
        if (e->kind == axisym::OutlineEdge::Kind::line && !(rho_1 <= e->length() * (1.0 + 1e-12)))
          throw std::invalid_argument("vertex_intensities: rho_1 is longer than part " + e->part);
        const double theta = leaving ? -alpha : alpha;
        t_vertex[static_cast<std::size_t>(f)] = prescribed(c, e->outward_normal_at(leaving ? 0.0 : 1.0));
        const auto [tv_r, tv_z] = t_vertex[static_cast<std::size_t>(f)];
        for (std::size_t j = 0; j < n; ++j)
          {
            const WedgeMode &dual = duals.modes[duals.mode_of[j]];
            const MeridianWedgeField g0 = real_field(wedge, dual, weighted_power_integral(dual.lambda, rho_1),
                                                     duals.part[j], 1.0, theta, beta, mu, nu);
            rhs[static_cast<Eigen::Index>(j)] += at.r * (tv_r * g0.u[0] + tv_z * g0.u[1]);
          }
        if (e->kind != axisym::OutlineEdge::Kind::line)
          continue; // the rest below, with the arcs' points
        // The rest on a line: q (r - r_v) t_h . u*.
        const double phi = theta + beta, t_r = std::cos(phi);
        for (Eigen::Index k = 0; k < gr.nodes.size(); ++k)
          {
            const double x = gr.nodes[k];
            const double q = interaction_weight(x, rho_1).first;
            for (std::size_t j = 0; j < n; ++j)
              {
                const MeridianWedgeField g = real_field(wedge, duals.modes[duals.mode_of[j]], 1.0, duals.part[j], x,
                                               theta, beta, mu, nu);
                rhs[static_cast<Eigen::Index>(j)] += gr.weights[k] * q * x * t_r * (tv_r * g.u[0] + tv_z * g.u[1]);
              }
          }
      }
    for (Eigen::Index k = 0; k < rule.arcs.weights.size(); ++k)
      {
        const Eigen::Index at_k = qd.weights.size() + k; // the field's row
        const std::size_t ks = static_cast<std::size_t>(k);
        const double r = rule.arcs.r[k], rho = rule.arc_rho[ks], theta = rule.arc_theta[ks];
        const double q = interaction_weight(rho, rho_1).first;
        const axisym::Point n_out = rule.normal[ks];
        const auto [tr_r, tr_z] = prescribed(problem.body->conditions.at(rule.edge[ks]->part), n_out);
        const std::size_t f = rule.leaving[ks] ? 1 : 0;
        const auto [tv_r, tv_z] = t_vertex[f];
        const double edge_theta = rule.leaving[ks] ? -alpha : alpha;
        const double ut_r = fh.u(at_k, 0) - fv.u(0, 0), ut_z = fh.u(at_k, 1) - fv.u(0, 1);
        for (std::size_t j = 0; j < n; ++j)
          {
            const WedgeMode &dual = duals.modes[duals.mode_of[j]];
            const MeridianWedgeField g = real_field(wedge, dual, 1.0, duals.part[j], rho, theta, beta, mu, nu);
            const MeridianWedgeField g0 = real_field(wedge, dual, 1.0, duals.part[j], rho, edge_theta, beta, mu, nu);
            const double ts_r = g.s[rr] * n_out.r + g.s[rz] * n_out.z, ts_z = g.s[rz] * n_out.r + g.s[zz] * n_out.z;
            // ds = weight; the closed-form part took q r_v t_h(v) . u*(rho, edge angle) drho.
            rhs[static_cast<Eigen::Index>(j)] +=
              rule.arcs.weights[k] * q * r * (tr_r * g.u[0] + tr_z * g.u[1] - ts_r * ut_r - ts_z * ut_z) -
              rule.arc_drho[ks] * q * at.r * (tv_r * g0.u[0] + tv_z * g0.u[1]);
          }
      }

    // r_v sum_i c_i B_ij = rhs_j for the real fields' coefficients c; K = c_re - i c_im.
    const Eigen::VectorXd c = (at.r * b.transpose()).partialPivLu().solve(rhs);
    Eigen::Index at_c = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      {
        const bool complex = modes.modes[i].lambda.imag() != 0.0;
        out[i].value = complex ? cd(c[at_c], -c[at_c + 1]) : cd(c[at_c], 0.0);
        at_c += complex ? 2 : 1;
      }
    return out;
  }

  nlohmann::json to_json(const std::vector<VertexIntensity> &intensities)
  {
    nlohmann::json j = nlohmann::json::array();
    for (const VertexIntensity &x : intensities)
      j.push_back({{"lambda", {x.lambda.real(), x.lambda.imag()}}, {"K", {x.value.real(), x.value.imag()}}});
    return j;
  }
} // namespace rfm
