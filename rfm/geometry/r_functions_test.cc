#include "rfm/geometry/r_functions.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace rfm
{
  namespace
  {
    using Field = std::function<RValue(double, double)>;

    // Central differences against the analytic gradient (Ceres gradient_checker style).
    void expect_gradient_matches(const Field &f, double r, double z)
    {
      const double h = 1e-6;
      const RValue v = f(r, z);
      const double fd_r = (f(r + h, z).value - f(r - h, z).value) / (2 * h);
      const double fd_z = (f(r, z + h).value - f(r, z - h).value) / (2 * h);
      const double scale = 1 + std::abs(v.d_r) + std::abs(v.d_z);
      EXPECT_NEAR(v.d_r, fd_r, 1e-6 * scale) << "at (" << r << ", " << z << ")";
      EXPECT_NEAR(v.d_z, fd_z, 1e-6 * scale) << "at (" << r << ", " << z << ")";
    }

    RValue segment_on_r_equals_02(double r, double z)
    {
      // Segment r = 0.2, z in [0, 0.1]: f = 0.2 - r, t = strip in z.
      const RValue f = half_plane(r, z, 0.2, 0.0, -1.0, 0.0);
      RValue t = strip(z, 0.0, 0.1);
      std::swap(t.d_r, t.d_z);
      return trimmed_segment(f, t, 0.1);
    }
  } // namespace

  TEST(RFunctions, GradientsMatchFiniteDifferences)
  {
    std::mt19937 gen(42);
    std::uniform_real_distribution<double> ur(0.11, 0.19), uz(-0.15, 0.15);
    const std::vector<Field> fields = {
      [](double r, double z) { return half_plane(r, z, 0.1, 0.0, 0.6, 0.8); },
      [](double r, double) { return strip(r, 0.1, 0.2); },
      [](double r, double z) { return disk(r, z, 0.15, 0.0, 0.3); },
      segment_on_r_equals_02,
      [](double r, double z) {
        return r_conjunction(half_plane(r, z, 0.1, 0, 1, 0), half_plane(r, z, 0, -0.2, 0, 1));
      },
      [](double r, double z) {
        return r_disjunction(strip(r, 0.1, 0.2), disk(r, z, 0.15, 0.1, 0.05));
      },
      [](double r, double z) { return r_negation(disk(r, z, 0.15, 0.1, 0.05)); },
      [](double r, double z) { return product(strip(r, 0.1, 0.2), half_plane(r, z, 0, -0.2, 0, 1)); },
    };
    for (std::size_t i = 0; i < fields.size(); ++i)
      for (int k = 0; k < 20; ++k)
        {
          SCOPED_TRACE("field " + std::to_string(i));
          expect_gradient_matches(fields[i], ur(gen), uz(gen));
        }
  }

  TEST(RFunctions, PrimitivesVanishOnTheirBoundaryWithUnitGradient)
  {
    for (double z : {-0.1, 0.0, 0.07})
      {
        const RValue s_lo = strip(0.1, 0.1, 0.2), s_hi = strip(0.2, 0.1, 0.2);
        EXPECT_DOUBLE_EQ(s_lo.value, 0.0);
        EXPECT_DOUBLE_EQ(s_hi.value, 0.0);
        EXPECT_NEAR(s_lo.d_r, 1.0, 1e-14);  // inward normal of r = 0.1 is +e_r
        EXPECT_NEAR(s_hi.d_r, -1.0, 1e-14); // inward normal of r = 0.2 is -e_r
        EXPECT_GT(strip(0.15, 0.1, 0.2).value, 0.0);
        const RValue h = half_plane(0.1, z, 0.1, 0.0, 1.0, 0.0);
        EXPECT_DOUBLE_EQ(h.value, 0.0);
      }
    const RValue d = disk(0.15 + 0.3 * 0.6, 0.3 * 0.8, 0.15, 0.0, 0.3);
    EXPECT_NEAR(d.value, 0.0, 1e-15);
    EXPECT_NEAR(std::hypot(d.d_r, d.d_z), 1.0, 1e-14);
  }

  TEST(RFunctions, TrimmedSegmentVanishesOnlyOnTheSegment)
  {
    for (double z = 0.0; z <= 0.1; z += 0.01)
      EXPECT_NEAR(segment_on_r_equals_02(0.2, z).value, 0.0, 1e-15) << z;
    // Beyond the ends on the same line it is positive (|t| there).
    EXPECT_NEAR(segment_on_r_equals_02(0.2, 0.15).value, std::abs(strip(0.15, 0.0, 0.1).value), 1e-15);
    EXPECT_GT(segment_on_r_equals_02(0.2, -0.02).value, 0.0);
    // Inside the section near the segment it behaves like the distance (normalized).
    const RValue w = segment_on_r_equals_02(0.2 - 1e-7, 0.05);
    EXPECT_NEAR(w.value, 1e-7, 1e-12);
    EXPECT_NEAR(w.d_r, -1.0, 1e-6);
  }

  TEST(RFunctions, ConjunctionIsZeroOnUnionOfBoundariesAndPositiveInside)
  {
    auto w = [](double r, double z) {
      return r_conjunction(strip(r, 0.1, 0.2), half_plane(r, z, 0.0, 0.0, 0.0, 1.0));
    };
    EXPECT_NEAR(w(0.1, 0.05).value, 0.0, 1e-15);
    EXPECT_NEAR(w(0.2, 0.05).value, 0.0, 1e-15);
    EXPECT_NEAR(w(0.15, 0.0).value, 0.0, 1e-15);
    EXPECT_GT(w(0.15, 0.05).value, 0.0);
    // Normalized on a side away from corners: gradient of unit length.
    const RValue g = w(0.15, 0.0);
    EXPECT_NEAR(std::hypot(g.d_r, g.d_z), 1.0, 1e-12);
    // Disjunction is negative only where both are; negation flips sign.
    EXPECT_LT(r_disjunction({-1, 0, 0}, {-2, 0, 0}).value, 0.0);
    EXPECT_GT(r_disjunction({-1, 0, 0}, {2, 0, 0}).value, 0.0);
    EXPECT_DOUBLE_EQ(r_negation({3, 1, 2}).value, -3);
  }

  TEST(RFunctions, NormalizeGivesUnitGradientOnZeroSet)
  {
    const RValue d = disk(0.15, 0.3, 0.15, 0.0, 0.3); // on the circle: d = 0
    const RValue scaled{5 * d.value, 5 * d.d_r, 5 * d.d_z};
    const RValue n = normalize(scaled);
    EXPECT_NEAR(n.value, 0.0, 1e-15);
    EXPECT_NEAR(std::hypot(n.d_r, n.d_z), 1.0, 1e-14);
    EXPECT_GT(normalize(disk(0.15, 0.1, 0.15, 0.0, 0.3)).value, 0.0);
  }
} // namespace rfm
