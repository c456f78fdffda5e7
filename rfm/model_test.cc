#include "rfm/model.h"

#include <gtest/gtest.h>

namespace rfm
{
  namespace
  {
    axisym::Problem lame(const double p_in)
    {
      return axisym::parse_problem(nlohmann::json::parse(
        R"({"geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
            "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
            "loading": {"inner_pressure": )" +
        std::to_string(p_in) + "}}"));
    }
  } // namespace

  // rfm.tolerance: p rises until the indicator is below the tolerance, and the default
  // tolerance 1e-8 buys about 1e-4 in stress: checked against Lame's closed form
  // sigma_rr = A - B / r^2, sigma_tt = A + B / r^2.
  TEST(SolveToTolerance, StopsAtTheFirstDegreeBelowTheToleranceWithStressNear1e4)
  {
    const axisym::Problem problem = lame(1e7);
    const ToleranceSolve s = solve_to_tolerance(problem, problem.rfm, 1e-8);
    ASSERT_TRUE(s.reached) << s.message;
    ASSERT_GE(s.steps.size(), 2u);
    EXPECT_LT(s.steps.back().indicator, 1e-8);
    EXPECT_GE(s.steps[s.steps.size() - 2].indicator, 1e-8);
    for (std::size_t k = 1; k < s.steps.size(); ++k)
      EXPECT_EQ(s.steps[k].degree, s.steps[k - 1].degree + 2);

    const double r1 = 0.1, r2 = 0.2, p = 1e7;
    const double a = p * r1 * r1 / (r2 * r2 - r1 * r1), b = a * r2 * r2;
    Eigen::VectorXd r(3), z(3);
    r << 0.11, 0.15, 0.19;
    z << 0.0, 0.1, 0.19;
    const FieldValues f = s.model->evaluate(r, z);
    for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(f.sigma(k, rr), a - b / (r[k] * r[k]), 1e-4 * p);
        EXPECT_NEAR(f.sigma(k, tt), a + b / (r[k] * r[k]), 1e-4 * p);
      }
  }

  TEST(SolveToTolerance, ReportsAToleranceNotReachedByTheLastDegree)
  {
    axisym::Problem problem = lame(1e7);
    problem.rfm.max_degree = 4;
    const ToleranceSolve s = solve_to_tolerance(problem, problem.rfm, 1e-12);
    EXPECT_FALSE(s.reached);
    EXPECT_EQ(s.steps.size(), 2u);
    EXPECT_NE(s.message.find("max_degree = 4"), std::string::npos) << s.message;
    ASSERT_TRUE(s.model);
  }
} // namespace rfm
