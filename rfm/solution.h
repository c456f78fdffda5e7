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

#include <functional>

namespace rfm
{
  struct FieldValues
  {
    Eigen::MatrixXd u;     ///< n x 2: (u_r, u_z) [m]
    Eigen::MatrixXd sigma; ///< n x 4: (sigma_rr, sigma_zz, sigma_tt, sigma_rz) [Pa]
    Eigen::MatrixXd strain; ///< n x 4: e(u) of the displacement field [-]
  };

  /// The fields of a body mirrored in z = 0 at its image points: evaluates at |z| and flips
  /// u_z, sigma_rz and gamma_rz (odd in z) where z < 0.
  template <typename Evaluate>
  FieldValues mirrored_fields(const Eigen::Ref<const Eigen::VectorXd> &r,
                              const Eigen::Ref<const Eigen::VectorXd> &z, const Evaluate &evaluate)
  {
    FieldValues f = evaluate(r, z.cwiseAbs());
    for (Eigen::Index k = 0; k < z.size(); ++k)
      if (z[k] < 0)
        {
          f.u(k, 1) = -f.u(k, 1);
          f.sigma(k, 3) = -f.sigma(k, 3); // rz
          f.strain(k, 3) = -f.strain(k, 3);
        }
    return f;
  }

  /// Adds the enrichment's part, columns e with coefficients q_s (stress) and q_u
  /// (displacement), to the fields f at the same points.
  void add_enrichment_fields(const EdgeColumns &e, const Eigen::Ref<const Eigen::VectorXd> &q_s,
                             const Eigen::Ref<const Eigen::VectorXd> &q_u, FieldValues &f);

  /// Fields at points (r, z), as RfmModel::evaluate: the RFM's, or another solver's sampled
  /// at the same points (the verification drivers).
  using FieldEvaluator = std::function<FieldValues(const Eigen::Ref<const Eigen::VectorXd> &,
                                                   const Eigen::Ref<const Eigen::VectorXd> &)>;

  struct Functionals
  {
    double lagrange = 0.0, castigliano = 0.0, reissner = 0.0; ///< J per radian
    /// |Phi_L - Phi_C| / |Phi_R|: a-posteriori indicator
    double indicator() const;
  };

  /// Which part of a field to evaluate: everything, or only the structure with its
  /// polynomial columns (s0 + polynomial columns, u0 + polynomial columns), or only the
  /// enrichment columns (the difference).
  enum class FieldPart { all, polynomial, enrichment };

  class RfmSolution
  {
  public:
    RfmSolution(const DiscreteSpace &space, const Material &material, Eigen::VectorXd q_s,
                Eigen::VectorXd q_u);

    /// Fields at points of the section (r, z inside the bounding box).
    FieldValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z,
                         FieldPart part = FieldPart::all) const;

    Functionals functionals() const;

    /// int g(f) over the section for pointwise integrands g of the fields (per radian, with
    /// the space's weight factor), on the same rules as the assembly: g of the polynomial
    /// part on the tensor rule plus g(all) - g(polynomial) on the near-edge rule. Exact in
    /// the sense of the assembly for g linear or bilinear in the fields. `g(f, r, z)`
    /// returns an n_points x m matrix (m integrands at once: the fields are evaluated once);
    /// the result has m entries.
    template <typename Integrand>
    Eigen::VectorXd integrate(Integrand g) const;

    /// Coefficients: q_s (n_s) and q_u (n_u), in the layout of DiscreteSpace.
    const Eigen::VectorXd &stress_coefficients() const { return q_s_; }
    const Eigen::VectorXd &displacement_coefficients() const { return q_u_; }

    const DiscreteSpace &space() const { return space_; }
    const Material &material() const { return material_; }

  private:
    const DiscreteSpace &space_;
    Material material_;
    Eigen::VectorXd q_s_, q_u_;
  };

  template <typename Integrand>
  Eigen::VectorXd RfmSolution::integrate(Integrand g) const
  {
    const Quadrature2D &q = space_.quadrature();
    const Eigen::MatrixXd tensor = g(evaluate(q.r, q.z, FieldPart::polynomial), q.r, q.z);
    Eigen::VectorXd sum = tensor.transpose() * space_.measure();
    if (space_.n_edge_columns() > 0)
      {
        const Quadrature2D &e = space_.edge_quadrature();
        const Eigen::MatrixXd all = g(evaluate(e.r, e.z, FieldPart::all), e.r, e.z);
        const Eigen::MatrixXd poly = g(evaluate(e.r, e.z, FieldPart::polynomial), e.r, e.z);
        sum += (all - poly).transpose() * space_.edge_measure();
      }
    return sum;
  }
} // namespace rfm
