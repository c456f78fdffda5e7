// Post-processing of a solved RFM system: displacements and stresses at any point of
// the section, and the energy functionals of paper section 3 (DESIGN.md section 3):
//
//   Phi_L = 1/2 int e(u).D e(u) - W(u),        W(u) = int_{S_t} t.u r ds (no body force)
//   Phi_C = -1/2 int s.C s + int_{S_u, S_c} (s n).u* r ds
//   Phi_R = int [s.e(u) - 1/2 s.C s] - W(u) - int_{S_u, S_c} (s n).(u - u*) r ds
//
// per radian over the whole body [J/rad]. At the exact solution all three equal -U for
// a traction-loaded body and +U for a displacement-driven one. Symmetry planes carry
// u_n* = 0 and contribute nothing.
#pragma once

#include "rfm/discrete_space.h"
#include "rfm/material.h"

#include <Eigen/Core>

namespace rfm
{
  struct FieldValues
  {
    Eigen::MatrixXd u;     ///< n x 2: (u_r, u_z) [m]
    Eigen::MatrixXd sigma; ///< n x 4: (sigma_rr, sigma_zz, sigma_tt, sigma_rz) [Pa]
    Eigen::MatrixXd strain; ///< n x 4: e(u) of the displacement field [-]
  };

  struct Functionals
  {
    double lagrange = 0.0, castigliano = 0.0, reissner = 0.0; ///< J per radian
    /// |Phi_L - Phi_C| / |Phi_R|: a-posteriori indicator
    double indicator() const;
  };

  class RfmSolution
  {
  public:
    RfmSolution(const DiscreteSpace &space, const Material &material, Eigen::VectorXd q_s,
                Eigen::VectorXd q_u);

    /// Fields at points of the section (r, z inside the bounding box).
    FieldValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;

    Functionals functionals() const;

    const DiscreteSpace &space() const { return space_; }
    const Material &material() const { return material_; }

  private:
    const DiscreteSpace &space_;
    Material material_;
    Eigen::VectorXd q_s_, q_u_;
  };
} // namespace rfm
