#include "rfm/spaces/local_basis.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rfm
{
  namespace
  {
    LocalBasis two_boxes()
    {
      LocalPatch a; // one-sided, on an end face z = 0.02 at the axis: t = e_r, n = -e_z
      a.r = 0.0, a.z = 0.02, a.t = {{1.0, 0.0}}, a.n = {{0.0, -1.0}}, a.half_size = 0.002;
      a.one_sided = true;
      LocalPatch b = a; // two-sided, on a side r = 0.01: t = e_z, n = -e_r
      b.r = 0.01, b.z = 0.0, b.t = {{0.0, 1.0}}, b.n = {{-1.0, 0.0}}, b.half_size = 0.004;
      b.one_sided = false;
      return LocalBasis({a, b}, 3);
    }
  } // namespace

  // Zero outside each box and on its sides inside the body (continuity), nonzero inside.
  TEST(LocalBasis, SupportedInItsBox)
  {
    const LocalBasis basis = two_boxes();
    // a: one-sided, degree 3 both ways (16); b: two-sided, 2 * 3 + 1 along t (8 x 4 = 32).
    ASSERT_EQ(basis.n_basis_functions(), 16 + 32);
    Eigen::VectorXd r(5), z(5);
    r << 0.001, 0.0025, 0.001, 0.009, 0.01 - 0.004;   // in a; beyond a's side; at a's depth;
    z << 0.019, 0.019, 0.02 - 0.002, 0.001, 0.001;   // in b; at b's depth
    const BasisValues v = basis.evaluate(r, z);
    EXPECT_GT(v.value.row(0).head(16).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_EQ(v.value.row(0).tail(32).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.value.row(1).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(v.value.row(2).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT(v.value.row(3).tail(32).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_EQ(v.value.row(3).head(16).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(v.value.row(4).cwiseAbs().maxCoeff(), 1e-12);
  }

  // The derivatives against central differences, inside both boxes.
  TEST(LocalBasis, DerivativesMatchFiniteDifferences)
  {
    const LocalBasis basis = two_boxes();
    Eigen::VectorXd r(2), z(2);
    r << 0.0013, 0.0085;
    z << 0.0187, 0.0012;
    const double h = 1e-7;
    const BasisValues v = basis.evaluate(r, z);
    const Eigen::VectorXd one = Eigen::VectorXd::Ones(2);
    const BasisValues rp = basis.evaluate(r + h * one, z), rm = basis.evaluate(r - h * one, z);
    const BasisValues zp = basis.evaluate(r, z + h * one), zm = basis.evaluate(r, z - h * one);
    const Eigen::MatrixXd d_r = (rp.value - rm.value) / (2 * h), d_z = (zp.value - zm.value) / (2 * h);
    const double scale = v.d_r.cwiseAbs().maxCoeff() + v.d_z.cwiseAbs().maxCoeff();
    EXPECT_LT((d_r - v.d_r).cwiseAbs().maxCoeff(), 1e-6 * scale);
    EXPECT_LT((d_z - v.d_z).cwiseAbs().maxCoeff(), 1e-6 * scale);
  }

  // The boxes' corners are the cell breaks: a one-sided box has its corners at the centre's
  // side too.
  TEST(LocalBasis, BreaksAreTheBoxesCorners)
  {
    const auto b = two_boxes().breaks();
    ASSERT_EQ(b[0].size(), 8u);
    EXPECT_DOUBLE_EQ(b[0][0], 0.0);
    EXPECT_DOUBLE_EQ(b[1][1], 0.018);
    EXPECT_DOUBLE_EQ(b[0][2], 0.002);
    EXPECT_DOUBLE_EQ(b[1][4], -0.004);
    EXPECT_DOUBLE_EQ(b[0][5], 0.006);
  }

  // The stress-only columns: on the box the products of Legendre polynomials of the box's
  // coordinates (x in [0, 1] mapped onto [-1, 1] for a one-sided box), without the cutoff, so
  // nonzero up to the box's sides; zero outside, including beyond a side.
  TEST(LocalBasis, PiecewiseValuesAreLegendreProductsOnTheBox)
  {
    const LocalBasis basis = two_boxes();
    // Box a one-sided: degree d both ways; box b two-sided: 2 d + 1 along t (its even and odd
    // parts in x each get d + 1 functions).
    const int d = 4, d_b = 2 * d + 1, per_a = (d + 1) * (d + 1), per_b = (d_b + 1) * (d + 1);
    Eigen::VectorXd r(4), z(4);
    r << 0.0015, 0.0021, 0.0099, 0.0099; // in a near its side; beyond a's side; in b; beyond b
    z << 0.0195, 0.0195, 0.0039, 0.0041;
    const Eigen::MatrixXd v = basis.piecewise_values(r, z, d);
    ASSERT_EQ(v.rows(), 4);
    ASSERT_EQ(v.cols(), per_a + per_b);
    // Legendre polynomials by Bonnet's recurrence (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}.
    const auto legendre = [](const int k, const double x) {
      double p0 = 1.0, p1 = x;
      if (k == 0)
        return p0;
      for (int m = 1; m < k; ++m)
        {
          const double p2 = ((2 * m + 1) * x * p1 - m * p0) / (m + 1);
          p0 = p1, p1 = p2;
        }
      return p1;
    };
    EXPECT_NEAR(legendre(4, 0.3), (35 * 0.0081 - 30 * 0.09 + 3) / 8.0, 1e-15);
    // Box a: x = r / 0.002 in [0, 1] -> xi = 2 x - 1, y = (0.02 - z) / 0.002 -> 2 y - 1.
    const double xi_a = 2 * (0.0015 / 0.002) - 1, eta_a = 2 * (0.0005 / 0.002) - 1;
    // Box b: x = z / 0.004 in [-1, 1], y = (0.01 - r) / 0.004.
    const double xi_b = 0.0039 / 0.004, eta_b = 2 * (0.0001 / 0.004) - 1;
    for (int j = 0; j <= d; ++j)
      {
        for (int i = 0; i <= d; ++i)
          EXPECT_NEAR(v(0, j * (d + 1) + i), legendre(i, xi_a) * legendre(j, eta_a), 1e-13);
        for (int i = 0; i <= d_b; ++i)
          EXPECT_NEAR(v(2, per_a + j * (d_b + 1) + i), legendre(i, xi_b) * legendre(j, eta_b), 1e-13)
            << "i = " << i << ", j = " << j;
      }
    EXPECT_EQ(v.row(0).tail(per_b).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.row(1).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.row(2).head(per_a).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.row(3).cwiseAbs().maxCoeff(), 0.0);
    // Near the side x -> 1 the values stay O(1) (no cutoff).
    EXPECT_GT(std::abs(v(2, per_a + 1)), 0.9); // P_1(xi_b) = 0.975
    EXPECT_THROW(basis.piecewise_values(r, z, -1), std::invalid_argument);
  }

  TEST(LocalBasis, RefusesBadBoxes)
  {
    LocalPatch p;
    p.half_size = 0.0;
    EXPECT_THROW(LocalBasis({p}, 2), std::invalid_argument);
    p.half_size = 1.0, p.n = {{1.0, 0.0}};
    EXPECT_THROW(LocalBasis({p}, 2), std::invalid_argument);
  }
} // namespace rfm
