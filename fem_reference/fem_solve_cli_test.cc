// fem_solve through its command line (FEM_SOLVE is the path of the executable under test):
// an outline problem end to end (with and without body loads), --vtu into a directory that
// does not exist yet, the input errors of the outline path and of the loads (exit 2,
// message naming the field, nothing written), and the warning for a sample at a vertex.
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  using Outcome = axisym::testing::CommandOutcome;

  Outcome run(const std::string &args)
  {
    return axisym::testing::run_command(std::string(FEM_SOLVE) + " " + args);
  }

  // The thick sphere of DESIGN.md 7.1 (quarter annulus, inner pressure), level 1.
  nlohmann::json sphere()
  {
    nlohmann::json j = axisym::testing::thick_sphere();
    j["samples"] = {{0.15, 0.0}, {0.0, 0.15}};
    j["fem"] = {{"degree", 2}, {"refinements", 1}};
    return j;
  }

  // A fresh scratch directory per test.
  fs::path scratch(const std::string &name)
  {
    return axisym::testing::scratch_directory("fem_cli_", name);
  }

  std::string read(const fs::path &p)
  {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  TEST(FemSolveCli, OutlineProblemRunsEndToEndAndVtuCreatesItsDirectory)
  {
    const fs::path dir = scratch("outline");
    const fs::path in = dir / "sphere.json", out = dir / "result.json";
    const fs::path vtu = dir / "new" / "nested";
    std::ofstream(in) << sphere().dump();
    const Outcome o =
      run(in.string() + " --output " + out.string() + " --vtu " + vtu.string());
    ASSERT_EQ(o.status, 0) << o.err;

    const nlohmann::json r = nlohmann::json::parse(read(out));
    EXPECT_EQ(r.at("solver"), "fem");
    EXPECT_FALSE(r.contains("contact"));
    // One global refinement splits every quadrilateral of the gmsh base mesh into four.
    const int base_cells = r.at("discretization").at("base_cells").get<int>();
    EXPECT_GT(base_cells, 0);
    EXPECT_EQ(r.at("discretization").at("cells").get<int>(), 4 * base_cells);
    // Traction problem: Phi_L = Phi_C = Phi_R = -U_h < 0 (per radian, the section as given).
    const nlohmann::json &f = r.at("functionals");
    EXPECT_LT(f.at("lagrange").get<double>(), 0.0);
    EXPECT_NEAR(f.at("castigliano").get<double>(), f.at("lagrange").get<double>(),
                1e-4 * std::abs(f.at("lagrange").get<double>()));
    ASSERT_EQ(r.at("samples").size(), 2u);
    // On the equator u_z = 0 (symmetry); on the axis u_r = 0 (to the rounding of locating
    // the sample in its cell).
    const nlohmann::json &equator = r.at("samples")[0], &axis = r.at("samples")[1];
    EXPECT_GT(equator.at("u_r").get<double>(), 0.0);
    EXPECT_LT(std::abs(equator.at("u_z").get<double>()), 1e-12 * equator.at("u_r").get<double>());
    EXPECT_GT(axis.at("u_z").get<double>(), 0.0);
    EXPECT_LT(std::abs(axis.at("u_r").get<double>()), 1e-12 * axis.at("u_z").get<double>());
    // Both samples lie at R = 0.15: Lame's radial displacement of the thick sphere
    // (a = 0.1, b = 0.2, inner pressure p), u_R = ((1 - 2 nu) A R + (1 + nu) B / (2 R^2)) / E,
    // A = p a^3 / (b^3 - a^3), B = A b^3. Measured at this level (Q2, L = 1): 3.9e-5 (equator)
    // and 6.9e-5 (axis) relative.
    {
      const double a = 0.1, b = 0.2, p = 1e7, e = 2.1e11, nu = 0.3, x = 0.15;
      const double big_a = p * a * a * a / (b * b * b - a * a * a), big_b = big_a * b * b * b;
      const double u_exact = ((1 - 2 * nu) * big_a * x + (1 + nu) * big_b / (2 * x * x)) / e;
      EXPECT_NEAR(equator.at("u_r").get<double>(), u_exact, 3e-4 * u_exact);
      EXPECT_NEAR(axis.at("u_z").get<double>(), u_exact, 3e-4 * u_exact);
    }

    ASSERT_TRUE(fs::is_directory(vtu));
    const std::string text = read(vtu / "fem_solution.vtu");
    EXPECT_NE(text.find("Name=\"displacement\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"sigma_tt\""), std::string::npos);
    fs::remove_all(dir);
  }

  TEST(FemSolveCli, VtuPathThatIsAFileExitsWith2AndWritesNothing)
  {
    const fs::path dir = scratch("vtu_file");
    const fs::path in = dir / "sphere.json", out = dir / "result.json", file = dir / "a_file";
    std::ofstream(in) << sphere().dump();
    std::ofstream(file) << "x";
    const Outcome o = run(in.string() + " --output " + out.string() + " --vtu " + file.string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("--vtu"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(out));
    // Below a file the directory cannot be created either.
    const Outcome below = run(in.string() + " --output " + out.string() + " --vtu " +
                              (file / "sub").string());
    EXPECT_EQ(below.status, 2) << below.err;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(dir);
  }

  // A rotating hollow cylinder a = 0.1 < r < b = 0.2, 0 < z < 0.1, in plane strain (symmetry
  // on both ends), free inner and outer surfaces, omega = 300 rad/s, steel: the hoop stress
  // sigma_tt = k (a^2 + b^2 + a^2 b^2 / r^2 - (1 + 2 nu) / (3 - 2 nu) r^2),
  // k = (3 - 2 nu) density omega^2 / (8 (1 - nu)) (checked symbolically: equilibrium
  // d sigma_rr/dr + (sigma_rr - sigma_tt)/r + density omega^2 r = 0, sigma_rr(a) = sigma_rr(b)
  // = 0, all four stresses from u_r alone with u_z = 0; see axisymmetric_fem_body_loads_test.cc).
  nlohmann::json rotating_cylinder()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.1, 0.0]},
        {"line_to": [0.2, 0.0], "part": "bottom"},
        {"line_to": [0.2, 0.1], "part": "outer"},
        {"line_to": [0.1, 0.1], "part": "top"},
        {"line_to": [0.1, 0.0], "part": "inner"}]},
      "boundary": {"bottom": {"symmetry": true}, "top": {"symmetry": true}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3, "density": 7850},
      "loading": {"angular_velocity": 300.0},
      "samples": [[0.15, 0.05]],
      "fem": {"degree": 2, "refinements": 2}})");
  }

  TEST(FemSolveCli, RotatingCylinderRunsEndToEndWithTheClosedFormHoopStress)
  {
    const fs::path dir = scratch("rotating");
    const fs::path in = dir / "rotating.json", out = dir / "result.json";
    std::ofstream(in) << rotating_cylinder().dump();
    const Outcome o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_NE(o.err.find("angular_velocity"), std::string::npos) << o.err; // configuration

    const nlohmann::json r = nlohmann::json::parse(read(out));
    const double a = 0.1, b = 0.2, nu = 0.3, rho_omega2 = 7850.0 * 300.0 * 300.0, x = 0.15;
    const double k = (3 - 2 * nu) * rho_omega2 / (8 * (1 - nu));
    const double sigma_tt =
      k * (a * a + b * b + a * a * b * b / (x * x) - (1 + 2 * nu) / (3 - 2 * nu) * x * x);
    const double sigma_max = k * (a * a + b * b + b * b - (1 + 2 * nu) / (3 - 2 * nu) * a * a);
    ASSERT_EQ(r.at("samples").size(), 1u);
    const nlohmann::json &sample = r.at("samples")[0];
    EXPECT_NEAR(sample.at("sigma_tt").get<double>(), sigma_tt, 1e-4 * sigma_max);
    // u_z = 0 exactly in the closed form; on the unstructured mesh the discrete u_z is of the
    // size of the discretization error (-1.4e-13 m against u_r = 9.6e-6 m when written).
    EXPECT_NEAR(sample.at("u_z").get<double>(), 0.0, 1e-6 * sample.at("u_r").get<double>());
    // The body force does work: Phi_L = U_h - W(u_h) = -U_h (W = 2 U_h) < 0.
    const nlohmann::json &f = r.at("functionals");
    EXPECT_GT(f.at("body_force_work").get<double>(), 0.0);
    EXPECT_EQ(f.at("body_force_work").get<double>(), f.at("external_work").get<double>());
    EXPECT_NEAR(f.at("lagrange").get<double>(), -f.at("strain_energy").get<double>(),
                1e-8 * f.at("strain_energy").get<double>());
    // Both ends are supports: plane strain needs the axial force of sigma_zz = nu (sigma_rr +
    // sigma_tt), 2 pi int_a^b sigma_zz r dr = pi nu density omega^2 (b^4 - a^4) / 2 [N],
    // which the top end exerts on the body (pulling, +z) and the bottom end in -z; no radial
    // force on a symmetry plane. Measured: 5.2e-14 (bottom) and 1.9e-14 (top) of the closed
    // form; force_r exactly 0.
    ASSERT_EQ(r.at("reactions").size(), 2u);
    const double axial = M_PI * nu * rho_omega2 * (b * b * b * b - a * a * a * a) / 2;
    for (const nlohmann::json &reaction : r.at("reactions"))
      {
        const std::string part = reaction.at("part");
        ASSERT_TRUE(part == "bottom" || part == "top") << part;
        EXPECT_EQ(reaction.at("condition"), "symmetry");
        const double expected = part == "top" ? axial : -axial;
        EXPECT_NEAR(reaction.at("force_z").get<double>(), expected, 3e-13 * axial) << part;
        EXPECT_NEAR(reaction.at("force_r").get<double>(), 0.0, 1e-12 * axial) << part;
      }
    EXPECT_NE(r.at("reactions")[0].at("part"), r.at("reactions")[1].at("part"));
    fs::remove_all(dir);
  }

  // A load without its material constant, or a bad constant, is the parser's bad input: exit 2
  // naming the field, before any work (no result, no VTU directory).
  TEST(FemSolveCli, LoadWithoutOrWithABadMaterialConstantExitsWith2NamingTheField)
  {
    const fs::path dir = scratch("body_loads");
    const fs::path in = dir / "rotating.json", out = dir / "result.json";
    struct Case
    {
      nlohmann::json problem;
      std::string field;
    };
    std::vector<Case> cases;
    nlohmann::json j = rotating_cylinder();
    j["material"].erase("density");
    cases.push_back({j, "material.density"});
    j = rotating_cylinder();
    j["material"]["density"] = -7850;
    cases.push_back({j, "material.density"});
    j = rotating_cylinder();
    j["loading"] = {{"temperature", {{"field", {10.0, 0.0, 0.0}}}}};
    cases.push_back({j, "material.thermal_expansion"});
    j = rotating_cylinder();
    j["material"]["thermal_expansion"] = 1.2e-5;
    j["loading"] = {{"temperature", {{"field", {10.0, "hot", 0.0}}}}};
    cases.push_back({j, "loading.temperature.field[1]"});
    for (const Case &c : cases)
      {
        std::ofstream(in) << c.problem.dump();
        const Outcome o = run(in.string() + " --output " + out.string() + " --vtu " +
                              (dir / "vtu").string());
        EXPECT_EQ(o.status, 2) << c.field << ": " << o.err;
        EXPECT_NE(o.err.find(c.field), std::string::npos) << o.err;
        EXPECT_FALSE(fs::exists(out));
        EXPECT_FALSE(fs::exists(dir / "vtu"));
      }
    fs::remove_all(dir);
  }

  // Adaptive refinement from the command line (issue 25 item 1): the cycles in the result;
  // a bad fem.refinement is exit 2 naming the field, and so is a bad --adaptive-tolerance.
  TEST(FemSolveCli, AdaptiveRefinementWritesItsCyclesAndRejectsBadSettings)
  {
    const fs::path dir = scratch("adaptive");
    const fs::path in = dir / "rotating.json", out = dir / "result.json";
    std::ofstream(in) << rotating_cylinder().dump();
    {
      const Outcome o = run(in.string() + " --refinements 0 --adaptive --adaptive-tolerance 1e-4 --output " +
                            out.string());
      ASSERT_EQ(o.status, 0) << o.err;
      std::ifstream f(out);
      const nlohmann::json r = nlohmann::json::parse(f);
      const nlohmann::json &d = r.at("discretization");
      EXPECT_EQ(d.at("refinement_strategy"), "adaptive");
      const nlohmann::json &cycles = d.at("adaptive").at("cycles");
      ASSERT_GE(cycles.size(), 2u);
      EXPECT_EQ(cycles.back().at("dofs"), d.at("dofs"));
      for (std::size_t k = 1; k < cycles.size(); ++k)
        EXPECT_GT(cycles[k].at("dofs").get<long>(), cycles[k - 1].at("dofs").get<long>());
      EXPECT_NE(d.at("adaptive").at("stopped").get<std::string>().find("tolerance"), std::string::npos);
    }
    fs::remove(out);
    struct Case
    {
      nlohmann::json refinement;
      std::string field;
    };
    for (const Case &c : {Case{{{"strategy", "kelly"}}, "fem.refinement.strategy"},
                          Case{{{"tolerance", 1e-6}}, "fem.refinement.strategy"},
                          Case{{{"strategy", "adaptive"}, {"tolerance", 0.0}}, "fem.refinement.tolerance"},
                          Case{{{"strategy", "adaptive"}, {"max_dofs", 10}}, "fem.refinement.max_dofs"},
                          Case{{{"strategy", "adaptive"}, {"cells", 10}}, "fem.refinement.cells"},
                          Case{{{"strategy", "adaptive"}, {"goal", "stress"}}, "fem.refinement.goal"}})
      {
        nlohmann::json j = rotating_cylinder();
        j["fem"] = {{"refinement", c.refinement}};
        std::ofstream(in) << j.dump();
        const Outcome o = run(in.string() + " --output " + out.string());
        EXPECT_EQ(o.status, 2) << c.field << ": " << o.err;
        EXPECT_NE(o.err.find(c.field), std::string::npos) << o.err;
        EXPECT_FALSE(fs::exists(out));
      }
    std::ofstream(in) << rotating_cylinder().dump();
    const Outcome o = run(in.string() + " --adaptive --adaptive-tolerance 2 --output " + out.string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("--adaptive-tolerance"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(dir);
  }

  // The hollow-cylinder form's die with an outer pressure: the outer side is the die's part.
  TEST(FemSolveCli, HollowCylinderDieWithAnOuterPressureExitsWith2)
  {
    const fs::path dir = scratch("outer_pressure");
    const fs::path in = dir / "die.json";
    std::ofstream(in) << R"({
      "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "loading": {"inner_pressure": 0.0, "outer_pressure": 1.0e6},
      "die": {"indentation": 1.0e-6}})";
    const Outcome o = run(in.string() + " --refinements 0");
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("loading.outer_pressure"), std::string::npos) << o.err;
    fs::remove_all(dir);
  }
  // A sample at a vertex where the stress has no value warns, as rfm_solve's does
  // (problem/sample_checks.h): the stepped ring's 270-degree step corner and the pressure
  // band's end. Samples 1 cm off them do not.
  TEST(FemSolveCli, SampleAtASingularVertexOrATractionJumpWarns)
  {
    const fs::path dir = scratch("vertex_sample");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    const std::array<std::tuple<nlohmann::json, std::array<double, 2>, std::string>, 2> cases{
      {{axisym::testing::stepped_ring(), {0.15, 0.1}, "singular"},
       {axisym::testing::pressure_band(), {0.5, 0.25}, "traction_jump"}}};
    for (const auto &[problem, vertex, kind] : cases)
      {
        nlohmann::json j = problem;
        j["samples"] = {vertex, {vertex[0] + 0.01, vertex[1] + 0.01}};
        std::ofstream(in) << j.dump();
        const Outcome o = run(in.string() + " --refinements 0 --output " + out.string());
        ASSERT_EQ(o.status, 0) << o.err;
        const nlohmann::json r = nlohmann::json::parse(read(out));
        const nlohmann::json &d = r.at("diagnostics");
        EXPECT_EQ(d.at("status"), "warning") << kind;
        EXPECT_EQ(d.at("warnings")[0].at("check"), "samples_at_vertices") << kind;
        ASSERT_EQ(d.at("samples_at_vertices").size(), 1u) << kind;
        const nlohmann::json &s = d.at("samples_at_vertices")[0];
        EXPECT_EQ(s.at("kind"), kind);
        EXPECT_EQ(s.at("r").get<double>(), vertex[0]);
        EXPECT_EQ(s.at("z").get<double>(), vertex[1]);
        if (kind == "singular")
          {
            EXPECT_NEAR(s.at("exponent").get<double>(), 0.5444837, 1e-6);
          }
        EXPECT_NE(d.at("message").get<std::string>().find("the stress has no value there"), std::string::npos);
        EXPECT_NE(o.err.find("fem_solve: warning:"), std::string::npos) << o.err;
        // The samples are still written, both of them.
        ASSERT_EQ(r.at("samples").size(), 2u);
        if (kind == "singular")
          {
            // Why: one level finer, the vertex's value grows with the mesh's grading toward it
            // (measured: sigma_zz -427, -1107, -4675, -13841 MPa at L = 0 to 3), while the
            // sample 1 cm off holds (-2.086, -2.089, -2.088, -2.088 MPa).
            const Outcome finer = run(in.string() + " --refinements 1 --output " + out.string());
            ASSERT_EQ(finer.status, 0) << finer.err;
            const nlohmann::json f = nlohmann::json::parse(read(out)).at("samples");
            auto zz = [](const nlohmann::json &samples, const int k) {
              return samples[k].at("sigma_zz").get<double>();
            };
            EXPECT_GT(std::abs(zz(f, 0)), 1.5 * std::abs(zz(r.at("samples"), 0)));
            EXPECT_NEAR(zz(f, 1), zz(r.at("samples"), 1), 1e-2 * std::abs(zz(f, 1)));
          }

        j["samples"] = {{vertex[0] + 0.01, vertex[1] + 0.01}};
        std::ofstream(in) << j.dump();
        const Outcome off = run(in.string() + " --refinements 0 --output " + out.string());
        ASSERT_EQ(off.status, 0) << off.err;
        const nlohmann::json quiet = nlohmann::json::parse(read(out)).at("diagnostics");
        EXPECT_EQ(quiet.at("status"), "ok") << kind;
        EXPECT_FALSE(quiet.contains("samples_at_vertices"));
      }
    fs::remove_all(dir);
  }
  // The goal-oriented cycles leave out a sample at a vertex where the stress has no value:
  // with the stepped ring's 270-degree corner among the samples they used to chase it through
  // all 100 cycles (sigma_zz -9 to -7.4e5 MPa) and left the sample 1.4 cm away at -2.035 MPa,
  // 2.5 % off the graded meshes' -2.088 (L = 1 to 3: -2.089, -2.088, -2.088). Now they stop on
  // their tolerance with that sample within 0.1 % of it. With every sample at a vertex there
  // is no goal: exit 2, nothing written.
  TEST(FemSolveCli, AdaptiveGoalLeavesOutSamplesAtVertices)
  {
    const fs::path dir = scratch("goal_vertex");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    nlohmann::json j = axisym::testing::stepped_ring();
    j["samples"] = {{0.15, 0.1}, {0.16, 0.11}};
    std::ofstream(in) << j.dump();
    const std::string adaptive = " --refinements 0 --adaptive --adaptive-goal samples --adaptive-tolerance 1e-4";
    const Outcome o = run(in.string() + adaptive + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(read(out));
    const nlohmann::json &a = r.at("discretization").at("adaptive");
    EXPECT_NE(a.at("stopped").get<std::string>().find("below the tolerance"), std::string::npos) << a.at("stopped");
    EXPECT_NEAR(r.at("samples")[1].at("sigma_zz").get<double>(), -2.088e6, 1e-3 * 2.088e6);
    EXPECT_EQ(r.at("diagnostics").at("status"), "warning");

    fs::remove(out);
    j["samples"] = {{0.15, 0.1}};
    std::ofstream(in) << j.dump();
    const Outcome none = run(in.string() + adaptive + " --output " + out.string());
    EXPECT_EQ(none.status, 2) << none.err;
    EXPECT_NE(none.err.find("--adaptive-goal samples"), std::string::npos) << none.err;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(dir);
  }
} // namespace
