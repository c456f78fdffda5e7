// The discrete space of the Ritz method: coordinate functions, solution structures and
// the quadrature they are integrated with, evaluated once at the quadrature points.
//
// Integrals are per radian, over the whole body: the measure is
//   weight_factor * r dr dz,
// where weight_factor = 2 when the section is the upper half of a body symmetric about
// z = 0 (bottom side a symmetry plane), so that energies and forces refer to the full
// body as in DESIGN.md section 1.
#pragma once

#include "rfm/basis.h"
#include "rfm/edge_modes.h"
#include "rfm/quadrature.h"
#include "rfm/structures.h"

#include "problem/settings.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace rfm
{
  /// The "rfm" settings of a problem file (problem/settings.h, with their ranges).
  using DiscretizationOptions = axisym::RfmSettings;

  /// Points on the boundary parts where boundary integrals are taken.
  struct BoundaryQuadrature
  {
    Eigen::VectorXd r, z, weights; ///< weights include r ds and the weight factor
    Eigen::VectorXd n_r, n_z;      ///< outward unit normal
    std::vector<int> part;         ///< index into Section::parts()
  };

  /// The edges where a contact part of the outer side ends inside it (the zone [.., c]
  /// followed by a traction part): one (r_edge, z_edge) each.
  std::vector<std::array<double, 2>> contact_edges(const Section &section);

  /// Unknown layout: q_s = (q_rr, q_zz, q_tt, q_rz, q_edge), each q_c of size N and q_edge
  /// one coefficient per enrichment column; q_u = (q_r, q_z, q_edge) likewise. The
  /// enrichment columns are vector fields (chi times a mode), the polynomial ones carry one
  /// component each (structures.h).
  ///
  /// Integrals: products of two polynomial columns with the tensor rule on the whole
  /// section (`quadrature()`); every product with an enrichment column with the near-edge
  /// rule on the half disc that supports it (`edge_quadrature()`), where the singular
  /// products are polynomials in rho = rho_0 s^2. Post-processing integrates fields the
  /// same way (a bilinear form of two fields: the polynomial parts on the tensor rule,
  /// the rest on the near-edge rule), so functionals match the assembled system.
  class DiscreteSpace
  {
  public:
    /// The material enters the enrichment columns only (the modes are elastic fields).
    DiscreteSpace(const Structures &structures, const DiscretizationOptions &options,
                  const Material &material);

    const Structures &structures() const { return structures_; }
    const TensorLegendreBasis &basis() const { return basis_; }
    const DiscretizationOptions &options() const { return options_; }
    Eigen::Index n_basis_functions() const { return basis_.n_basis_functions(); }
    double weight_factor() const { return weight_factor_; }

    // At the interior quadrature points:
    const Quadrature2D &quadrature() const { return quadrature_; }
    /// weight_factor * w * r: the per-radian measure at each point.
    const Eigen::VectorXd &measure() const { return measure_; }
    const BasisValues &basis_values() const { return basis_values_; }
    const StressStructureValues &stress_structure() const { return stress_; }
    const DisplacementStructureValues &displacement_structure() const { return displacement_; }

    const BoundaryQuadrature &boundary_quadrature() const { return boundary_; }

    // Enrichment (nullptr / empty without a contact edge or with edge_modes = 0):
    const EdgeEnrichment *enrichment() const { return enrichment_ ? &*enrichment_ : nullptr; }
    Eigen::Index n_edge_columns() const { return enrichment_ ? enrichment_->n_columns() : 0; }
    Eigen::Index n_stress_unknowns() const { return 4 * n_basis_functions() + n_edge_columns(); }
    Eigen::Index n_displacement_unknowns() const
    {
      return 2 * n_basis_functions() + n_edge_columns();
    }
    /// The near-edge rule and, at its points, the per-radian measure and everything the
    /// tensor rule has, plus the enrichment columns.
    const Quadrature2D &edge_quadrature() const { return edge_quadrature_; }
    const Eigen::VectorXd &edge_measure() const { return edge_measure_; }
    const BasisValues &edge_basis_values() const { return edge_basis_values_; }
    const StressStructureValues &edge_stress_structure() const { return edge_stress_; }
    const DisplacementStructureValues &edge_displacement_structure() const
    {
      return edge_displacement_;
    }
    const EdgeColumns &edge_columns() const { return edge_columns_; }

  private:
    Structures structures_;
    DiscretizationOptions options_;
    TensorLegendreBasis basis_;
    double weight_factor_;
    Quadrature2D quadrature_;
    Eigen::VectorXd measure_;
    BasisValues basis_values_;
    StressStructureValues stress_;
    DisplacementStructureValues displacement_;
    BoundaryQuadrature boundary_;
    std::optional<EdgeEnrichment> enrichment_;
    Quadrature2D edge_quadrature_;
    Eigen::VectorXd edge_measure_;
    BasisValues edge_basis_values_;
    StressStructureValues edge_stress_;
    DisplacementStructureValues edge_displacement_;
    EdgeColumns edge_columns_;
  };
} // namespace rfm
