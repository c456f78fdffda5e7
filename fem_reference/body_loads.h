// Pointwise body loads of an outline problem (DESIGN.md 7.1) as the FEM reference applies
// them: the body force per unit volume and the thermal strain. No deal.II here (the local
// integrands of the axisymmetric_fem*.cc units call these at their quadrature points).
//
//   f = (f_r, f_z) = (density omega^2 r, -density g)   [N/m^3]
//   T = T0 + T_r r + T_z z                             [K], the change from the stress-free state
//   e_th = alpha T (1, 1, 1, 0)                        in the order (rr, zz, tt, rz): no shear
//
// omega = loading.angular_velocity [rad/s] (the rotation about the z axis: f is the
// centrifugal force of the rotating frame, along +e_r), g = loading.gravity [m/s^2] (gravity
// along -e_z for g > 0), alpha = material.thermal_expansion [1/K]. The legacy hollow cylinder
// has no body loads (the form cannot state them): every value is then an exact zero.
// Precondition (the parser's check): density is set when omega or g is not zero, alpha when
// the temperature field is not zero.
#pragma once

#include "problem/problem.h"

#include <array>

namespace fem
{
  /// The loads of one problem, checked once; the values come from the problem layer
  /// (axisym::body_force, axisym::thermal_strain), the one definition both solvers use.
  class BodyLoadField
  {
  public:
    explicit BodyLoadField(const axisym::Problem &problem);

    /// A body force (rotation or gravity) is applied.
    bool has_force() const { return has_force_; }
    /// A thermal strain is applied (the temperature field is not zero).
    bool has_thermal_strain() const { return has_thermal_; }
    bool any() const { return has_force_ || has_thermal_; }

    /// f = (density omega^2 r, -density g) [N/m^3].
    std::array<double, 2> force(double r, double z) const
    {
      return has_force_ ? axisym::body_force(loads_, material_, r, z) : std::array<double, 2>{};
    }
    /// alpha T: each of e_rr, e_zz, e_tt of the thermal strain (e_rz = 0).
    double thermal_strain(double r, double z) const
    {
      return has_thermal_ ? axisym::thermal_strain(loads_, material_, r, z) : 0.0;
    }

  private:
    bool has_force_ = false, has_thermal_ = false;
    axisym::BodyLoads loads_;
    axisym::Material material_;
  };
} // namespace fem
