#include "rfm/solution.h"

#include "rfm/assembly.h"

#include <cmath>

namespace rfm
{
  void add_enrichment_fields(const EdgeColumns &e, const Eigen::Ref<const Eigen::VectorXd> &q_s,
                             const Eigen::Ref<const Eigen::VectorXd> &q_u, FieldValues &f)
  {
    for (int k = 0; k < n_stress_components; ++k)
      {
        f.sigma.col(k) += e.stress[k] * q_s;
        f.strain.col(k) += e.strain[k] * q_u;
      }
    for (int m = 0; m < 2; ++m)
      f.u.col(m) += e.u[m] * q_u;
  }

  double Functionals::indicator() const
  {
    return std::abs(lagrange - castigliano) / std::abs(reissner);
  }

  RfmSolution::RfmSolution(const DiscreteSpace &space, const Material &material,
                           Eigen::VectorXd q_s, Eigen::VectorXd q_u)
    : space_(space), material_(material), q_s_(std::move(q_s)), q_u_(std::move(q_u))
  {}

  FieldValues RfmSolution::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                    const Eigen::Ref<const Eigen::VectorXd> &z,
                                    const FieldPart part) const
  {
    const Eigen::Index n = space_.n_basis_functions(), n_p = r.size();
    FieldValues f;
    f.sigma.setZero(n_p, n_stress_components);
    f.u.setZero(n_p, 2);
    f.strain.setZero(n_p, n_stress_components);
    if (part != FieldPart::enrichment)
      {
        const BasisValues b = space_.basis().evaluate(r, z);
        const StressStructureValues s = space_.structures().stress(r, z);
        const DisplacementStructureValues d = space_.structures().displacement(r, z);
        const DisplacementBasisValues v = displacement_basis(b, d);
        f.sigma = s.s0;
        for (int k = 0; k < n_stress_components; ++k)
          f.sigma.col(k) += s.omega.col(k).cwiseProduct(b.value * q_s_.segment(k * n, n));

        f.u = d.u0;
        Eigen::MatrixXd du_dr = d.u0_r, du_dz = d.u0_z;
        for (int m = 0; m < 2; ++m)
          {
            const auto q = q_u_.segment(m * n, n);
            f.u.col(m) += v.value[m] * q;
            du_dr.col(m) += v.d_r[m] * q;
            du_dz.col(m) += v.d_z[m] * q;
          }
        f.strain.col(rr) = du_dr.col(0);
        f.strain.col(zz) = du_dz.col(1);
        f.strain.col(tt) = f.u.col(0).cwiseQuotient(r);
        f.strain.col(rz) = du_dz.col(0) + du_dr.col(1);
      }
    const Eigen::Index n_e = space_.n_edge_columns();
    if (part != FieldPart::polynomial && n_e > 0)
      {
        const EdgeColumns e = space_.enrichment()->evaluate(r, z);
        add_enrichment_fields(e, q_s_.tail(n_e), q_u_.tail(n_e), f);
      }
    return f;
  }

  Functionals RfmSolution::functionals() const
  {
    const Eigen::Matrix4d c = material_.compliance(), dm = material_.stiffness();

    // 1. Domain integrals on the assembly's rules: 1/2 s.C s, 1/2 e.D e and s.e.
    const Eigen::Vector3d energies = integrate(
      [&](const FieldValues &f, const auto &, const auto &) -> Eigen::MatrixXd {
        Eigen::MatrixXd g(f.sigma.rows(), 3);
        g.col(0) = 0.5 * f.sigma.cwiseProduct(f.sigma * c.transpose()).rowwise().sum();
        g.col(1) = 0.5 * f.strain.cwiseProduct(f.strain * dm.transpose()).rowwise().sum();
        g.col(2) = f.sigma.cwiseProduct(f.strain).rowwise().sum();
        return g;
      });
    const double complementary = energies[0], strain_energy = energies[1], mixed = energies[2];

    // 2. Boundary integrals: work of prescribed tractions; (s n).u* and (s n).(u - u*)
    //    on the parts with prescribed normal displacement (displacement, contact,
    //    symmetry with u* = 0).
    const BoundaryQuadrature &bq = space_.boundary_quadrature();
    const auto &parts = space_.structures().section().parts();
    const FieldValues fb = evaluate(bq.r, bq.z);
    double work = 0.0, kinematic = 0.0, mismatch = 0.0;
    for (Eigen::Index k = 0; k < bq.weights.size(); ++k)
      {
        const BoundaryPart &p = parts[bq.part[k]];
        const double n_r = bq.n_r[k], n_z = bq.n_z[k], w = bq.weights[k];
        const double u_r = fb.u(k, 0), u_z = fb.u(k, 1);
        if (p.condition == Condition::traction)
          {
            work += w * p.normal_stress * (n_r * u_r + n_z * u_z);
            continue;
          }
        const double t_r = fb.sigma(k, rr) * n_r + fb.sigma(k, rz) * n_z;
        const double t_z = fb.sigma(k, rz) * n_r + fb.sigma(k, zz) * n_z;
        double u_star_r = 0.0, u_star_z = 0.0;
        if (p.condition == Condition::displacement || p.condition == Condition::contact)
          {
            const double s = (p.side == Side::inner || p.side == Side::outer) ? bq.z[k] : bq.r[k];
            const double u_n = p.normal_displacement(s);
            u_star_r = u_n * n_r, u_star_z = u_n * n_z;
          }
        kinematic += w * (t_r * u_star_r + t_z * u_star_z);
        // On contact and symmetry parts only the normal component is prescribed; the
        // tangential traction vanishes there by construction, so the full dot product
        // equals its normal part.
        mismatch += w * (t_r * (u_r - u_star_r) + t_z * (u_z - u_star_z));
      }

    Functionals out;
    out.lagrange = strain_energy - work;
    out.castigliano = -complementary + kinematic;
    out.reissner = mixed - complementary - work - mismatch;
    return out;
  }
} // namespace rfm
