#include "rfm/solve/symmetric_eigen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace
{
  constexpr double pi = 3.14159265358979323846;

  // The second-difference matrix tridiag(-1, 2, -1) of order n: eigenvalues
  // 2 - 2 cos(k pi / (n + 1)), k = 1..n, in closed form.
  Eigen::MatrixXd second_difference(const int n)
  {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      {
        a(i, i) = 2.0;
        if (i + 1 < n)
          a(i + 1, i) = a(i, i + 1) = -1.0;
      }
    return a;
  }
} // namespace

TEST(SymmetricEigen, SecondDifferenceEigenvaluesAreTheClosedForm)
{
  const int n = 300;
  const rfm::SymmetricEigen e = rfm::symmetric_eigen(second_difference(n), false);
  ASSERT_EQ(e.values.size(), n);
  EXPECT_EQ(e.vectors.size(), 0);
  for (int k = 1; k <= n; ++k)
    EXPECT_NEAR(e.values[k - 1], 2.0 - 2.0 * std::cos(k * pi / (n + 1)), 1e-13) << "k = " << k;
}

TEST(SymmetricEigen, VectorsAreOrthonormalAndDiagonalize)
{
  // A random symmetric matrix with a cluster of equal eigenvalues (rank-deficient Gram-like
  // part), read from its lower triangle only: the upper one holds garbage.
  const int n = 200;
  std::srand(7);
  const Eigen::MatrixXd x = Eigen::MatrixXd::Random(n, n / 2);
  Eigen::MatrixXd a = x * x.transpose();
  const Eigen::MatrixXd exact = a;
  a.triangularView<Eigen::StrictlyUpper>().setConstant(1e30);
  const rfm::SymmetricEigen e = rfm::symmetric_eigen(a, true);
  ASSERT_EQ(e.vectors.rows(), n);
  ASSERT_EQ(e.vectors.cols(), n);
  const double scale = e.values.cwiseAbs().maxCoeff();
  EXPECT_LT((e.vectors.transpose() * e.vectors - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(),
            1e-12);
  EXPECT_LT((exact * e.vectors - e.vectors * e.values.asDiagonal()).cwiseAbs().maxCoeff(),
            1e-12 * scale);
  for (int k = 1; k < n; ++k)
    EXPECT_LE(e.values[k - 1], e.values[k]);
  // Rank n / 2: the lower half of the spectrum vanishes to rounding.
  EXPECT_LT(e.values.head(n / 2).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_GT(e.values[n / 2], 1e-6 * scale);
}

TEST(SymmetricEigen, ANonSquareMatrixIsRefused)
{
  EXPECT_THROW(rfm::symmetric_eigen(Eigen::MatrixXd::Zero(3, 2), false), std::invalid_argument);
}
