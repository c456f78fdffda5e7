#include "rfm/solve/saddle_point_solver.h"

#include "rfm/hardware.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <limits>

namespace rfm
{
  namespace
  {
    ReissnerSystem random_system(int ns, int nu, unsigned seed)
    {
      std::srand(seed);
      ReissnerSystem s;
      const Eigen::MatrixXd a = Eigen::MatrixXd::Random(ns, ns);
      s.r11 = -(a * a.transpose() + ns * Eigen::MatrixXd::Identity(ns, ns)) * 1e-12;
      s.r12 = Eigen::MatrixXd::Random(ns, nu) * 1e-3;
      s.p_s = Eigen::VectorXd::Random(ns) * 1e-8;
      s.p_u = Eigen::VectorXd::Random(nu) * 1e2;
      return s;
    }
  } // namespace

  TEST(SaddlePointSolver, MatchesDenseLuOfTheFullSystem)
  {
    const ReissnerSystem s = random_system(40, 20, 3);
    const SaddlePointSolution sol = solve_saddle_point(s);
    ASSERT_TRUE(sol.summary.success) << sol.summary.message;
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(60, 60);
    full.topLeftCorner(40, 40) = s.r11;
    full.topRightCorner(40, 20) = s.r12;
    full.bottomLeftCorner(20, 40) = s.r12.transpose();
    Eigen::VectorXd rhs(60);
    rhs << -s.p_s, -s.p_u;
    const Eigen::VectorXd x = full.fullPivLu().solve(rhs);
    EXPECT_LT((sol.q_s - x.head(40)).norm(), 1e-9 * x.head(40).norm());
    EXPECT_LT((sol.q_u - x.tail(20)).norm(), 1e-9 * x.tail(20).norm());
    EXPECT_GT(sol.summary.inf_sup, 0.0);
    EXPECT_LE(sol.summary.inf_sup, 1.0);
    EXPECT_GE(sol.summary.cond_schur, 1.0);
  }

  TEST(SaddlePointSolver, DetectsRankLossOfR12)
  {
    ReissnerSystem s = random_system(30, 10, 5);
    s.r12.col(3) = 2.0 * s.r12.col(1); // two displacement functions do the same work
    const SaddlePointSolution sol = solve_saddle_point(s);
    EXPECT_FALSE(sol.summary.success);
    EXPECT_NE(sol.summary.message.find("inf-sup"), std::string::npos) << sol.summary.message;
  }

  TEST(SaddlePointSolver, DetectsIndefiniteStressBlock)
  {
    ReissnerSystem s = random_system(30, 10, 9);
    s.r11(0, 0) = -s.r11(0, 0); // wrong sign: not negative definite
    const SaddlePointSolution sol = solve_saddle_point(s);
    EXPECT_FALSE(sol.summary.success);
    EXPECT_NE(sol.summary.message.find("R11"), std::string::npos) << sol.summary.message;
  }

  // The solver reads R11's lower triangle only (AssemblyOptions::full_r11 = false), and a
  // system large enough for the tiled factorization on two threads (1000 unknowns and
  // more) gives the same bits as on one.
  TEST(SaddlePointSolver, ReadsTheLowerTriangleAndIsTheSameOnEveryThreadCount)
  {
    const ReissnerSystem s = random_system(720, 330, 5);
    ReissnerSystem lower = s;
    lower.r11.triangularView<Eigen::StrictlyUpper>().setConstant(
      std::numeric_limits<double>::quiet_NaN());
    const int before = n_threads();
    set_n_threads(1);
    const SaddlePointSolution one = solve_saddle_point(s);
    set_n_threads(2);
    const SaddlePointSolution two = solve_saddle_point(lower);
    set_n_threads(before);
    ASSERT_TRUE(one.summary.success) << one.summary.message;
    ASSERT_TRUE(two.summary.success) << two.summary.message;
    EXPECT_TRUE(one.q_s == two.q_s);
    EXPECT_TRUE(one.q_u == two.q_u);
    EXPECT_EQ(one.summary.rcond_stress, two.summary.rcond_stress);
    EXPECT_EQ(one.summary.rcond_schur, two.summary.rcond_schur);
  }
} // namespace rfm
