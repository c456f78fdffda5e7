#include "rfm/spaces/basis.h"

#include <stdexcept>

namespace rfm
{
  void legendre_values(const int degree, const double x, Eigen::Ref<Eigen::VectorXd> p,
                       Eigen::Ref<Eigen::VectorXd> dp)
  {
    p[0] = 1.0;
    dp[0] = 0.0;
    if (degree == 0)
      return;
    p[1] = x;
    dp[1] = 1.0;
    for (int n = 1; n < degree; ++n)
      {
        p[n + 1] = ((2.0 * n + 1.0) * x * p[n] - n * p[n - 1]) / (n + 1.0);
        dp[n + 1] = dp[n - 1] + (2.0 * n + 1.0) * p[n];
      }
  }

  TensorLegendreBasis::TensorLegendreBasis(const int degree, const double r_min,
                                           const double r_max, const double z_min,
                                           const double z_max, const bool even_in_r,
                                           const int degree_z)
    : degree_(degree)
    , degree_z_(degree_z < 0 ? degree : degree_z)
    , r_min_(r_min)
    , r_max_(r_max)
    , z_min_(z_min)
    , z_max_(z_max)
    , even_r_(even_in_r)
  {
    if (degree < 0)
      throw std::invalid_argument("TensorLegendreBasis: degree must be >= 0");
    if (!(r_max > r_min) || !(z_max > z_min))
      throw std::invalid_argument("TensorLegendreBasis: empty bounding box");
    if (even_in_r && r_min != 0.0)
      throw std::invalid_argument("TensorLegendreBasis: even in r needs a box from the axis");
  }

  BasisValues TensorLegendreBasis::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                            const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n_points = r.size(), m = degree_ + 1, m_z = degree_z_ + 1;
    const double sr = 2.0 / (r_max_ - r_min_), sz = 2.0 / (z_max_ - z_min_);
    BasisValues b;
    b.value.resize(n_points, m * m_z);
    b.d_r.resize(n_points, m * m_z);
    b.d_z.resize(n_points, m * m_z);
    // 1-D tables first (point by degree), then every product as a contiguous column
    // operation (the per-point loop wrote rows of column-major matrices: stride n_points).
    Eigen::MatrixXd pr(n_points, m), dpr(n_points, m), pz(n_points, m_z), dpz(n_points, m_z);
    Eigen::VectorXd p1(m), dp1(m), q1(m_z), dq1(m_z);
    const double se = 2.0 / (r_max_ * r_max_);
    for (Eigen::Index k = 0; k < n_points; ++k)
      {
        if (even_r_)
          {
            // xi = se r^2 - 1, d xi / dr = 2 se r (sr is applied below).
            legendre_values(degree_, se * r[k] * r[k] - 1.0, p1, dp1);
            dp1 *= 2.0 * se * r[k] / sr;
          }
        else
          legendre_values(degree_, sr * (r[k] - r_min_) - 1.0, p1, dp1);
        pr.row(k) = p1.transpose(), dpr.row(k) = dp1.transpose();
        legendre_values(degree_z_, sz * (z[k] - z_min_) - 1.0, q1, dq1);
        pz.row(k) = q1.transpose(), dpz.row(k) = dq1.transpose();
      }
    for (Eigen::Index j = 0; j < m_z; ++j)
      for (Eigen::Index i = 0; i < m; ++i)
        {
          const Eigen::Index col = j * m + i;
          b.value.col(col) = pr.col(i).cwiseProduct(pz.col(j));
          b.d_r.col(col) = (sr * dpr.col(i)).cwiseProduct(pz.col(j));
          b.d_z.col(col) = (sz * pr.col(i)).cwiseProduct(dpz.col(j));
        }
    return b;
  }
} // namespace rfm
