#include "rfm/solution.h"

#include "rfm/assembly.h"
#include "rfm/saddle_point_solver.h"
#include "rfm/test_sections.h"

#include <gtest/gtest.h>

namespace rfm
{
  using namespace rfm::testing;

  namespace
  {
    struct Solved
    {
      DiscreteSpace space;
      SaddlePointSolution s;
    };
    Solved solve(const Section &section, int degree)
    {
      DiscretizationOptions o;
      o.degree = degree;
      DiscreteSpace space(Structures(section), o, Material{});
      SaddlePointSolution s = solve_saddle_point(assemble_reissner_system(space, Material{}));
      return {std::move(space), std::move(s)};
    }
  } // namespace

  // Patch test: equal inner and outer pressure p gives the uniform state
  // sigma_rr = sigma_tt = -p, sigma_zz = sigma_rz = 0, u_r = -(1 - nu) p r / E,
  // u_z = 2 nu p z / E, which lies in the discrete space for p >= 1: the method must
  // reproduce it to rounding.
  TEST(RfmSolution, ReproducesUniformPressureExactly)
  {
    const double p = 5e6;
    const Material mat;
    const Solved solved = solve(lame_section(p, p), 2);
    ASSERT_TRUE(solved.s.summary.success) << solved.s.summary.message;
    const RfmSolution sol(solved.space, mat, solved.s.q_s, solved.s.q_u);
    Eigen::VectorXd r(4), z(4);
    r << 0.1, 0.13, 0.17, 0.2;
    z << 0.0, 0.05, 0.15, 0.2;
    const FieldValues f = sol.evaluate(r, z);
    const double e = mat.youngs_modulus, nu = mat.poisson_ratio;
    for (int k = 0; k < 4; ++k)
      {
        EXPECT_NEAR(f.sigma(k, rr), -p, 1e-8 * p);
        EXPECT_NEAR(f.sigma(k, tt), -p, 1e-8 * p);
        EXPECT_NEAR(f.sigma(k, zz), 0.0, 1e-8 * p);
        EXPECT_NEAR(f.sigma(k, rz), 0.0, 1e-8 * p);
        EXPECT_NEAR(f.u(k, 0), -(1 - nu) * p * r[k] / e, 1e-8 * p * r[k] / e);
        EXPECT_NEAR(f.u(k, 1), 2 * nu * p * z[k] / e, 1e-8 * p * a / e);
      }
    // Energy: U = p^2 (1 - nu) / E * volume per radian, Phi = -U for all three.
    const double volume = 0.5 * (r2 * r2 - r1 * r1) * 2 * a; // per radian, full length
    const double u_exact = p * p * (1 - nu) / e * volume;
    const Functionals phi = sol.functionals();
    EXPECT_NEAR(phi.lagrange, -u_exact, 1e-9 * u_exact);
    EXPECT_NEAR(phi.castigliano, -u_exact, 1e-9 * u_exact);
    EXPECT_NEAR(phi.reissner, -u_exact, 1e-9 * u_exact);
  }

  // For a traction-loaded body the second block row gives int s.e(u) = W(u), hence
  // Phi_C = Phi_R at every N (DESIGN.md section 3), and Phi_L >= Phi_C.
  TEST(RfmSolution, CastiglianoEqualsReissnerForTractionProblems)
  {
    for (int degree : {0, 1, 3})
      {
        const Solved solved = solve(lame_section(), degree);
        ASSERT_TRUE(solved.s.summary.success);
        const Functionals phi =
          RfmSolution(solved.space, Material{}, solved.s.q_s, solved.s.q_u).functionals();
        EXPECT_NEAR(phi.castigliano, phi.reissner, 1e-10 * std::abs(phi.reissner)) << degree;
        EXPECT_GT(phi.lagrange, phi.reissner) << degree;
      }
  }
} // namespace rfm
