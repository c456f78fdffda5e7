#include "rfm/spaces/traction_jump.h"

#include "problem/wedge_modes.h"
#include "rfm/material.h"
#include "rfm/spaces/edge_modes.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rfm
{
  std::optional<TractionJump> TractionJump::make(const axisym::OutlineEdge &arriving,
                                                 const FaceLoad &on_arriving,
                                                 const axisym::OutlineEdge &leaving,
                                                 const FaceLoad &on_leaving, const double cutoff_radius,
                                                 const double poisson_ratio, const bool hoop_shadow,
                                                 std::string *why)
  {
    auto fail = [why](const char *reason) -> std::optional<TractionJump> {
      if (why)
        *why = reason;
      return std::nullopt;
    };
    if (!(cutoff_radius > 0.0))
      throw std::invalid_argument("TractionJump: the cutoff radius must be positive");
    using Kind = axisym::OutlineEdge::Kind;
    if ((arriving.kind == Kind::arc && !on_arriving.follows_normal) ||
        (leaving.kind == Kind::arc && !on_leaving.follows_normal))
      return fail("an arc carries a fixed traction vector");

    TractionJump j;
    j.frame_ = WedgeFrame(arriving, leaving);
    j.cutoff_radius_ = cutoff_radius;
    j.poisson_ratio_ = poisson_ratio;

    // The faces' outward normals and tractions at v.
    const axisym::Point n[2] = {leaving.outward_normal_at(0.0), arriving.outward_normal_at(1.0)};
    const std::array<double, 2> t[2] = {on_leaving.traction, on_arriving.traction};
    Eigen::Vector4d rhs(t[0][0], t[0][1], t[1][0], t[1][1]);
    const double scale = rhs.cwiseAbs().maxCoeff();
    if (!(scale > 0.0))
      return fail("both faces are free at the vertex");

    // A constant stress (rr, zz, rz) with S n_f = t_f on both faces: no jump.
    Eigen::Matrix<double, 4, 3> constant;
    for (int f = 0; f < 2; ++f)
      {
        constant.row(2 * f) << n[f].r, 0.0, n[f].z;
        constant.row(2 * f + 1) << 0.0, n[f].z, n[f].r;
      }
    const Eigen::Vector3d s_const = constant.colPivHouseholderQr().solve(rhs);
    if ((constant * s_const - rhs).norm() <= 1e-12 * scale)
      return fail("a constant stress meets both faces' tractions");

    // The wedge: the tractions of the unit coefficients at theta = 0 and beta.
    Eigen::Matrix4d m;
    for (int k = 0; k < 4; ++k)
      {
        j.coefficients_ = {0, 0, 0, 0};
        j.coefficients_[k] = 1.0;
        for (int f = 0; f < 2; ++f)
          {
            const std::array<double, 3> s = j.wedge_stress(f == 0 ? 0.0 : j.frame_.angle());
            m(2 * f, k) = s[0] * n[f].r + s[2] * n[f].z;
            m(2 * f + 1, k) = s[2] * n[f].r + s[1] * n[f].z;
          }
      }
    Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix4d> cod(m);
    cod.setThreshold(1e-12);
    const Eigen::Vector4d x = cod.solve(rhs);
    if ((m * x - rhs).norm() > 1e-9 * scale || x.cwiseAbs().maxCoeff() > 1e4 * scale)
      return fail("the wedge has no stress field of degree 0 for these tractions (a log term)");
    j.coefficients_ = {x[0], x[1], x[2], x[3]};
    if (hoop_shadow && j.frame_.vertex().r > 0.0 && x[3] != 0.0)
      j.make_shadow();
    return j;
  }

  void TractionJump::make_shadow()
  {
    const double r_v = frame_.vertex().r, alpha = 0.5 * frame_.angle(), nu = poisson_ratio_;
    const WedgeCollocation c(alpha, nu, axisym::WedgeFace::free, axisym::WedgeFace::free, 40);
    const int n = c.size(), N = n - 1;
    const double a = c.a(), kappa = 3.0 - 4.0 * nu;
    // The D term for D / mu = 1: u / rho = U_0 + ln rho U_1 (polar), U_0 = ((kappa - 1) theta / 2,
    // (kappa + 1) ln rho_0 / 2), U_1 = (0, -(kappa + 1) / 2); h = u_r / r_v = rho (H_0 + ln rho H_1).
    Eigen::VectorXd h0(n), h1(n), c_rho(n), c_th(n);
    for (int j = 0; j < n; ++j)
      {
        const double theta = c.angle(j) + alpha, phi = frame_.leaving_direction() + theta;
        const double cs = std::cos(phi), sn = std::sin(phi);
        const double u0_p = 0.5 * (kappa - 1.0) * theta, u0_q = 0.5 * (kappa + 1.0) * std::log(cutoff_radius_);
        const double u1_q = -0.5 * (kappa + 1.0);
        h0[j] = (u0_p * cs - u0_q * sn) / r_v;
        h1[j] = -u1_q * sn / r_v;
        // The stresses over mu, 2 theta, 2 theta, -1; the equilibrium's (sigma_rr - sigma_tt,
        // sigma_rz) / r_v in polar components, sigma_tt = nu (sigma_rr + sigma_zz).
        const double s_pp = 2.0 * theta, s_qq = 2.0 * theta, s_pq = -1.0;
        const std::array<double, 3> s = turned_tensor(s_pp, s_qq, s_pq, cs, sn);
        const double cx = s[0] - nu * (s_pp + s_qq), cy = s[2];
        c_rho[j] = (cx * cs + cy * sn) / r_v;
        c_th[j] = (-cx * sn + cy * cs) / r_v;
      }
    const Eigen::VectorXd dh0 = c.derivative() * h0, dh1 = c.derivative() * h1;
    // b = a grad h + c: level 0 a (H_0 + H_1, H_0') + c, level 1 a (H_1, H_1'); the free faces'
    // rows: S_thth + a H = 0, S_rhoth = 0.
    Eigen::VectorXd rhs0 = Eigen::VectorXd::Zero(2 * n), rhs1 = Eigen::VectorXd::Zero(2 * n);
    for (int j = 1; j < N; ++j)
      {
        rhs0[j] = -(a * (h0[j] + h1[j]) + c_rho[j]);
        rhs0[n + j] = -(a * dh0[j] + c_th[j]);
        rhs1[j] = -a * h1[j];
        rhs1[n + j] = -a * dh1[j];
      }
    for (const int j : {0, N})
      {
        rhs0[j] = -a * h0[j];
        rhs1[j] = -a * h1[j];
      }
    shadow_ = LogSeriesShadow(c, 2.0, {rhs0, rhs1}, {h0, h1});
    // The collocation's self-check (8e-12 and 2e-11 on the pressure band and issue 24's hub).
    has_shadow_ = shadow_.residual() < 1e-8;
  }

  std::array<double, 3> TractionJump::wedge_stress(const double theta) const
  {
    const auto [a, b, c, d] = coefficients_;
    const double c2 = std::cos(2.0 * theta), s2 = std::sin(2.0 * theta);
    const double s_pp = 2 * a - 2 * b * c2 - 2 * c * s2 + 2 * d * theta;
    const double s_qq = 2 * a + 2 * b * c2 + 2 * c * s2 + 2 * d * theta;
    const double s_pq = 2 * b * s2 - 2 * c * c2 - d;
    const double gamma = frame_.leaving_direction();
    return turned_tensor(s_pp, s_qq, s_pq, std::cos(gamma + theta), std::sin(gamma + theta));
  }

  Eigen::MatrixXd TractionJump::displacement(const Eigen::Ref<const Eigen::VectorXd> &r,
                                             const Eigen::Ref<const Eigen::VectorXd> &z,
                                             const double mu) const
  {
    Eigen::MatrixXd u(r.size(), 2);
    const double d_ = coefficients_[3];
    const double kappa = 3.0 - 4.0 * poisson_ratio_;
    for (Eigen::Index k = 0; k < r.size(); ++k)
      {
        const double rho = std::hypot(r[k] - frame_.vertex().r, z[k] - frame_.vertex().z);
        if (!(rho > 1e-14 * cutoff_radius_))
          {
            u(k, 0) = u(k, 1) = 0.0;
            continue;
          }
        const auto [theta, a] = frame_.mapped_angle(r[k], z[k], 1e-14 * cutoff_radius_);
        double u_p = (kappa - 1.0) * d_ * theta * rho / (2.0 * mu);
        double u_q = -(kappa + 1.0) * d_ * rho * std::log(rho / cutoff_radius_) / (2.0 * mu);
        if (has_shadow_)
          {
            const LogSeriesShadow::Values v = shadow_.evaluate(rho, theta - 0.5 * frame_.angle());
            u_p += d_ / mu * v.u[0];
            u_q += d_ / mu * v.u[1];
          }
        // Polar to (r, z) at the mapped angle, then turned by a.
        const double phi = frame_.leaving_direction() + theta + a;
        u(k, 0) = u_p * std::cos(phi) - u_q * std::sin(phi);
        u(k, 1) = u_p * std::sin(phi) + u_q * std::cos(phi);
      }
    return u;
  }

  Eigen::MatrixXd TractionJump::stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                                       const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    Eigen::MatrixXd s(r.size(), 4);
    for (Eigen::Index k = 0; k < r.size(); ++k)
      {
        const auto [theta, a] = frame_.mapped_angle(r[k], z[k], 1e-14 * cutoff_radius_);
        std::array<double, 3> w = wedge_stress(theta);
        const double rho = std::hypot(r[k] - frame_.vertex().r, z[k] - frame_.vertex().z);
        if (has_shadow_ && rho > 1e-14 * cutoff_radius_)
          {
            const LogSeriesShadow::Values v = shadow_.evaluate(rho, theta - 0.5 * frame_.angle());
            const double d_ = coefficients_[3], phi = frame_.leaving_direction() + theta;
            const std::array<double, 3> t =
              turned_tensor(d_ * v.s[0], d_ * v.s[1], d_ * v.s[2], std::cos(phi), std::sin(phi));
            for (int i = 0; i < 3; ++i)
              w[i] += t[i];
          }
        // Q(a) S Q(a)^T.
        const auto [s_rr, s_zz, s_rz] = turned_tensor(w[0], w[1], w[2], std::cos(a), std::sin(a));
        s(k, rr) = s_rr, s(k, zz) = s_zz, s(k, rz) = s_rz;
        s(k, tt) = poisson_ratio_ * (s_rr + s_zz);
      }
    return s;
  }

  Eigen::VectorXd TractionJump::cutoff(const Eigen::Ref<const Eigen::VectorXd> &r,
                                       const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    Eigen::VectorXd chi(r.size());
    for (Eigen::Index k = 0; k < r.size(); ++k)
      chi[k] = edge_cutoff(std::hypot(r[k] - frame_.vertex().r, z[k] - frame_.vertex().z), cutoff_radius_).value;
    return chi;
  }

  Quadrature2D TractionJump::near_rule(const int n_radial, const int n_angular, const int n_layers,
                                   const std::vector<Circle> &rims, const int n_beyond_rims) const
  {
    return frame_.near_rule(cutoff_radius_, n_radial, n_angular, n_layers, rims, n_beyond_rims);
  }

  std::optional<TractionJump::FaceLoad> face_load(const axisym::Body &body, const axisym::OutlineEdge &e,
                                                  const double t)
  {
    const std::optional<axisym::Point> traction = axisym::edge_traction(body, e, t);
    if (!traction)
      return std::nullopt;
    // A free face's or a pressure's traction turns with the normal on an arc; a fixed
    // traction vector does not.
    return TractionJump::FaceLoad{{traction->r, traction->z},
                                  body.conditions.at(e.part).kind != axisym::PartCondition::Kind::traction};
  }

  std::vector<std::size_t> traction_jump_vertices(const axisym::Body &body, const double poisson_ratio)
  {
    const std::vector<axisym::OutlineEdge> &edges = body.outline.edges();
    const std::vector<axisym::Point> jumps = axisym::traction_jump_vertices(body);
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < edges.size(); ++i)
      {
        const axisym::OutlineEdge &arriving = edges[i], &leaving = edges[(i + 1) % edges.size()];
        // The vertex is the arriving edge's end, the very point the problem layer gives.
        if (std::none_of(jumps.begin(), jumps.end(), [&](const axisym::Point &j) {
              return j.r == arriving.end.r && j.z == arriving.end.z;
            }))
          continue;
        const auto on_arriving = face_load(body, arriving, 1.0), on_leaving = face_load(body, leaving, 0.0);
        if (on_arriving && on_leaving &&
            TractionJump::make(arriving, *on_arriving, leaving, *on_leaving, 1.0, poisson_ratio, false).has_value())
          out.push_back(i);
      }
    return out;
  }
} // namespace rfm
