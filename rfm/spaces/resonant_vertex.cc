#include "rfm/spaces/resonant_vertex.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
  }

  ResonantVertex::ResonantVertex(const axisym::OutlineEdge &arriving, const axisym::OutlineEdge &leaving,
                                 const bool symmetry_leaves, const double cutoff_radius,
                                 const Material &material, const int multiplier_degree,
                                 const int displacement_degree)
    : frame_(arriving, leaving)
    , symmetry_leaves_(symmetry_leaves)
    , cutoff_radius_(cutoff_radius)
    , material_(material)
    , degree_(multiplier_degree)
    , displacement_degree_(displacement_degree)
  {
    if (!(cutoff_radius > 0.0))
      throw std::invalid_argument("ResonantVertex: the cutoff radius must be positive");
    if (!(frame_.vertex().r > 0.0))
      throw std::invalid_argument("ResonantVertex: the vertex must lie off the axis (r > 0)");
    if (multiplier_degree < 0)
      throw std::invalid_argument("ResonantVertex: the multiplier degree must be >= 0");
    if (displacement_degree < -1 || displacement_degree > multiplier_degree)
      throw std::invalid_argument("ResonantVertex: the displacement columns' degree must be in "
                                  "[-1, the multiplier degree]");
    if (!(std::abs(frame_.angle() - 0.5 * pi) < 1e-9))
      throw std::invalid_argument("ResonantVertex: the interior angle must be a right angle");
    if ((symmetry_leaves ? leaving : arriving).kind != axisym::OutlineEdge::Kind::line)
      throw std::invalid_argument("ResonantVertex: the symmetry face must be a line");
    const double g = frame_.leaving_direction(), b = g + frame_.angle();
    const std::array<double, 2> leave{std::cos(g), std::sin(g)}, arrive{std::cos(b), std::sin(b)};
    ex_ = symmetry_leaves ? leave : arrive;
    ey_ = symmetry_leaves ? arrive : leave;
  }

  double ResonantVertex::theory_amplitude(const std::array<double, 2> &temperature_gradient) const
  {
    const double g = temperature_gradient[0] * ey_[0] + temperature_gradient[1] * ey_[1];
    return 2.0 * material_.youngs_modulus * material_.thermal_expansion.value_or(0.0) * g /
           (pi * (1.0 - material_.poisson_ratio));
  }

  ResonantVertex::FrameField ResonantVertex::frame_field(const double x, const double y, const double nu)
  {
    FrameField f;
    const double rho = std::hypot(x, y);
    const double log_rho = rho > 0.0 ? std::log(rho) : 0.0;
    const double psi = rho > 0.0 ? std::atan2(y, x) : 0.0;
    f.s[0] = x + y * psi;
    f.s[1] = -2.0 * x * log_rho - 2.0 * x / 3.0 + y * psi;
    f.s[2] = -x * psi;
    f.u[0] = ((3.0 - 4.0 * nu) * x * x + 6.0 * (1.0 - 2.0 * nu) * x * y * psi - 4.0 * (1.0 - nu) * y * y +
              6.0 * (nu * x * x + (1.0 - nu) * y * y) * log_rho) /
             12.0;
    f.u[1] = ((6.0 * nu - 9.0) * x * x * psi + (5.0 - 8.0 * nu) * x * y + (3.0 - 6.0 * nu) * y * y * psi -
              12.0 * (1.0 - nu) * x * y * log_rho) /
             12.0;
    return f;
  }

  EdgeColumns ResonantVertex::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                       const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n = r.size();
    EdgeColumns out = EdgeColumns::zero(n, n_columns());
    const double nu = material_.poisson_ratio;
    const double mu = material_.youngs_modulus / (2.0 * (1.0 + nu));
    const double e_over_rv = material_.youngs_modulus / frame_.vertex().r;
    const double rho_0 = cutoff_radius_;
    const axisym::Point v = frame_.vertex();
    // (r, z) components of a frame tensor (xx, yy, xy).
    auto to_meridian = [this](const double xx, const double yy, const double xy) {
      const auto &a = ex_, &b = ey_;
      return std::array<double, 3>{xx * a[0] * a[0] + yy * b[0] * b[0] + 2.0 * xy * a[0] * b[0],
                                   xx * a[1] * a[1] + yy * b[1] * b[1] + 2.0 * xy * a[1] * b[1],
                                   xx * a[0] * a[1] + yy * b[0] * b[1] + xy * (a[0] * b[1] + a[1] * b[0])};
    };
    std::vector<double> xi_pow(degree_ + 1), eta_pow(degree_ + 1);
    for (Eigen::Index k = 0; k < n; ++k)
      {
        const double dr = r[k] - v.r, dz = z[k] - v.z;
        const double rho = std::hypot(dr, dz);
        const Cutoff chi = edge_cutoff(rho, rho_0);
        if (chi.value == 0.0 && chi.derivative == 0.0)
          continue;
        // The displacement and its strains, unmapped.
        const FrameField f = frame_field((dr * ex_[0] + dz * ex_[1]) / rho_0, (dr * ey_[0] + dz * ey_[1]) / rho_0, nu);
        const double u[2] = {rho_0 * (f.u[0] * ex_[0] + f.u[1] * ey_[0]) / mu,
                             rho_0 * (f.u[0] * ex_[1] + f.u[1] * ey_[1]) / mu};
        const double tr = nu * (f.s[0] + f.s[1]);
        // Plane-strain Hooke's law, tensor strains; then engineering shear.
        const std::array<double, 3> e =
          to_meridian((f.s[0] - tr) / (2.0 * mu), (f.s[1] - tr) / (2.0 * mu), f.s[2] / (2.0 * mu));
        // The stress at the mapped angle, less the uniform gradient, turned by a.
        const auto [theta, a] = frame_.mapped_angle(r[k], z[k], 1e-14 * rho_0);
        const double psi = symmetry_leaves_ ? theta : frame_.angle() - theta;
        const double xm = rho / rho_0 * std::cos(psi), ym = rho / rho_0 * std::sin(psi);
        const FrameField fm = frame_field(xm, ym, nu);
        const std::array<double, 3> w = to_meridian(fm.s[0] - 0.5 * pi * ym, fm.s[1], fm.s[2]);
        const auto [s_rr, s_zz, s_rz] = turned_tensor(w[0], w[1], w[2], std::cos(a), std::sin(a));
        const double s_tt = nu * (s_rr + s_zz) + e_over_rv * u[0];
        // g = chi xi^i eta^j and its gradient.
        const double chi_r = rho > 0.0 ? chi.derivative * dr / rho : 0.0;
        const double chi_z = rho > 0.0 ? chi.derivative * dz / rho : 0.0;
        const double xi = dr / rho_0, eta = dz / rho_0;
        xi_pow[0] = eta_pow[0] = 1.0;
        for (int i = 1; i <= degree_; ++i)
          xi_pow[i] = xi_pow[i - 1] * xi, eta_pow[i] = eta_pow[i - 1] * eta;
        Eigen::Index col = 0;
        for (int deg = 0; deg <= degree_; ++deg)
          for (int jb = 0; jb <= deg; ++jb, ++col)
            {
              const int ia = deg - jb;
              const double mono = xi_pow[ia] * eta_pow[jb];
              const double mono_r = ia > 0 ? ia * xi_pow[ia - 1] * eta_pow[jb] / rho_0 : 0.0;
              const double mono_z = jb > 0 ? jb * xi_pow[ia] * eta_pow[jb - 1] / rho_0 : 0.0;
              const double g = chi.value * mono;
              const double g_r = chi_r * mono + chi.value * mono_r, g_z = chi_z * mono + chi.value * mono_z;
              out.stress[rr](k, col) = g * s_rr;
              out.stress[zz](k, col) = g * s_zz;
              out.stress[tt](k, col) = g * s_tt;
              out.stress[rz](k, col) = g * s_rz;
              if (deg > displacement_degree_)
                continue;
              out.u[0](k, col) = g * u[0];
              out.u[1](k, col) = g * u[1];
              // e(g u) = g e(u) + sym(grad g (x) u), engineering shear.
              out.strain[rr](k, col) = g * e[0] + g_r * u[0];
              out.strain[zz](k, col) = g * e[1] + g_z * u[1];
              out.strain[tt](k, col) = g * u[0] / r[k];
              out.strain[rz](k, col) = 2.0 * g * e[2] + g_z * u[0] + g_r * u[1];
            }
      }
    return out;
  }

  Quadrature2D ResonantVertex::near_rule(const int n_radial, const int n_angular, const int n_layers,
                                   const std::vector<Circle> &rims, const int n_beyond_rims) const
  {
    return frame_.near_rule(cutoff_radius_, n_radial, n_angular, n_layers, rims, n_beyond_rims);
  }
} // namespace rfm
