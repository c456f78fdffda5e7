// Gauss-Legendre quadrature on intervals and on tensor-product cells of the meridian
// section, with splitting at break points and geometric grading toward them.
//
// An n-point Gauss-Legendre rule is exact for polynomials of degree 2n-1. Nodes and
// weights are computed (Newton iteration on P_n from the Chebyshev-Gauss guess), not
// tabulated; the unit tests check exactness and the weight sum.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace rfm
{
  /// Nodes and weights of the n-point Gauss-Legendre rule on [-1, 1]. Precondition: n >= 1.
  struct GaussRule1D
  {
    Eigen::VectorXd nodes;
    Eigen::VectorXd weights;
  };
  GaussRule1D gauss_legendre(int n_points);

  /// Cell ends partitioning [a, b]: split at every break point strictly inside (a, b),
  /// and, for n_graded_layers > 0, graded geometrically toward each break point: the
  /// cell touching the break point has width ratio^n_graded_layers times the width of
  /// the sub-interval beside it (0 < ratio < 1). Break points outside (a, b) are
  /// ignored, except that grading is applied toward a break point equal to a or b.
  std::vector<double> graded_partition(double a, double b,
                                       const std::vector<double> &break_points,
                                       int n_graded_layers, double ratio);

  /// Quadrature points in the meridian plane: coordinates (r, z) and plain area
  /// weights dr dz (the r of the axisymmetric measure is not included).
  struct Quadrature2D
  {
    Eigen::VectorXd r, z, weights;
    Eigen::Index n_points() const { return weights.size(); }
  };

  /// Tensor-product Gauss rule with n_points x n_points points on every cell of the
  /// grid r_cells x z_cells (cell ends as returned by graded_partition).
  Quadrature2D tensor_gauss(const std::vector<double> &r_cells,
                            const std::vector<double> &z_cells, int n_points);

  /// Gauss rule on the cells of a 1-D partition: nodes and plain length weights.
  GaussRule1D gauss_on_cells(const std::vector<double> &cells, int n_points);
} // namespace rfm
