#include "rfm/spaces/wedge_shadow.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
  }

  WedgeShadow::WedgeShadow(const axisym::Wedge &wedge, const axisym::WedgeMode &mode,
                           const double bisector, const double r_v, const double poisson_ratio,
                           const WedgeFrame *frame, const int n_points)
    : alpha_(wedge.half_angle())
    , a_(2.0 * poisson_ratio / (1.0 - 2.0 * poisson_ratio))
    , m_(mode.lambda + 1.0)
  {
    if (n_points < 8)
      throw std::invalid_argument("WedgeShadow: at least 8 collocation points");
    if (!(r_v > 0.0))
      throw std::invalid_argument("WedgeShadow: the vertex must lie off the axis");
    // Resonance, or near it (the header).
    for (const axisym::WedgeMode &other : wedge.modes(m_.real() + 0.5))
      if (std::abs(other.lambda - m_) < resonance_distance ||
          std::abs(std::conj(other.lambda) - m_) < resonance_distance)
        return;
    const int n = n_points, N = n - 1;
    using cd = std::complex<double>;
    x_.resize(n);
    weights_.resize(n);
    for (int j = 0; j < n; ++j)
      {
        x_[j] = std::cos(pi * j / N);
        weights_[j] = (j % 2 == 0 ? 1.0 : -1.0) * (j == 0 || j == N ? 0.5 : 1.0);
      }
    // The Chebyshev differentiation matrix on [-1, 1], over alpha: d / dtheta.
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      {
        const double ci = (i == 0 || i == N) ? 2.0 : 1.0;
        for (int j = 0; j < n; ++j)
          if (i != j)
            {
              const double cj = (j == 0 || j == N) ? 2.0 : 1.0;
              d(i, j) = (ci / cj) * ((i + j) % 2 == 0 ? 1.0 : -1.0) / (x_[i] - x_[j]);
            }
        d(i, i) = -d.row(i).sum();
      }
    d /= alpha_;
    const Eigen::MatrixXd d2 = d * d;
    // The forcing at the points (shear modulus 1), and the mode's stresses F (rho = 1).
    const double nu = poisson_ratio, a = a_;
    Eigen::VectorXcd c_rho(n), c_th(n), f_rr(n), f_tt(n), f_rt(n);
    h_.resize(n);
    for (int j = 0; j < n; ++j)
      {
        const double theta = alpha_ * x_[j], phi = theta + bisector;
        const double c = std::cos(phi), s = std::sin(phi);
        const axisym::WedgeFieldValues v = wedge.evaluate(mode, 1.0, theta);
        h_[j] = (v.u_r * c - v.u_t * s) / r_v;
        const cd s_xx = v.s_rr * c * c + v.s_tt * s * s - 2.0 * v.s_rt * c * s;
        const cd s_xy = (v.s_rr - v.s_tt) * c * s + v.s_rt * (c * c - s * s);
        const cd cx = s_xx - nu * (v.s_rr + v.s_tt), cy = s_xy;
        c_rho[j] = (cx * c + cy * s) / r_v;
        c_th[j] = (-cx * s + cy * c) / r_v;
        f_rr[j] = v.s_rr, f_tt[j] = v.s_tt, f_rt[j] = v.s_rt;
      }
    // L: the linearization of the map's change theta' - theta = rho D(theta) and turn
    // a = rho A(theta) (wedge_frame.h), from the map at a small distance.
    l_ = Eigen::MatrixXcd::Zero(n, 3);
    if (frame)
      {
        double radius = std::numeric_limits<double>::infinity();
        for (int f = 0; f < 2; ++f)
          if (frame->face_is_arc(f))
            radius = std::min(radius, frame->face_radius(f));
        const double rho_s = 1e-6 * radius;
        const Eigen::MatrixXcd dc = d.cast<cd>();
        const Eigen::VectorXcd df_rr = dc * f_rr, df_tt = dc * f_tt, df_rt = dc * f_rt;
        for (int j = 0; j < n; ++j)
          {
            const double theta = alpha_ * x_[j], phi = theta + bisector;
            const auto [mapped, turn] = frame->mapped_angle(frame->vertex().r + rho_s * std::cos(phi),
                                                            frame->vertex().z + rho_s * std::sin(phi), 0.0);
            const double dd = (mapped - 0.5 * frame->angle() - theta) / rho_s, aa = turn / rho_s;
            l_(j, 0) = dd * (df_rr[j] - 2.0 * f_rt[j]) - 2.0 * aa * f_rt[j];
            l_(j, 1) = dd * (df_tt[j] + 2.0 * f_rt[j]) + 2.0 * aa * f_rt[j];
            l_(j, 2) = dd * (df_rt[j] + f_rr[j] - f_tt[j]) + aa * (f_rr[j] - f_tt[j]);
          }
      }
    const Eigen::VectorXcd dh = d.cast<cd>() * h_;
    const cd lambda = mode.lambda, m = m_;
    const Eigen::VectorXcd b_rho = a * lambda * h_ + c_rho, b_th = a * dh + c_th;
    // The collocation system for (P, Q): the ODEs inside, two conditions at each face.
    Eigen::MatrixXcd sys = Eigen::MatrixXcd::Zero(2 * n, 2 * n);
    Eigen::VectorXcd rhs(2 * n);
    for (int j = 1; j < N; ++j)
      {
        for (int k = 0; k < n; ++k)
          {
            sys(j, k) = d2(j, k);
            sys(j, n + k) = ((a + 1.0) * m - a - 3.0) * d(j, k);
            sys(n + j, n + k) = (a + 2.0) * d2(j, k);
            sys(n + j, k) = ((a + 1.0) * m + a + 3.0) * d(j, k);
          }
        sys(j, j) += (a + 2.0) * (m * m - 1.0);
        sys(n + j, n + j) += m * m - 1.0;
        rhs[j] = -b_rho[j];
        rhs[n + j] = -b_th[j];
      }
    for (const int j : {0, N})
      {
        const axisym::WedgeFace face = j == 0 ? wedge.face_plus() : wedge.face_minus();
        rhs[j] = rhs[n + j] = 0.0;
        switch (face)
          {
            case axisym::WedgeFace::free:
              // sigma1 . n = L . n: S_thth + a H = L_thth, S_rhoth = L_rhoth.
              for (int k = 0; k < n; ++k)
                {
                  sys(j, n + k) = (a + 2.0) * d(j, k);
                  sys(n + j, k) = d(j, k);
                }
              sys(j, j) += a * m + a + 2.0;
              sys(n + j, n + j) += m - 1.0;
              rhs[j] = l_(j, 1) - a * h_[j];
              rhs[n + j] = l_(j, 2);
              break;
            case axisym::WedgeFace::clamped:
              sys(j, j) = 1.0;
              sys(n + j, n + j) = 1.0;
              break;
            case axisym::WedgeFace::symmetry:
              sys(j, n + j) = 1.0;
              for (int k = 0; k < n; ++k)
                sys(n + j, k) = d(j, k);
              sys(n + j, n + j) += m - 1.0;
              break;
          }
      }
    const Eigen::VectorXcd sol = sys.fullPivLu().solve(rhs);
    residual_ = (sys * sol - rhs).cwiseAbs().maxCoeff() / std::max(rhs.cwiseAbs().maxCoeff(), 1e-300);
    p_ = sol.head(n);
    q_ = sol.tail(n);
    dp_ = d.cast<cd>() * p_;
    dq_ = d.cast<cd>() * q_;
    valid_ = sol.allFinite() && residual_ < 1e-8;
  }

  WedgeShadow::Values WedgeShadow::evaluate(const double rho, const double theta) const
  {
    using cd = std::complex<double>;
    Values out{};
    if (!valid_ || !(rho > 0.0))
      return out;
    // Barycentric interpolation at x = theta / alpha.
    const double x = theta / alpha_;
    cd p = 0.0, q = 0.0, dp = 0.0, dq = 0.0, h = 0.0, l[3] = {0.0, 0.0, 0.0};
    double den = 0.0;
    bool hit = false;
    for (Eigen::Index j = 0; j < x_.size() && !hit; ++j)
      if (x == x_[j])
        {
          p = p_[j], q = q_[j], dp = dp_[j], dq = dq_[j], h = h_[j];
          for (int c = 0; c < 3; ++c)
            l[c] = l_(j, c);
          hit = true;
        }
    if (!hit)
      {
        for (Eigen::Index j = 0; j < x_.size(); ++j)
          {
            const double t = weights_[j] / (x - x_[j]);
            p += t * p_[j], q += t * q_[j], dp += t * dp_[j], dq += t * dq_[j], h += t * h_[j];
            for (int c = 0; c < 3; ++c)
              l[c] += t * l_(j, c);
            den += t;
          }
        p /= den, q /= den, dp /= den, dq /= den, h /= den;
        for (int c = 0; c < 3; ++c)
          l[c] /= den;
      }
    const cd m = m_, a = a_;
    const cd rho_l = std::exp((m - 1.0) * std::log(rho)); // rho^lambda
    const cd g = dp + (m - 1.0) * q;                       // engineering shear over rho^lambda
    out.u[0] = rho_l * rho * p;
    out.u[1] = rho_l * rho * q;
    out.e[0] = rho_l * m * p;
    out.e[1] = rho_l * (dq + p);
    out.e[2] = rho_l * g;
    out.s[0] = rho_l * (((a + 2.0) * m + a) * p + a * dq + a * h);
    out.s[1] = rho_l * ((a * m + a + 2.0) * p + (a + 2.0) * dq + a * h);
    out.s[2] = rho_l * g;
    for (int c = 0; c < 3; ++c)
      out.t[c] = out.s[c] - rho_l * l[c];
    return out;
  }
} // namespace rfm
