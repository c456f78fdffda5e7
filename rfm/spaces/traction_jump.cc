#include "rfm/spaces/traction_jump.h"

#include "rfm/material.h"
#include "rfm/spaces/edge_modes.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    double cross(const axisym::Point a, const axisym::Point b) { return a.r * b.z - a.z * b.r; }
    double dot(const axisym::Point a, const axisym::Point b) { return a.r * b.r + a.z * b.z; }
  } // namespace

  std::optional<TractionJump> TractionJump::make(const axisym::OutlineEdge &arriving,
                                                 const FaceLoad &on_arriving,
                                                 const axisym::OutlineEdge &leaving,
                                                 const FaceLoad &on_leaving, const double cutoff_radius,
                                                 const double poisson_ratio, std::string *why)
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
    j.at_ = leaving.start;
    j.cutoff_radius_ = cutoff_radius;
    j.poisson_ratio_ = poisson_ratio;
    const axisym::Point d0 = leaving.tangent_at(0.0);
    const axisym::Point t1 = arriving.tangent_at(1.0), d1{-t1.r, -t1.z};
    j.gamma_ = std::atan2(d0.z, d0.r);
    j.beta_ = std::atan2(cross(d0, d1), dot(d0, d1));
    if (!(j.beta_ > 1e-12))
      j.beta_ += 2.0 * pi;
    const axisym::OutlineEdge *edges[2] = {&leaving, &arriving};
    for (int f = 0; f < 2; ++f)
      if (edges[f]->kind == Kind::arc)
        j.faces_[f] = {edges[f]->center, edges[f]->radius(), edges[f]->sweep() > 0 ? 1 : -1};

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
            const std::array<double, 3> s = j.wedge_stress(f == 0 ? 0.0 : j.beta_);
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
    return j;
  }

  std::array<double, 3> TractionJump::wedge_stress(const double theta) const
  {
    const auto [a, b, c, d] = coefficients_;
    const double c2 = std::cos(2.0 * theta), s2 = std::sin(2.0 * theta);
    const double s_pp = 2 * a - 2 * b * c2 - 2 * c * s2 + 2 * d * theta;
    const double s_qq = 2 * a + 2 * b * c2 + 2 * c * s2 + 2 * d * theta;
    const double s_pq = 2 * b * s2 - 2 * c * c2 - d;
    const double cs = std::cos(gamma_ + theta), sn = std::sin(gamma_ + theta);
    return {s_pp * cs * cs + s_qq * sn * sn - 2.0 * s_pq * cs * sn,
            s_pp * sn * sn + s_qq * cs * cs + 2.0 * s_pq * cs * sn,
            (s_pp - s_qq) * cs * sn + s_pq * (cs * cs - sn * sn)};
  }

  double TractionJump::polar_angle(const double r, const double z) const
  {
    const axisym::Point d0{std::cos(gamma_), std::sin(gamma_)}, x{r - at_.r, z - at_.z};
    double theta = std::atan2(cross(d0, x), dot(d0, x));
    if (theta < 0.5 * beta_ - pi)
      theta += 2.0 * pi;
    else if (theta >= 0.5 * beta_ + pi)
      theta -= 2.0 * pi;
    return theta;
  }

  double TractionJump::arc_angle(const int face, const double r, const double z) const
  {
    const Face &f = faces_[face];
    if (f.sweep_sign == 0)
      return 0.0;
    const axisym::Point u{at_.r - f.center.r, at_.z - f.center.z}, v{r - f.center.r, z - f.center.z};
    return std::atan2(cross(u, v), dot(u, v));
  }

  std::array<double, 2> TractionJump::mapped_angle(const double r, const double z) const
  {
    if (!(std::hypot(r - at_.r, z - at_.z) > 1e-14 * cutoff_radius_))
      return {0.5 * beta_, 0.0};
    const double p0 = arc_angle(0, r, z), p1 = arc_angle(1, r, z);
    const double polar = polar_angle(r, z);
    const double w = (polar - 0.5 * p0) / (beta_ + 0.5 * p1 - 0.5 * p0);
    return {polar - 0.5 * ((1.0 - w) * p0 + w * p1), (1.0 - w) * p0 + w * p1};
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
        const double rho = std::hypot(r[k] - at_.r, z[k] - at_.z);
        if (!(rho > 1e-14 * cutoff_radius_))
          {
            u(k, 0) = u(k, 1) = 0.0;
            continue;
          }
        const auto [theta, a] = mapped_angle(r[k], z[k]);
        const double u_p = (kappa - 1.0) * d_ * theta * rho / (2.0 * mu);
        const double u_q = -(kappa + 1.0) * d_ * rho * std::log(rho / cutoff_radius_) / (2.0 * mu);
        // Polar to (r, z) at the mapped angle, then turned by a.
        const double phi = gamma_ + theta + a;
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
        const auto [theta, a] = mapped_angle(r[k], z[k]);
        const std::array<double, 3> w = wedge_stress(theta);
        // Q(a) S Q(a)^T.
        const double c = std::cos(a), sn = std::sin(a);
        const double xx = w[0], yy = w[1], xy = w[2];
        const double s_rr = c * c * xx - 2 * c * sn * xy + sn * sn * yy;
        const double s_zz = sn * sn * xx + 2 * c * sn * xy + c * c * yy;
        const double s_rz = c * sn * (xx - yy) + (c * c - sn * sn) * xy;
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
      chi[k] = edge_cutoff(std::hypot(r[k] - at_.r, z[k] - at_.z), cutoff_radius_).value;
    return chi;
  }

  Quadrature2D TractionJump::near_rule(const int n_radial, const int n_angular, const int n_layers) const
  {
    if (n_radial < 1 || n_angular < 1 || n_layers < 0)
      throw std::invalid_argument("TractionJump::near_rule: point counts must be positive");
    const GaussRule1D radial = polar_radial_rule(cutoff_radius_, n_radial, n_layers), ga = gauss_legendre(n_angular);
    std::vector<double> rs, zs, ws;
    for (Eigen::Index k = 0; k < radial.nodes.size(); ++k)
      {
        const double rho = radial.nodes[k], w_rho = radial.weights[k];
        // The faces at this radius: the chord angles of arcs.
        auto chord = [rho](const Face &f) {
          return f.sweep_sign == 0 ? 0.0 : std::asin(std::min(1.0, rho / (2.0 * f.radius)));
        };
        const double theta_lo = faces_[0].sweep_sign * chord(faces_[0]);
        const double theta_hi = beta_ - faces_[1].sweep_sign * chord(faces_[1]);
        std::vector<double> breaks{theta_lo, theta_hi};
        if (beta_ > pi + 1e-12) // the faces' lines continued into the body
          for (const double b : {beta_ - pi, pi})
            if (b > theta_lo && b < theta_hi)
              breaks.push_back(b);
        std::sort(breaks.begin(), breaks.end());
        for (std::size_t p = 0; p + 1 < breaks.size(); ++p)
          {
            const double a = breaks[p], b = breaks[p + 1];
            const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / (0.5 * pi) - 1e-9)));
            for (int piece = 0; piece < pieces; ++piece)
              {
                const double pa = a + (b - a) * piece / pieces, pb = a + (b - a) * (piece + 1) / pieces;
                for (Eigen::Index l = 0; l < ga.nodes.size(); ++l)
                  {
                    const double theta = pa + 0.5 * (ga.nodes[l] + 1.0) * (pb - pa);
                    rs.push_back(at_.r + rho * std::cos(gamma_ + theta));
                    zs.push_back(at_.z + rho * std::sin(gamma_ + theta));
                    ws.push_back(w_rho * 0.5 * ga.weights[l] * (pb - pa));
                  }
              }
          }
      }
    Quadrature2D q;
    const Eigen::Index n = static_cast<Eigen::Index>(ws.size());
    q.r = Eigen::Map<const Eigen::VectorXd>(rs.data(), n);
    q.z = Eigen::Map<const Eigen::VectorXd>(zs.data(), n);
    q.weights = Eigen::Map<const Eigen::VectorXd>(ws.data(), n);
    return q;
  }
} // namespace rfm
