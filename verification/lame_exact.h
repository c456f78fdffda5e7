// Exact solution of the Lame cylinder (DESIGN.md section 4, problem 1): a hollow
// cylinder R1 <= r <= R2 under inner pressure p_in and outer pressure p_out with free
// ends. Plane stress in z (sigma_zz = 0), exact in 3-D:
//
//   A = (p_in R1^2 - p_out R2^2) / (R2^2 - R1^2),  B = (p_in - p_out) R1^2 R2^2 / (R2^2 - R1^2)
//   sigma_rr = A - B / r^2,  sigma_tt = A + B / r^2,  sigma_zz = sigma_rz = 0
//   u_r = ((1 - nu) A r + (1 + nu) B / r) / E,  u_z = -2 nu A z / E
//
// The strain energy per radian follows from the work of the pressures on the
// displacements they cause (Clapeyron): U = 1/2 * 2a * (p_in R1 u_r(R1) - p_out R2 u_r(R2)).
// This header is the verification oracle: it shares no code with rfm/ or fem_reference/.
#pragma once

#include <array>

namespace verification
{
  struct LameCylinder
  {
    double inner_radius, outer_radius, length; // [m]
    double youngs_modulus, poisson_ratio;      // [Pa], [-]
    double inner_pressure, outer_pressure;     // [Pa]

    double a_coefficient() const
    {
      const double r1s = inner_radius * inner_radius, r2s = outer_radius * outer_radius;
      return (inner_pressure * r1s - outer_pressure * r2s) / (r2s - r1s);
    }
    double b_coefficient() const
    {
      const double r1s = inner_radius * inner_radius, r2s = outer_radius * outer_radius;
      return (inner_pressure - outer_pressure) * r1s * r2s / (r2s - r1s);
    }
    /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) [Pa]
    std::array<double, 4> stress(double r, double /*z*/) const
    {
      const double a = a_coefficient(), b = b_coefficient();
      return {a - b / (r * r), 0.0, a + b / (r * r), 0.0};
    }
    /// (u_r, u_z) [m]
    std::array<double, 2> displacement(double r, double z) const
    {
      const double a = a_coefficient(), b = b_coefficient(), nu = poisson_ratio;
      return {((1 - nu) * a * r + (1 + nu) * b / r) / youngs_modulus,
              -2 * nu * a * z / youngs_modulus};
    }
    /// Strain energy per radian of the whole body [J/rad].
    double strain_energy() const
    {
      return 0.5 * length *
             (inner_pressure * inner_radius * displacement(inner_radius, 0)[0] -
              outer_pressure * outer_radius * displacement(outer_radius, 0)[0]);
    }
  };
} // namespace verification
