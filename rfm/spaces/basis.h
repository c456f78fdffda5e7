// Coordinate functions: tensor-product Legendre polynomials on the bounding box of the
// meridian section (paper eqs. 2.3, 2.4).
//
//   phi_{ij}(r, z) = P_i(xi(r)) P_j(eta(z)),  0 <= i, j <= degree,
//   xi = (2 r - r_min - r_max) / (r_max - r_min),  eta likewise in z,
//
// complete in the polynomials of degree <= p in each variable and linearly independent:
// N = (p + 1)^2 functions per unknown component (the paper's Table 1 uses N = 1, 9, 64).
// Ordering: index = j * (p + 1) + i (r fastest). With a degree of its own along z
// (rfm.z_degree_ratio: 0 <= j <= p_z) N = (p + 1)(p_z + 1), index = j * (p + 1) + i.
//
// Even in r (a box on the axis, r_min = 0; the axis parity of outline_model.h): xi =
// 2 (r / r_max)^2 - 1, so that the functions are the polynomials of degree <= p in r^2. Since
// r dr = r_max^2 / 4 d xi, they are orthogonal in the r-weighted inner product of the
// functionals on the box, as the plain ones are in dr dz.
#pragma once

#include <Eigen/Core>

namespace rfm
{
  /// Values and first derivatives of all N basis functions at n points:
  /// row k holds the functions at point k (n_points x N, column-major: GEMM-ready).
  struct BasisValues
  {
    Eigen::MatrixXd value, d_r, d_z;
  };

  class TensorLegendreBasis
  {
  public:
    /// Precondition: degree >= 0, r_max > r_min, z_max > z_min, and r_min = 0 if even_in_r.
    /// `degree_z`: the degree along z (-1: `degree`, as along r).
    TensorLegendreBasis(int degree, double r_min, double r_max, double z_min, double z_max,
                        bool even_in_r = false, int degree_z = -1);

    /// The degree along r (in r^2 when even_in_r) and along z.
    int degree() const { return degree_; }
    int degree_z() const { return degree_z_; }
    Eigen::Index n_basis_functions() const
    {
      return static_cast<Eigen::Index>(degree_ + 1) * (degree_z_ + 1);
    }

    BasisValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;

    bool even_in_r() const { return even_r_; }

  private:
    int degree_, degree_z_;
    double r_min_, r_max_, z_min_, z_max_;
    bool even_r_ = false;
  };

  /// P_0..P_p and their derivatives at x (three-term recurrence and
  /// P'_{n+1} = P'_{n-1} + (2n + 1) P_n). Output vectors of length p + 1.
  void legendre_values(int degree, double x, Eigen::Ref<Eigen::VectorXd> p,
                       Eigen::Ref<Eigen::VectorXd> dp);
} // namespace rfm
