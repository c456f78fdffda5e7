// The half-space punch (half_space.h) against closed forms derived by hand, not by its
// quadratures: Hertz for the paraboloid; for the rounded flat punch (flat radius b, edge
// radius rho) psi(t) = (t / rho) (sqrt(t^2 - b^2) - b arccos(b / t)) beyond b and
// int_0^a psi dt = ((a^2 - b^2)^(3/2) / 3 - (b a^2 / 2) arccos(b / a) + (b^2 / 2)
// sqrt(a^2 - b^2)) / rho (by parts), psi'(t) = (2 sqrt(t^2 - b^2) - b arccos(b / t)) / rho.
#include "rfm/contact/half_space.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace rfm;

  axisym::DieProfile paraboloid(const double radius)
  {
    axisym::DieProfile g0;
    g0.shape = axisym::DieProfile::Shape::paraboloid;
    g0.radius = radius;
    return g0;
  }

  axisym::DieProfile rounded(const double b, const double rho)
  {
    axisym::DieProfile g0;
    g0.shape = axisym::DieProfile::Shape::flat_rounded;
    g0.flat_radius = b, g0.edge_radius = rho;
    return g0;
  }

  constexpr double e_star = 2.1e11 / (1 - 0.09);

  TEST(HalfSpace, ParaboloidIsHertz)
  {
    const double radius = 0.1, a = 8.66e-4;
    const axisym::DieProfile g0 = paraboloid(radius);
    EXPECT_NEAR(half_space::indentation(g0, a), a * a / radius, 1e-14 * a * a / radius);
    const double p_hertz = 4 * e_star * a * a * a / (3 * radius);
    EXPECT_NEAR(half_space::force(g0, a, e_star), p_hertz, 1e-13 * p_hertz);
    for (const double x : {0.0, 0.3, 0.77, 1.0})
      EXPECT_NEAR(half_space::pressure_shape(g0, a, x), 2 * a / radius, 1e-13 * a / radius) << x;
    // The radius of Hertz's force and of its indentation.
    axisym::DieCondition die;
    die.profile = g0;
    die.force = 2000.0;
    const double a_hertz = std::cbrt(3 * 2000.0 * radius / (4 * e_star));
    EXPECT_NEAR(*half_space::contact_radius(die, e_star, 0.02), a_hertz, 1e-12 * a_hertz);
    die.force.reset();
    die.indentation = 2e-6;
    EXPECT_NEAR(*half_space::contact_radius(die, e_star, 0.02), std::sqrt(radius * 2e-6), 1e-12 * a);
    // Beyond the limit: none.
    EXPECT_FALSE(half_space::contact_radius(die, e_star, 1e-4).has_value());
  }

  TEST(HalfSpace, RoundedFlatPunchIsItsClosedForm)
  {
    const double b = 5e-4, rho = 0.05;
    const axisym::DieProfile g0 = rounded(b, rho);
    auto psi = [&](double t) { return t <= b ? 0.0 : t / rho * (std::sqrt(t * t - b * b) - b * std::acos(b / t)); };
    auto dpsi = [&](double t) { return t <= b ? 0.0 : (2 * std::sqrt(t * t - b * b) - b * std::acos(b / t)) / rho; };
    for (const double t : {2e-4, 5e-4, 5.0001e-4, 6e-4, 7.5e-4, 2e-3})
      {
        EXPECT_NEAR(half_space::psi(g0, t), psi(t), 1e-13 * psi(2e-3)) << t;
        EXPECT_NEAR(half_space::psi_slope(g0, t), dpsi(t), 1e-12 * dpsi(2e-3)) << t;
      }
    for (const double a : {6e-4, 7.47e-4, 2e-3})
      {
        const double root = std::sqrt(a * a - b * b);
        const double integral = (root * root * root / 3 - b * a * a / 2 * std::acos(b / a) + b * b / 2 * root) / rho;
        const double p = 2 * e_star * (a * psi(a) - integral);
        EXPECT_NEAR(half_space::force(g0, a, e_star), p, 1e-10 * p) << a;
        // The pressure's shape at the edge is psi'(a); inside, Sneddon's integral taken
        // another way (t = r cosh theta, dt / sqrt(t^2 - r^2) = d theta; midpoint rule).
        EXPECT_NEAR(half_space::pressure_shape(g0, a, 1.0), dpsi(a), 1e-12 * dpsi(a));
        for (const double x : {0.05, 0.5, b / a, 0.9})
          {
            const double r = x * a, th0 = std::acosh(std::max(r, b) / r), th1 = std::acosh(a / r);
            const int n = 200000;
            double sum = 0.0;
            for (int i = 0; i < n; ++i)
              sum += dpsi(r * std::cosh(th0 + (i + 0.5) * (th1 - th0) / n));
            const double reference = sum * (th1 - th0) / n / std::sqrt(1 - x * x);
            EXPECT_NEAR(half_space::pressure_shape(g0, a, x), reference, 1e-6 * reference) << a << " " << x;
          }
      }
    // Inside the flat (a <= b) a smooth edge needs delta = 0: no radius for delta > 0 below b.
    axisym::DieCondition die;
    die.profile = g0;
    die.indentation = 2e-6;
    const double a = *half_space::contact_radius(die, e_star, 0.02);
    EXPECT_GT(a, b);
    EXPECT_NEAR(psi(a), 2e-6, 1e-12 * 2e-6);
  }

  // Sneddon's radius of the rounded punch of dies_on_parts at the FEM's force (616.025 N, the
  // FEM's L = 4 zone is 0.747413 mm; the closing note of issue 23, session 14: 0.747448 mm).
  TEST(HalfSpace, RoundedPunchRadiusAtTheFemsForce)
  {
    axisym::DieCondition die;
    die.profile = rounded(5e-4, 0.05);
    die.force = 616.025;
    EXPECT_NEAR(*half_space::contact_radius(die, e_star, 0.02), 7.47448e-4, 1e-9);
  }

  TEST(HalfSpace, SharpEdgeAndBadArgumentsHaveNoRadius)
  {
    axisym::DieCondition die;
    die.profile.shape = axisym::DieProfile::Shape::flat;
    die.profile.radius = 1e-3;
    die.indentation = 1e-6;
    EXPECT_FALSE(half_space::contact_radius(die, e_star, 0.02).has_value());
    die.profile = paraboloid(0.1);
    die.force = 10.0; // both set
    EXPECT_FALSE(half_space::contact_radius(die, e_star, 0.02).has_value());
    EXPECT_THROW(half_space::pressure_shape(die.profile, 1e-3, 1.5), std::invalid_argument);
    EXPECT_THROW(half_space::pressure_shape(die.profile, 0.0, 0.5), std::invalid_argument);
  }
} // namespace
