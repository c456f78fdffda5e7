#include "rfm/assembly.h"

namespace rfm
{
  DisplacementBasisValues displacement_basis(const BasisValues &b,
                                             const DisplacementStructureValues &d)
  {
    DisplacementBasisValues v;
    for (int m = 0; m < 2; ++m)
      {
        v.value[m] = d.omega.col(m).asDiagonal() * b.value;
        v.d_r[m] = d.omega_r.col(m).asDiagonal() * b.value;
        v.d_r[m].noalias() += d.omega.col(m).asDiagonal() * b.d_r;
        v.d_z[m] = d.omega_z.col(m).asDiagonal() * b.value;
        v.d_z[m].noalias() += d.omega.col(m).asDiagonal() * b.d_z;
      }
    return v;
  }

  ReissnerSystem assemble_reissner_system(const DiscreteSpace &space, const Material &material)
  {
    const Eigen::Index n = space.n_basis_functions();
    const Eigen::Matrix4d c = material.compliance();
    const Eigen::VectorXd &mu = space.measure();
    const Eigen::VectorXd &r = space.quadrature().r;
    const BasisValues &b = space.basis_values();
    const StressStructureValues &s = space.stress_structure();
    const DisplacementStructureValues &d = space.displacement_structure();
    const Eigen::Index n_q = mu.size();

    ReissnerSystem sys;
    sys.r11.setZero(4 * n, 4 * n);
    sys.r12.setZero(4 * n, 2 * n);

    // Weighted stress bases: WX_c = diag(mu omega_c) B. Products with them give every block.
    Eigen::MatrixXd wx[n_stress_components];
    for (int k = 0; k < n_stress_components; ++k)
      wx[k] = (mu.cwiseProduct(s.omega.col(k))).asDiagonal() * b.value;

    // 1. R11 = - int X . C X: blocks (k, l) = -C_kl (WX_k)^T (omega_l B).
    for (int k = 0; k < n_stress_components; ++k)
      for (int l = k; l < n_stress_components; ++l)
        {
          if (c(k, l) == 0.0)
            continue;
          const Eigen::MatrixXd omega_b = s.omega.col(l).asDiagonal() * b.value;
          sys.r11.block(k * n, l * n, n, n).noalias() = -c(k, l) * (wx[k].transpose() * omega_b);
          if (l != k)
            sys.r11.block(l * n, k * n, n, n) = sys.r11.block(k * n, l * n, n, n).transpose();
        }

    // 2. R12 = int X . e(Phi).
    const DisplacementBasisValues v = displacement_basis(b, d);
    const Eigen::VectorXd inv_r = r.cwiseInverse();
    sys.r12.block(rr * n, 0, n, n).noalias() = wx[rr].transpose() * v.d_r[0];
    sys.r12.block(tt * n, 0, n, n).noalias() =
      wx[tt].transpose() * (inv_r.asDiagonal() * v.value[0]);
    sys.r12.block(rz * n, 0, n, n).noalias() = wx[rz].transpose() * v.d_z[0];
    sys.r12.block(zz * n, n, n, n).noalias() = wx[zz].transpose() * v.d_z[1];
    sys.r12.block(rz * n, n, n, n).noalias() = wx[rz].transpose() * v.d_r[1];

    // 3. p_s = int X . (e(u0) - C s0).
    Eigen::MatrixXd e0(n_q, n_stress_components);
    e0.col(rr) = d.u0_r.col(0);
    e0.col(zz) = d.u0_z.col(1);
    e0.col(tt) = d.u0.col(0).cwiseProduct(inv_r);
    e0.col(rz) = d.u0_z.col(0) + d.u0_r.col(1);
    const Eigen::MatrixXd residual = e0 - s.s0 * c.transpose(); // rows: (e0 - C s0)^T
    sys.p_s.resize(4 * n);
    for (int k = 0; k < n_stress_components; ++k)
      sys.p_s.segment(k * n, n).noalias() = wx[k].transpose() * residual.col(k);

    // 4. p_u = int s0 . e(Phi) - int_{S_t} t . Phi.
    const Eigen::VectorXd m_rr = mu.cwiseProduct(s.s0.col(rr));
    const Eigen::VectorXd m_zz = mu.cwiseProduct(s.s0.col(zz));
    const Eigen::VectorXd m_tt = mu.cwiseProduct(s.s0.col(tt)).cwiseProduct(inv_r);
    const Eigen::VectorXd m_rz = mu.cwiseProduct(s.s0.col(rz));
    sys.p_u.resize(2 * n);
    sys.p_u.segment(0, n).noalias() = v.d_r[0].transpose() * m_rr + v.value[0].transpose() * m_tt +
                                      v.d_z[0].transpose() * m_rz;
    sys.p_u.segment(n, n).noalias() = v.d_z[1].transpose() * m_zz + v.d_r[1].transpose() * m_rz;

    const BoundaryQuadrature &bq = space.boundary_quadrature();
    const auto &parts = space.structures().section().parts();
    const BasisValues bb = space.basis().evaluate(bq.r, bq.z);
    const DisplacementStructureValues bd = space.structures().displacement(bq.r, bq.z);
    for (Eigen::Index k = 0; k < bq.weights.size(); ++k)
      {
        const BoundaryPart &part = parts[bq.part[k]];
        if (part.condition != Condition::traction)
          continue;
        // t = sigma_nn n (zero shear): only the normal displacement component works.
        const double t_r = part.normal_stress * bq.n_r[k];
        const double t_z = part.normal_stress * bq.n_z[k];
        sys.p_u.segment(0, n) -= (bq.weights[k] * t_r * bd.omega(k, 0)) * bb.value.row(k).transpose();
        sys.p_u.segment(n, n) -= (bq.weights[k] * t_z * bd.omega(k, 1)) * bb.value.row(k).transpose();
      }
    return sys;
  }
} // namespace rfm
