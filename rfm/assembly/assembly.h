// Assembly of the resolving system (paper eq. 2.5; DESIGN.md section 2):
//
//   [ R11   R12 ] [q_s]     [ p_s ]
//   [ R12^T  0  ] [q_u] = - [ p_u ]
//
//   R11_kl = - int X_k . C X_l  r dr dz       (symmetric negative definite)
//   R12_km =   int X_k . e(Phi_m) r dr dz
//   p_s,k  =   int X_k . (e(u0) - C s0 - e_th) r dr dz
//   p_u,m  =   int s0 . e(Phi_m) r dr dz - int_{S_t} t . Phi_m r ds - int f . Phi_m r dr dz
//
// with f the body force and e_th the thermal strain (DESIGN.md 7.1). This file assembles
// the parts without them; the outline model (outline_model.h) subtracts the f and e_th
// terms after add_polynomial_blocks, and adds the boundary and enrichment columns.
//
// with the stress basis X_{c,j} = omega_c phi_j e_c (c = rr, zz, tt, rz) and the
// displacement basis Phi_{m,j} = omega_m phi_j e_m (m = r, z). Strain of a displacement
// (DESIGN.md section 1): e(u) = (du_r/dr, du_z/dz, u_r/r, du_r/dz + du_z/dr).
//
// Unknown ordering: q_s = (q_rr, q_zz, q_tt, q_rz), q_u = (q_r, q_z), N each.
// Every polynomial block is a dense product B^T G over the quadrature points, with B the
// basis values and G = diag(w) B + diag(w_r) B_r + diag(w_z) B_z formed pointwise (w:
// mu * omega_c * C_cl for R11, mu * omega_c times the strain's omega factors for R12).
// The points are taken in chunks (chunk_points of add_polynomial_blocks) so that the chunk's B,
// B_r, B_z and G stay in L2 while the block GEMMs of the chunk run: assembly then runs
// at GEMM speed instead of streaming n_q x N temporaries through memory. Each R11 block
// B^T diag(w) B is symmetric: only its lower triangle is computed, then mirrored.
#pragma once

#include "problem/settings.h"
#include "rfm/material.h"
#include "rfm/spaces/basis.h"
#include "rfm/spaces/edge_modes.h"

#include <Eigen/Core>

#include <vector>

#include <array>

namespace rfm
{
  /// The "rfm" settings of a problem file (problem/settings.h, with their ranges).
  using DiscretizationOptions = axisym::RfmSettings;

  /// Stress structure at points: columns in StressComponent order (n_points x 4).
  ///
  /// hoop_coupled: the polynomial column (rr, j) is omega_rr phi_j (e_rr + e_tt) rather than
  /// omega_rr phi_j e_rr, so that sigma_tt = sigma_rr + omega_tt P_tt (OutlineModel: the axis
  /// coupling, sigma_tt = sigma_rr on r = 0 with omega_tt = r). s0 is the full particular
  /// stress either way.
  struct StressStructureValues
  {
    Eigen::MatrixXd omega, s0;
    bool hoop_coupled = false;
  };

  /// The compliance between the polynomial blocks: C, or with s.hoop_coupled T^T C T, where
  /// T (the blocks' components to the stress's) adds the rr block to sigma_tt.
  Eigen::Matrix4d block_compliance(const Eigen::Matrix4d &c, bool hoop_coupled);

  /// Displacement structure at points: columns (u_r, u_z) (n_points x 2), with the
  /// r and z derivatives of omega and u0.
  struct DisplacementStructureValues
  {
    Eigen::MatrixXd omega, omega_r, omega_z, u0, u0_r, u0_z;
  };

  /// Sizes: n_s = 4N + n_b + n_e stress and n_u = 2N + n_e displacement unknowns (the
  /// polynomial columns first, then the boundary columns, the enrichment columns last).
  struct ReissnerSystem
  {
    /// n_s x n_s, symmetric; only its lower triangle is written when the assembly was asked
    /// for that alone (full_r11 = false below), the strict upper then unset.
    Eigen::MatrixXd r11;
    Eigen::MatrixXd r12; ///< n_s x n_u
    Eigen::VectorXd p_s; ///< n_s
    Eigen::VectorXd p_u; ///< n_u
  };

  /// Points per chunk for N basis functions and an L2 cache of l2_bytes: the chunk's
  /// B, B_r, B_z and one weighted product (4 N doubles per point) fill half of L2 (the
  /// other half holds the GEMM's packed panels), rounded down to a multiple of 8 and
  /// clamped to [min_chunk_points, max_chunk_points].
  Eigen::Index assembly_chunk_points(Eigen::Index n_basis_functions, long l2_bytes);
  inline constexpr Eigen::Index min_chunk_points = 64, max_chunk_points = 4096;

  /// Displacement basis at points: for m = r, z the matrices omega_m phi_j and its r and
  /// z derivatives (n_points x N each). Shared by assembly and post-processing.
  struct DisplacementBasisValues
  {
    Eigen::MatrixXd value[2], d_r[2], d_z[2];
  };
  DisplacementBasisValues displacement_basis(const BasisValues &b,
                                             const DisplacementStructureValues &d);

  /// The blocks of the polynomial columns (N per component, first in q_s and q_u) at
  /// quadrature points with per-radian measure mu: R11 and R12 blocks, p_s and the s0 part
  /// of p_u, written into the leading rows and columns of `sys` (sized by the caller;
  /// nothing else is touched). chunk_points: quadrature points per chunk (0:
  /// assembly_chunk_points(N, l2_cache_bytes())). full_r11: also write R11's strict upper
  /// triangle (a transposing copy of the lower one; the solver reads the lower one only: the
  /// copy took 0.39 ms of a 7.4 ms one-thread assembly at Lame p = 14).
  void add_polynomial_blocks(const Eigen::Ref<const Eigen::VectorXd> &mu,
                             const Eigen::Ref<const Eigen::VectorXd> &r, const BasisValues &b,
                             const StressStructureValues &s, const DisplacementStructureValues &d,
                             const Eigen::Matrix4d &c, ReissnerSystem &sys,
                             Eigen::Index chunk_points = 0, bool full_r11 = true);

  /// The products with enrichment columns (edge_modes.h) on a near-edge rule with points r
  /// and per-radian measure mu, where b, s, d and e are the polynomial basis, the structures and
  /// the enrichment columns: the borders of R11 and R12 with every other column and the
  /// enrichment rows of p_s and p_u, added to `sys` (sized by the caller; so a rule may come in
  /// blocks of points) in the layout
  /// q_s = (4 N polynomial, n_b boundary columns, n_e enrichment), q_u = (2 N, n_e);
  /// `boundary` the outline's boundary columns at the points (nullptr: n_b = 0), and the
  /// thermal strain and body force at the points when there are body loads (nullptr: none).
  /// The traction term of p_u (- int_St t . Phi_e) is the caller's: it is a boundary integral.
  /// `columns` (optional): e holds only these of the enrichment's columns, in this order (the
  /// others are zero at the points: a vertex's local columns beyond its disc).
  void add_enrichment_blocks(const Eigen::Ref<const Eigen::VectorXd> &mu,
                             const Eigen::Ref<const Eigen::VectorXd> &r, const BasisValues &b,
                             const StressStructureValues &s, const DisplacementStructureValues &d,
                             const EdgeColumns &e, const std::array<Eigen::MatrixXd, 4> *boundary,
                             const Eigen::VectorXd *thermal_strain, const Eigen::MatrixXd *body_force,
                             const Eigen::Matrix4d &c, ReissnerSystem &sys,
                             const std::vector<Eigen::Index> *columns = nullptr);

  /// e(u0) - C s0 at points (n_points x 4): the data of p_s.
  Eigen::MatrixXd initial_strain_residual(const StressStructureValues &s,
                                          const DisplacementStructureValues &d,
                                          const Eigen::Ref<const Eigen::VectorXd> &r,
                                          const Eigen::Matrix4d &c);
} // namespace rfm
