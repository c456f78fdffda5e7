#include "rfm/fields/vertex_intensity.h"

#include "rfm/fields/interaction_integral.h"

#include <Eigen/LU>

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

  } // namespace

  Quadrature2D vertex_interaction_quadrature(const VertexEnrichment &frame, const double rho_1)
  {
    if (!(rho_1 > 0.0))
      throw std::invalid_argument("vertex_interaction_quadrature: rho_1 must be positive");
    const double alpha = frame.wedge().half_angle(), leaving = frame.bisector_angle() - alpha;
    const VertexEnrichment sector(frame.vertex(), {std::cos(leaving), std::sin(leaving)},
                                  frame.wedge(), {}, rho_1, frame.material());
    return sector.near_rule(8, 12);
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
    const Quadrature2D qd = vertex_interaction_quadrature(frame, rho_1);
    const FieldValues fh = field(qd.r, qd.z);
    const FieldValues fv = field(Eigen::VectorXd::Constant(1, at.r), Eigen::VectorXd::Constant(1, at.z));
    const axisym::BodyLoads &loads = problem.body_loads;
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
            rhs[static_cast<Eigen::Index>(j)] -= qd.weights[k] * (q * div_w + (w_r * e_r + w_z * e_z) * dq);
          }
      }

    // The faces' part where a part carries a traction: int q r t_h . u* ds along each face.
    const double tol = 1e-9 * problem.body->outline.size();
    for (const axisym::OutlineEdge &e : problem.body->outline.edges())
      {
        const bool leaving = std::hypot(e.start.r - at.r, e.start.z - at.z) < tol;
        const bool arriving = std::hypot(e.end.r - at.r, e.end.z - at.z) < tol;
        if (!leaving && !arriving)
          continue;
        if (e.kind != axisym::OutlineEdge::Kind::line)
          throw std::invalid_argument("vertex_intensities: the vertex at (" + std::to_string(at.r) + ", " +
                                      std::to_string(at.z) + ") lies on an arc (part " + e.part + ")");
        const axisym::PartCondition &c = problem.body->conditions.at(e.part);
        using Kind = axisym::PartCondition::Kind;
        if (c.kind != Kind::pressure && c.kind != Kind::traction)
          continue;
        if (!(rho_1 <= e.length() * (1.0 + 1e-12)))
          throw std::invalid_argument("vertex_intensities: rho_1 is longer than part " + e.part);
        const double theta = leaving ? -alpha : alpha, phi = theta + beta;
        const double t_r = std::cos(phi), t_z = std::sin(phi);
        // The outward normal: the body lies toward the bisector.
        const double n_r = leaving ? t_z : -t_z, n_z = leaving ? -t_r : t_r;
        const double tr_r = c.kind == Kind::pressure ? -c.pressure * n_r : c.traction[0];
        const double tr_z = c.kind == Kind::pressure ? -c.pressure * n_z : c.traction[1];
        // Geometric cells toward the vertex, where u* grows like x^(-Re lambda).
        std::vector<double> cells{0.0};
        for (int l = 8; l >= 0; --l)
          cells.push_back(rho_1 * std::pow(0.2, l));
        const GaussRule1D gx = gauss_on_cells(cells, 12, {0.0});
        for (Eigen::Index k = 0; k < gx.nodes.size(); ++k)
          {
            const double x = gx.nodes[k], r = at.r + x * t_r;
            const double q = interaction_weight(x, rho_1).first;
            for (std::size_t j = 0; j < n; ++j)
              {
                const MeridianWedgeField g = real_field(wedge, duals.modes[duals.mode_of[j]], 1.0, duals.part[j], x,
                                               theta, beta, mu, nu);
                rhs[static_cast<Eigen::Index>(j)] += gx.weights[k] * q * r * (tr_r * g.u[0] + tr_z * g.u[1]);
              }
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
