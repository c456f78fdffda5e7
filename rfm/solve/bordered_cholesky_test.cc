#include "rfm/solve/bordered_cholesky.h"

#include "rfm/solve/test_matrices.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include <cmath>
#include <cstring>

namespace rfm
{
  using rfm::testing::spd;

  namespace
  {
    // The bordered matrix's lower triangle, with garbage where the factorization must
    // neither read nor write (the strict upper triangle and the trailing block).
    Eigen::MatrixXd bordered(const Eigen::MatrixXd &m, const Eigen::MatrixXd &b)
    {
      const Eigen::Index n1 = m.rows(), n2 = b.cols();
      Eigen::MatrixXd a = Eigen::MatrixXd::Constant(n1 + n2, n1 + n2, 1e300);
      a.topLeftCorner(n1, n1).triangularView<Eigen::Lower>() = m;
      a.bottomLeftCorner(n2, n1) = b.transpose();
      return a;
    }

    bool strict_upper_untouched(const Eigen::MatrixXd &a)
    {
      for (Eigen::Index j = 1; j < a.cols(); ++j)
        for (Eigen::Index i = 0; i < j; ++i)
          if (a(i, j) != 1e300)
            return false;
      return true;
    }
  } // namespace

  // Against an independent route: Eigen's LLT of M, B^T M^-1 B formed explicitly, and the
  // LLT of E K E; tiles that do not divide the blocks (301 = 4 x 64 + 45, 97 < 2 x 64).
  TEST(BorderedCholesky, FactorsMatchTheSchurRouteOnEveryThreadCount)
  {
    const Eigen::Index n1 = 301, n2 = 97;
    const Eigen::MatrixXd m = spd(n1, 4.0);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(n1, n2);
    const Eigen::LLT<Eigen::MatrixXd> llt_m(m);
    const Eigen::MatrixXd l11 = llt_m.matrixL();
    const Eigen::MatrixXd l21 = l11.triangularView<Eigen::Lower>().solve(b).transpose();
    const Eigen::MatrixXd k = b.transpose() * llt_m.solve(b);
    const Eigen::VectorXd e = k.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd eke = e.asDiagonal() * k * e.asDiagonal();
    const Eigen::MatrixXd l22 = Eigen::LLT<Eigen::MatrixXd>(eke).matrixL();
    const double eke_norm = eke.cwiseAbs().colwise().sum().maxCoeff();

    Eigen::MatrixXd first;
    for (int threads : {1, 2, 3})
      {
        Eigen::MatrixXd a = bordered(m, b);
        const BorderedCholesky f = factorize_bordered(a, n1, threads, 64);
        ASSERT_EQ(f.status, BorderedCholesky::Status::ok) << threads;
        const Eigen::MatrixXd got11 = a.topLeftCorner(n1, n1).triangularView<Eigen::Lower>();
        const Eigen::MatrixXd got22 = a.bottomRightCorner(n2, n2).triangularView<Eigen::Lower>();
        // Forward errors of a Cholesky factor grow with the condition number (1e4 here).
        EXPECT_LT((got11 - l11).norm() / l11.norm(), 1e-11) << threads;
        EXPECT_LT((a.bottomLeftCorner(n2, n1) - l21).norm() / l21.norm(), 1e-10) << threads;
        EXPECT_LT((got22 - l22).norm() / l22.norm(), 1e-9) << threads;
        EXPECT_LT((f.e - e).norm() / e.norm(), 1e-11) << threads;
        EXPECT_NEAR(f.k_l1_norm, eke_norm, 1e-11 * eke_norm) << threads;
        EXPECT_TRUE(strict_upper_untouched(a)) << threads;
        // The backward view: the factors reproduce M and E K E to rounding.
        EXPECT_LT((got11 * got11.transpose() - m).norm() / m.norm(), 1e-14) << threads;
        EXPECT_LT((got22 * got22.transpose() - eke).norm() / eke.norm(), 1e-12) << threads;
        if (threads == 1)
          first = a;
        else // bitwise, whatever thread ran which tile
          EXPECT_EQ(std::memcmp(a.data(), first.data(), sizeof(double) * a.size()), 0)
            << threads << " threads differ from one";
      }
  }

  TEST(BorderedCholesky, ReportsWhichBlockFailed)
  {
    const Eigen::Index n1 = 150, n2 = 40;
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(n1, n2);
    {
      Eigen::MatrixXd m = spd(n1, 1.0);
      m(100, 100) = -1.0; // not positive definite
      Eigen::MatrixXd a = bordered(m, b);
      EXPECT_EQ(factorize_bordered(a, n1, 2, 32).status,
                BorderedCholesky::Status::stress_block_not_positive);
    }
    {
      Eigen::MatrixXd b0 = b;
      b0.col(17).setZero(); // a displacement function that does no work
      Eigen::MatrixXd a = bordered(spd(n1, 1.0), b0);
      EXPECT_EQ(factorize_bordered(a, n1, 2, 32).status,
                BorderedCholesky::Status::zero_schur_column);
    }
  }
} // namespace rfm
