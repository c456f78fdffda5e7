// Isotropic linear elastic material in the axisymmetric stress ordering
// s = (sigma_rr, sigma_zz, sigma_tt, sigma_rz), e = (e_rr, e_zz, e_tt, gamma_rz)
// (engineering shear), e = C s (DESIGN.md section 1). SI units: Pa. Shared by both solvers.
#pragma once

#include <Eigen/Core>

#include <optional>

namespace axisym
{
  enum StressComponent : int { rr = 0, zz = 1, tt = 2, rz = 3 };
  inline constexpr int n_stress_components = 4;

  struct Material
  {
    double youngs_modulus = 2.1e11; ///< E [Pa], > 0
    double poisson_ratio = 0.3;     ///< nu, in (-1, 0.5)
    /// Needed only by body loads (DESIGN.md 7.1): rotation and gravity need the density,
    /// a temperature field the thermal expansion coefficient.
    std::optional<double> density;           ///< [kg/m^3], > 0
    std::optional<double> thermal_expansion; ///< alpha [1/K], finite

    /// C = 1/E [[1,-nu,-nu,0],[-nu,1,-nu,0],[-nu,-nu,1,0],[0,0,0,2(1+nu)]].
    Eigen::Matrix4d compliance() const
    {
      const double e = youngs_modulus, nu = poisson_ratio;
      Eigen::Matrix4d c;
      c << 1, -nu, -nu, 0, -nu, 1, -nu, 0, -nu, -nu, 1, 0, 0, 0, 0, 2 * (1 + nu);
      return c / e;
    }
    /// D = C^-1 (Lame form: lambda on the normal block plus 2 mu I, mu on shear).
    Eigen::Matrix4d stiffness() const
    {
      const double e = youngs_modulus, nu = poisson_ratio;
      const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
      Eigen::Matrix4d d = Eigen::Matrix4d::Zero();
      d.topLeftCorner<3, 3>().setConstant(lambda);
      d.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
      d(3, 3) = mu;
      return d;
    }
  };
} // namespace axisym
