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
#include "rfm/quadrature.h"
#include "rfm/structures.h"

#include <Eigen/Core>

namespace rfm
{
  struct DiscretizationOptions
  {
    int degree = 8;             ///< p: N = (p + 1)^2 functions per unknown component
    int extra_gauss_points = 4; ///< Gauss points per direction and cell = p + this
    int n_cells_r = 1;          ///< uniform cells in r before splitting at break points
    int n_cells_z = 1;          ///< uniform cells in z before splitting at break points
    int n_graded_layers = 8;    ///< geometric layers toward each break point
    double grading_ratio = 0.35; ///< width ratio between successive graded layers

    /// Throws std::invalid_argument naming the field, the value and the rule.
    void validate() const;
  };

  /// Points on the boundary parts where boundary integrals are taken.
  struct BoundaryQuadrature
  {
    Eigen::VectorXd r, z, weights; ///< weights include r ds and the weight factor
    Eigen::VectorXd n_r, n_z;      ///< outward unit normal
    std::vector<int> part;         ///< index into Section::parts()
  };

  class DiscreteSpace
  {
  public:
    DiscreteSpace(const Structures &structures, const DiscretizationOptions &options);

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
  };

  /// Uniform cells on [a, b], then split and graded at the break points.
  std::vector<double> section_cells(double a, double b, int n_uniform,
                                    const std::vector<double> &break_points,
                                    int n_graded_layers, double grading_ratio);
} // namespace rfm
