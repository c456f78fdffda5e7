// The wedge's exponents against published values, and every mode an elastic field that meets
// both face conditions (wedge_modes.h).
#include "problem/wedge_modes.h"

#include "problem/problem.h"
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace axisym
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    constexpr double nu = 0.3;
    using cd = std::complex<double>;

    std::vector<cd> exponents(const std::vector<WedgeMode> &modes)
    {
      std::vector<cd> out;
      for (const WedgeMode &m : modes)
        out.push_back(m.lambda);
      return out;
    }

    // Equilibrium, Hooke's law (plane strain, mu = 1) by central differences of the fields,
    // and the two faces' conditions, for every mode of the wedge.
    void expect_elastic_modes(const Wedge &w, const WedgeFace minus, const WedgeFace plus,
                              const std::vector<WedgeMode> &modes)
    {
      const double a = w.half_angle(), lame = 2 * nu / (1 - 2 * nu);
      for (const WedgeMode &m : modes)
        {
          // Inside: rho = 0.7, a few angles.
          for (const double t : {-0.8 * a, -0.3 * a, 0.1 * a, 0.6 * a, 0.95 * a})
            {
              const double rho = 0.7, h = 1e-5;
              const WedgeFieldValues v = w.evaluate(m, rho, t);
              const WedgeFieldValues rp = w.evaluate(m, rho + h, t), rm = w.evaluate(m, rho - h, t);
              const WedgeFieldValues tp = w.evaluate(m, rho, t + h), tm = w.evaluate(m, rho, t - h);
              const double scale = std::abs(v.s_rr) + std::abs(v.s_tt) + std::abs(v.s_rt);
              // e_rr = du_r/drho, e_tt = (u_r + du_t/dtheta) / rho, g = du_r/dtheta / rho + du_t/drho - u_t / rho.
              const cd e_rr = (rp.u_r - rm.u_r) / (2 * h);
              const cd e_tt = (v.u_r + (tp.u_t - tm.u_t) / (2 * h)) / rho;
              const cd g = (tp.u_r - tm.u_r) / (2 * h) / rho + (rp.u_t - rm.u_t) / (2 * h) - v.u_t / rho;
              EXPECT_LT(std::abs(v.s_rr - (lame * (e_rr + e_tt) + 2.0 * e_rr)), 1e-7 * scale) << m.lambda;
              EXPECT_LT(std::abs(v.s_tt - (lame * (e_rr + e_tt) + 2.0 * e_tt)), 1e-7 * scale) << m.lambda;
              EXPECT_LT(std::abs(v.s_rt - g), 1e-7 * scale) << m.lambda;
              const cd eq_r = (rp.s_rr - rm.s_rr) / (2 * h) + (tp.s_rt - tm.s_rt) / (2 * h) / rho +
                              (v.s_rr - v.s_tt) / rho;
              const cd eq_t = (rp.s_rt - rm.s_rt) / (2 * h) + (tp.s_tt - tm.s_tt) / (2 * h) / rho +
                              2.0 * v.s_rt / rho;
              EXPECT_LT(std::abs(eq_r), 1e-7 * scale / rho) << m.lambda;
              EXPECT_LT(std::abs(eq_t), 1e-7 * scale / rho) << m.lambda;
            }
          // The faces, to rounding.
          for (const auto &[t, face] : {std::pair{-a, minus}, std::pair{a, plus}})
            {
              const WedgeFieldValues v = w.evaluate(m, 0.7, t);
              const WedgeFieldValues in = w.evaluate(m, 0.7, 0.5 * t);
              const double s = std::abs(in.s_rr) + std::abs(in.s_tt) + std::abs(in.s_rt);
              const double u = std::abs(in.u_r) + std::abs(in.u_t);
              switch (face)
                {
                  case WedgeFace::free:
                    EXPECT_LT(std::abs(v.s_tt) + std::abs(v.s_rt), 1e-9 * s) << m.lambda;
                    break;
                  case WedgeFace::clamped:
                    EXPECT_LT(std::abs(v.u_r) + std::abs(v.u_t), 1e-9 * u) << m.lambda;
                    break;
                  case WedgeFace::symmetry:
                    EXPECT_LT(std::abs(v.u_t), 1e-9 * u) << m.lambda;
                    EXPECT_LT(std::abs(v.s_rt), 1e-9 * s) << m.lambda;
                    break;
                }
            }
        }
    }
  } // namespace

  // Free-free at 270 degrees (the L-shaped re-entrant corner): Williams' 0.5444837
  // (symmetric) and 0.9085292 (antisymmetric), each simple.
  TEST(WedgeModes, FreeFreeReentrantCornerHasWilliamsExponents)
  {
    const Wedge w(1.5 * pi, WedgeFace::free, WedgeFace::free, nu);
    const std::vector<WedgeMode> m = w.modes(1.0);
    ASSERT_EQ(m.size(), 2u);
    EXPECT_NEAR(m[0].lambda.real(), 0.5444837, 1e-7);
    EXPECT_NEAR(m[1].lambda.real(), 0.9085292, 1e-7);
    EXPECT_EQ(m[0].lambda.imag(), 0.0);
    expect_elastic_modes(w, WedgeFace::free, WedgeFace::free, w.modes(3.0));
  }

  // The crack (free-free at 360 degrees): lambda = 1/2 twice (modes I and II), then 3/2 twice.
  TEST(WedgeModes, CrackHasTwoModesAtOneHalf)
  {
    const Wedge w(2 * pi, WedgeFace::free, WedgeFace::free, nu);
    const std::vector<WedgeMode> m = w.modes(1.6);
    ASSERT_EQ(m.size(), 4u);
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(std::abs(m[k].lambda - (k < 2 ? 0.5 : 1.5)), 0.0, 1e-7);
    expect_elastic_modes(w, WedgeFace::free, WedgeFace::free, m);
  }

  // Clamped-free at 180 degrees (the bonded rigid punch's edge): 1/2 + i ln(kappa) / (2 pi),
  // oscillatory (its conjugate is the same real fields).
  TEST(WedgeModes, BondedPunchEdgeIsOscillatory)
  {
    const Wedge w(pi, WedgeFace::clamped, WedgeFace::free, nu);
    const std::vector<WedgeMode> m = w.modes(1.0);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_NEAR(m[0].lambda.real(), 0.5, 1e-9);
    EXPECT_NEAR(m[0].lambda.imag(), std::log(3 - 4 * nu) / (2 * pi), 1e-9);
    expect_elastic_modes(w, WedgeFace::clamped, WedgeFace::free, w.modes(2.6));
  }

  // The contact edge (a die zone beside a free face on a straight part, DESIGN.md 4.4): the
  // half-integers 1/2, 3/2, 5/2 of the edge modes (edge_modes.h), each simple.
  TEST(WedgeModes, ContactEdgeHasTheEdgeModesExponents)
  {
    const Wedge w(pi, WedgeFace::symmetry, WedgeFace::free, nu);
    const std::vector<cd> l = exponents(w.modes(2.6));
    ASSERT_EQ(l.size(), 3u);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(std::abs(l[k] - (0.5 + k)), 0.0, 1e-9);
    expect_elastic_modes(w, WedgeFace::symmetry, WedgeFace::free, w.modes(2.6));
  }

  // A straight free face and a free right angle have no singular term (no exponent below 1).
  // Free-free and clamped-clamped wedges against the scalar equations of DESIGN.md 4.5,
  // sin(2 lambda alpha) = +- lambda sin(2 alpha) (free-free) and the same divided by kappa
  // (clamped-clamped), solved here on their own: every root of the 4 x 4 determinant below 2
  // is a root of one of them, and at 193 degrees (issue 24's mild re-entrant corner) the
  // free-free exponent is 0.8739 (DESIGN.md: "about 0.88"); clamped-clamped at 270 degrees
  // gives 0.595156 and 0.759042.
  TEST(WedgeModes, SymmetricFacesFollowTheirScalarEquations)
  {
    EXPECT_TRUE(Wedge(pi, WedgeFace::free, WedgeFace::free, nu).modes(0.99).empty());
    EXPECT_TRUE(Wedge(0.5 * pi, WedgeFace::free, WedgeFace::free, nu).modes(0.99).empty());
    const double kappa = 3 - 4 * nu;
    for (const double degrees : {193.0, 230.0, 270.0, 330.0})
      for (const WedgeFace face : {WedgeFace::free, WedgeFace::clamped})
        {
          const double alpha = 0.5 * degrees * pi / 180;
          const double k = face == WedgeFace::free ? 1.0 : 1.0 / kappa;
          const Wedge w(2 * alpha, face, face, nu);
          const std::vector<WedgeMode> m = w.modes(2.0);
          ASSERT_FALSE(m.empty()) << degrees;
          for (const WedgeMode &mode : m)
            {
              const cd l = mode.lambda;
              const double residual = std::min(std::abs(std::sin(2.0 * l * alpha) - k * l * std::sin(2 * alpha)),
                                               std::abs(std::sin(2.0 * l * alpha) + k * l * std::sin(2 * alpha)));
              EXPECT_LT(residual, 1e-9) << degrees << " degrees, lambda = " << l;
            }
          // The scalar equations' real roots in (0, 1) by bisection, independently: the same.
          std::vector<double> scalar;
          for (const double sign : {1.0, -1.0})
            {
              auto g = [&](double x) { return std::sin(2 * x * alpha) - sign * k * x * std::sin(2 * alpha); };
              for (double x = 1e-3; x < 0.999; x += 1e-3)
                if (g(x) * g(x + 1e-3) < 0)
                  {
                    double lo = x, hi = x + 1e-3;
                    for (int it = 0; it < 60; ++it)
                      (g(lo) * g(0.5 * (lo + hi)) <= 0 ? hi : lo) = 0.5 * (lo + hi);
                    scalar.push_back(0.5 * (lo + hi));
                  }
            }
          std::sort(scalar.begin(), scalar.end());
          std::vector<double> found;
          for (const WedgeMode &mode : m)
            if (mode.lambda.imag() == 0.0 && mode.lambda.real() < 0.999)
              found.push_back(mode.lambda.real());
          ASSERT_EQ(found.size(), scalar.size()) << degrees;
          for (std::size_t i = 0; i < found.size(); ++i)
            EXPECT_NEAR(found[i], scalar[i], 1e-9) << degrees;
          expect_elastic_modes(w, face, face, m);
        }
    EXPECT_NEAR(Wedge(193.0 * pi / 180, WedgeFace::free, WedgeFace::free, nu).modes(1.0).at(0).lambda.real(),
                0.8739, 1e-4);
  }

  TEST(WedgeModes, RejectsABadAngle)
  {
    EXPECT_THROW(Wedge(0.0, WedgeFace::free, WedgeFace::free, nu), std::invalid_argument);
    EXPECT_THROW(Wedge(7.0, WedgeFace::free, WedgeFace::free, nu), std::invalid_argument);
  }

  // The vertices of outlines: an L-shaped ring section (a rectangular step inward, one 270-
  // degree free-free corner), and a cylinder clamped
  // at its end (two clamped-free right angles; the axis' corners are left out).
  TEST(WedgeModes, FindsTheSingularVerticesOfAnOutline)
  {
    const Problem step = parse_problem(testing::stepped_ring());
    const std::vector<SingularVertex> v = singular_vertices(*step.body, nu);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_NEAR(v[0].at.r, 0.15, 1e-12);
    EXPECT_NEAR(v[0].at.z, 0.1, 1e-12);
    EXPECT_NEAR(v[0].angle, 1.5 * pi, 1e-12);
    EXPECT_EQ(v[0].part_before, "step_side");
    ASSERT_EQ(v[0].modes.size(), 2u);
    EXPECT_NEAR(v[0].modes[0].lambda.real(), 0.5444837, 1e-7);
    const Problem clamped = parse_problem(nlohmann::json::parse(R"({
      "geometry": {"outline": [{"start": [0.0, 0.0]}, {"line_to": [0.05, 0.0], "part": "base"},
                               {"line_to": [0.05, 0.2], "part": "side"}, {"line_to": [0.0, 0.2], "part": "end"},
                               {"line_to": [0.0, 0.0], "part": "axis"}]},
      "boundary": {"base": {"displacement": [0.0, 0.0]}, "end": {"traction": [0.0, 1.0e6]}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})"));
    const std::vector<SingularVertex> c = singular_vertices(*clamped.body, nu);
    ASSERT_EQ(c.size(), 1u); // the clamped base meets the free side; the loaded end's corner is smooth
    EXPECT_NEAR(c[0].at.r, 0.05, 1e-12);
    EXPECT_NEAR(c[0].at.z, 0.0, 1e-12);
    EXPECT_NEAR(c[0].angle, 0.5 * pi, 1e-12);
    const std::vector<WedgeMode> direct = Wedge(0.5 * pi, WedgeFace::clamped, WedgeFace::free, nu).modes(0.999);
    ASSERT_EQ(c[0].modes.size(), direct.size());
    EXPECT_EQ(c[0].modes[0].lambda, direct[0].lambda);
    EXPECT_LT(c[0].modes[0].lambda.real(), 1.0);
  }

  // Traction jumps: the pressure band (10 MPa on the lower half of a straight bore) jumps where
  // it ends, at 180 degrees; at its right-angled corners (pressure or free against symmetry,
  // free against free) nothing jumps. A uniaxial traction on an end face meets the free side at
  // 90 degrees with the constant stress sigma_zz = t (no jump); a shear traction there cannot
  // be met (sigma_rz would have to be t on the end and 0 on the side).
  TEST(WedgeModes, FindsTheVerticesWhereATractionJumps)
  {
    const Problem band = parse_problem(testing::pressure_band());
    const std::vector<Point> j = traction_jump_vertices(*band.body);
    ASSERT_EQ(j.size(), 1u);
    EXPECT_NEAR(j[0].r, 0.5, 1e-12);
    EXPECT_NEAR(j[0].z, 0.25, 1e-12);
    // Issue 24's hub: the inner arc's pressure ends at the free bore (133.4 degrees, an arc and
    // a line); its other vertices are free against free or meet a symmetry line.
    const Problem hub = parse_problem(testing::tapered_hub());
    const std::vector<Point> h = traction_jump_vertices(*hub.body);
    ASSERT_EQ(h.size(), 1u);
    EXPECT_NEAR(h[0].r, 0.55, 1e-12);
    EXPECT_NEAR(h[0].z, 0.5809475019311126, 1e-12);
    auto end_loaded = [](const double t_r, const double t_z) {
      nlohmann::json p = nlohmann::json::parse(R"({
        "geometry": {"outline": [{"start": [0.0, 0.0]}, {"line_to": [0.05, 0.0], "part": "base"},
                                 {"line_to": [0.05, 0.2], "part": "side"}, {"line_to": [0.0, 0.2], "part": "end"},
                                 {"line_to": [0.0, 0.0], "part": "axis"}]},
        "boundary": {"base": {"symmetry": true}},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
      p["boundary"]["end"]["traction"] = {t_r, t_z};
      return parse_problem(p);
    };
    EXPECT_TRUE(traction_jump_vertices(*end_loaded(0.0, 1.0e6).body).empty());
    const std::vector<Point> shear = traction_jump_vertices(*end_loaded(1.0e6, 0.0).body);
    ASSERT_EQ(shear.size(), 1u);
    EXPECT_NEAR(shear[0].r, 0.05, 1e-12);
    EXPECT_NEAR(shear[0].z, 0.2, 1e-12);
  }
} // namespace axisym

namespace axisym
{
  // Notch roots: the grooved shaft's groove (radius 0.01 m, 0.063 of the section's size)
  // meets the mid-plane at (0.04, 0) at 90 degrees; its lip (the groove against the free
  // surface) is no root. The hub's inner arc (radius 0.8 m, 0.46 of its size) and the thick
  // sphere's (0.35) are too large, and the hub's outer arc is convex.
  TEST(WedgeModes, FindsTheNotchRoots)
  {
    const Problem shaft = parse_problem(testing::grooved_shaft());
    const std::vector<NotchRoot> n = notch_roots(*shaft.body);
    ASSERT_EQ(n.size(), 1u);
    EXPECT_NEAR(n[0].at.r, 0.04, 1e-12);
    EXPECT_NEAR(n[0].at.z, 0.0, 1e-12);
    EXPECT_NEAR(n[0].angle, pi / 2, 1e-12);
    EXPECT_NEAR(n[0].radius, 0.01, 1e-12);
    EXPECT_TRUE(notch_roots(*parse_problem(testing::tapered_hub()).body).empty());
    EXPECT_TRUE(notch_roots(*parse_problem(testing::thick_sphere()).body).empty());
    // The groove turned into a bead (the same arc, convex: centre (0.05, 0) reached from
    // (0.06, 0) counter-clockwise): no root.
    nlohmann::json bead = testing::grooved_shaft();
    bead["geometry"]["outline"][1]["line_to"] = {0.06, 0.0};
    bead["geometry"]["outline"][2]["center"] = {0.05, 0.0};
    EXPECT_TRUE(notch_roots(*parse_problem(bead).body).empty());
  }

  // Rough vertices: on issue 24's hub the bore meets the pressed inner arc at 133.4 degrees,
  // two free faces in the wedge: its exponents solve the symmetric free-free equation
  // sin(lambda beta) + lambda sin(beta) = 0 (Williams), whose first root off the integers is
  // 1.9047 +- 0.3884 i (Newton on that closed form, outside this code). The stepped ring's
  // 270-degree vertex is singular, not rough, and its right-angled corners (free-free:
  // 2.74 +- 1.12 i; free against symmetry: integers) are smooth enough; so is the pressure
  // band's straight jump (a half plane).
  TEST(WedgeModes, FindsTheRoughVertices)
  {
    const Problem hub = parse_problem(testing::tapered_hub());
    const std::vector<SingularVertex> v = rough_vertices(*hub.body, nu);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_NEAR(v[0].at.r, 0.55, 1e-12);
    EXPECT_NEAR(v[0].at.z, 0.5809475019311126, 1e-12);
    EXPECT_EQ(v[0].part_before, "bore");
    EXPECT_EQ(v[0].part_after, "inner_arc");
    const double beta = v[0].angle;
    EXPECT_NEAR(beta * 180.0 / pi, 133.4325, 1e-3);
    ASSERT_EQ(v[0].modes.size(), 1u); // the conjugate pair, once
    const std::complex<double> lambda = v[0].modes[0].lambda;
    EXPECT_NEAR(lambda.real(), 1.90475, 1e-4);
    EXPECT_NEAR(std::abs(lambda.imag()), 0.38844, 1e-4);
    EXPECT_LT(std::abs(std::sin(lambda * beta) + lambda * std::sin(beta)), 1e-8);
    for (const SingularVertex &s : singular_vertices(*hub.body, nu))
      EXPECT_GT(std::hypot(s.at.r - v[0].at.r, s.at.z - v[0].at.z), 0.1);
    EXPECT_TRUE(rough_vertices(*parse_problem(testing::stepped_ring()).body, nu).empty());
    EXPECT_TRUE(rough_vertices(*parse_problem(testing::pressure_band()).body, nu).empty());
  }

  // Resonant vertices: issue 24's hub with its pressure kept (a traction part) and a body
  // load. Its symmetry lines z = 0 and z = 1.6 meet the arcs and the neck and bore at right
  // angles: T_z crosses them (four vertices), T_r runs along them (none); gravity is left out.
  TEST(WedgeModes, FindsTheResonantVertices)
  {
    auto hub = [](const double t_r, const double t_z, const double g) {
      nlohmann::json p = testing::tapered_hub();
      p["material"]["thermal_expansion"] = 1.2e-5;
      p["material"]["density"] = 7800.0;
      if (t_r != 0.0 || t_z != 0.0)
        p["loading"]["temperature"]["field"] = {0.0, t_r, t_z};
      if (g != 0.0)
        p["loading"]["gravity"] = g;
      return parse_problem(p);
    };
    const Problem heated = hub(100.0, 100.0, 0.0);
    const std::vector<ResonantSite> s = resonant_vertices(*heated.body, heated.body_loads);
    ASSERT_EQ(s.size(), 4u);
    const Point expected[4] = {{1.2, 0.0}, {0.85, 1.6}, {0.55, 1.6}, {0.8, 0.0}}; // outline order
    const char *symmetry[4] = {"mid", "top", "top", "mid"};
    const char *traction[4] = {"outer_arc", "neck", "bore", "inner_arc"};
    for (std::size_t k = 0; k < 4; ++k)
      {
        EXPECT_NEAR(s[k].at.r, expected[k].r, 1e-12);
        EXPECT_NEAR(s[k].at.z, expected[k].z, 1e-12);
        EXPECT_EQ(s[k].symmetry_part, symmetry[k]);
        EXPECT_EQ(s[k].traction_part, traction[k]);
      }
    const Problem along = hub(100.0, 0.0, 0.0);
    EXPECT_TRUE(resonant_vertices(*along.body, along.body_loads).empty());
    const Problem weight = hub(0.0, 0.0, 9.81); // left out (wedge_modes.h)
    EXPECT_TRUE(resonant_vertices(*weight.body, weight.body_loads).empty());
    const Problem pressure_only = parse_problem(testing::tapered_hub());
    EXPECT_TRUE(resonant_vertices(*pressure_only.body, pressure_only.body_loads).empty());
  }
} // namespace axisym
