#include "fem_reference/axisymmetric_fem.h"

#include "problem/test_problems.h"
#include "verification/lame_exact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace fem
{
  namespace
  {
    // Named tolerances.
    constexpr double rate_tolerance = 0.3;      // observed vs expected order (brief)
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
    // L = 4: on the unstructured (ungraded) mesh of the outline path u_z is 2.5e-6 off at
    // L = 3 (the graded rectangle of the old path met 1e-6 there).
    const FemResult r = solve(p, quiet(2, 4));
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

  // The hollow-cylinder form is its half section as an outline, mirrored: the outline file
  // of that half section (not mirrored) gives half the force and half the functionals, on
  // the same mesh; at z < 0 the mirrored body's fields are the mirror images.
  TEST(AxisymmetricFem, HollowCylinderFormIsTheMirroredHalfSection)
  {
    const axisym::Problem legacy = die_problem("fixed");
    nlohmann::json j = axisym::testing::paper_die_outline();
    j["contact"] = {{"method", "fixed"}, {"half_width", 0.12}};
    axisym::Problem half = axisym::parse_problem(j);
    axisym::Problem fixed_legacy = legacy;
    fixed_legacy.contact.half_width = 0.12;
    const FemResult a = solve(fixed_legacy, quiet(2, 1));
    const FemResult b = solve(half, quiet(2, 1));
    ASSERT_TRUE(a.success && b.success);
    EXPECT_EQ(a.n_dofs, b.n_dofs);
    EXPECT_NEAR(a.contact->force, 2 * b.contact->force, 1e-9 * a.contact->force);
    EXPECT_NEAR(a.contact->force_trace, 2 * b.contact->force_trace, 1e-9 * a.contact->force);
    EXPECT_NEAR(a.functionals.lagrange, 2 * b.functionals.lagrange, 1e-9 * a.functionals.lagrange);
    EXPECT_NEAR(a.functionals.castigliano, 2 * b.functionals.castigliano,
                1e-9 * a.functionals.lagrange);
    EXPECT_DOUBLE_EQ(a.contact->half_width, 0.12);
    EXPECT_FALSE(a.contact->zone);
  }

  // Bilateral c = a (paper iteration 0), checked without the paper's numbers: the force and
  // the energy converge over levels 1, 2, 3 (Richardson extrapolation with the observed
  // order puts the finest level within converged_tolerance of the limit), and Clapeyron's
  // identity 2 U = int_{S_c} (s n).u* r ds (the work of the reactions on the prescribed
  // displacement; Phi_C = -U + that work = U = Phi_L) to the accuracy of the element traces
  // s_h n (1.5e-4 or better on levels 2 and 3, 2.2e-3 on level 1; not monotone in L).
  TEST(AxisymmetricFem, BilateralFullZoneForceConvergesAndSatisfiesClapeyron)
  {
    const axisym::Problem p = die_problem("fixed");
    std::vector<FemResult> r;
    for (int level = 1; level <= 3; ++level)
      {
        r.push_back(solve(p, quiet(2, level)));
        ASSERT_TRUE(r.back().success) << r.back().message;
      }
    const auto richardson = [](double x1, double x2, double x3, double *order) {
      *order = std::log2((x1 - x2) / (x2 - x3));
      return x3 + (x3 - x2) / (std::pow(2.0, *order) - 1);
    };
    double force_order = 0, energy_order = 0;
    const double force = richardson(r[0].contact->force, r[1].contact->force,
                                    r[2].contact->force, &force_order);
    const double energy =
      richardson(r[0].functionals.lagrange, r[1].functionals.lagrange,
                 r[2].functionals.lagrange, &energy_order);
    std::cout.precision(10);
    std::cout << "bilateral c = a: P = " << r[0].contact->force << ", " << r[1].contact->force
              << ", " << r[2].contact->force << " -> " << force << " (order " << force_order
              << "); Phi_L = " << r[2].functionals.lagrange << " -> " << energy << " (order "
              << energy_order << ")\n";
    EXPECT_GT(force_order, 1.0);
    EXPECT_GT(energy_order, 1.0);
    EXPECT_NEAR(r[2].contact->force, force, converged_tolerance * force);
    EXPECT_NEAR(r[2].functionals.lagrange, energy, converged_tolerance * energy);
    EXPECT_NEAR(r[2].contact->force_trace, r[2].contact->force, 1e-2 * force);
    for (const FemResult &x : r)
      {
        // The zone is the whole side z in [0, a]: the gap u_r - u_r* vanishes at every face
        // point up to the end z = a (measured: exactly 0 on levels 1-3; the points are the
        // Q2 nodes on r = R2, where the constraint is imposed), and the end is in tension
        // (paper Fig. 3, iteration 0; measured p(a) = -1.89 MPa on levels 1-3). A zone cut
        // short would leave a gap of order delta and no tension beyond it.
        const double a = p.geometry.half_length(), delta = p.die->indentation;
        ASSERT_FALSE(x.contact->pressure.empty());
        double max_gap = 0.0;
        for (const PressurePoint &pt : x.contact->pressure)
          max_gap = std::max(max_gap, std::abs(pt.gap));
        EXPECT_LT(max_gap, 1e-12 * delta);
        EXPECT_GT(x.contact->pressure.back().z, a - x.contact->h_min);
        EXPECT_LT(x.contact->pressure.back().p, 0.0);
        // Displacement-driven: Phi_L = U; reissner == lagrange (u_h = u* on the zone, p = 2).
        EXPECT_NEAR(x.functionals.reissner, x.functionals.lagrange,
                    1e-9 * x.functionals.lagrange);
        const double clapeyron =
          std::abs(x.functionals.castigliano - x.functionals.lagrange) / x.functionals.lagrange;
        std::cout << "  level " << x.refinements << ": |Phi_C - Phi_L| / Phi_L = " << clapeyron
                  << '\n';
        // Level 1 on the outline path's ungraded base mesh (4 cells across the wall, h0 =
        // 0.025 m at r = R2; the old graded rectangle had 0.013 m there): 2.2e-3 measured,
        // levels 2 and 3: 9.2e-5 and 1.2e-4.
        EXPECT_LT(clapeyron, x.refinements == 1 ? 3e-3 : 1e-3);
      }
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
    // Pass 0 starts from the estimated zone and needs a few steps; the refitted pass starts
    // from the zone found and settles at once or nearly.
    EXPECT_EQ(c.edge_fitting_passes, 1);
    EXPECT_GT(c.iterations.size(), 2u);
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

  // A numerical failure is an outcome, not an exception: status, message and history. The
  // one step done starts from pass 0's estimate of the zone (where the die's paraboloid
  // overlaps the undeformed side, z < a / sqrt 2), with every contact point there active.
  TEST(AxisymmetricFem, ActiveSetIterationLimitIsReportedWithItsHistory)
  {
    FemOptions o = quiet(2, 1);
    o.max_active_set_iterations = 1;
    const FemResult r = solve(die_problem("iterate"), o);
    EXPECT_FALSE(r.success);
    EXPECT_NE(r.message.find("not converged"), std::string::npos) << r.message;
    ASSERT_TRUE(r.contact);
    ASSERT_EQ(r.contact->iterations.size(), 1u);
    const ActiveSetStep &step = r.contact->iterations[0];
    EXPECT_EQ(step.pass, 0);
    EXPECT_GT(step.n_active, 0);
    EXPECT_GT(step.n_changed, 0);
    EXPECT_GT(step.force, 0.0);
  }

  // ---- Outline problems (DESIGN.md 7.1) against closed forms written here. ----

  constexpr double youngs_modulus = 2.1e11, poisson_ratio = 0.3;

  // Solid cylinder 0 <= r <= 0.1, 0 <= z <= 0.2, pressure p on the top, symmetry at the
  // bottom, the axis r = 0: sigma_zz = -p, the other stresses 0, u_r = nu p r / E,
  // u_z = -p z / E (linear: Q_p reproduces it to rounding on any mesh).
  const char *const solid_cylinder_json = R"({
    "geometry": {"outline": [
      {"start": [0.0, 0.0]},
      {"line_to": [0.1, 0.0], "part": "bottom"},
      {"line_to": [0.1, 0.2], "part": "side"},
      {"line_to": [0.0, 0.2], "part": "top"},
      {"line_to": [0.0, 0.0], "part": "axis"}]},
    "boundary": {"bottom": {"symmetry": true}, "top": {"pressure": 1.0e7}},
    "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
    "samples": [[0.0, 0.1], [0.05, 0.1], [0.1, 0.2]],
    "fem": {"degree": 2, "refinements": 1}
  })";

  // Thick sphere a = 0.1 < R < b = 0.2 (DESIGN.md 7.1): the quarter annulus with the equator
  // symmetry plane and the axis, inner pressure p_i (and outer p_o, see below).
  const std::string sphere_json = [] {
    nlohmann::json j = axisym::testing::thick_sphere();
    j["samples"] = {{0.15, 0.0}, {0.1, 0.1}, {0.0, 0.15}, {0.2, 0.0}, {0.17320508075688773, 0.1}};
    j["fem"] = {{"degree", 2}, {"refinements", 2}};
    return j.dump();
  }();

  // The sphere's 60 degree sector (axisym::testing::thick_sphere_sector()), FEM Q2 at L = 2.
  const std::string sphere_sector_json = [] {
    nlohmann::json j = axisym::testing::thick_sphere_sector();
    j["fem"] = {{"degree", 2}, {"refinements", 2}};
    return j.dump();
  }();

  /// Lame's thick sphere: sigma_RR = A - B / R^3, sigma_phiphi = sigma_tt = A + B / (2 R^3)
  /// with B = (p_i - p_o) a^3 b^3 / (b^3 - a^3), A = (p_i a^3 - p_o b^3) / (b^3 - a^3)
  /// (sigma_RR(a) = -p_i, sigma_RR(b) = -p_o), u_R = ((1 - 2 nu) A R + (1 + nu) B / (2 R^2)) / E
  /// (from e_phiphi = u_R / R = ((1 - nu) sigma_phiphi - nu sigma_RR) / E). In (r, z) with
  /// c = r / R, s = z / R: sigma_rr = sigma_RR c^2 + sigma_phiphi s^2, sigma_zz = sigma_RR s^2
  /// + sigma_phiphi c^2, sigma_rz = (sigma_RR - sigma_phiphi) c s, u = u_R (c, s).
  struct ThickSphere
  {
    double a = 0.1, b = 0.2, p_i = 1e7, p_o = 0, e = youngs_modulus, nu = poisson_ratio;
    double big_a() const { return (p_i * a * a * a - p_o * b * b * b) / (b * b * b - a * a * a); }
    double big_b() const
    {
      return (p_i - p_o) * a * a * a * b * b * b / (b * b * b - a * a * a);
    }
    std::array<double, 4> stress(double r, double z) const
    {
      const double big_r = std::hypot(r, z), c = r / big_r, s = z / big_r;
      const double s_rr = big_a() - big_b() / (big_r * big_r * big_r);
      const double s_pp = big_a() + big_b() / (2 * big_r * big_r * big_r);
      return {{s_rr * c * c + s_pp * s * s, s_rr * s * s + s_pp * c * c, s_pp,
               (s_rr - s_pp) * c * s}};
    }
    std::array<double, 2> displacement(double r, double z) const
    {
      const double big_r = std::hypot(r, z);
      const double u = ((1 - 2 * nu) * big_a() * big_r +
                        (1 + nu) * big_b() / (2 * big_r * big_r)) / e;
      return {{u * r / big_r, u * z / big_r}};
    }
  };

  axisym::Problem outline_problem(const char *json)
  {
    return axisym::parse_problem(nlohmann::json::parse(json));
  }

  struct Errors
  {
    double stress = 0, displacement = 0; // relative r-weighted L2
  };

  Errors sphere_errors(const axisym::Problem &p, const ThickSphere &exact, int level,
                       FemOptions::OutlineGeometry geometry = FemOptions::OutlineGeometry::curved,
                       FemResult *result = nullptr)
  {
    FemOptions o = quiet(2, level);
    o.outline_geometry = geometry;
    const FemResult r =
      solve(p, o, [&](double rr, double zz) { return exact.stress(rr, zz); },
            [&](double rr, double zz) { return exact.displacement(rr, zz); });
    EXPECT_TRUE(r.success) << r.message;
    if (result)
      *result = r;
    return {*r.stress_l2_error / *r.stress_l2_norm,
            *r.displacement_l2_error / *r.displacement_l2_norm};
  }

  // Uniaxial compression is linear: Q2 reproduces it to rounding on the unstructured mesh,
  // the axis (u_r = 0 constraint, hoop strain at Gauss points only) included.
  TEST(AxisymmetricFemOutline, SolidCylinderUnderEndPressureIsReproducedExactly)
  {
    const axisym::Problem p = outline_problem(solid_cylinder_json);
    const double pressure = 1e7, e = youngs_modulus, nu = poisson_ratio;
    const auto stress = [&](double, double) { return std::array<double, 4>{{0, -pressure, 0, 0}}; };
    const auto displacement = [&](double r, double z) {
      return std::array<double, 2>{{nu * pressure * r / e, -pressure * z / e}};
    };
    // The same load as a traction (t_r, t_z) = (0, -p) on the top.
    nlohmann::json j = nlohmann::json::parse(solid_cylinder_json);
    j["boundary"]["top"] = {{"traction", {0.0, -pressure}}};
    const axisym::Problem with_traction = axisym::parse_problem(j);
    for (int level = 0; level <= 1; ++level)
      for (const axisym::Problem *problem : {&p, &with_traction})
      {
        const FemResult r = solve(*problem, quiet(2, level), stress, displacement);
        ASSERT_TRUE(r.success) << r.message;
        EXPECT_FALSE(r.contact);
        const double stress_error = *r.stress_l2_error / *r.stress_l2_norm;
        const double u_error = *r.displacement_l2_error / *r.displacement_l2_norm;
        std::cout << "solid cylinder L = " << level << ": " << r.n_cells << " cells, stress "
                  << stress_error << ", displacement " << u_error << '\n';
        EXPECT_LT(stress_error, 1e-10);
        EXPECT_LT(u_error, 1e-10);
        ASSERT_EQ(r.samples.size(), 3u);
        for (const FieldSample &s : r.samples)
          {
            EXPECT_NEAR(s.u_r, nu * pressure * s.r / e, 1e-10 * pressure * 0.2 / e);
            EXPECT_NEAR(s.u_z, -pressure * s.z / e, 1e-10 * pressure * 0.2 / e);
            EXPECT_NEAR(s.sigma[1], -pressure, 1e-9 * pressure);
            for (const int k : {0, 2, 3})
              EXPECT_NEAR(s.sigma[k], 0.0, 1e-9 * pressure) << "component " << k;
          }
        // W = 2 U for a traction problem; U = 1/2 p^2 / E * volume per radian (h R^2 / 2).
        const double energy = 0.5 * pressure * pressure / e * 0.2 * 0.01 / 2;
        EXPECT_NEAR(r.functionals.strain_energy, energy, 1e-10 * energy);
        EXPECT_NEAR(r.functionals.lagrange, -energy, 1e-10 * energy);
        EXPECT_NEAR(r.functionals.castigliano, -energy, 1e-10 * energy);
        EXPECT_NEAR(r.functionals.reissner, -energy, 1e-10 * energy);
      }
  }

  // Uniaxial strain: the top pushed down by d (displacement [0, -d]), the side held by a
  // symmetry condition (u_r = 0), the bottom symmetric: u = (0, -d z / h), sigma_zz =
  // (lambda + 2 mu) e, sigma_rr = sigma_tt = lambda e, e = -d / h. Corners where the
  // displacement part meets the side and the axis take both conditions. Displacement-driven:
  // Phi_L = U, and Clapeyron makes Phi_C = -U + int_top t.u* r ds = U, Phi_R = Phi_L.
  TEST(AxisymmetricFemOutline, PrescribedDisplacementGivesUniaxialStrainAndClapeyron)
  {
    nlohmann::json j = nlohmann::json::parse(solid_cylinder_json);
    const double d = 1e-5, h = 0.2, radius = 0.1;
    j["boundary"] = {{"bottom", {{"symmetry", true}}},
                     {"side", {{"symmetry", true}}},
                     {"top", {{"displacement", {0.0, -d}}}}};
    const axisym::Problem p = axisym::parse_problem(j);
    const double e = youngs_modulus, nu = poisson_ratio;
    const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
    const double strain = -d / h;
    const auto stress = [&](double, double) {
      return std::array<double, 4>{{lambda * strain, (lambda + 2 * mu) * strain,
                                    lambda * strain, 0}};
    };
    const auto displacement = [&](double, double z) {
      return std::array<double, 2>{{0.0, strain * z}};
    };
    const FemResult r = solve(p, quiet(2, 0), stress, displacement);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_LT(*r.stress_l2_error / *r.stress_l2_norm, 1e-10);
    EXPECT_LT(*r.displacement_l2_error / *r.displacement_l2_norm, 1e-10);
    const double energy = 0.5 * (lambda + 2 * mu) * strain * strain * h * radius * radius / 2;
    const Functionals &f = r.functionals;
    EXPECT_NEAR(f.strain_energy, energy, 1e-10 * energy);
    EXPECT_EQ(f.external_work, 0.0);
    EXPECT_NEAR(f.lagrange, energy, 1e-10 * energy);
    EXPECT_NEAR(f.castigliano, energy, 1e-9 * energy);
    EXPECT_NEAR(f.reissner, energy, 1e-9 * energy);
  }

  // Q2 on the curved quarter annulus: the r-weighted L2 stress error converges at order
  // 2 and the displacement error at 3 when the arcs are arcs (manifolds + MappingQ2);
  // with straight-sided cells the geometry error takes over.
  TEST(AxisymmetricFemOutline, SphereQ2ConvergesAtItsNominalOrdersOnCurvedBoundaries)
  {
    const axisym::Problem p = outline_problem(sphere_json.c_str());
    const ThickSphere exact;
    std::vector<Errors> e;
    FemResult finest;
    for (int level = 1; level <= 3; ++level)
      e.push_back(sphere_errors(p, exact, level, FemOptions::OutlineGeometry::curved, &finest));
    for (std::size_t k = 0; k < e.size(); ++k)
      std::cout << "sphere L = " << k + 1 << ": stress " << e[k].stress << ", displacement "
                << e[k].displacement << '\n';
    const double stress_rate = std::log2(e[1].stress / e[2].stress);
    const double u_rate = std::log2(e[1].displacement / e[2].displacement);
    std::cout << "rates (L = 2 -> 3): stress " << stress_rate << ", displacement " << u_rate
              << '\n';
    EXPECT_GE(stress_rate, 1.8);
    EXPECT_GE(std::log2(e[0].stress / e[1].stress), 1.8);
    EXPECT_NEAR(u_rate, 3.0, rate_tolerance);

    // Samples as given (no mirroring), on the axis (hoop strain du_r/dr there) and on the
    // corner of the outer arc with the equator.
    ASSERT_EQ(finest.samples.size(), 5u); // the last one on the outer arc
    const double p_i = exact.p_i;
    for (const FieldSample &s : finest.samples)
      {
        const auto u = exact.displacement(s.r, s.z);
        const auto sigma = exact.stress(s.r, s.z);
        const double u_scale = std::hypot(u[0], u[1]);
        EXPECT_NEAR(s.u_r, u[0], 1e-5 * u_scale) << "(" << s.r << ", " << s.z << ")";
        EXPECT_NEAR(s.u_z, u[1], 1e-5 * u_scale) << "(" << s.r << ", " << s.z << ")";
        for (int k = 0; k < 4; ++k)
          EXPECT_NEAR(s.sigma[k], sigma[k], 2e-3 * p_i)
            << "(" << s.r << ", " << s.z << ") component " << k;
      }
    // Traction problem: the three functionals are -U_h, and U_h -> U = W / 2 with the work
    // per radian of the quarter section W = int p_i u_R(a) r ds over the inner arc
    // = p_i u_R(a) a^2 int_0^(pi/2) cos(phi) dphi = p_i a^2 u_R(a).
    const double u_a = exact.displacement(exact.a, 0)[0];
    const double energy = 0.5 * p_i * exact.a * exact.a * u_a;
    const Functionals &f = finest.functionals;
    EXPECT_NEAR(f.strain_energy, energy, 1e-6 * energy); // -3.9e-8 when written
    EXPECT_NEAR(f.lagrange, -f.strain_energy, 1e-6 * energy);
    EXPECT_NEAR(f.castigliano, -f.strain_energy, 1e-12 * energy);
    EXPECT_NEAR(f.reissner, f.lagrange, 1e-12 * energy);
  }

  // Without the curved representation the order is lost. Straight-sided cells through
  // vertices on the arcs (MappingQ1): the O(h^2) boundary error caps the displacement at
  // order 2 (the stress keeps order 2, which is also Q2's, with a larger constant: 1.40e-3
  // against 1.05e-3 at L = 2 when this was written). The base mesh's polygon (no manifolds)
  // does not converge at all (3 % stress error at every level).
  TEST(AxisymmetricFemOutline, SphereWithoutCurvedCellsLosesTheOrder)
  {
    const axisym::Problem p = outline_problem(sphere_json.c_str());
    const ThickSphere exact;
    using Geometry = FemOptions::OutlineGeometry;
    for (const Geometry g : {Geometry::straight_cells, Geometry::coarse_polygon})
      {
        std::vector<Errors> e;
        for (int level = 1; level <= 3; ++level)
          e.push_back(sphere_errors(p, exact, level, g));
        const char *name = g == Geometry::straight_cells ? "straight cells" : "coarse polygon";
        for (std::size_t k = 0; k < e.size(); ++k)
          std::cout << "sphere " << name << " L = " << k + 1 << ": stress " << e[k].stress
                    << ", displacement " << e[k].displacement << '\n';
        const double stress_rate = std::log2(e[1].stress / e[2].stress);
        const double u_rate = std::log2(e[1].displacement / e[2].displacement);
        std::cout << "rates " << name << " (L = 2 -> 3): stress " << stress_rate
                  << ", displacement " << u_rate << '\n';
        if (g == Geometry::straight_cells)
          {
            EXPECT_NEAR(u_rate, 2.0, rate_tolerance) << name;
            EXPECT_GT(e[1].stress, 1.2 * sphere_errors(p, exact, 2).stress) << name;
          }
        else
          {
            EXPECT_LT(stress_rate, 0.5) << name;
            EXPECT_LT(u_rate, 0.5) << name;
          }
      }
  }

  // Pressures on both arcs: the load on the outer arc uses the normal of the curved face.
  TEST(AxisymmetricFemOutline, OuterPressureOnAnArcUsesTheTrueNormal)
  {
    nlohmann::json j = nlohmann::json::parse(sphere_json);
    j["boundary"]["outer"] = {{"pressure", 4.0e6}};
    const axisym::Problem p = axisym::parse_problem(j);
    ThickSphere exact;
    exact.p_o = 4e6;
    const Errors coarse = sphere_errors(p, exact, 1), fine = sphere_errors(p, exact, 2);
    std::cout << "sphere p_i, p_o L = 1, 2: stress " << coarse.stress << ", " << fine.stress
              << ", displacement " << coarse.displacement << ", " << fine.displacement << '\n';
    EXPECT_GE(std::log2(coarse.stress / fine.stress), 1.8);
    EXPECT_GE(std::log2(coarse.displacement / fine.displacement), 2.7);
    EXPECT_LT(fine.stress, 2e-3);
  }

  // An inclined straight symmetry edge (the cone of the sector): u.n = 0 as one constraint
  // line per node.
  TEST(AxisymmetricFemOutline, InclinedSymmetryEdgeMatchesTheSphere)
  {
    const axisym::Problem p = outline_problem(sphere_sector_json.c_str());
    const ThickSphere exact;
    const Errors coarse = sphere_errors(p, exact, 1), fine = sphere_errors(p, exact, 2);
    std::cout << "sphere sector L = 1, 2: stress " << coarse.stress << ", " << fine.stress
              << ", displacement " << coarse.displacement << ", " << fine.displacement << '\n';
    EXPECT_GE(std::log2(coarse.stress / fine.stress), 1.8);
    EXPECT_GE(std::log2(coarse.displacement / fine.displacement), 2.7);
    EXPECT_LT(fine.stress, 2e-3);
  }

  // Flat corners: gmsh's recombination of the quarter disk (solid sphere section) at the
  // default 4 cells on the shortest edge leaves one quad with two faces on the outer arc, a
  // corner of 180 degrees once the arc is curved (with 5 it does not); a ring of circular
  // section gets one where its two arcs join smoothly.
  TEST(AxisymmetricFemOutline, FlatBoundaryCornersOfTheBaseMeshAreAvoided)
  {
    const axisym::Problem disk = outline_problem(R"({
      "geometry": {"outline": [
        {"start": [0.0, 0.0]},
        {"line_to": [0.1, 0.0], "part": "equator"},
        {"arc_to": [0.0, 0.1], "center": [0.0, 0.0], "part": "outer"},
        {"line_to": [0.0, 0.0], "part": "axis"}]},
      "boundary": {"equator": {"symmetry": true}, "outer": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
    // The generator makes the base mesh again with one more cell on the shortest edge while
    // a flat corner remains: the disk (one at 4 cells) and a ring whose two arcs join
    // smoothly at the top (one at 4 cells, at the join) come out without.
    const axisym::Problem ring = outline_problem(R"({
      "geometry": {"outline": [
        {"start": [0.11, 0.0]},
        {"line_to": [0.19, 0.0], "part": "equator"},
        {"arc_to": [0.15, 0.04], "center": [0.15, 0.0], "part": "outer"},
        {"arc_to": [0.11, 0.0], "center": [0.15, 0.0], "part": "inner"}]},
      "boundary": {"equator": {"symmetry": true}, "outer": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
    for (const axisym::Problem *p : {&disk, &ring})
      {
        const FemResult r = solve(*p, quiet(2, 0));
        ASSERT_TRUE(r.success) << r.message;
        EXPECT_EQ(r.base_mesh_flat_corners, 0u);
      }
    for (const char *json : {solid_cylinder_json, sphere_json.c_str(), sphere_sector_json.c_str()})
      EXPECT_EQ(solve(outline_problem(json), quiet(2, 0)).base_mesh_flat_corners, 0u);
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

  // Grading toward a singular vertex (FemOptions::grade_toward_vertices): the stepped ring's
  // 270-degree vertex (lambda = 0.5445). Reference: the energy's Richardson limit of uniform
  // refinement, L = 3, 4, 5 (-0.42827312, -0.42829412, -0.42830399 J/rad at the observed
  // order 1.09 = 2 lambda: -0.4283127). Uniform L = 2 is 2.0e-4 from it; graded L = 2 (95 684
  // DoFs) 5.3e-8 (4.3e-7 with the earlier geometric grading at 28 298 DoFs; the graded
  // levels' own limit is -0.4283127263).
  TEST(AxisymmetricFemOutline, GradingTowardASingularVertexRecoversTheEnergy)
  {
    const axisym::Problem p = axisym::parse_problem(axisym::testing::stepped_ring());
    const double limit = -0.4283127;
    FemOptions o;
    o.degree = 2;
    o.refinements = 2;
    o.progress = false;
    const FemResult graded = solve(p, o);
    ASSERT_TRUE(graded.success) << graded.message;
    ASSERT_EQ(graded.graded_vertices.size(), 1u);
    EXPECT_NEAR(graded.graded_vertices[0][0], 0.15, 1e-12);
    EXPECT_GT(graded.graded_vertices[0][3], 10.0);
    EXPECT_LT(std::abs(graded.functionals.reissner / limit - 1.0), 2e-6);
    o.grade_toward_vertices = false;
    const FemResult uniform = solve(p, o);
    ASSERT_TRUE(uniform.success) << uniform.message;
    EXPECT_TRUE(uniform.graded_vertices.empty());
    EXPECT_GT(std::abs(uniform.functionals.reissner / limit - 1.0), 1e-4);
  }

  // The radical grading's point (FemOptions::grade_toward_vertices): at a singular vertex the
  // energy converges at the order of a smooth field, h^4 per level with Q2, not h^(2 lambda).
  // The stepped ring at L = 0, 1, 2 (8 176, 27 092, 95 684 DoFs): the energy changes by
  // 5.2e-7 and 4.1e-8 J/rad, a ratio of 12.6 (order 3.66). With the earlier geometric grading
  // (the cells within two diameters of the vertex halved, a shell of cells of the level's size
  // a few cells away) the same levels (9 678, 14 214, 28 298 DoFs) gave 7.2, and the ratio fell
  // to 2.9 further on (order 1.52 at L = 2, 3, 4).
  TEST(AxisymmetricFemOutline, GradingTowardASingularVertexConvergesAtTheSmoothOrder)
  {
    const axisym::Problem p = axisym::parse_problem(axisym::testing::stepped_ring());
    double phi[3];
    for (int level = 0; level < 3; ++level)
      {
        const FemResult r = solve(p, quiet(2, level));
        ASSERT_TRUE(r.success) << r.message;
        phi[level] = r.functionals.reissner;
      }
    const double ratio = (phi[1] - phi[0]) / (phi[2] - phi[1]);
    EXPECT_GT(ratio, 10.0) << "observed order " << std::log2(ratio);
  }

  // Grading toward a traction jump (axisym::traction_jump_vertices, as lambda = 1): the
  // pressure band (verification/problems/pressure_band_ring.json: 10 MPa on the lower half of
  // the bore). Reference: the Richardson limit -18.6658441 J/rad, from the uniform levels L =
  // 2, 3, 4 (observed order 1.99: -18.66584417) and from the graded ones (order 3.64:
  // -18.66584409), measured. Graded L = 2 (31 046 DoFs) is 5.4e-8 from it (3.4e-7 with the
  // earlier geometric grading at 13 756 DoFs), uniform L = 2 2.8e-5.
  TEST(AxisymmetricFemOutline, GradingTowardATractionJumpRecoversTheEnergy)
  {
    const axisym::Problem p = axisym::parse_problem(axisym::testing::pressure_band());
    const double limit = -18.6658441;
    FemOptions o = quiet(2, 2);
    const FemResult graded = solve(p, o);
    ASSERT_TRUE(graded.success) << graded.message;
    ASSERT_EQ(graded.graded_vertices.size(), 1u);
    EXPECT_NEAR(graded.graded_vertices[0][0], 0.5, 1e-12);
    EXPECT_NEAR(graded.graded_vertices[0][1], 0.25, 1e-12);
    EXPECT_EQ(graded.graded_vertices[0][2], 1.0);
    EXPECT_LT(std::abs(graded.functionals.reissner / limit - 1.0), 1e-6);
    o.grade_toward_vertices = false;
    const FemResult uniform = solve(p, o);
    ASSERT_TRUE(uniform.success) << uniform.message;
    EXPECT_GT(std::abs(uniform.functionals.reissner / limit - 1.0), 1e-5);
  }

  // Grading toward a resonant vertex (axisym::resonant_vertices, as lambda = 1): the ring
  // [0.8, 1.2] x [0, 0.4] m on the symmetry plane z = 0 under T = 100 z K
  // (verification/problems/heated_ring_axial_gradient.json), whose stress has a rho log rho
  // term at (0.8, 0) and (1.2, 0). Reference for sigma_zz(0.8, 0): the RFM with the resonant
  // vertices' log columns (rfm/spaces/resonant_vertex.h), -25.1121 MPa at p = 20 (-25.1095 at
  // p = 16, indicator 4.6e-10 at p = 20), measured. Graded L = 2 reads -25.1137 (6.4e-5 off;
  // -25.1086 with the earlier geometric grading), uniform L = 2 -24.675 (1.7e-2 off).
  TEST(AxisymmetricFemOutline, GradingTowardAResonantVertexRecoversItsStress)
  {
    const axisym::Problem p = axisym::parse_problem(nlohmann::json::parse(R"({
      "geometry": {"outline": [{"start": [0.8, 0.0]}, {"line_to": [1.2, 0.0], "part": "mid"},
        {"line_to": [1.2, 0.4], "part": "outer"}, {"line_to": [0.8, 0.4], "part": "top"},
        {"line_to": [0.8, 0.0], "part": "bore"}]},
      "boundary": {"mid": {"symmetry": true}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3, "thermal_expansion": 1.2e-5},
      "loading": {"temperature": {"field": [0.0, 0.0, 100.0]}},
      "samples": [[0.8, 0.0]]})"));
    const double reference = -25.1121e6;
    FemOptions o = quiet(2, 2);
    const FemResult graded = solve(p, o);
    ASSERT_TRUE(graded.success) << graded.message;
    ASSERT_EQ(graded.graded_vertices.size(), 2u);
    EXPECT_EQ(graded.graded_vertices[0][2], 1.0);
    EXPECT_LT(std::abs(graded.samples.at(0).sigma[1] / reference - 1.0), 5e-4);
    o.grade_toward_vertices = false;
    const FemResult uniform = solve(p, o);
    ASSERT_TRUE(uniform.success) << uniform.message;
    EXPECT_GT(std::abs(uniform.samples.at(0).sigma[1] / reference - 1.0), 1e-3);
  }

  // Adaptive refinement (FemOptions::adaptive, issue 25 item 1) from the stepped ring's base
  // mesh, without the a-priori grading: Kelly's estimate finds the vertex. At the tolerance 1e-6
  // it stops at 16 570 DoFs, 2.2e-7 from the uniform meshes' limit above (measured), where
  // uniform L = 2 (16 130 DoFs) is 2.0e-4 from it and each further level (4 times the DoFs)
  // gains a factor 2.1 only.
  TEST(AxisymmetricFemOutline, AdaptiveRefinementFindsTheSingularVertex)
  {
    const axisym::Problem p = axisym::parse_problem(axisym::testing::stepped_ring());
    const double limit = -0.4283127;
    FemOptions o = quiet(2, 0);
    o.adaptive = true;
    o.adaptive_tolerance = 1e-6;
    const FemResult r = solve(p, o);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.graded_vertices.empty()) << "adaptive: no a-priori grading";
    ASSERT_GE(r.adaptive_cycles.size(), 5u);
    for (std::size_t k = 1; k < r.adaptive_cycles.size(); ++k)
      EXPECT_GT(r.adaptive_cycles[k].n_dofs, r.adaptive_cycles[k - 1].n_dofs);
    EXPECT_EQ(r.adaptive_cycles.back().n_dofs, r.n_dofs);
    EXPECT_NE(r.adaptive_stop.find("below the tolerance"), std::string::npos) << r.adaptive_stop;
    EXPECT_LT(std::abs(r.functionals.reissner / limit - 1.0), 1e-6);
    EXPECT_LT(r.n_dofs, 40000u);
    // The first cycles' estimate falls (the vertex's cells are the ones refined).
    EXPECT_LT(r.adaptive_cycles.back().estimate, 0.1 * r.adaptive_cycles.front().estimate);
  }

  // Goal-oriented refinement (FemOptions::AdaptiveGoal::samples) for a sample stress: the
  // filleted groove's root (verification/problems/filleted_groove_shaft_tension.json).
  // Reference: Richardson's limit of uniform refinement L = 1, 2, 3 (K_t = 1.907162, 1.906155,
  // 1.905872 at 83 k, 330 k and 1.32 M DoFs; order 1.83): 1.905761. On the same budget of 23 000
  // DoFs (from 20 934 at L = 0), refinement for the root's stress gets K_t within 1e-5 of it
  // (measured 1.905777 at 22 986 DoFs; 1.905771 at 44 k with the tolerance 1e-4 and no DoF
  // limit), refinement for the energy 7.3e-4 off (1.907155 at 22 920 DoFs).
  TEST(AxisymmetricFemOutline, GoalOrientedRefinementResolvesASampleStress)
  {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "two runs of about 20 cycles on 21-23 k DoFs: too long under the sanitizers; "
                    "the Release run checks it";
#endif
    const axisym::Problem p = axisym::parse_problem(nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.0, 0.0]}, {"line_to": [0.04, 0.0], "part": "mid_plane"},
        {"arc_to": [0.0475, 0.012990381056766580], "center": [0.055, 0.0], "part": "groove"},
        {"arc_to": [0.05, 0.017320508075688773], "center": [0.045, 0.017320508075688773], "part": "fillet"},
        {"line_to": [0.05, 0.075], "part": "surface"}, {"line_to": [0.0, 0.075], "part": "end"},
        {"line_to": [0.0, 0.0], "part": "axis"}]},
      "boundary": {"mid_plane": {"symmetry": true}, "end": {"traction": [0.0, 1.0e7]}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "samples": [[0.04, 0.0]]})"));
    const double net = 1e7 * 0.05 * 0.05 / (0.04 * 0.04), reference = 1.905761;
    FemOptions o = quiet(2, 0);
    o.adaptive = true;
    o.adaptive_tolerance = 1e-4;
    o.adaptive_max_dofs = 23000;
    o.adaptive_goal = FemOptions::AdaptiveGoal::samples;
    const FemResult goal = solve(p, o);
    ASSERT_TRUE(goal.success) << goal.message;
    const double k_goal = goal.samples.at(0).sigma[axisym::zz] / net;
    EXPECT_NEAR(k_goal, reference, 5e-5 * reference) << goal.n_dofs << " dofs";
    o.adaptive_goal = FemOptions::AdaptiveGoal::energy;
    const FemResult energy = solve(p, o);
    ASSERT_TRUE(energy.success) << energy.message;
    const double k_energy = energy.samples.at(0).sigma[axisym::zz] / net;
    std::printf("K_t: goal %.7f (%lu dofs), energy %.7f (%lu dofs)\n", k_goal, goal.n_dofs, k_energy, energy.n_dofs);
    EXPECT_GT(std::abs(k_energy - reference), 10.0 * std::abs(k_goal - reference));
  }
} // namespace fem
