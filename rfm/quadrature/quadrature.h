// Gauss-Legendre quadrature on intervals and on tensor-product cells of the meridian
// section, with splitting at break points and geometric grading toward them.
//
// An n-point Gauss-Legendre rule is exact for polynomials of degree 2n-1. Nodes and
// weights are computed (Newton iteration on P_n from the Chebyshev-Gauss guess), not
// tabulated; the unit tests check exactness and the weight sum.
#pragma once

#include <Eigen/Core>
#include <limits>
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

  /// A radial rule on [0, rho_0] for polar rules about a point: n_points Gauss points on each
  /// geometric layer [0.2^(i+1), 0.2^i] rho_0 (i < n_layers) and on the innermost
  /// [0, 0.2^n_layers rho_0] with rho = rho_in s^2; the weights include the Jacobian rho (so
  /// that sum w f(rho) = int f(rho) rho drho). Precondition: n_points >= 1, n_layers >= 0.
  /// `breaks` in (0, rho_0) split the layer they fall in (n_points on each piece; in the
  /// innermost layer the piece below a break keeps the s^2 map); the pieces above the lowest
  /// break take n_points_beyond points instead where that is larger.
  GaussRule1D polar_radial_rule(double rho_0, int n_points, int n_layers,
                                const std::vector<double> &breaks = {}, int n_points_beyond = 0);

  /// Cell ends partitioning [a, b]: split at every break point strictly inside (a, b),
  /// and, for n_graded_layers > 0, graded geometrically toward each break point: the
  /// cell touching the break point has width ratio^n_graded_layers times the width of
  /// the sub-interval beside it (0 < ratio < 1). Break points outside (a, b) are
  /// ignored, except that grading is applied toward a break point equal to a or b.
  std::vector<double> graded_partition(double a, double b,
                                       const std::vector<double> &break_points,
                                       int n_graded_layers, double ratio);

  /// n_uniform uniform cells on [a, b], then split and graded at the break points
  /// (graded_partition); the cell ends, sorted.
  std::vector<double> section_cells(double a, double b, int n_uniform,
                                    const std::vector<double> &break_points,
                                    int n_graded_layers, double grading_ratio);

  /// Quadrature points in the meridian plane: coordinates (r, z) and plain area
  /// weights dr dz (the r of the axisymmetric measure is not included).
  struct Quadrature2D
  {
    Eigen::VectorXd r, z, weights;
    Eigen::Index n_points() const { return weights.size(); }
  };

  /// Tensor-product Gauss rule with n_points x n_points points on every cell of the
  /// grid r_cells x z_cells (cell ends as returned by graded_partition); r_in_square: in r,
  /// gauss_in_square_on_cells (cells in r >= 0).
  Quadrature2D tensor_gauss(const std::vector<double> &r_cells,
                            const std::vector<double> &z_cells, int n_points,
                            bool r_in_square = false);

  /// Gauss rule in s = x^2 on the cells of a partition of x >= 0: nodes x_k = sqrt(s_k) and
  /// plain length weights w_k such that sum_k w_k x_k f(x_k) = int f(x) x dx (= int f ds / 2)
  /// exactly for f a polynomial in x^2 of degree <= 2 n_points - 1 on each cell: the
  /// r-weighted integrals of the axis parity's functions (polynomials in r^2, section_basis.h)
  /// with the points of a degree-p rule instead of a degree-2p one.
  GaussRule1D gauss_in_square_on_cells(const std::vector<double> &cells, int n_points);

  /// Gauss rule on the cells of a 1-D partition: nodes and plain length weights.
  /// A cell with an end at one of `sqrt_points` is mapped by x = x_s + (x_o - x_s) t^2,
  /// t in [0, 1] (x_s the singular end, x_o the other), so that integrands behaving like
  /// |x - x_s|^(k/2) (the traces of the contact-edge modes) become polynomials in t:
  /// exact for |x - x_s|^(k/2) with k <= 4 n - 2, k >= -1.
  GaussRule1D gauss_on_cells(const std::vector<double> &cells, int n_points,
                             const std::vector<double> &sqrt_points = {});

  /// Polar rule on the half disc of radius rho_0 about (r_c, z_c) on the side r <= r_c
  /// (the near-edge rule of a contact edge on an outer side): r = r_c - rho sin theta,
  /// z = z_c - rho cos theta, theta in [0, pi] in two panels split at pi/2, and
  /// rho = rho_0 s^2 with Gauss in s, so that rho dr dz = 2 rho_0^2 s^3 ds dtheta.
  /// Integrands rho^(k/2) g(theta) with k >= -2 become polynomials in s: the rule is exact
  /// in rho for k/2 + 1 <= n_radial - 1 and converges exponentially in theta for smooth g.
  /// Weights are plain area weights dr dz, as in tensor_gauss.
  /// With z_max < z_c + rho_0 the half disc is clipped at z = z_max: on the rays that meet
  /// that line first, rho = L(theta) s^2 with L = (z_max - z_c) / (-cos theta), in a third
  /// panel from the angle where L = rho_0 to pi (integrands stay polynomial in s).
  Quadrature2D half_disc_gauss(double r_c, double z_c, double rho_0, int n_radial,
                               int n_angular,
                               double z_max = std::numeric_limits<double>::infinity());

  /// The step of the partition of unity between a disc's rule and the rules around it:
  /// S(t) of order 3 in t = (rho / rho_0)^2, S = O(t^4) at 0, 1 - O((1 - t)^4) at 1 (three
  /// continuous derivatives on the rim), 1 from t = 1 on.
  double disc_partition_step(double t);

  /// A disc's own rule (plain area weights) and the disc it covers.
  struct DiscRule
  {
    Quadrature2D rule;
    double r_c, z_c, radius;
  };

  /// One rule from a rule over a whole region and rules over discs inside it: at x the
  /// region's rule takes the share 1 / (1 + sum_j s_j) of its weight and disc j's rule
  /// s_j / (1 + sum_j s_j), s_j = (1 - S_j) / S_j with S_j the step at x for disc j (0 outside
  /// it). Every integrand is counted once, and the region's share vanishes like rho^8 at each
  /// disc's centre, so that a disc's rule alone takes what is singular or rough there.
  Quadrature2D blend_disc_rules(const Quadrature2D &region, const std::vector<DiscRule> &discs);
} // namespace rfm
