#include "rfm/assembly.h"

#include <array>

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

  AllColumns all_columns(const DiscreteSpace &space, const BasisValues &b,
                         const StressStructureValues &s, const DisplacementStructureValues &d,
                         const EdgeColumns *edge, const Eigen::Ref<const Eigen::VectorXd> &r)
  {
    const Eigen::Index n = space.n_basis_functions(), n_e = edge ? edge->stress[0].cols() : 0;
    const Eigen::Index n_p = r.size();
    AllColumns a;
    for (int c = 0; c < n_stress_components; ++c)
      {
        a.stress[c].setZero(n_p, 4 * n + n_e);
        a.stress[c].middleCols(c * n, n) = s.omega.col(c).asDiagonal() * b.value;
        if (n_e > 0)
          a.stress[c].rightCols(n_e) = edge->stress[c];
        a.strain[c].setZero(n_p, 2 * n + n_e);
        if (n_e > 0)
          a.strain[c].rightCols(n_e) = edge->strain[c];
      }
    const DisplacementBasisValues v = displacement_basis(b, d);
    a.strain[rr].middleCols(0, n) = v.d_r[0];
    a.strain[tt].middleCols(0, n) = r.cwiseInverse().asDiagonal() * v.value[0];
    a.strain[rz].middleCols(0, n) = v.d_z[0];
    a.strain[zz].middleCols(n, n) = v.d_z[1];
    a.strain[rz].middleCols(n, n) = v.d_r[1];
    return a;
  }

  namespace
  {
    // weight * t_m at the boundary points of the traction parts (t = sigma_nn n: the shear
    // traction is zero there), 0 elsewhere: W_t(Phi) = sum_m (weighted t_m) . Phi_m.
    std::array<Eigen::VectorXd, 2> weighted_tractions(const DiscreteSpace &space)
    {
      const BoundaryQuadrature &bq = space.boundary_quadrature();
      const auto &parts = space.structures().section().parts();
      std::array<Eigen::VectorXd, 2> w{Eigen::VectorXd::Zero(bq.weights.size()),
                                       Eigen::VectorXd::Zero(bq.weights.size())};
      for (Eigen::Index k = 0; k < bq.weights.size(); ++k)
        {
          const BoundaryPart &part = parts[bq.part[k]];
          if (part.condition != Condition::traction)
            continue;
          w[0][k] = bq.weights[k] * part.normal_stress * bq.n_r[k];
          w[1][k] = bq.weights[k] * part.normal_stress * bq.n_z[k];
        }
      return w;
    }

    // The products with the enrichment columns, on the near-edge rule: the borders of
    // R11 and R12 and the enrichment rows of p_s and p_u. The polynomial-polynomial blocks
    // (tensor rule) are not touched.
    void add_edge_terms(const DiscreteSpace &space, const Material &material, ReissnerSystem &sys)
    {
      const Eigen::Index n = space.n_basis_functions(), n_e = space.n_edge_columns();
      const Eigen::Index n_s = sys.r11.rows();
      const Eigen::Matrix4d c = material.compliance();
      const Quadrature2D &q = space.edge_quadrature();
      const Eigen::VectorXd &mu = space.edge_measure();
      const StressStructureValues &s = space.edge_stress_structure();
      const DisplacementStructureValues &d = space.edge_displacement_structure();
      const AllColumns a = all_columns(space, space.edge_basis_values(), s, d,
                                       &space.edge_columns(), q.r);

      // C X_e for the enrichment stress columns (n_points x n_e per component), weighted.
      Eigen::MatrixXd cx[n_stress_components];
      for (int k = 0; k < n_stress_components; ++k)
        {
          cx[k].setZero(q.n_points(), n_e);
          for (int l = 0; l < n_stress_components; ++l)
            if (c(k, l) != 0.0)
              cx[k] += c(k, l) * a.stress[l].rightCols(n_e);
          cx[k] = mu.asDiagonal() * cx[k];
        }
      // 1. R11 border: - int X_all . C X_e, mirrored.
      Eigen::MatrixXd border = Eigen::MatrixXd::Zero(n_s, n_e);
      for (int k = 0; k < n_stress_components; ++k)
        border.noalias() -= a.stress[k].transpose() * cx[k];
      sys.r11.rightCols(n_e) = border;
      sys.r11.bottomRows(n_e) = border.transpose();

      // 2. R12 borders: int X_all . e(Phi_e) and int X_e . e(Phi_poly).
      Eigen::MatrixXd wx_e[n_stress_components];
      for (int k = 0; k < n_stress_components; ++k)
        wx_e[k] = mu.asDiagonal() * a.stress[k].rightCols(n_e);
      Eigen::MatrixXd col_border = Eigen::MatrixXd::Zero(n_s, n_e);
      Eigen::MatrixXd row_border = Eigen::MatrixXd::Zero(n_e, 2 * n);
      for (int k = 0; k < n_stress_components; ++k)
        {
          col_border.noalias() +=
            a.stress[k].transpose() * (mu.asDiagonal() * a.strain[k].rightCols(n_e));
          row_border.noalias() += wx_e[k].transpose() * a.strain[k].leftCols(2 * n);
        }
      sys.r12.rightCols(n_e) = col_border;
      sys.r12.bottomLeftCorner(n_e, 2 * n) = row_border;

      // 3. p_s rows: int X_e . (e(u0) - C s0).
      const Eigen::MatrixXd residual = initial_strain_residual(s, d, q.r, c);
      for (int k = 0; k < n_stress_components; ++k)
        sys.p_s.tail(n_e).noalias() += wx_e[k].transpose() * residual.col(k);

      // 4. p_u rows: int s0 . e(Phi_e) - int_{S_t} t . Phi_e.
      for (int k = 0; k < n_stress_components; ++k)
        sys.p_u.tail(n_e).noalias() +=
          a.strain[k].rightCols(n_e).transpose() * mu.cwiseProduct(s.s0.col(k));
      const BoundaryQuadrature &bq = space.boundary_quadrature();
      const EdgeColumns be = space.enrichment()->evaluate(bq.r, bq.z);
      const std::array<Eigen::VectorXd, 2> wt = weighted_tractions(space);
      sys.p_u.tail(n_e) -= be.u[0].transpose() * wt[0] + be.u[1].transpose() * wt[1];
    }
  } // namespace

  Eigen::MatrixXd initial_strain_residual(const StressStructureValues &s,
                                          const DisplacementStructureValues &d,
                                          const Eigen::Ref<const Eigen::VectorXd> &r,
                                          const Eigen::Matrix4d &c)
  {
    Eigen::MatrixXd e0(r.size(), n_stress_components);
    e0.col(rr) = d.u0_r.col(0);
    e0.col(zz) = d.u0_z.col(1);
    e0.col(tt) = d.u0.col(0).cwiseQuotient(r);
    e0.col(rz) = d.u0_z.col(0) + d.u0_r.col(1);
    return e0 - s.s0 * c.transpose(); // rows: (e0 - C s0)^T
  }

  void add_polynomial_blocks(const Eigen::Ref<const Eigen::VectorXd> &mu,
                             const Eigen::Ref<const Eigen::VectorXd> &r, const BasisValues &b,
                             const StressStructureValues &s, const DisplacementStructureValues &d,
                             const Eigen::Matrix4d &c, ReissnerSystem &sys)
  {
    const Eigen::Index n = b.value.cols();

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
    const Eigen::MatrixXd residual = initial_strain_residual(s, d, r, c);
    for (int k = 0; k < n_stress_components; ++k)
      sys.p_s.segment(k * n, n).noalias() = wx[k].transpose() * residual.col(k);

    // 4. p_u = int s0 . e(Phi) (the traction term is added by the caller).
    const Eigen::VectorXd m_rr = mu.cwiseProduct(s.s0.col(rr));
    const Eigen::VectorXd m_zz = mu.cwiseProduct(s.s0.col(zz));
    const Eigen::VectorXd m_tt = mu.cwiseProduct(s.s0.col(tt)).cwiseProduct(inv_r);
    const Eigen::VectorXd m_rz = mu.cwiseProduct(s.s0.col(rz));
    sys.p_u.segment(0, n).noalias() = v.d_r[0].transpose() * m_rr + v.value[0].transpose() * m_tt +
                                      v.d_z[0].transpose() * m_rz;
    sys.p_u.segment(n, n).noalias() = v.d_z[1].transpose() * m_zz + v.d_r[1].transpose() * m_rz;
  }

  ReissnerSystem assemble_reissner_system(const DiscreteSpace &space, const Material &material)
  {
    const Eigen::Index n = space.n_basis_functions();
    const Eigen::Index n_s = space.n_stress_unknowns(), n_u = space.n_displacement_unknowns();
    ReissnerSystem sys;
    sys.r11.setZero(n_s, n_s);
    sys.r12.setZero(n_s, n_u);
    sys.p_s.setZero(n_s);
    sys.p_u.setZero(n_u);
    add_polynomial_blocks(space.measure(), space.quadrature().r, space.basis_values(),
                          space.stress_structure(), space.displacement_structure(),
                          material.compliance(), sys);

    const BoundaryQuadrature &bq = space.boundary_quadrature();
    const BasisValues bb = space.basis().evaluate(bq.r, bq.z);
    const DisplacementStructureValues bd = space.structures().displacement(bq.r, bq.z);
    const std::array<Eigen::VectorXd, 2> wt = weighted_tractions(space);
    for (int m = 0; m < 2; ++m)
      sys.p_u.segment(m * n, n).noalias() -= bb.value.transpose() * bd.omega.col(m).cwiseProduct(wt[m]);
    if (space.n_edge_columns() > 0)
      add_edge_terms(space, material, sys);
    return sys;
  }
} // namespace rfm
