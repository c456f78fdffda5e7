#include "rfm/spaces/wedge_shadow.h"

#include <Eigen/Dense>

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

  WedgeCollocation::WedgeCollocation(const double half_angle, const double poisson_ratio,
                                     const axisym::WedgeFace minus, const axisym::WedgeFace plus,
                                     const int n_points)
    : alpha_(half_angle)
    , a_(2.0 * poisson_ratio / (1.0 - 2.0 * poisson_ratio))
    , minus_(minus)
    , plus_(plus)
  {
    if (n_points < 8)
      throw std::invalid_argument("WedgeCollocation: at least 8 collocation points");
    const int n = n_points, N = n - 1;
    x_.resize(n);
    weights_.resize(n);
    for (int j = 0; j < n; ++j)
      {
        x_[j] = std::cos(pi * j / N);
        weights_[j] = (j % 2 == 0 ? 1.0 : -1.0) * (j == 0 || j == N ? 0.5 : 1.0);
      }
    // The Chebyshev differentiation matrix on [-1, 1], over alpha: d / dtheta.
    d_ = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      {
        const double ci = (i == 0 || i == N) ? 2.0 : 1.0;
        for (int j = 0; j < n; ++j)
          if (i != j)
            {
              const double cj = (j == 0 || j == N) ? 2.0 : 1.0;
              d_(i, j) = (ci / cj) * ((i + j) % 2 == 0 ? 1.0 : -1.0) / (x_[i] - x_[j]);
            }
        d_(i, i) = -d_.row(i).sum();
      }
    d_ /= alpha_;
  }

  Eigen::MatrixXcd WedgeCollocation::system(const std::complex<double> m) const
  {
    const int n = size(), N = n - 1;
    const double a = a_;
    const Eigen::MatrixXd d2 = d_ * d_;
    Eigen::MatrixXcd sys = Eigen::MatrixXcd::Zero(2 * n, 2 * n);
    for (int j = 1; j < N; ++j)
      {
        for (int k = 0; k < n; ++k)
          {
            sys(j, k) = d2(j, k);
            sys(j, n + k) = ((a + 1.0) * m - a - 3.0) * d_(j, k);
            sys(n + j, n + k) = (a + 2.0) * d2(j, k);
            sys(n + j, k) = ((a + 1.0) * m + a + 3.0) * d_(j, k);
          }
        sys(j, j) += (a + 2.0) * (m * m - 1.0);
        sys(n + j, n + j) += m * m - 1.0;
      }
    for (const int j : {0, N})
      switch (face(j))
        {
          case axisym::WedgeFace::free:
            // S_thth and S_rhoth.
            for (int k = 0; k < n; ++k)
              {
                sys(j, n + k) = (a + 2.0) * d_(j, k);
                sys(n + j, k) = d_(j, k);
              }
            sys(j, j) += a * m + a + 2.0;
            sys(n + j, n + j) += m - 1.0;
            break;
          case axisym::WedgeFace::clamped:
            sys(j, j) = 1.0;
            sys(n + j, n + j) = 1.0;
            break;
          case axisym::WedgeFace::symmetry:
            sys(j, n + j) = 1.0;
            for (int k = 0; k < n; ++k)
              sys(n + j, k) = d_(j, k);
            sys(n + j, n + j) += m - 1.0;
            break;
        }
    return sys;
  }

  Eigen::RowVectorXd WedgeCollocation::interpolation(const double theta) const
  {
    const double x = theta / alpha_;
    Eigen::RowVectorXd w = Eigen::RowVectorXd::Zero(size());
    for (int j = 0; j < size(); ++j)
      if (x == x_[j])
        {
          w[j] = 1.0;
          return w;
        }
    for (int j = 0; j < size(); ++j)
      w[j] = weights_[j] / (x - x_[j]);
    return w / w.sum();
  }

  LogSeriesShadow::LogSeriesShadow(const WedgeCollocation &collocation, const double m,
                                   const std::vector<Eigen::VectorXd> &rhs,
                                   const std::vector<Eigen::VectorXd> &hoop)
    : collocation_(collocation)
    , m_(m)
    , a_(collocation.a())
  {
    const int n = collocation.size(), K = static_cast<int>(rhs.size()) + 2, s = 2 * n;
    // L(m) = L0 + m L1 + m^2 L2, from three values.
    const Eigen::MatrixXd l_0 = collocation.system(0.0).real(), l_p = collocation.system(1.0).real(),
                          l_m = collocation.system(-1.0).real();
    const Eigen::MatrixXd l_1 = 0.5 * (l_p - l_m), l_2 = 0.5 * (l_p + l_m) - l_0;
    const Eigen::MatrixXd l = l_0 + m * l_1 + m * m * l_2, dl = l_1 + 2.0 * m * l_2;
    Eigen::MatrixXd big = Eigen::MatrixXd::Zero(K * s, K * s);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(K * s);
    for (int k = 0; k < K; ++k)
      {
        big.block(k * s, k * s, s, s) = l;
        if (k + 1 < K)
          big.block(k * s, (k + 1) * s, s, s) = dl;
        if (k + 2 < K)
          big.block(k * s, (k + 2) * s, s, s) = l_2;
        if (k < static_cast<int>(rhs.size()))
          b.segment(k * s, s) = rhs[k];
      }
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(big);
    cod.setThreshold(1e-11);
    const Eigen::VectorXd x = cod.solve(b);
    residual_ = (big * x - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
    // The levels up to the last one that is not zero.
    int used = K;
    while (used > std::max<int>(1, static_cast<int>(hoop.size())) &&
           x.segment((used - 1) * s, s).cwiseAbs().maxCoeff() <= 1e-12 * x.cwiseAbs().maxCoeff())
      --used;
    const Eigen::MatrixXd &d = collocation.derivative();
    for (int k = 0; k < used; ++k)
      {
        p_.push_back(x.segment(k * s, n));
        q_.push_back(x.segment(k * s + n, n));
        dp_.push_back(d * p_.back());
        dq_.push_back(d * q_.back());
        h_.push_back(k < static_cast<int>(hoop.size()) ? hoop[k] : Eigen::VectorXd::Zero(n));
      }
  }

  LogSeriesShadow::Values LogSeriesShadow::evaluate(const double rho, const double theta) const
  {
    Values out{};
    if (p_.empty() || !(rho > 0.0))
      return out;
    const Eigen::RowVectorXd w = collocation_.interpolation(theta);
    const double a = a_, m = m_, log_rho = std::log(rho);
    const int K = levels();
    // The levels' values at theta; the next level's P and Q enter the rho-derivatives.
    std::vector<double> p(K + 1, 0.0), q(K + 1, 0.0);
    for (int k = 0; k < K; ++k)
      p[k] = w.dot(p_[k]), q[k] = w.dot(q_[k]);
    double power = 1.0; // ln^k rho / k!
    for (int k = 0; k < K; ++k)
      {
        const double dp = w.dot(dp_[k]), dq = w.dot(dq_[k]), h = w.dot(h_[k]);
        const double e_pp = m * p[k] + p[k + 1], e_qq = p[k] + dq, g = dp + (m - 1.0) * q[k] + q[k + 1];
        out.u[0] += power * p[k];
        out.u[1] += power * q[k];
        out.s[0] += power * ((a + 2.0) * e_pp + a * e_qq + a * h);
        out.s[1] += power * (a * e_pp + (a + 2.0) * e_qq + a * h);
        out.s[2] += power * g;
        power *= log_rho / (k + 1);
      }
    const double rho_m = std::pow(rho, m);
    out.u[0] *= rho_m, out.u[1] *= rho_m;
    for (double &c : out.s)
      c *= rho_m / rho;
    return out;
  }

  WedgeShadow::WedgeShadow(const axisym::Wedge &wedge, const axisym::WedgeMode &mode,
                           const double bisector, const double r_v, const double poisson_ratio,
                           const WedgeFrame *frame, const int n_points)
    : a_(2.0 * poisson_ratio / (1.0 - 2.0 * poisson_ratio))
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
    collocation_ =
      WedgeCollocation(wedge.half_angle(), poisson_ratio, wedge.face_minus(), wedge.face_plus(), n_points);
    const WedgeCollocation &collocation = collocation_;
    const int n = n_points, N = n - 1;
    using cd = std::complex<double>;
    const Eigen::MatrixXd &d = collocation.derivative();
    // The forcing at the points (shear modulus 1), and the mode's stresses F (rho = 1).
    const double nu = poisson_ratio, a = a_;
    Eigen::VectorXcd c_rho(n), c_th(n), f_rr(n), f_tt(n), f_rt(n);
    h_.resize(n);
    for (int j = 0; j < n; ++j)
      {
        const double theta = collocation.angle(j), phi = theta + bisector;
        const double c = std::cos(phi), s = std::sin(phi);
        const axisym::WedgeFieldValues v = wedge.evaluate(mode, 1.0, theta);
        h_[j] = (v.u_r * c - v.u_t * s) / r_v;
        const std::array<cd, 3> t = turned_tensor(v.s_rr, v.s_tt, v.s_rt, c, s);
        const cd cx = t[0] - nu * (v.s_rr + v.s_tt), cy = t[2];
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
            const double theta = collocation.angle(j), phi = theta + bisector;
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
    Eigen::MatrixXcd sys = collocation.system(m);
    Eigen::VectorXcd rhs(2 * n);
    for (int j = 1; j < N; ++j)
      {
        rhs[j] = -b_rho[j];
        rhs[n + j] = -b_th[j];
      }
    for (const int j : {0, N})
      {
        rhs[j] = rhs[n + j] = 0.0;
        if (collocation.face(j) == axisym::WedgeFace::free)
          {
            // sigma1 . n = L . n: S_thth + a H = L_thth, S_rhoth = L_rhoth.
            rhs[j] = l_(j, 1) - a * h_[j];
            rhs[n + j] = l_(j, 2);
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
    const Eigen::RowVectorXcd w = collocation_.interpolation(theta).cast<cd>();
    const cd p = (w * p_).value(), q = (w * q_).value(), dp = (w * dp_).value(), dq = (w * dq_).value(),
             h = (w * h_).value();
    cd l[3];
    for (int c = 0; c < 3; ++c)
      l[c] = (w * l_.col(c)).value();
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
