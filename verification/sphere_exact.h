// Exact solution of a thick spherical shell a <= R <= b under inner pressure p_i and outer
// pressure p_o (Lame, spherical symmetry; Timoshenko and Goodier, Theory of Elasticity,
// section 141), in the meridian coordinates (r, z), R = sqrt(r^2 + z^2):
//
//   A = (p_i a^3 - p_o b^3) / (b^3 - a^3),  B = (p_i - p_o) a^3 b^3 / (b^3 - a^3)
//   sigma_RR = A - B / R^3,  sigma_phiphi = sigma_thetatheta = A + B / (2 R^3)
//   u_R = ((1 - 2 nu) A R + (1 + nu) B / (2 R^2)) / E
//
// with sigma_rr = sigma_RR c^2 + sigma_phiphi s^2, sigma_zz = sigma_RR s^2 + sigma_phiphi c^2,
// sigma_rz = (sigma_RR - sigma_phiphi) c s (c = r / R, s = z / R) and the hoop stress
// sigma_tt = sigma_phiphi. The strain energy per radian of the quarter section (the
// hemisphere z >= 0) is U = 1/2 (p_i a^2 u_R(a) - p_o b^2 u_R(b)) (Clapeyron; r ds on the
// quarter circle of radius R integrates to R^2). Verification oracle: shares no code with
// rfm/ or fem_reference/.
#pragma once

#include <array>
#include <cmath>

namespace verification
{
  struct ThickSphere
  {
    double inner_radius, outer_radius;     // a, b [m]
    double youngs_modulus, poisson_ratio;  // [Pa], [-]
    double inner_pressure, outer_pressure; // [Pa]

    double a_coefficient() const
    {
      const double a3 = std::pow(inner_radius, 3), b3 = std::pow(outer_radius, 3);
      return (inner_pressure * a3 - outer_pressure * b3) / (b3 - a3);
    }
    double b_coefficient() const
    {
      const double a3 = std::pow(inner_radius, 3), b3 = std::pow(outer_radius, 3);
      return (inner_pressure - outer_pressure) * a3 * b3 / (b3 - a3);
    }
    double radial_displacement(double rho) const
    {
      const double nu = poisson_ratio;
      return ((1 - 2 * nu) * a_coefficient() * rho +
              (1 + nu) * b_coefficient() / (2 * rho * rho)) /
             youngs_modulus;
    }
    /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) [Pa]
    std::array<double, 4> stress(double r, double z) const
    {
      const double rho = std::hypot(r, z), c = r / rho, s = z / rho;
      const double s_rr = a_coefficient() - b_coefficient() / (rho * rho * rho);
      const double s_pp = a_coefficient() + b_coefficient() / (2 * rho * rho * rho);
      return {s_rr * c * c + s_pp * s * s, s_rr * s * s + s_pp * c * c, s_pp, (s_rr - s_pp) * c * s};
    }
    /// (u_r, u_z) [m]
    std::array<double, 2> displacement(double r, double z) const
    {
      const double rho = std::hypot(r, z), u = radial_displacement(rho);
      return {u * r / rho, u * z / rho};
    }
    /// Strain energy of the hemisphere shell z >= 0, per radian [J].
    double strain_energy() const
    {
      const double a = inner_radius, b = outer_radius;
      return 0.5 * (inner_pressure * a * a * radial_displacement(a) -
                    outer_pressure * b * b * radial_displacement(b));
    }
  };
} // namespace verification
