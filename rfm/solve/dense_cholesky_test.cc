#include "rfm/solve/dense_cholesky.h"

#include "rfm/solve/test_matrices.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>

#include <cmath>

namespace rfm
{
  using rfm::testing::spd;

  TEST(DenseCholesky, FactorReproducesTheMatrixAndSolves)
  {
    constexpr double tolerance = 1e-13;
    const Eigen::Index n = 5 * DenseCholesky::leaf_size + 3; // three levels of recursion
    const Eigen::MatrixXd a = spd(n, 3.0);
    Eigen::MatrixXd f = a;
    f.triangularView<Eigen::StrictlyUpper>().setConstant(7.0); // must stay untouched
    const DenseCholesky llt(f);
    ASSERT_TRUE(llt.success());
    EXPECT_TRUE((f.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().array() ==
                 Eigen::MatrixXd(Eigen::MatrixXd::Constant(n, n, 7.0))
                   .triangularView<Eigen::StrictlyUpper>()
                   .toDenseMatrix()
                   .array())
                  .all());
    const Eigen::MatrixXd l = f.triangularView<Eigen::Lower>();
    EXPECT_LT((l * l.transpose() - a).norm(), tolerance * a.norm());
    // The same factor as Eigen's LLT to rounding (the factor is unique).
    Eigen::MatrixXd e = a;
    const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> reference(e);
    EXPECT_LT((l - Eigen::MatrixXd(e.triangularView<Eigen::Lower>())).norm(), 1e3 * tolerance * l.norm());

    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    const Eigen::VectorXd x = llt.solve(b);
    EXPECT_LT((a * x - b).norm(), 1e3 * tolerance * b.norm()); // cond(a) = 1e3
  }

  TEST(DenseCholesky, RcondEstimatesTheOneNormCondition)
  {
    const Eigen::MatrixXd a = spd(300, 6.0);
    const double exact = 1.0 / (a.cwiseAbs().colwise().sum().maxCoeff() *
                                a.inverse().cwiseAbs().colwise().sum().maxCoeff());
    Eigen::MatrixXd f = a;
    const DenseCholesky llt(f);
    ASSERT_TRUE(llt.success());
    // The estimator bounds |A^-1|_1 from below: rcond from above.
    EXPECT_GE(llt.rcond(), 0.999 * exact);
    EXPECT_LE(llt.rcond(), 10.0 * exact);
  }

  TEST(DenseCholesky, IndefiniteMatrixFailsInEitherHalf)
  {
    for (Eigen::Index pivot : {Eigen::Index(20), Eigen::Index(290)})
      {
        Eigen::MatrixXd a = spd(300, 1.0);
        a(pivot, pivot) = -1.0;
        const DenseCholesky llt(a);
        EXPECT_FALSE(llt.success()) << "pivot " << pivot;
        EXPECT_EQ(llt.rcond(), 0.0);
      }
  }
} // namespace rfm
