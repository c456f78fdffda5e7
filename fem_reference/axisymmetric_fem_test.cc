#include "fem_reference/axisymmetric_fem.h"

#include "verification/lame_exact.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fem
{
  namespace
  {
    // Named tolerances.
    constexpr double rate_tolerance = 0.3;      // observed vs expected order (brief)
    constexpr double paper_tolerance = 3e-3;    // 0.3 % to the paper's 128.7 kN and 0.0176 J
    constexpr double converged_tolerance = 1e-3; // relative change between two levels

    axisym::Problem lame_problem()
    {
      return axisym::parse_problem(nlohmann::json::parse(R"({
        "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
        "loading": {"inner_pressure": 1.0e7, "outer_pressure": 2.0e6},
        "samples": [[0.15, 0.1], [0.15, -0.1], [0.2, 0.2]]
      })"));
    }

    verification::LameCylinder lame_exact(const axisym::Problem &p)
    {
      return {p.geometry.inner_radius,    p.geometry.outer_radius,
              p.geometry.length,          p.material.youngs_modulus,
              p.material.poisson_ratio,   p.loading->inner_pressure,
              p.loading->outer_pressure};
    }

    axisym::Problem die_problem(const std::string &method)
    {
      auto j = nlohmann::json::parse(R"({
        "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
        "die": {"indentation": 1.0e-6, "profile": "parabolic"},
        "contact": {"method": "fixed"}
      })");
      j["contact"]["method"] = method;
      return axisym::parse_problem(j);
    }

    FemOptions quiet(int degree, int refinements)
    {
      FemOptions o;
      o.degree = degree;
      o.refinements = refinements;
      o.progress = false;
      return o;
    }

    // Observed order of the r-weighted L2 stress error (or of the max error at the cells'
    // Gauss-Lobatto points) on levels 0..n_levels-1 (h halves).
    std::vector<double> stress_rates(int degree, int n_levels, bool max_norm = false)
    {
      const axisym::Problem p = lame_problem();
      const verification::LameCylinder exact = lame_exact(p);
      const StressFunction s = [&](double r, double z) { return exact.stress(r, z); };
      std::vector<double> errors, rates;
      for (int level = 0; level < n_levels; ++level)
        {
          const FemResult r = solve(p, quiet(degree, level), s);
          EXPECT_TRUE(r.success) << r.message;
          errors.push_back(max_norm ? *r.stress_max_error / *r.stress_max_norm
                                    : *r.stress_l2_error / *r.stress_l2_norm);
          if (level > 0)
            rates.push_back(std::log2(errors[level - 1] / errors[level]));
        }
      return rates;
    }
  } // namespace

  TEST(AxisymmetricFem, LameStressConvergesAtOrderOneForQ1)
  {
    const std::vector<double> rates = stress_rates(1, 4);
    EXPECT_NEAR(rates.back(), 1.0, rate_tolerance);
  }

  TEST(AxisymmetricFem, LameStressConvergesAtOrderTwoForQ2)
  {
    const std::vector<double> rates = stress_rates(2, 4);
    EXPECT_NEAR(rates.back(), 2.0, rate_tolerance);
  }

  // The stress error in the max norm, boundary included, converges at the same order
  // h^p for a smooth solution (1.82 on levels 2 -> 3 for this problem, p_in = 10 MPa,
  // p_out = 2 MPa, when this test was written; it approaches 2 from below).
  TEST(AxisymmetricFem, LameMaxStressErrorConvergesAtOrderTwoForQ2)
  {
    const std::vector<double> rates = stress_rates(2, 4, true);
    EXPECT_NEAR(rates.back(), 2.0, rate_tolerance);
  }

  // Traction problem: Phi_L = Phi_C = Phi_R = -U_h, and U_h <= U (Phi_L >= exact, -U).
  TEST(AxisymmetricFem, LameFunctionalsApproachMinusTheExactEnergyFromAbove)
  {
    const axisym::Problem p = lame_problem();
    const double exact = -lame_exact(p).strain_energy();
    double previous_error = 1;
    for (int level = 1; level <= 3; ++level)
      {
        const FemResult r = solve(p, quiet(2, level));
        ASSERT_TRUE(r.success) << r.message;
        const Functionals &f = r.functionals;
        const double error = (f.lagrange - exact) / std::abs(exact);
        EXPECT_GE(error, -1e-12);
        EXPECT_LT(error, previous_error);
        previous_error = error;
        EXPECT_NEAR(f.castigliano, f.lagrange, 1e-9 * std::abs(exact));
        EXPECT_NEAR(f.reissner, f.lagrange, 1e-9 * std::abs(exact));
      }
    EXPECT_LT(previous_error, 1e-6);
  }

  // Samples against the exact field; z < 0 mirrored (u_z, sigma_rz odd in z).
  TEST(AxisymmetricFem, LameSamplesMatchTheExactFieldAndMirror)
  {
    const axisym::Problem p = lame_problem();
    const verification::LameCylinder exact = lame_exact(p);
    const FemResult r = solve(p, quiet(2, 3));
    ASSERT_TRUE(r.success) << r.message;
    ASSERT_EQ(r.samples.size(), 3u);
    for (const FieldSample &s : r.samples)
      {
        const auto u = exact.displacement(s.r, s.z);
        const auto sigma = exact.stress(s.r, s.z);
        EXPECT_NEAR(s.u_r, u[0], 1e-6 * std::abs(u[0]));
        EXPECT_NEAR(s.u_z, u[1], 1e-6 * std::abs(exact.displacement(s.r, 0.2)[1]));
        EXPECT_NEAR(s.sigma[0], sigma[0], 1e-3 * p.loading->inner_pressure);
        EXPECT_NEAR(s.sigma[2], sigma[2], 1e-3 * p.loading->inner_pressure);
      }
    EXPECT_EQ(r.samples[0].u_z, -r.samples[1].u_z);
    EXPECT_EQ(r.samples[0].sigma[3], -r.samples[1].sigma[3]);
  }

  // The gmsh and the structured generators build the same vertices: same answer.
  TEST(AxisymmetricFem, GmshAndStructuredMeshesAgree)
  {
    const axisym::Problem p = die_problem("fixed");
    FemOptions o = quiet(2, 1);
    const FemResult a = solve(p, o);
    o.mesh = FemOptions::MeshGenerator::structured;
    const FemResult b = solve(p, o);
    ASSERT_TRUE(a.success && b.success);
    EXPECT_EQ(a.n_cells, b.n_cells);
    EXPECT_EQ(a.n_dofs, b.n_dofs);
    EXPECT_NEAR(a.contact->force, b.contact->force, 1e-9 * std::abs(b.contact->force));
    EXPECT_NEAR(a.functionals.lagrange, b.functionals.lagrange, 1e-9 * b.functionals.lagrange);
  }

  // Bilateral c = a (paper iteration 0): converged under refinement, and the paper's
  // 128.7 kN and 0.0176 J/rad within 0.3 % (sanity range; the converged value is the test).
  TEST(AxisymmetricFem, BilateralFullZoneForceConvergesToThePaperValue)
  {
    const axisym::Problem p = die_problem("fixed");
    const FemResult coarse = solve(p, quiet(2, 2));
    const FemResult fine = solve(p, quiet(2, 3));
    ASSERT_TRUE(coarse.success && fine.success);
    const double force = fine.contact->force;
    EXPECT_NEAR(force, coarse.contact->force, converged_tolerance * force);
    EXPECT_NEAR(force, 128.7e3, paper_tolerance * 128.7e3);
    EXPECT_NEAR(fine.contact->force_trace, force, 1e-2 * force);
    EXPECT_NEAR(fine.functionals.lagrange, 0.0176, paper_tolerance * 0.0176);
    EXPECT_EQ(fine.contact->half_width, p.geometry.half_length());
    // Displacement-driven: Phi_L = U; reissner == lagrange (u_h = u* on the zone for p = 2).
    EXPECT_NEAR(fine.functionals.reissner, fine.functionals.lagrange,
                1e-9 * fine.functionals.lagrange);
    // The domain reaction equals the work identity 2U = int t.u* (Clapeyron): P delta-scaled.
    EXPECT_NEAR(fine.functionals.castigliano, fine.functionals.lagrange,
                1e-2 * fine.functionals.lagrange);
  }

  // Unilateral penalty contact: the active set settles, 0 < c < a, and the force exceeds
  // the bilateral c = a force (which has tensile pressure near the ends).
  TEST(AxisymmetricFem, UnilateralContactSettlesWithAPartialZoneAndALargerForce)
  {
    const FemResult bilateral = solve(die_problem("fixed"), quiet(2, 2));
    const axisym::Problem p = die_problem("iterate");
    const FemResult r = solve(p, quiet(2, 2));
    ASSERT_TRUE(r.success) << r.message;
    const ContactResult &c = *r.contact;
    EXPECT_TRUE(c.unilateral);
    // Pass 0 starts from the whole side in contact and needs several steps; the fitted pass
    // starts from z < c and settles at once or nearly.
    EXPECT_EQ(c.edge_fitting_passes, 1);
    EXPECT_GT(c.iterations.size(), 3u);
    EXPECT_EQ(c.iterations.front().pass, 0);
    EXPECT_EQ(c.iterations.back().pass, 1);
    EXPECT_EQ(c.iterations.back().n_changed, 0);
    EXPECT_GT(c.half_width, 0.0);
    EXPECT_LT(c.half_width, p.geometry.half_length());
    // Converged reference (L = 5, Q2, see the report): c/a = 0.5193; loose range at L = 2.
    EXPECT_NEAR(c.half_width / p.geometry.half_length(), 0.5193, 5e-3);
    EXPECT_GT(c.force, bilateral.contact->force);
    EXPECT_NEAR(c.force_penalty, c.force, 1e-6 * c.force);
    for (const PressurePoint &pt : c.pressure)
      EXPECT_GE(pt.p, 0.0);
  }

  // A numerical failure is an outcome, not an exception: status, message and history.
  TEST(AxisymmetricFem, ActiveSetIterationLimitIsReportedWithItsHistory)
  {
    FemOptions o = quiet(2, 1);
    o.max_active_set_iterations = 1;
    const FemResult r = solve(die_problem("iterate"), o);
    EXPECT_FALSE(r.success);
    EXPECT_NE(r.message.find("not converged"), std::string::npos) << r.message;
    ASSERT_TRUE(r.contact);
    ASSERT_EQ(r.contact->iterations.size(), 1u);
    EXPECT_EQ(r.contact->iterations[0].n_active, r.contact->iterations[0].n_active);
    EXPECT_NEAR(r.contact->iterations[0].force, 128.7e3, paper_tolerance * 128.7e3);
  }

  TEST(AxisymmetricFem, RejectsBadOptionsNamingTheField)
  {
    FemOptions o = quiet(2, 9);
    try
      {
        o.validate();
        ADD_FAILURE() << "accepted refinements = 9";
      }
    catch (const axisym::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find("refinements"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("9"), std::string::npos) << e.what();
      }
    o = quiet(2, 1);
    o.penalty_factor = -1;
    EXPECT_THROW(solve(die_problem("iterate"), o), axisym::InputError);
  }
} // namespace fem
