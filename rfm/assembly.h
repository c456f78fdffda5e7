// Assembly of the resolving system (paper eq. 2.5; DESIGN.md section 2):
//
//   [ R11   R12 ] [q_s]     [ p_s ]
//   [ R12^T  0  ] [q_u] = - [ p_u ]
//
//   R11_kl = - int X_k . C X_l  r dr dz       (symmetric negative definite)
//   R12_km =   int X_k . e(Phi_m) r dr dz
//   p_s,k  =   int X_k . (e(u0) - C s0) r dr dz
//   p_u,m  =   int s0 . e(Phi_m) r dr dz - int_{S_t} t . Phi_m r ds   (no body force)
//
// with the stress basis X_{c,j} = omega_c phi_j e_c (c = rr, zz, tt, rz) and the
// displacement basis Phi_{m,j} = omega_m phi_j e_m (m = r, z). Strain of a displacement
// (DESIGN.md section 1): e(u) = (du_r/dr, du_z/dz, u_r/r, du_r/dz + du_z/dr).
//
// Unknown ordering: q_s = (q_rr, q_zz, q_tt, q_rz), q_u = (q_r, q_z), N each.
// Every block is one dense product B^T diag(weights) B' over the quadrature points
// with pointwise weights mu * omega_c * C_cl, so assembly runs at GEMM speed.
#pragma once

#include "rfm/discrete_space.h"
#include "rfm/material.h"

#include <Eigen/Core>

namespace rfm
{
  /// Sizes: n_s = 4N + n_e stress and n_u = 2N + n_e displacement unknowns
  /// (DiscreteSpace: the enrichment columns last).
  struct ReissnerSystem
  {
    Eigen::MatrixXd r11; ///< n_s x n_s
    Eigen::MatrixXd r12; ///< n_s x n_u
    Eigen::VectorXd p_s; ///< n_s
    Eigen::VectorXd p_u; ///< n_u
  };

  ReissnerSystem assemble_reissner_system(const DiscreteSpace &space, const Material &material);

  /// Displacement basis at points: for m = r, z the matrices omega_m phi_j and its r and
  /// z derivatives (n_points x N each). Shared by assembly and post-processing.
  struct DisplacementBasisValues
  {
    Eigen::MatrixXd value[2], d_r[2], d_z[2];
  };
  DisplacementBasisValues displacement_basis(const BasisValues &b,
                                             const DisplacementStructureValues &d);

  /// Every column of both spaces at points, as dense component matrices: stress[c] is
  /// n_points x n_s (component c of every stress column), strain[c] is n_points x n_u
  /// (component c of e(Phi) for every displacement column). The polynomial columns are block-sparse here (zeros elsewhere): used
  /// on the near-edge rule only, where all products with the enrichment are taken.
  struct AllColumns
  {
    Eigen::MatrixXd stress[4], strain[4];
  };
  AllColumns all_columns(const DiscreteSpace &space, const BasisValues &b,
                         const StressStructureValues &s, const DisplacementStructureValues &d,
                         const EdgeColumns *edge, const Eigen::Ref<const Eigen::VectorXd> &r);

  /// The blocks of the polynomial columns (N per component, first in q_s and q_u) at
  /// quadrature points with per-radian measure mu: R11 and R12 blocks, p_s and the s0 part
  /// of p_u, written into the leading rows and columns of `sys` (sized by the caller).
  void add_polynomial_blocks(const Eigen::Ref<const Eigen::VectorXd> &mu,
                             const Eigen::Ref<const Eigen::VectorXd> &r, const BasisValues &b,
                             const StressStructureValues &s, const DisplacementStructureValues &d,
                             const Eigen::Matrix4d &c, ReissnerSystem &sys);

  /// e(u0) - C s0 at points (n_points x 4): the data of p_s.
  Eigen::MatrixXd initial_strain_residual(const StressStructureValues &s,
                                          const DisplacementStructureValues &d,
                                          const Eigen::Ref<const Eigen::VectorXd> &r,
                                          const Eigen::Matrix4d &c);
} // namespace rfm
