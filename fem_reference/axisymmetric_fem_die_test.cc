// Dies on outline parts in the FEM reference (issue 23 item 4, DESIGN.md 7.1) against closed
// forms and against independent models of the same body:
//  * Hertz: a rigid paraboloid pressed by a force on the end face of a solid cylinder 23 times
//    the contact radius in radius and height: a = (3 P R / 4 E*)^(1/3), p0 = 3 P / (2 pi a^2)
//    (Johnson, Contact Mechanics, eq. 4.22-4.23; the finite body changes them at third order
//    in a / H).
//  * Force control against indentation control: the indentation found for the force, given
//    back as an indentation, gives that force (two independent paths through the solver).
//  * A ring die at the mid-length of a shaft, modelled whole (two free edges), against the
//    mirrored half shaft (one free edge, centre on the symmetry plane), and the whole model's
//    zone symmetric about the centre.
#include "fem_reference/axisymmetric_fem.h"
#include "problem/problem.h"
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

namespace fem
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    FemOptions quiet(int refinements)
    {
      FemOptions o;
      o.refinements = refinements;
      o.progress = false;
      return o;
    }

    double peak_pressure(const ContactResult &c)
    {
      double p0 = 0;
      for (const PressurePoint &p : c.pressure)
        p0 = std::max(p0, p.p);
      return p0;
    }

    /// A solid shaft r <= 0.01 m, |z| <= h with u_z = 0 on both ends (symmetry), pressed by a
    /// ring die (paraboloid, R = 0.05 m, 2 um) centred at z = 0 on its side; with `half`
    /// the mirrored model z in [0, h] (the die's centre on the symmetry plane by default).
    nlohmann::json ring_die_shaft(bool half, double h = 0.02)
    {
      const double z0 = half ? 0.0 : -h;
      nlohmann::json j;
      j["geometry"]["outline"] = {{{"start", {0.0, z0}}},
                                  {{"line_to", {0.01, z0}}, {"part", "bottom"}},
                                  {{"line_to", {0.01, h}}, {"part", "side"}},
                                  {{"line_to", {0.0, h}}, {"part", "top"}},
                                  {{"line_to", {0.0, z0}}, {"part", "axis"}}};
      j["boundary"]["bottom"]["symmetry"] = true;
      j["boundary"]["top"]["symmetry"] = true;
      j["boundary"]["side"]["die"] = {{"indentation", 2e-6},
                                      {"profile", {{"shape", "paraboloid"}, {"radius", 0.05}}}};
      if (!half)
        j["boundary"]["side"]["die"]["center"] = {0.01, 0.0};
      j["material"] = {{"youngs_modulus", 2.1e11}, {"poisson_ratio", 0.3}};
      return j;
    }
  } // namespace

  // At L = 3 (35k dofs, 1.5 s) the contact radius was within 2e-4 and p0 within 1.1e-4 of
  // Hertz when written (L = 4: 8.6e-5 and 1.6e-5); the issue asks 0.3 % and 1 %.
  TEST(FemDie, HertzContactRadiusAndPeakPressure)
  {
    const axisym::Problem p = axisym::parse_problem(axisym::testing::punched_cylinder());
    const FemResult r = solve(p, quiet(3));
    ASSERT_TRUE(r.success) << r.message;
    ASSERT_TRUE(r.contact);
    const double force = 2000.0, radius = 0.1;
    const double e_star = 2.1e11 / (1 - 0.3 * 0.3);
    const double a = std::cbrt(3 * force * radius / (4 * e_star));
    const double p0 = 3 * force / (2 * pi * a * a);
    EXPECT_EQ(r.contact->part, "top");
    EXPECT_FALSE(r.contact->zone); // one free edge: the centre is on the axis
    EXPECT_NEAR(r.contact->half_width, a, 3e-3 * a);
    EXPECT_NEAR(peak_pressure(*r.contact), p0, 1e-2 * p0);
    // The asked force, by the linearity in delta on the final active set.
    EXPECT_NEAR(r.contact->force, force, 1e-6 * force);
    // The element trace of the normal stress carries the same force less its trace error.
    EXPECT_NEAR(r.contact->force_trace, force, 5e-2 * force);
    // Hertz's indentation of a half-space is a^2 / R; the finite column is stiffer in the
    // far field: smaller, but of that size.
    EXPECT_GT(r.contact->indentation, 0.9 * a * a / radius);
    EXPECT_LT(r.contact->indentation, a * a / radius);
  }

  // Pass 0 refines around different estimates of the zone (Hertz's radius for a force, the
  // overlap g0 < delta for an indentation), so the two final meshes differ a little: measured
  // when written 1.9e-6 (P), 1.4e-8 (c) and 1.3e-6 (Phi_L) relative.
  TEST(FemDie, IndentationFoundForAForceGivesThatForce)
  {
    auto j = axisym::testing::punched_cylinder();
    const FemResult by_force = solve(axisym::parse_problem(j), quiet(2));
    ASSERT_TRUE(by_force.success) << by_force.message;
    j["boundary"]["top"]["die"].erase("force");
    j["boundary"]["top"]["die"]["indentation"] = by_force.contact->indentation;
    const FemResult by_indentation = solve(axisym::parse_problem(j), quiet(2));
    ASSERT_TRUE(by_indentation.success) << by_indentation.message;
    EXPECT_NEAR(by_indentation.contact->force, 2000.0, 1e-5 * 2000.0);
    EXPECT_NEAR(by_indentation.contact->half_width, by_force.contact->half_width,
                1e-6 * by_force.contact->half_width);
    EXPECT_NEAR(by_indentation.functionals.lagrange, by_force.functionals.lagrange,
                1e-5 * std::abs(by_force.functionals.lagrange));
  }

  // Measured when written (L = 2): whole c 2.1368e-4 m with the zone symmetric to 2e-5 of c,
  // half c 2.1369e-4 m, forces 10344.4 N and 2 x 5172.2 N.
  TEST(FemDie, RingDieWithTwoFreeEdgesMatchesTheMirroredHalf)
  {
    const FemResult whole = solve(axisym::parse_problem(ring_die_shaft(false)), quiet(2));
    const FemResult half = solve(axisym::parse_problem(ring_die_shaft(true)), quiet(2));
    ASSERT_TRUE(whole.success) << whole.message;
    ASSERT_TRUE(half.success) << half.message;
    ASSERT_TRUE(whole.contact->zone);
    EXPECT_FALSE(half.contact->zone);
    const auto [lo, hi] = *whole.contact->zone;
    const double c = half.contact->half_width;
    EXPECT_NEAR(-lo, c, 1e-3 * c);
    EXPECT_NEAR(hi, c, 1e-3 * c);
    EXPECT_NEAR(whole.contact->half_width, 0.5 * (hi - lo), 1e-12);
    EXPECT_NEAR(whole.contact->force, 2 * half.contact->force, 1e-3 * whole.contact->force);
    // Plane-strain Hertz for the ring (a cylinder on a flat, per unit length of the
    // circumference P' = P / (2 pi r)): b = sqrt(4 P' R / (pi E*)); the shaft's curvature
    // about the axis and its finite size enter at the per cent level.
    const double p_line = whole.contact->force / (2 * pi * 0.01);
    const double b = std::sqrt(4 * p_line * 0.05 / (pi * 2.1e11 / (1 - 0.09)));
    EXPECT_NEAR(c, b, 2e-2 * b);
  }

  // contact.method = "fixed" on the ring die (two free ends, the zone [-c, c]): Barber's
  // principle, P(c) of the bilateral problem is largest at the unilateral zone c* (flat
  // there), smaller for a shorter and for a longer zone; the whole shaft carries twice the
  // mirrored half's force. Measured when written (L = 2): c* = 2.1372e-4 m, unilateral P =
  // 10344.74 N; fixed P(0.8 c*) = 10236.62, P(c*) = 10344.64, P(1.2 c*) = 10239.09 N, the
  // half's 2 P(c*) = 10344.61 N, the trace 10295.95 N.
  TEST(FemDie, FixedZoneForceIsLargestAtTheUnilateralZone)
  {
    const FemResult free_zone = solve(axisym::parse_problem(ring_die_shaft(false)), quiet(2));
    ASSERT_TRUE(free_zone.success) << free_zone.message;
    const double c = free_zone.contact->half_width;
    auto fixed = [&](bool half, double half_width) {
      auto j = ring_die_shaft(half);
      j["contact"] = {{"method", "fixed"}, {"half_width", half_width}};
      const FemResult r = solve(axisym::parse_problem(j), quiet(2));
      EXPECT_TRUE(r.success) << r.message;
      EXPECT_FALSE(r.contact->unilateral);
      return r;
    };
    const FemResult at = fixed(false, c), shorter = fixed(false, 0.8 * c),
                    longer = fixed(false, 1.2 * c), half = fixed(true, c);
    std::cout.precision(8);
    std::cout << "ring die: unilateral c = " << c << " m, P = " << free_zone.contact->force
              << " N; fixed P(0.8 c) = " << shorter.contact->force << ", P(c) = "
              << at.contact->force << ", P(1.2 c) = " << longer.contact->force
              << ", half 2 P(c) = " << 2 * half.contact->force << " N, trace "
              << at.contact->force_trace << " N\n";
    ASSERT_TRUE(at.contact->zone);
    EXPECT_NEAR((*at.contact->zone)[0], -c, 1e-12);
    EXPECT_NEAR((*at.contact->zone)[1], c, 1e-12);
    EXPECT_NEAR(at.contact->force, free_zone.contact->force, 1e-4 * free_zone.contact->force);
    EXPECT_LT(shorter.contact->force, at.contact->force);
    EXPECT_LT(longer.contact->force, at.contact->force);
    EXPECT_NEAR(at.contact->force, 2 * half.contact->force, 1e-4 * at.contact->force);
    // The consistent reaction and the element trace of the same field.
    EXPECT_NEAR(at.contact->force_trace, at.contact->force, 1e-2 * at.contact->force);
    // On the zone the die's surface is met exactly (the Q2 nodes carry the constraint).
    for (const PressurePoint &pt : at.contact->pressure)
      {
        if (std::abs(pt.s) < c * (1 - 1e-9))
          {
            EXPECT_LT(std::abs(pt.gap), 1e-12 * 2e-6);
          }
      }
  }

  TEST(FemDie, FixedZoneWithAForceControlledDieIsRefused)
  {
    auto j = axisym::testing::punched_cylinder();
    j["contact"] = {{"method", "fixed"}, {"half_width", 0.001}};
    try
      {
        solve(axisym::parse_problem(j), quiet(1));
        ADD_FAILURE() << "no InputError";
      }
    catch (const axisym::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find("boundary.top.die.force"), std::string::npos)
          << e.what();
      }
  }
} // namespace fem
