#include "rfm/outline_model.h"

#include "problem/test_problems.h"

#include <gtest/gtest.h>

namespace rfm
{
  namespace
  {
    // Thick spherical shell a = 0.1, b = 0.2 under inner pressure p (DESIGN.md 7.1): a quarter
    // annulus with the equator (symmetry) and the axis. Exact (Lame, spherical):
    // sigma_RR = A - B / R^3, sigma_phiphi = A + B / (2 R^3), A = p a^3 / (b^3 - a^3), B = A b^3
    // (axisym::testing::thick_sphere()).
    double sphere_stress_error(const OutlineModel &m)
    {
      const double a = 0.1, b = 0.2, p = 1e7;
      const double A = p * a * a * a / (b * b * b - a * a * a), B = A * b * b * b;
      Eigen::VectorXd r(21 * 21), z(21 * 21);
      for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j)
          {
            const double rho = a + (b - a) * i / 20.0, th = 0.5 * M_PI * j / 20.0;
            r[21 * i + j] = std::max(rho * std::cos(th), 1e-9), z[21 * i + j] = rho * std::sin(th);
          }
      const FieldValues f = m.evaluate(r, z);
      double err = 0, max = 0;
      for (Eigen::Index k = 0; k < r.size(); ++k)
        {
          const double rho = std::hypot(r[k], z[k]), c = r[k] / rho, s = z[k] / rho;
          const double s_rr = A - B / (rho * rho * rho), s_pp = A + B / (2 * rho * rho * rho);
          const double exact[4] = {s_rr * c * c + s_pp * s * s, s_rr * s * s + s_pp * c * c, s_pp,
                                   (s_rr - s_pp) * c * s};
          for (int q = 0; q < 4; ++q)
            err = std::max(err, std::abs(f.sigma(k, q) - exact[q])), max = std::max(max, std::abs(exact[q]));
        }
      return err / max;
    }
  } // namespace

  // The sphere converges against its closed form; the three functionals meet at
  // -U = -1/2 p u_R(a) a^2 per radian, Phi_C = Phi_R (mixed), Phi_L above.
  TEST(OutlineModel, ThickSphereConvergesToLamesSolution)
  {
    const axisym::Problem problem = axisym::parse_problem(axisym::testing::thick_sphere());
    const double a = 0.1, b = 0.2, p = 1e7, e = 2.1e11, nu = 0.3;
    const double A = p * a * a * a / (b * b * b - a * a * a), B = A * b * b * b;
    const double u_a = ((1 - 2 * nu) * A * a + (1 + nu) * B / (2 * a * a)) / e;
    const double phi_exact = -0.5 * p * u_a * a * a;
    double previous = 1.0;
    for (const int degree : {4, 8, 10})
      {
        DiscretizationOptions o = problem.rfm;
        o.degree = degree;
        const OutlineModel m(problem, o);
        ASSERT_TRUE(m.ok()) << m.summary().message;
        const double err = sphere_stress_error(m);
        EXPECT_LT(err, 0.5 * previous) << "p = " << degree;
        previous = err;
        const Functionals f = m.functionals();
        EXPECT_NEAR(f.castigliano, f.reissner, 1e-10 * std::abs(phi_exact));
        EXPECT_GE(f.lagrange, phi_exact * (1 + 1e-12));
        if (degree == 10)
          {
            EXPECT_LT(err, 5e-3);
            EXPECT_NEAR(f.reissner, phi_exact, 1e-7 * std::abs(phi_exact));
            EXPECT_LT(f.indicator(), 1e-7);
          }
      }
  }

  // A solid cylinder (R1 = 0: the axis) under end pressure: uniform sigma_zz = -p.
  TEST(OutlineModel, SolidCylinderUnderEndPressureHasUniformStress)
  {
    const axisym::Problem problem = axisym::parse_problem(nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.0, 0.0]}, {"line_to": [0.05, 0.0], "part": "bottom"},
        {"line_to": [0.05, 0.1], "part": "side"}, {"line_to": [0.0, 0.1], "part": "top"},
        {"line_to": [0.0, 0.0], "part": "axis"}]},
      "boundary": {"bottom": {"symmetry": true}, "top": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})"));
    DiscretizationOptions o = problem.rfm;
    o.degree = 8;
    const OutlineModel m(problem, o);
    ASSERT_TRUE(m.ok()) << m.summary().message;
    Eigen::VectorXd r(5), z(5);
    r << 0.001, 0.025, 0.049, 0.03, 0.01;
    z << 0.001, 0.05, 0.099, 0.02, 0.09;
    const FieldValues f = m.evaluate(r, z);
    for (int k = 0; k < 5; ++k)
      {
        EXPECT_NEAR(f.sigma(k, zz), -1e7, 1e-3 * 1e7) << k;
        EXPECT_NEAR(f.sigma(k, rr), 0.0, 1e-3 * 1e7) << k;
        EXPECT_NEAR(f.sigma(k, tt), 0.0, 1e-3 * 1e7) << k;
        EXPECT_NEAR(f.u(k, 1), -1e7 * z[k] / 2.1e11, 1e-3 * 1e7 * 0.1 / 2.1e11) << k;
        EXPECT_NEAR(f.u(k, 0), 0.3 * 1e7 * r[k] / 2.1e11, 1e-3 * 1e7 * 0.05 / 2.1e11) << k;
      }
  }
} // namespace rfm
