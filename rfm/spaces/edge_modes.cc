#include "rfm/spaces/edge_modes.h"

#include <cmath>
#include <stdexcept>

namespace rfm
{
  EdgeModeValue edge_mode(const int n, const double r, const double z, const double r_edge,
                          const double z_edge, const Material &material)
  {
    return edge_mode(n, r, z, EdgeFrame::outer_side(r_edge, z_edge), material);
  }

  EdgeModeValue edge_mode(const int n, const double r, const double z, const EdgeFrame &frame,
                          const Material &material)
  {
    const double nu = material.poisson_ratio;
    const double mu = material.youngs_modulus / (2.0 * (1.0 + nu));
    const double kappa = 3.0 - 4.0 * nu;
    const double dr = r - frame.r, dz = z - frame.z;
    const double x = dr * frame.t[0] + dz * frame.t[1], y = dr * frame.n[0] + dz * frame.n[1];
    const double rho = std::hypot(x, y);
    // The body is the half plane y >= 0 and its free face theta = pi. On the free face y is a
    // zero whose sign comes from the frame's components (n = (-0, -1) gives y = -0): atan2
    // would put such a point at theta = -pi, the other side of the branch cut, where u_y has
    // the opposite sign. A point on the face is taken from the body's side.
    const double theta = std::atan2(y == 0.0 ? 0.0 : y, x);
    const double h = 0.5 * n, s = (n % 2 == 0) ? 1.0 : -1.0;

    EdgeModeValue v;
    if (rho == 0.0 && h <= 1.0)
      {
        // Displacements vanish (h > 0) or are singular (h < 0); stresses are 0 (h > 1),
        // finite but direction-dependent (h = 1) or singular (h < 1): no value.
        return v;
      }
    const double rho_h = std::pow(rho, h), rho_h1 = std::pow(rho, h - 1.0);
    const double u_x = rho_h / (2.0 * mu) *
                       ((kappa + h + s) * std::cos(h * theta) - h * std::cos((h - 2.0) * theta));
    const double u_y = rho_h / (2.0 * mu) *
                       ((kappa - h - s) * std::sin(h * theta) + h * std::sin((h - 2.0) * theta));
    const double s_xx = h * rho_h1 *
                        ((2.0 + h + s) * std::cos((h - 1.0) * theta) -
                         (h - 1.0) * std::cos((h - 3.0) * theta));
    const double s_yy = h * rho_h1 *
                        ((2.0 - h - s) * std::cos((h - 1.0) * theta) +
                         (h - 1.0) * std::cos((h - 3.0) * theta));
    const double s_xy = h * rho_h1 *
                        (-(h + s) * std::sin((h - 1.0) * theta) +
                         (h - 1.0) * std::sin((h - 3.0) * theta));
    // Back to the meridian components (the legacy frame gives u_r = -u_y, u_z = -u_x,
    // sigma_rr = sigma_yy, sigma_zz = sigma_xx, sigma_rz = sigma_xy exactly).
    const double t_r = frame.t[0], t_z = frame.t[1], n_r = frame.n[0], n_z = frame.n[1];
    v.u_r = u_x * t_r + u_y * n_r;
    v.u_z = u_x * t_z + u_y * n_z;
    const double cross = t_r * n_z + t_z * n_r;
    v.sigma << s_xx * t_r * t_r + 2.0 * s_xy * t_r * n_r + s_yy * n_r * n_r,
      s_xx * t_z * t_z + 2.0 * s_xy * t_z * n_z + s_yy * n_z * n_z, nu * (s_xx + s_yy),
      s_xx * t_r * t_z + s_xy * cross + s_yy * n_r * n_z;
    // Plane-strain Hooke's law: eps = (sigma - nu tr sigma) / (2 mu), gamma = sigma_xy / mu.
    const double tr = nu * (s_xx + s_yy);
    const double e_xx = (s_xx - tr) / (2.0 * mu), e_yy = (s_yy - tr) / (2.0 * mu), g_xy = s_xy / mu;
    v.strain << e_xx * t_r * t_r + g_xy * t_r * n_r + e_yy * n_r * n_r,
      e_xx * t_z * t_z + g_xy * t_z * n_z + e_yy * n_z * n_z, v.u_r / r,
      2.0 * e_xx * t_r * t_z + g_xy * cross + 2.0 * e_yy * n_r * n_z;
    return v;
  }

  Cutoff edge_cutoff(const double rho, const double cutoff_radius)
  {
    const double t = rho / cutoff_radius;
    if (t >= 1.0)
      return {0.0, 0.0};
    const double t2 = t * t;
    return {1.0 - t2 * t * (10.0 - 15.0 * t + 6.0 * t2),
            -30.0 * t2 * (1.0 - t) * (1.0 - t) / cutoff_radius};
  }

  EdgeEnrichment::EdgeEnrichment(const EdgeFrame &frame, const double cutoff_radius,
                                 std::vector<int> modes, const Material &material,
                                 const int multiplier_degree, const double end_distance)
    : EdgeEnrichment(frame.r, frame.z, cutoff_radius, std::move(modes), material,
                     multiplier_degree)
  {
    if (!(end_distance > 0.0))
      throw std::invalid_argument("EdgeEnrichment: the clipping end must lie beyond the edge");
    frame_ = frame;
    end_distance_ = end_distance;
  }

  EdgeEnrichment::EdgeEnrichment(const double r_edge, const double z_edge,
                                 const double cutoff_radius, std::vector<int> modes,
                                 const Material &material, const int multiplier_degree,
                                 const double end_z)
    : frame_(EdgeFrame::outer_side(r_edge, z_edge))
    , r_edge_(r_edge)
    , z_edge_(z_edge)
    , cutoff_radius_(cutoff_radius)
    , modes_(std::move(modes))
    , material_(material)
    , multiplier_degree_(multiplier_degree)
    , end_z_(end_z)
    , end_distance_(end_z - z_edge)
  {
    if (!(end_z > z_edge))
      throw std::invalid_argument("EdgeEnrichment: the clipping end must lie beyond the edge");
    if (multiplier_degree < 0)
      throw std::invalid_argument("EdgeEnrichment: multiplier degree must be >= 0");
    if (!(cutoff_radius > 0.0))
      throw std::invalid_argument("EdgeEnrichment: cutoff radius must be positive");
    for (const int n : modes_)
      if (n < 1 || n % 2 == 0)
        throw std::invalid_argument("EdgeEnrichment: modes must be odd and >= 1 (even modes "
                                    "are polynomials, already in the basis)");

  }

  Eigen::Index EdgeEnrichment::singular_column() const
  {
    for (std::size_t j = 0; j < modes_.size(); ++j)
      if (modes_[j] == 1)
        return static_cast<Eigen::Index>(j) * columns_per_mode();
    return -1;
  }

  std::vector<Eigen::Index> EdgeColumns::nonzero_columns() const
  {
    std::vector<Eigen::Index> out;
    for (Eigen::Index j = 0; j < u[0].cols(); ++j)
      {
        bool nonzero = false;
        for (const Eigen::MatrixXd *m : {&stress[0], &stress[1], &stress[2], &stress[3], &u[0], &u[1],
                                         &strain[0], &strain[1], &strain[2], &strain[3]})
          if ((nonzero = (m->col(j).array() != 0.0).any()))
            break;
        if (nonzero)
          out.push_back(j);
      }
    return out;
  }

  std::vector<Eigen::Index> EdgeColumns::displacement_columns() const
  {
    std::vector<Eigen::Index> out;
    for (Eigen::Index j = 0; j < u[0].cols(); ++j)
      for (const Eigen::MatrixXd *m : {&u[0], &u[1], &strain[0], &strain[1], &strain[2], &strain[3]})
        if ((m->col(j).array() != 0.0).any())
          {
            out.push_back(j);
            break;
          }
    return out;
  }

  EdgeColumns EdgeColumns::columns(const std::vector<Eigen::Index> &which) const
  {
    EdgeColumns out;
    for (int k = 0; k < 4; ++k)
      out.stress[k] = stress[k](Eigen::all, which), out.strain[k] = strain[k](Eigen::all, which);
    for (int m = 0; m < 2; ++m)
      out.u[m] = u[m](Eigen::all, which);
    return out;
  }

  std::vector<Eigen::Index> EdgeColumns::drop_zero_columns()
  {
    std::vector<Eigen::Index> live = nonzero_columns();
    if (live.size() < static_cast<std::size_t>(u[0].cols()))
      *this = columns(live);
    return live;
  }

  EdgeColumns EdgeEnrichment::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                       const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n = r.size();
    EdgeColumns out = EdgeColumns::zero(n, n_columns());
    const int d = multiplier_degree_;
    std::vector<double> xi_pow(d + 1), eta_pow(d + 1);
    std::vector<EdgeModeValue> v(modes_.size());
    for (Eigen::Index k = 0; k < n; ++k)
      {
        const double dr = r[k] - r_edge_, dz = z[k] - z_edge_;
        const double rho = std::hypot(dr, dz);
        const Cutoff chi = edge_cutoff(rho, cutoff_radius_);
        if (chi.value == 0.0 && chi.derivative == 0.0)
          continue;
        // grad chi = chi'(rho) (r - r_edge, z - z_edge) / rho (zero at rho = 0: chi'(0) = 0).
        const double chi_r = rho > 0.0 ? chi.derivative * dr / rho : 0.0;
        const double chi_z = rho > 0.0 ? chi.derivative * dz / rho : 0.0;
        const double xi = dz / cutoff_radius_, eta = dr / cutoff_radius_;
        // The stress columns' end factor (1 without clipping).
        const double g = std::isfinite(end_distance_)
                           ? 1.0 + (dr * frame_.t[0] + dz * frame_.t[1]) / end_distance_
                           : 1.0;
        xi_pow[0] = eta_pow[0] = 1.0;
        for (int i = 1; i <= d; ++i)
          {
            xi_pow[i] = xi_pow[i - 1] * xi;
            eta_pow[i] = eta_pow[i - 1] * eta;
          }
        for (std::size_t j = 0; j < modes_.size(); ++j)
          v[j] = edge_mode(modes_[j], r[k], z[k], frame_, material_);
        for (std::size_t j = 0; j < modes_.size(); ++j)
          {
            Eigen::Index col = static_cast<Eigen::Index>(j) * columns_per_mode();
            for (int deg = 0; deg <= d; ++deg)
              for (int b = 0; b <= deg; ++b, ++col)
                {
                  // Weight w = chi xi^a eta^b (a + b = deg) and its gradient.
                  const int a = deg - b;
                  const double mono = xi_pow[a] * eta_pow[b];
                  const double mono_z =
                    a > 0 ? a * xi_pow[a - 1] * eta_pow[b] / cutoff_radius_ : 0.0;
                  const double mono_r =
                    b > 0 ? b * xi_pow[a] * eta_pow[b - 1] / cutoff_radius_ : 0.0;
                  const double w = chi.value * mono;
                  const double w_r = chi_r * mono + chi.value * mono_r;
                  const double w_z = chi_z * mono + chi.value * mono_z;
                  for (int c = 0; c < n_stress_components; ++c)
                    out.stress[c](k, col) = g * w * v[j].sigma[c];
                  out.u[0](k, col) = w * v[j].u_r;
                  out.u[1](k, col) = w * v[j].u_z;
                  // e(w u) = w e(u) + sym(grad w (x) u) in engineering components.
                  out.strain[rr](k, col) = w * v[j].strain[rr] + w_r * v[j].u_r;
                  out.strain[zz](k, col) = w * v[j].strain[zz] + w_z * v[j].u_z;
                  out.strain[tt](k, col) = w * v[j].strain[tt];
                  out.strain[rz](k, col) = w * v[j].strain[rz] + w_z * v[j].u_r + w_r * v[j].u_z;
                }
          }
      }
    return out;
  }
} // namespace rfm
