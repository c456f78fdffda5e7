#include "rfm/local_basis.h"

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
    ASSERT_EQ(basis.n_basis_functions(), 2 * 16);
    Eigen::VectorXd r(5), z(5);
    r << 0.001, 0.0025, 0.001, 0.009, 0.01 - 0.004;   // in a; beyond a's side; at a's depth;
    z << 0.019, 0.019, 0.02 - 0.002, 0.001, 0.001;   // in b; at b's depth
    const BasisValues v = basis.evaluate(r, z);
    EXPECT_GT(v.value.row(0).head(16).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_EQ(v.value.row(0).tail(16).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.value.row(1).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(v.value.row(2).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT(v.value.row(3).tail(16).cwiseAbs().maxCoeff(), 1e-3);
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
    const int d = 4, per = (d + 1) * (d + 1);
    Eigen::VectorXd r(4), z(4);
    r << 0.0015, 0.0021, 0.0099, 0.0099; // in a near its side; beyond a's side; in b; beyond b
    z << 0.0195, 0.0195, 0.0039, 0.0041;
    const Eigen::MatrixXd v = basis.piecewise_values(r, z, d);
    ASSERT_EQ(v.rows(), 4);
    ASSERT_EQ(v.cols(), 2 * per);
    const auto legendre = [](const int k, const double x) {
      const double p[] = {1.0, x, 0.5 * (3 * x * x - 1), 0.5 * (5 * x * x * x - 3 * x),
                          (35 * x * x * x * x - 30 * x * x + 3) / 8.0};
      return p[k];
    };
    // Box a: x = r / 0.002 in [0, 1] -> xi = 2 x - 1, y = (0.02 - z) / 0.002 -> 2 y - 1.
    const double xi_a = 2 * (0.0015 / 0.002) - 1, eta_a = 2 * (0.0005 / 0.002) - 1;
    // Box b: x = z / 0.004 in [-1, 1], y = (0.01 - r) / 0.004.
    const double xi_b = 0.0039 / 0.004, eta_b = 2 * (0.0001 / 0.004) - 1;
    for (int j = 0; j <= d; ++j)
      for (int i = 0; i <= d; ++i)
        {
          EXPECT_NEAR(v(0, j * (d + 1) + i), legendre(i, xi_a) * legendre(j, eta_a), 1e-13);
          EXPECT_NEAR(v(2, per + j * (d + 1) + i), legendre(i, xi_b) * legendre(j, eta_b), 1e-13);
        }
    EXPECT_EQ(v.row(0).tail(per).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.row(1).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.row(2).head(per).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(v.row(3).cwiseAbs().maxCoeff(), 0.0);
    // Near the side x -> 1 the values stay O(1) (no cutoff).
    EXPECT_GT(std::abs(v(2, per + d)), 0.5);
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
