#include "rfm/spaces/wedge_frame.h"

#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

namespace
{
  using axisym::Point;
  using rfm::Circle;
  using rfm::Quadrature2D;
  using rfm::WedgeFrame;
  using axisym::testing::line;
  constexpr double pi = 3.14159265358979323846;

  // The area of the lens where the discs of radii a and b, d apart, overlap.
  double lens_area(const double a, const double b, const double d)
  {
    return a * a * std::acos((d * d + a * a - b * b) / (2 * d * a)) +
           b * b * std::acos((d * d + b * b - a * a) / (2 * d * b)) -
           0.5 * std::sqrt((-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b));
  }

  // sum w f over the rule, f = g(|x - c|^2 / R^2) inside the circle (c, R), 0 outside.
  template <typename G>
  double integrate_in(const Quadrature2D &q, const Circle &c, G g)
  {
    double sum = 0.0;
    for (Eigen::Index k = 0; k < q.weights.size(); ++k)
      {
        const double t = (std::pow(q.r[k] - c.centre.r, 2) + std::pow(q.z[k] - c.centre.z, 2)) /
                         (c.radius * c.radius);
        if (t < 1.0)
          sum += q.weights[k] * g(t);
      }
    return sum;
  }

  // The near rule of a disc that another disc overlaps (rfm.vertex_disc_overlap): broken at
  // the other's rim, it integrates what jumps or kinks there as if it were smooth; without
  // the breaks it does not. Here the vertex is a straight point of the boundary (the half
  // disc of radius 1 about (1, 0) in z > 0) and the other disc, of radius 0.8 about
  // (1, 1.5), lies in z > 0, so that the common part is a lens.
  TEST(WedgeFrame, NearRuleBreaksAtTheRimsOfOverlappingDiscs)
  {
    const WedgeFrame frame(line({0.0, 0.0}, {1.0, 0.0}), line({1.0, 0.0}, {2.0, 0.0}));
    const Circle other{{1.0, 1.5}, 0.8};
    const double lens = lens_area(1.0, 0.8, 1.5);
    const Quadrature2D plain = frame.near_rule(1.0, 12, 12, 8);
    const Quadrature2D broken = frame.near_rule(1.0, 12, 12, 8, {other});
    auto one = [](double) { return 1.0; };
    // The area of the half disc: both rules.
    EXPECT_NEAR(plain.weights.sum(), 0.5 * pi, 1e-12);
    EXPECT_NEAR(broken.weights.sum(), 0.5 * pi, 1e-12);
    // The lens (a jump on the rim): the radial pieces start where the rings reach the rim,
    // with a square-root onset there.
    const double e_plain = std::abs(integrate_in(plain, other, one) - lens) / lens;
    const double e_broken = std::abs(integrate_in(broken, other, one) - lens) / lens;
    EXPECT_LT(e_broken, 1e-4) << "broken at the rim"; // measured 7.5e-5 (plain 3.2e-2)
    EXPECT_GT(e_plain, 100 * e_broken) << "not broken";
    // A cutoff-like kink, (1 - t)^3 (its third derivative jumps on the rim), against the
    // broken rule with four times the points.
    auto kink = [](const double t) { return std::pow(1.0 - t, 3); };
    const double fine = integrate_in(frame.near_rule(1.0, 48, 48, 8, {other}), other, kink);
    const double k_plain = std::abs(integrate_in(plain, other, kink) - fine) / fine;
    const double k_broken = std::abs(integrate_in(broken, other, kink) - fine) / fine;
    EXPECT_LT(k_broken, 1e-8); // measured 5.8e-10 (plain 1.2e-3)
    EXPECT_GT(k_plain, 100 * k_broken);
    // A rim whose disc holds the vertex is not another vertex's disc.
    EXPECT_THROW(frame.near_rule(1.0, 12, 12, 8, {Circle{{1.0, 0.5}, 0.8}}), std::invalid_argument);
  }

  TEST(TurnedTensor, IsTheRotationOfTheTensor)
  {
    // A uniaxial stress sigma along e_1 = (cos phi, sin phi) is sigma e_1 e_1 in the fixed axes;
    // turning back by -phi gives the components along (e_1, e_2) again; trace and determinant
    // stay; complex components turn their real and imaginary parts alike.
    for (const double phi : {0.0, 0.3, 1.2, pi / 2, 2.5, -0.7})
      {
        const double c = std::cos(phi), s = std::sin(phi);
        const std::array<double, 3> u = rfm::turned_tensor(2.0, 0.0, 0.0, c, s);
        EXPECT_NEAR(u[0], 2.0 * c * c, 1e-15);
        EXPECT_NEAR(u[1], 2.0 * s * s, 1e-15);
        EXPECT_NEAR(u[2], 2.0 * c * s, 1e-15);
        const double a11 = 3.0, a22 = -1.5, a12 = 0.8;
        const std::array<double, 3> t = rfm::turned_tensor(a11, a22, a12, c, s);
        EXPECT_NEAR(t[0] + t[1], a11 + a22, 1e-14);
        EXPECT_NEAR(t[0] * t[1] - t[2] * t[2], a11 * a22 - a12 * a12, 1e-14);
        const std::array<double, 3> back = rfm::turned_tensor(t[0], t[1], t[2], c, -s);
        EXPECT_NEAR(back[0], a11, 1e-14);
        EXPECT_NEAR(back[1], a22, 1e-14);
        EXPECT_NEAR(back[2], a12, 1e-14);
        using cd = std::complex<double>;
        const std::array<cd, 3> z = rfm::turned_tensor(cd(a11, 1.0), cd(a22, -2.0), cd(a12, 0.5), c, s);
        const std::array<double, 3> im = rfm::turned_tensor(1.0, -2.0, 0.5, c, s);
        for (int i = 0; i < 3; ++i)
          {
            EXPECT_NEAR(z[i].real(), t[i], 1e-14);
            EXPECT_NEAR(z[i].imag(), im[i], 1e-14);
          }
      }
  }
} // namespace
