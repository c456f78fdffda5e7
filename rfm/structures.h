// Solution structures (paper eqs. 2.1, 2.2) for a rectangular meridian section whose
// sides carry the conditions of section.h. Every boundary condition holds identically,
// for any coefficients of the coordinate functions phi_j:
//
//   sigma_c = s0_c + omega_c * sum_j q_{c,j} phi_j,  c in {rr, zz, tt, rz}
//   u_m     = u0_m + omega_m * sum_j q_{m,j} phi_j,  m in {r, z}
//
//   omega_rr: vanishes on the traction parts of the inner and outer sides;
//   omega_zz: vanishes on the traction parts of the bottom and top sides;
//   omega_rz: vanishes on every part with prescribed (zero) shear: all but `displacement`;
//   omega_tt = 1 (the hoop stress is not a traction on any side);
//   omega_r:  vanishes on the displacement and contact parts (u_r = u_n* there);
//   omega_z:  vanishes on the displacement parts (u_z = 0) and symmetry planes (u_z = 0).
//   s0_rr, s0_zz: linear in r (resp. z) between the normal stresses of opposite sides;
//   s0_rz = s0_tt = 0; u0_r: linear in r between the sides' prescribed u_r(z); u0_z = 0.
//
// Each omega is the product of the parts' omega functions. The product vanishes on the
// union of the parts, as the R0 conjunction does, but stays a polynomial on whole sides:
// the R0 conjunction sqrt(x^2 + y^2) of the two sides r = R1 and r = R2 has complex
// branch points at distance (R2 - R1)/2 from the mid-line, which caps the polynomial
// convergence rate at (1 + sqrt 2)^-p instead of the rate of the solution itself.
//
// A rigid translation in z must be removed: construction throws if no part fixes u_z.
#pragma once

#include "rfm/material.h"
#include "rfm/section.h"

#include <Eigen/Core>

namespace rfm
{
  /// Stress structure at points: columns in StressComponent order (n_points x 4).
  struct StressStructureValues
  {
    Eigen::MatrixXd omega, s0;
  };

  /// Displacement structure at points: columns (u_r, u_z) (n_points x 2), with the
  /// r and z derivatives of omega and u0.
  struct DisplacementStructureValues
  {
    Eigen::MatrixXd omega, omega_r, omega_z, u0, u0_r, u0_z;
  };

  class Structures
  {
  public:
    /// Validates the section; throws std::invalid_argument if it is inconsistent or
    /// leaves the rigid translation in z free.
    explicit Structures(const Section &section);

    StressStructureValues stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                                 const Eigen::Ref<const Eigen::VectorXd> &z) const;
    DisplacementStructureValues displacement(const Eigen::Ref<const Eigen::VectorXd> &r,
                                             const Eigen::Ref<const Eigen::VectorXd> &z) const;

    const Section &section() const { return section_; }

  private:
    // Product of the omega functions of the parts selected by `take`.
    template <typename Predicate>
    RValue omega_of(double r, double z, Predicate take) const;
    // Prescribed normal stress / displacement of a side at s (0 where not prescribed).
    double side_normal_stress(Side side) const;
    double side_u_r(Side side, double z, double &du_r_dz) const;

    Section section_;
  };
} // namespace rfm
