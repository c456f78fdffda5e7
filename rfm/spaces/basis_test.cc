#include "rfm/quadrature/quadrature.h"
#include "rfm/spaces/basis.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace rfm
{
  TEST(Legendre, KnownValuesAndDerivatives)
  {
    Eigen::VectorXd p(5), dp(5);
    const double x = 0.3;
    legendre_values(4, x, p, dp);
    EXPECT_NEAR(p[2], 0.5 * (3 * x * x - 1), 1e-15);
    EXPECT_NEAR(p[3], 0.5 * (5 * x * x * x - 3 * x), 1e-15);
    EXPECT_NEAR(p[4], (35 * std::pow(x, 4) - 30 * x * x + 3) / 8, 1e-15);
    EXPECT_NEAR(dp[3], 0.5 * (15 * x * x - 3), 1e-14);
    EXPECT_NEAR(dp[4], (140 * x * x * x - 60 * x) / 8, 1e-14);
  }

  TEST(TensorLegendreBasis, DerivativesMatchFiniteDifferences)
  {
    const TensorLegendreBasis b(6, 0.1, 0.2, 0.0, 0.2);
    ASSERT_EQ(b.n_basis_functions(), 49);
    Eigen::VectorXd r(3), z(3);
    r << 0.11, 0.153, 0.199;
    z << 0.01, 0.1, 0.17;
    const double h = 1e-7;
    const BasisValues v = b.evaluate(r, z);
    const BasisValues vr = b.evaluate((r.array() + h).matrix(), z);
    const BasisValues vrm = b.evaluate((r.array() - h).matrix(), z);
    const BasisValues vz = b.evaluate(r, (z.array() + h).matrix());
    const BasisValues vzm = b.evaluate(r, (z.array() - h).matrix());
    const Eigen::MatrixXd fd_r = (vr.value - vrm.value) / (2 * h);
    const Eigen::MatrixXd fd_z = (vz.value - vzm.value) / (2 * h);
    EXPECT_LT((fd_r - v.d_r).cwiseAbs().maxCoeff(), 1e-5 * v.d_r.cwiseAbs().maxCoeff());
    EXPECT_LT((fd_z - v.d_z).cwiseAbs().maxCoeff(), 1e-5 * v.d_z.cwiseAbs().maxCoeff());
  }

  TEST(TensorLegendreBasis, LinearlyIndependentAndOrthogonalOnTheBox)
  {
    // On [-1, 1]^2 the Gram matrix of the Legendre products is diagonal:
    // int P_i(x) P_k(x) dx int P_j(y) P_l(y) dy = 4 / ((2i + 1)(2j + 1)) delta_ik delta_jl.
    // The integrands have degree <= 2p in each variable, so the tensor (p + 1)-point
    // Gauss-Legendre rule (exact to degree 2p + 1; quadrature.h, with its own Legendre
    // recurrence, tested on monomials in quadrature_test.cc) gives them to rounding.
    const int p = 5, m = p + 1;
    const TensorLegendreBasis b(p, -1.0, 1.0, -1.0, 1.0);
    const GaussRule1D g = gauss_legendre(m);
    Eigen::VectorXd x(m * m), y(m * m), w(m * m);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        x[j * m + i] = g.nodes[i], y[j * m + i] = g.nodes[j],
                  w[j * m + i] = g.weights[i] * g.weights[j];
    const BasisValues v = b.evaluate(x, y);
    const Eigen::MatrixXd gram = v.value.transpose() * w.asDiagonal() * v.value;
    ASSERT_EQ(gram.rows(), m * m);
    // Measured: 8.9e-16 on the diagonal, 3.3e-16 off it (entries up to 4); 1e-14 leaves room
    // for another BLAS's summation order (the midpoint rule used before needed 2e-3).
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        EXPECT_NEAR(gram(j * m + i, j * m + i), 4.0 / ((2 * i + 1) * (2 * j + 1)), 1e-14);
    const Eigen::MatrixXd off = gram - Eigen::MatrixXd(gram.diagonal().asDiagonal());
    EXPECT_LT(off.cwiseAbs().maxCoeff(), 1e-14);
  }

  // A degree of its own along z (rfm.z_degree_ratio): (p + 1)(p_z + 1) functions P_i(xi)
  // P_j(eta), index j (p + 1) + i, with the Legendre values along each variable (Legendre's
  // own recurrence, checked against closed forms above) and the diagonal Gram matrix
  // 4 / ((2 i + 1)(2 j + 1)) on [-1, 1]^2 under a Gauss rule exact for the products.
  TEST(TensorLegendreBasis, DegreeAlongZOfItsOwn)
  {
    const int p = 2, p_z = 5, m = p + 1, m_z = p_z + 1;
    const TensorLegendreBasis b(p, -1.0, 1.0, -1.0, 1.0, false, p_z);
    ASSERT_EQ(b.degree(), p);
    ASSERT_EQ(b.degree_z(), p_z);
    ASSERT_EQ(b.n_basis_functions(), m * m_z);
    const GaussRule1D g = gauss_legendre(m_z);
    Eigen::VectorXd x(m_z * m_z), y(m_z * m_z), w(m_z * m_z);
    for (int j = 0; j < m_z; ++j)
      for (int i = 0; i < m_z; ++i)
        x[j * m_z + i] = g.nodes[i], y[j * m_z + i] = g.nodes[j], w[j * m_z + i] = g.weights[i] * g.weights[j];
    const BasisValues v = b.evaluate(x, y);
    ASSERT_EQ(v.value.cols(), m * m_z);
    Eigen::VectorXd px(m), dpx(m), py(m_z), dpy(m_z);
    for (Eigen::Index k = 0; k < x.size(); ++k)
      {
        legendre_values(p, x[k], px, dpx);
        legendre_values(p_z, y[k], py, dpy);
        for (int j = 0; j < m_z; ++j)
          for (int i = 0; i < m; ++i)
            {
              EXPECT_NEAR(v.value(k, j * m + i), px[i] * py[j], 1e-14);
              EXPECT_NEAR(v.d_r(k, j * m + i), dpx[i] * py[j], 1e-13);
              EXPECT_NEAR(v.d_z(k, j * m + i), px[i] * dpy[j], 1e-13);
            }
      }
    const Eigen::MatrixXd gram = v.value.transpose() * w.asDiagonal() * v.value;
    for (int j = 0; j < m_z; ++j)
      for (int i = 0; i < m; ++i)
        EXPECT_NEAR(gram(j * m + i, j * m + i), 4.0 / ((2 * i + 1) * (2 * j + 1)), 1e-14);
    EXPECT_LT((gram - Eigen::MatrixXd(gram.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 1e-14);
  }

  // Even in r: the functions are P_i(2 (r / R)^2 - 1) P_j(eta), even in r with derivatives
  // that match finite differences, and orthogonal in the r-weighted measure on [0, R] x
  // [z0, z1]: int_0^R P_i P_k r dr = R^2 / 4 int P_i P_k d xi = R^2 / (2 (2 i + 1)) delta_ik.
  TEST(TensorLegendreBasis, EvenInROrthogonalInTheRWeightedMeasure)
  {
    const int p = 5, m = p + 1;
    const double R = 0.2, z0 = 0.0, z1 = 0.1;
    const TensorLegendreBasis b(p, 0.0, R, z0, z1, true);
    EXPECT_TRUE(b.even_in_r());
    EXPECT_THROW(TensorLegendreBasis(p, 0.05, R, z0, z1, true), std::invalid_argument);
    // Gauss in r with 2 m points (degree 4 p + 1 with the weight r), m in z.
    const GaussRule1D gr = gauss_on_cells({0.0, R}, 2 * m), gz = gauss_on_cells({z0, z1}, m);
    const Eigen::Index nr = gr.nodes.size(), nz = gz.nodes.size();
    Eigen::VectorXd r(nr * nz), z(nr * nz), w(nr * nz);
    for (Eigen::Index j = 0; j < nz; ++j)
      for (Eigen::Index i = 0; i < nr; ++i)
        r[j * nr + i] = gr.nodes[i], z[j * nr + i] = gz.nodes[j],
                   w[j * nr + i] = gr.weights[i] * gz.weights[j] * gr.nodes[i];
    const BasisValues v = b.evaluate(r, z);
    const Eigen::MatrixXd gram = v.value.transpose() * w.asDiagonal() * v.value;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        EXPECT_NEAR(gram(j * m + i, j * m + i),
                    R * R / (2.0 * (2 * i + 1)) * (z1 - z0) / (2 * j + 1), 1e-15);
    const Eigen::MatrixXd off = gram - Eigen::MatrixXd(gram.diagonal().asDiagonal());
    EXPECT_LT(off.cwiseAbs().maxCoeff(), 1e-16);
    Eigen::VectorXd rp(3), zp(3);
    rp << 0.01, 0.093, 0.19;
    zp << 0.01, 0.05, 0.09;
    const double h = 1e-7;
    const BasisValues at = b.evaluate(rp, zp), mirror = b.evaluate(-rp, zp);
    EXPECT_LT((at.value - mirror.value).cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_LT((at.d_r + mirror.d_r).cwiseAbs().maxCoeff(), 1e-10);
    const Eigen::MatrixXd fd_r =
      (b.evaluate((rp.array() + h).matrix(), zp).value - b.evaluate((rp.array() - h).matrix(), zp).value) / (2 * h);
    EXPECT_LT((fd_r - at.d_r).cwiseAbs().maxCoeff(), 1e-5 * at.d_r.cwiseAbs().maxCoeff());
  }
} // namespace rfm
