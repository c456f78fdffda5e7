#include "rfm/quadrature/quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rfm
{
  namespace
  {
    double integrate_monomial(const GaussRule1D &g, int k)
    {
      double s = 0;
      for (Eigen::Index i = 0; i < g.nodes.size(); ++i)
        s += g.weights[i] * std::pow(g.nodes[i], k);
      return s;
    }
  } // namespace

  TEST(GaussLegendre, ExactForDegree2nMinus1)
  {
    for (int n = 1; n <= 30; ++n)
      {
        const GaussRule1D g = gauss_legendre(n);
        for (int k = 0; k <= 2 * n - 1; ++k)
          {
            const double exact = (k % 2 == 1) ? 0.0 : 2.0 / (k + 1);
            EXPECT_NEAR(integrate_monomial(g, k), exact, 1e-14 * (1 + k))
              << "n = " << n << ", x^" << k;
          }
      }
  }

  TEST(GaussLegendre, NotExactForDegree2n)
  {
    // The rule must fail at degree 2n: otherwise the test above could not fail either.
    for (int n = 1; n <= 10; ++n)
      EXPECT_GT(std::abs(integrate_monomial(gauss_legendre(n), 2 * n) - 2.0 / (2 * n + 1)),
                1e-6);
  }

  // polar_radial_rule: sum w f = int_0^rho_0 f(rho) rho drho, with and without breaks; a
  // break splits its layer (more nodes, all inside the pieces) and is a node-free point.
  TEST(PolarRadialRule, IntegratesPolynomialsWithBreaks)
  {
    const double rho_0 = 0.7;
    const GaussRule1D plain = polar_radial_rule(rho_0, 6, 3);
    const GaussRule1D broken = polar_radial_rule(rho_0, 6, 3, {0.3, 0.01, 0.7, 2.0, 0.3});
    // The layers [0.7, 0.14, 0.028, 0.0056, 0] and the breaks 0.3 and 0.01 (0.7 and 2.0
    // are not inside, the second 0.3 a repeat): two more pieces.
    EXPECT_EQ(plain.nodes.size(), 4 * 6);
    EXPECT_EQ(broken.nodes.size(), 6 * 6);
    for (Eigen::Index i = 0; i < broken.nodes.size(); ++i)
      {
        EXPECT_GT(broken.nodes[i], 0.0);
        EXPECT_LT(broken.nodes[i], rho_0);
        EXPECT_GT(std::abs(broken.nodes[i] - 0.3), 1e-6);
      }
    // rho^k rho: exact up to k = 10 on every piece (the innermost in rho = rho_in s^2 is a
    // polynomial of degree 2 k + 3 in s).
    for (int k = 0; k <= 4; ++k)
      {
        const double exact = std::pow(rho_0, k + 2) / (k + 2);
        EXPECT_NEAR(integrate_monomial(plain, k), exact, 1e-14 * exact) << k;
        EXPECT_NEAR(integrate_monomial(broken, k), exact, 1e-14 * exact) << k;
      }
  }

  TEST(GaussLegendre, NodesSortedInsideInterval)
  {
    const GaussRule1D g = gauss_legendre(17);
    for (Eigen::Index i = 0; i + 1 < g.nodes.size(); ++i)
      EXPECT_LT(g.nodes[i], g.nodes[i + 1]);
    EXPECT_GT(g.nodes[0], -1.0);
    EXPECT_LT(g.nodes[16], 1.0);
    EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  }

  TEST(GradedPartition, SplitsAndGradesTowardBreakPoint)
  {
    const auto cells = graded_partition(0.0, 1.0, {0.25}, 3, 0.5);
    // 0 | graded toward 0.25 from the left | 0.25 | graded away on the right | 1
    EXPECT_DOUBLE_EQ(cells.front(), 0.0);
    EXPECT_DOUBLE_EQ(cells.back(), 1.0);
    bool has_break = false;
    for (std::size_t i = 0; i + 1 < cells.size(); ++i)
      {
        EXPECT_LT(cells[i], cells[i + 1]);
        has_break |= std::abs(cells[i] - 0.25) < 1e-15;
      }
    EXPECT_TRUE(has_break);
    EXPECT_EQ(cells.size(), 2u + 1u + 3u + 3u);
    // Smallest cells touch the break point, width 0.25 * 0.5^3 on the left.
    const auto it = std::find_if(cells.begin(), cells.end(),
                                 [](double x) { return std::abs(x - 0.25) < 1e-15; });
    EXPECT_NEAR(*it - *(it - 1), 0.25 * 0.125, 1e-15);
    EXPECT_NEAR(*(it + 1) - *it, 0.75 * 0.125, 1e-15);
  }

  TEST(TensorGauss, IntegratesPolynomialOnGradedCells)
  {
    const auto rc = graded_partition(0.1, 0.2, {0.13}, 4, 0.3);
    const auto zc = graded_partition(0.0, 0.2, {0.05}, 4, 0.3);
    const Quadrature2D q = tensor_gauss(rc, zc, 4); // exact to degree 7 per variable
    double s = 0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      s += q.weights[k] * std::pow(q.r[k], 7) * std::pow(q.z[k], 6);
    const double exact = (std::pow(0.2, 8) - std::pow(0.1, 8)) / 8 * std::pow(0.2, 7) / 7;
    EXPECT_NEAR(s, exact, 1e-13 * exact);
  }

  // The t^2 map toward a singular end integrates x^(k/2) exactly for k >= -1.
  TEST(GaussOnCells, SqrtMapIntegratesHalfPowersExactly)
  {
    const std::vector<double> cells{0.0, 0.5, 1.0};
    const GaussRule1D g = gauss_on_cells(cells, 6, {0.5});
    for (const double power : {-0.5, 0.5, 1.5, 2.5})
      {
        double s = 0.0;
        for (Eigen::Index k = 0; k < g.nodes.size(); ++k)
          s += g.weights[k] * std::pow(std::abs(g.nodes[k] - 0.5), power);
        const double exact = 2.0 * std::pow(0.5, power + 1) / (power + 1);
        EXPECT_NEAR(s, exact, 1e-13 * exact) << "power " << power;
      }
    // Without singular points it is the plain rule.
    const GaussRule1D plain = gauss_on_cells(cells, 6);
    EXPECT_NEAR(plain.weights.sum(), 1.0, 1e-15);
  }

  // Half-disc rule: area and moments of the half disc r <= r_c (a polynomial of degree
  // d in r, z is a polynomial of degree 2 d in s times trigonometric terms in theta).
  TEST(HalfDiscGauss, AreaAndMoments)
  {
    const double rc = 0.2, zc = 0.1, rho0 = 0.05;
    const Quadrature2D q = half_disc_gauss(rc, zc, rho0, 12, 16);
    EXPECT_NEAR(q.weights.sum(), 0.5 * M_PI * rho0 * rho0, 1e-15);
    EXPECT_LE(q.r.maxCoeff(), rc);
    // int (rc - r) dA = int rho sin(theta) rho drho dtheta = 2 rho0^3 / 3
    EXPECT_NEAR(q.weights.dot((rc - q.r.array()).matrix()), 2.0 * std::pow(rho0, 3) / 3.0, 1e-17);
    // int (z - zc)^2 dA = int rho^2 cos^2 rho drho dtheta = rho0^4 pi / 8
    EXPECT_NEAR(q.weights.dot((q.z.array() - zc).square().matrix()), std::pow(rho0, 4) * M_PI / 8.0,
                1e-13 * std::pow(rho0, 4));
    // int rho^-1 dA = pi rho0 (the 1/rho singularity of two n = 1 stresses)
    double s = 0.0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      s += q.weights[k] / std::hypot(q.r[k] - rc, q.z[k] - zc);
    EXPECT_NEAR(s, M_PI * rho0, 1e-14);
  }

  // Clipped at z = zc + d (an edge near the end): area, the integral of 1/rho and the
  // moment in z against closed forms; every point inside. The clipped panel's ray length
  // d / cos(phi) has its pole 13 degrees beyond the panel (d / rho0 = 0.22): Gauss converges
  // exponentially but more slowly there (3e-11 with 16 points, measured; 32 used here).
  TEST(HalfDiscGauss, ClippedAtTheEnd)
  {
    const double rc = 0.2, zc = 0.18, rho0 = 0.09, d = 0.02;
    const Quadrature2D q = half_disc_gauss(rc, zc, rho0, 12, 32, zc + d);
    EXPECT_LE(q.r.maxCoeff(), rc);
    EXPECT_LE(q.z.maxCoeff(), zc + d);
    EXPECT_GT(q.weights.minCoeff(), 0.0);
    // The half disc minus half of the circular segment beyond z = zc + d.
    const double root = std::sqrt(rho0 * rho0 - d * d);
    const double segment = rho0 * rho0 * std::acos(d / rho0) - d * root;
    const double area = 0.5 * M_PI * rho0 * rho0 - 0.5 * segment;
    EXPECT_NEAR(q.weights.sum(), area, 1e-14 * area);
    // int rho^-1 dA = int L(theta) dtheta = rho0 theta* + d ln((rho0 + root) / d).
    const double theta_star = M_PI - std::acos(d / rho0);
    const double inv_rho = rho0 * theta_star + d * std::log((rho0 + root) / d);
    double s = 0.0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      s += q.weights[k] / std::hypot(q.r[k] - rc, q.z[k] - zc);
    EXPECT_NEAR(s, inv_rho, 1e-13 * inv_rho);
    // int (z - zc) dA: the half disc gives -2 rho0^3 / 3 on z < zc and +2 rho0^3 / 3 on
    // z > zc; the clipped part of the latter is half of the segment's moment about z = zc,
    // int_d^rho0 t 2 sqrt(rho0^2 - t^2) dt = (2/3) root^3.
    const double moment = -std::pow(root, 3) / 3.0;
    EXPECT_NEAR(q.weights.dot((q.z.array() - zc).matrix()), moment,
                1e-13 * std::pow(rho0, 3));
  }

  // Gauss in x^2 (the axis parity): sum w x f(x) = int f(x) x dx exactly for f = x^(2k),
  // k <= 2 n - 1, on cells of [0, 1]; not for k = 2 n, nor for an odd power.
  TEST(GaussInSquare, ExactForPolynomialsInXSquaredWithTheWeightX)
  {
    const int n = 4;
    const GaussRule1D g = gauss_in_square_on_cells({0.0, 0.3, 1.0}, n);
    ASSERT_EQ(g.nodes.size(), 2 * n);
    EXPECT_GT(g.nodes.minCoeff(), 0.0);
    auto moment = [&](const double power) {
      return (g.weights.array() * g.nodes.array() * g.nodes.array().pow(power)).sum();
    };
    for (int k = 0; k <= 2 * n - 1; ++k)
      EXPECT_NEAR(moment(2 * k), 1.0 / (2 * k + 2), 1e-15) << k;
    EXPECT_GT(std::abs(moment(4 * n) - 1.0 / (4 * n + 2)), 1e-12);
    EXPECT_GT(std::abs(moment(1) - 1.0 / 3.0), 1e-6);
  }

  // A square's tensor rule blended with a full disc's polar rule (two half discs) about its
  // centre: the blended weights still integrate polynomials over the square, and the disc's
  // rule alone takes the singularity 1 / rho at the centre, which the square's rule misses.
  // The square's rule crosses the disc's rim, where the step has three continuous
  // derivatives: one cell of 40 x 40 points is 2.1e-6 off on the polynomial (measured), of
  // 80 x 80 2.3e-8 (3.1e-8 on 1 / rho; the square's rule alone 8.9e-3 there).
  TEST(BlendDiscRules, CountsEveryIntegrandOnceAndLeavesTheCentreToTheDisc)
  {
    const double c = 0.5, rho0 = 0.3;
    const Quadrature2D square = tensor_gauss({0.0, 1.0}, {0.0, 1.0}, 80);
    Quadrature2D disc = half_disc_gauss(c, c, rho0, 16, 24);
    const Eigen::Index h = disc.n_points();
    disc.r.conservativeResize(2 * h), disc.z.conservativeResize(2 * h), disc.weights.conservativeResize(2 * h);
    disc.r.tail(h) = (2.0 * c - disc.r.head(h).array()).matrix();
    disc.z.tail(h) = disc.z.head(h), disc.weights.tail(h) = disc.weights.head(h);
    const Quadrature2D q = blend_disc_rules(square, {{disc, c, c, rho0}});
    ASSERT_EQ(q.n_points(), square.n_points() + disc.n_points());
    // int (1 + r)^5 (1 + z)^4 over the unit square: (2^6 - 1) / 6 (2^5 - 1) / 5.
    double poly = 0.0, singular = 0.0, singular_square = 0.0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      {
        poly += q.weights[k] * std::pow(1.0 + q.r[k], 5) * std::pow(1.0 + q.z[k], 4);
        singular += q.weights[k] / std::hypot(q.r[k] - c, q.z[k] - c);
      }
    for (Eigen::Index k = 0; k < square.n_points(); ++k)
      singular_square += square.weights[k] / std::hypot(square.r[k] - c, square.z[k] - c);
    EXPECT_NEAR(poly, 63.0 / 6.0 * 31.0 / 5.0, 1e-7 * 63.0 / 6.0 * 31.0 / 5.0);
    // int 1 / rho over the square about its centre: 4 asinh(1).
    const double exact = 4.0 * std::asinh(1.0);
    EXPECT_NEAR(singular, exact, 1e-7 * exact);
    EXPECT_GT(std::abs(singular_square - exact), 1e-4 * exact);
    EXPECT_NEAR(disc_partition_step(0.0), 0.0, 0.0);
    EXPECT_NEAR(disc_partition_step(1.0), 1.0, 1e-15);
    EXPECT_EQ(disc_partition_step(1.5), 1.0);
  }
} // namespace rfm
