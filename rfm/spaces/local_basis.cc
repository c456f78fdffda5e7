#include "rfm/spaces/local_basis.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace rfm
{
  namespace
  {
    // A box's frame: the degree along t, where x starts (0 one-sided, -1 two-sided), d xi / dx
    // for the map of [x_lo, 1] onto [-1, 1], and the scaled coordinates (x, y) of a point.
    struct BoxFrame
    {
      BoxFrame(const LocalPatch &patch, const int degree)
        : p(patch)
        , d_t(LocalBasis::t_degree(patch, degree))
        , x_lo(patch.one_sided ? 0.0 : -1.0)
        , sx(2.0 / (1.0 - x_lo))
      {}
      std::array<double, 2> coordinates(const double r, const double z) const
      {
        const double dr = r - p.r, dz = z - p.z;
        return {(dr * p.t[0] + dz * p.t[1]) / p.half_size, (dr * p.n[0] + dz * p.n[1]) / p.half_size};
      }
      const LocalPatch &p;
      int d_t;
      double x_lo, sx;
    };
  } // namespace
  LocalBasis::LocalBasis(std::vector<LocalPatch> patches, const int degree)
    : patches_(std::move(patches)), degree_(degree)
  {
    if (degree < 0)
      throw std::invalid_argument("LocalBasis: degree must be >= 0");
    for (const LocalPatch &p : patches_)
      {
        if (!(p.half_size > 0.0))
          throw std::invalid_argument("LocalBasis: a box's half size must be > 0");
        const double tt = p.t[0] * p.t[0] + p.t[1] * p.t[1], nn = p.n[0] * p.n[0] + p.n[1] * p.n[1],
                     tn = p.t[0] * p.n[0] + p.t[1] * p.n[1];
        if (std::abs(tt - 1.0) > 1e-12 || std::abs(nn - 1.0) > 1e-12 || std::abs(tn) > 1e-12)
          throw std::invalid_argument("LocalBasis: t and n must be orthonormal");
      }
  }

  Eigen::Index LocalBasis::n_functions(const int d) const
  {
    Eigen::Index n = 0;
    for (const LocalPatch &p : patches_)
      n += n_functions(p, d);
    return n;
  }

  BasisValues LocalBasis::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                   const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n_points = r.size(), m = degree_ + 1;
    BasisValues b;
    b.value.setZero(n_points, n_basis_functions());
    b.d_r.setZero(n_points, n_basis_functions());
    b.d_z.setZero(n_points, n_basis_functions());
    Eigen::VectorXd px, dpx, py(m), dpy(m);
    Eigen::Index first = 0;
    for (std::size_t l = 0; l < patches_.size(); first += n_functions(patches_[l], degree_), ++l)
      {
        const LocalPatch &p = patches_[l];
        const BoxFrame f(p, degree_);
        const int d_t = f.d_t;
        const Eigen::Index m_t = d_t + 1;
        px.resize(m_t), dpx.resize(m_t);
        const double h = p.half_size, x_lo = f.x_lo, sx = f.sx;
        for (Eigen::Index k = 0; k < n_points; ++k)
          {
            const auto [x, y] = f.coordinates(r[k], z[k]);
            if (!(x > x_lo - 1e-14 && x < 1.0 && y > -1e-14 && y < 1.0))
              continue;
            // The cutoff c(x, y) = cx(x) cy(y) and its derivatives.
            const double cx = p.one_sided ? 1.0 - x : (1.0 - x) * (1.0 + x);
            const double dcx = p.one_sided ? -1.0 : -2.0 * x;
            const double cy = 1.0 - y, dcy = -1.0;
            legendre_values(d_t, sx * (x - x_lo) - 1.0, px, dpx);
            legendre_values(degree_, 2.0 * y - 1.0, py, dpy);
            for (Eigen::Index j = 0; j < m; ++j)
              for (Eigen::Index i = 0; i < m_t; ++i)
                {
                  const double fx = cx * px[i], dfx = dcx * px[i] + cx * sx * dpx[i];
                  const double fy = cy * py[j], dfy = dcy * py[j] + cy * 2.0 * dpy[j];
                  const Eigen::Index col = first + j * m_t + i;
                  const double d_x = dfx * fy / h, d_y = fx * dfy / h; // per metre
                  b.value(k, col) = fx * fy;
                  b.d_r(k, col) = d_x * p.t[0] + d_y * p.n[0];
                  b.d_z(k, col) = d_x * p.t[1] + d_y * p.n[1];
                }
          }
      }
    return b;
  }

  Eigen::MatrixXd LocalBasis::piecewise_values(const Eigen::Ref<const Eigen::VectorXd> &r,
                                               const Eigen::Ref<const Eigen::VectorXd> &z,
                                               const int degree) const
  {
    if (degree < 0)
      throw std::invalid_argument("LocalBasis: degree must be >= 0");
    const Eigen::Index n_points = r.size(), m = degree + 1;
    Eigen::MatrixXd v = Eigen::MatrixXd::Zero(n_points, n_functions(degree));
    Eigen::VectorXd px, dpx, py(m), dpy(m);
    Eigen::Index first = 0;
    for (std::size_t l = 0; l < patches_.size(); first += n_functions(patches_[l], degree), ++l)
      {
        const BoxFrame f(patches_[l], degree);
        const int d_t = f.d_t;
        const Eigen::Index m_t = d_t + 1;
        px.resize(m_t), dpx.resize(m_t);
        const double x_lo = f.x_lo, sx = f.sx;
        for (Eigen::Index k = 0; k < n_points; ++k)
          {
            const auto [x, y] = f.coordinates(r[k], z[k]);
            if (!(x >= x_lo && x < 1.0 && y >= 0.0 && y < 1.0))
              continue;
            legendre_values(d_t, sx * (x - x_lo) - 1.0, px, dpx);
            legendre_values(degree, 2.0 * y - 1.0, py, dpy);
            for (Eigen::Index j = 0; j < m; ++j)
              for (Eigen::Index i = 0; i < m_t; ++i)
                v(k, first + j * m_t + i) = px[i] * py[j];
          }
      }
    return v;
  }

  std::array<std::vector<double>, 2> LocalBasis::breaks() const
  {
    std::array<std::vector<double>, 2> out;
    for (const LocalPatch &p : patches_)
      {
        const double h = p.half_size;
        for (const double x : {p.one_sided ? 0.0 : -1.0, 1.0})
          for (const double y : {0.0, 1.0})
            {
              out[0].push_back(p.r + h * (x * p.t[0] + y * p.n[0]));
              out[1].push_back(p.z + h * (x * p.t[1] + y * p.n[1]));
            }
      }
    return out;
  }
} // namespace rfm
