// Bad input through the command line of rfm_solve: every case must exit with status 2,
// say on stderr what is wrong (a fragment naming the field or the rule), and write
// nothing; a numerical failure exits 3 with the history written. RFM_SOLVE is the path of
// the executable under test.
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <tuple>

namespace
{
  namespace fs = std::filesystem;

  using Outcome = axisym::testing::CommandOutcome;

  Outcome run(const std::string &args)
  {
    return axisym::testing::run_command(std::string(RFM_SOLVE) + " " + args);
  }

  /// An empty directory for one test's files: <temp>/rfm_cli_<name>.
  fs::path scratch(const std::string &name)
  {
    const fs::path dir = fs::temp_directory_path() / ("rfm_cli_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
  }

  nlohmann::json valid()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "loading": {"inner_pressure": 1.0e7, "outer_pressure": 0.0},
      "rfm": {"degree": 2}
    })");
  }

  struct Case
  {
    std::string name;
    std::string text;      // problem file content
    std::string fragment;  // expected in the message
  };

  std::string with(const std::string &pointer, const nlohmann::json &value)
  {
    nlohmann::json j = valid();
    j[nlohmann::json::json_pointer(pointer)] = value;
    return j.dump();
  }
  std::string without(const std::string &key)
  {
    nlohmann::json j = valid();
    j.erase(key);
    return j.dump();
  }

  class BadInput : public ::testing::TestWithParam<Case>
  {};

  TEST_P(BadInput, ExitsWithStatus2NamingTheProblemAndWritesNothing)
  {
    const Case &c = GetParam();
    const fs::path dir = fs::temp_directory_path() / ("rfm_cli_" + c.name);
    fs::create_directories(dir);
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    fs::remove(out);
    std::ofstream(in) << c.text;
    const Outcome o = run(in.string() + " --output " + out.string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find(c.fragment), std::string::npos) << "stderr: " << o.err;
    EXPECT_FALSE(fs::exists(out));
  }

  const nlohmann::json die = {{"indentation", 1e-6}};

  // The thick sphere of DESIGN.md 7.1 in the outline form, changed at one JSON pointer.
  std::string sphere_with(const std::string &pointer, const nlohmann::json &value)
  {
    nlohmann::json j = axisym::testing::thick_sphere();
    j[nlohmann::json::json_pointer(pointer)] = value;
    return j.dump();
  }
  const nlohmann::json clockwise = nlohmann::json::parse(R"([
    {"start": [0.1, 0.0]}, {"arc_to": [0.0, 0.1], "center": [0.0, 0.0], "part": "inner"},
    {"line_to": [0.0, 0.2], "part": "axis"},
    {"arc_to": [0.2, 0.0], "center": [0.0, 0.0], "part": "outer"},
    {"line_to": [0.1, 0.0], "part": "equator"}])");

  INSTANTIATE_TEST_SUITE_P(
    Cases, BadInput,
    ::testing::Values(
      Case{"malformed_json", "{\"geometry\": ", "malformed JSON"},
      Case{"empty_file", "", "malformed JSON"},
      Case{"not_an_object", "[1, 2]", "must be a JSON object"},
      Case{"nan_literal", R"({"geometry": {"inner_radius": NaN}})", "malformed JSON"},
      Case{"unknown_top_key", with("/solver", "rfm"), "unknown key solver"},
      Case{"unknown_nested_key", with("/geometry/radius", 1.0), "geometry.radius"},
      Case{"missing_geometry", without("geometry"), "geometry"},
      Case{"missing_material", without("material"), "material"},
      Case{"missing_length", [] { auto j = valid(); j["geometry"].erase("length"); return j.dump(); }(),
           "geometry.length"},
      Case{"r1_zero", with("/geometry/inner_radius", 0.0), "geometry.inner_radius"},
      Case{"r1_negative", with("/geometry/inner_radius", -0.1), "geometry.inner_radius"},
      Case{"r1_ge_r2", with("/geometry/inner_radius", 0.25), "must exceed geometry.inner_radius"},
      Case{"length_zero", with("/geometry/length", 0.0), "geometry.length"},
      Case{"length_string", with("/geometry/length", "0.4"), "must be a number"},
      Case{"e_zero", with("/material/youngs_modulus", 0.0), "material.youngs_modulus"},
      Case{"e_negative", with("/material/youngs_modulus", -2e11), "material.youngs_modulus"},
      Case{"nu_half", with("/material/poisson_ratio", 0.5), "material.poisson_ratio"},
      Case{"nu_minus_one", with("/material/poisson_ratio", -1.0), "material.poisson_ratio"},
      Case{"nu_bool", with("/material/poisson_ratio", true), "must be a number"},
      Case{"huge_number", R"({"geometry": {"inner_radius": 1e999}})", "malformed JSON"},
      Case{"no_load", without("loading"), "needs at least one of"},
      Case{"pressure_string", with("/loading/inner_pressure", "10 MPa"), "loading.inner_pressure"},
      Case{"die_negative", with("/die", {{"indentation", -1e-6}}), "die.indentation"},
      Case{"die_too_deep", with("/die", {{"indentation", 5e-3}}), "small strain"},
      Case{"die_profile", with("/die", {{"indentation", 1e-6}, {"profile", "flat"}}), "die.profile"},
      Case{"contact_method", with("/contact", {{"method", "guess"}}), "contact.method"},
      Case{"edge_cutoff_one", with("/rfm", {{"edge_cutoff", 1.0}}), "rfm.edge_cutoff"},
      Case{"edge_cutoff_zero", with("/rfm", {{"edge_cutoff", 0.0}}), "rfm.edge_cutoff"},
      Case{"edge_modes_negative", with("/rfm", {{"edge_modes", -1}}), "rfm.edge_modes"},
      Case{"edge_modes_many", with("/rfm", {{"edge_modes", 5}}), "rfm.edge_modes"},
      Case{"edge_mode_degree_negative", with("/rfm", {{"edge_mode_degree", -1}}),
           "rfm.edge_mode_degree"},
      Case{"edge_mode_degree_large", with("/rfm", {{"edge_mode_degree", 7}}),
           "rfm.edge_mode_degree"},
      Case{"vertex_max_exponent_negative", with("/rfm", {{"vertex_max_exponent", -1.0}}),
           "rfm.vertex_max_exponent"},
      Case{"vertex_mode_degree_large", with("/rfm", {{"vertex_mode_degree", 7}}),
           "rfm.vertex_mode_degree"},
      Case{"vertex_cutoff_zero", with("/rfm", {{"vertex_cutoff", 0.0}}), "rfm.vertex_cutoff"},
      Case{"vertex_support_unknown", with("/rfm", {{"vertex_support", "global"}}), "rfm.vertex_support"},
      Case{"vertex_local_degree_large", with("/rfm", {{"vertex_local_degree", 25}}), "rfm.vertex_local_degree"},
      Case{"vertex_local_degree_ratio_low", with("/rfm", {{"vertex_local_degree_ratio", 0.2}}),
           "rfm.vertex_local_degree_ratio"},
      Case{"vertex_local_degree_ratio_high", with("/rfm", {{"vertex_local_degree_ratio", 1.6}}),
           "rfm.vertex_local_degree_ratio"},
      Case{"vertex_local_displacement_degree_large", with("/rfm", {{"vertex_local_displacement_degree", 13}}),
           "rfm.vertex_local_displacement_degree"},
      Case{"vertex_local_displacement_degree_low", with("/rfm", {{"vertex_local_displacement_degree", -2}}),
           "rfm.vertex_local_displacement_degree"},
      Case{"resonant_displacement_degree_large", with("/rfm", {{"resonant_displacement_degree", 5}}),
           "rfm.resonant_displacement_degree"},
      Case{"resonant_displacement_degree_low", with("/rfm", {{"resonant_displacement_degree", -2}}),
           "rfm.resonant_displacement_degree"},
      Case{"local_stress_degree_large", with("/rfm", {{"local_stress_degree", 13}}),
           "rfm.local_stress_degree"},
      Case{"local_stress_degree_low", with("/rfm", {{"local_stress_degree", -2}}),
           "rfm.local_stress_degree"},
      Case{"local_degree_low", with("/rfm", {{"local_degree", -2}}), "rfm.local_degree"},
      Case{"half_width_beyond", with("/contact", {{"method", "fixed"}, {"half_width", 0.3}}),
           "contact.half_width"},
      Case{"half_width_zero", with("/contact", {{"method", "fixed"}, {"half_width", 0.0}}),
           "contact.half_width"},
      Case{"sample_outside", with("/samples", {{0.05, 0.0}}), "samples[0]"},
      Case{"sample_beyond_end", with("/samples", {{0.15, 0.3}}), "samples[0]"},
      Case{"sample_not_pair", with("/samples", {{0.15}}), "samples[0]"},
      Case{"samples_not_array", with("/samples", 3), "samples"},
      Case{"degree_negative", with("/rfm/degree", -1), "rfm.degree"},
      Case{"degree_too_large", with("/rfm/degree", 1000), "rfm.degree"},
      Case{"degree_fraction", with("/rfm/degree", 2.5), "rfm.degree"},
      Case{"grading_ratio", with("/rfm/grading_ratio", 1.5), "rfm.grading_ratio"},
      Case{"ritz_bound_not_a_bool", with("/rfm/ritz_bound", 1), "rfm.ritz_bound"},
      Case{"notch_roots_not_a_bool", with("/rfm/notch_roots", "yes"), "rfm.notch_roots"},
      Case{"rough_vertices_not_a_bool", with("/rfm/rough_vertices", 1), "rfm.rough_vertices"},
      Case{"rough_vertices_unknown_word", with("/rfm/rough_vertices", "some"), "rfm.rough_vertices"},
      Case{"vertex_shadow_not_a_bool", with("/rfm/vertex_shadow", "yes"), "rfm.vertex_shadow"},
      Case{"jump_column_not_a_bool", with("/rfm/jump_column", 1), "rfm.jump_column"},
      Case{"vertex_inner_disc_not_a_bool", with("/rfm/vertex_inner_disc", 0), "rfm.vertex_inner_disc"},
      Case{"axis_coupling_not_a_bool", with("/rfm/axis_coupling", "no"), "rfm.axis_coupling"},
      Case{"vertex_disc_overlap_not_a_bool", with("/rfm/vertex_disc_overlap", "yes"), "rfm.vertex_disc_overlap"},
      Case{"z_degree_ratio_large", with("/rfm/z_degree_ratio", 5.0), "rfm.z_degree_ratio"},
      Case{"z_degree_ratio_beyond_48", with("/rfm", {{"degree", 20}, {"z_degree_ratio", 3.0}}),
           "rfm.z_degree_ratio"},
      Case{"fem_degree", with("/fem/degree", 9), "fem.degree"},
      Case{"outline_open", sphere_with("/geometry/outline/4/arc_to", {0.1, 0.01}),
           "geometry.outline"},
      Case{"outline_self_intersecting",
           sphere_with("/geometry/outline/1/line_to", {0.25, 0.0}), "geometry.outline"},
      Case{"outline_clockwise", sphere_with("/geometry/outline", clockwise), "counter-clockwise"},
      Case{"outline_r_negative", sphere_with("/geometry/outline/3/line_to", {-0.01, 0.1}),
           "geometry.outline"},
      Case{"outline_arc_off_circle", sphere_with("/geometry/outline/2/center", {0.0, 0.01}),
           "geometry.outline[2]"},
      Case{"outline_unknown_part", sphere_with("/boundary/hole", {{"pressure", 1.0}}),
           "boundary.hole"},
      Case{"outline_condition_on_axis", sphere_with("/boundary/axis", {{"pressure", 1.0}}),
           "boundary.axis"},
      Case{"outline_symmetry_on_arc", sphere_with("/boundary/outer", {{"symmetry", true}}),
           "boundary.outer.symmetry"},
      Case{"outline_sample_outside", sphere_with("/samples", {{0.05, 0.05}}), "samples[0]"},
      Case{"outline_load_without_density", sphere_with("/loading", {{"gravity", 9.81}}),
           "material.density"},
      Case{"outline_heat_without_expansion",
           sphere_with("/loading", {{"temperature", {{"field", {10.0, 0.0, 0.0}}}}}),
           "material.thermal_expansion"},
      Case{"outline_negative_density", sphere_with("/material/density", -7850.0),
           "material.density"},
      Case{"outline_temperature_not_a_number",
           sphere_with("/loading", nlohmann::json::parse(R"({"temperature": {"field": [1, "x", 0]}})")),
           "loading.temperature.field[1]"},
      Case{"outline_temperature_short",
           sphere_with("/loading", nlohmann::json::parse(R"({"temperature": {"field": [1, 2]}})")),
           "loading.temperature.field"},
      Case{"outline_inclined_symmetry_in_rfm",
           sphere_with("/geometry/outline", nlohmann::json::parse(R"([
             {"start": [0.1, 0.0]}, {"line_to": [0.2, 0.0], "part": "bottom"},
             {"line_to": [0.2, 0.1], "part": "side"}, {"line_to": [0.1, 0.05], "part": "equator"},
             {"line_to": [0.1, 0.0], "part": "inner"}])")),
           "symmetry edges along r or z"},
      Case{"degree_and_tolerance", with("/rfm", {{"degree", 4}, {"tolerance", 1e-8}}), "not both"},
      Case{"tolerance_too_small", with("/rfm", {{"tolerance", 1e-16}}), "rfm.tolerance"},
      Case{"tolerance_for_die", [] { auto j = valid(); j["die"] = {{"indentation", 1e-6}};
             j["rfm"] = {{"tolerance", 1e-6}}; return j.dump(); }(), "rfm.tolerance"},
      Case{"max_degree", with("/rfm", {{"max_degree", 1}}), "rfm.max_degree"},
      Case{"memory_too_large",
           with("/rfm", {{"degree", 40}, {"extra_gauss_points", 40}, {"n_cells_r", 64}, {"n_cells_z", 64}}),
           "GiB"}),
    [](const ::testing::TestParamInfo<Case> &info) { return info.param.name; });

  TEST(RfmSolveCli, MissingFileAndUnwritableOutput)
  {
    Outcome o = run("/nonexistent/problem.json");
    EXPECT_EQ(o.status, 2);
    EXPECT_NE(o.err.find("cannot be opened"), std::string::npos) << o.err;

    const fs::path dir = fs::temp_directory_path() / "rfm_cli_output";
    fs::create_directories(dir);
    const fs::path in = dir / "problem.json";
    std::ofstream(in) << valid().dump();
    o = run(in.string() + " --output /nonexistent/dir/result.json");
    EXPECT_EQ(o.status, 2);
    EXPECT_NE(o.err.find("--output"), std::string::npos) << o.err;

    o = run(in.string() + " --degree 99");
    EXPECT_EQ(o.status, 2) << o.err;
    o = run("");
    EXPECT_EQ(o.status, 2) << o.err;
  }

  TEST(RfmSolveCli, ValidInputWritesAResult)
  {
    const fs::path dir = fs::temp_directory_path() / "rfm_cli_valid";
    fs::create_directories(dir);
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    fs::remove(out);
    std::ofstream(in) << valid().dump();
    const Outcome o = run(in.string() + " --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err;
    ASSERT_TRUE(fs::exists(out));
    std::ifstream f(out);
    const nlohmann::json r = nlohmann::json::parse(f);
    EXPECT_EQ(r.at("solver"), "rfm");
    EXPECT_LT(r.at("functionals").at("reissner").get<double>(), 0.0);
  }

  // An outline section (the sphere of DESIGN.md 7.1) solves: samples on the section, the
  // three functionals, and the VTU with cells inside the section only.
  TEST(RfmSolveCli, OutlineSectionSolves)
  {
    const fs::path dir = scratch("outline");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << sphere_with("/samples", {{0.15, 0.0}});
    const Outcome o = run(in.string() + " --degree 10 --output " + out.string() + " --vtu " +
                          (dir / "vtu").string());
    EXPECT_EQ(o.status, 0) << o.err;
    std::ifstream f(out);
    const nlohmann::json r = nlohmann::json::parse(f);
    // Lame's sphere at R = 0.15: sigma_RR = A - B / R^3 = -1.958e6 Pa (0.3 % of max at p = 10).
    EXPECT_NEAR(r.at("samples")[0].at("sigma_rr").get<double>(), -1.9577e6, 4e4);
    EXPECT_LT(r.at("functionals").at("indicator").get<double>(), 1e-3);
    EXPECT_TRUE(fs::exists(dir / "vtu" / "rfm_solution.vtu"));
    // Where the gap lies: with homogeneous prescribed displacements (symmetry, axis) the
    // constitutive-relation error is Phi_L - Phi_C, so its relative value is the indicator;
    // 8 x 8 cells with shares adding to 1, and its density in the VTU.
    const nlohmann::json &e = r.at("diagnostics").at("constitutive_error");
    const double relative = e.at("relative").get<double>();
    EXPECT_NEAR(relative / r.at("functionals").at("indicator").get<double>(), 1.0, 1e-3);
    EXPECT_LT(std::abs(e.at("gap_minus_error").get<double>()), 1e-3 * relative);
    ASSERT_EQ(e.at("cells").at("share").size(), 8u);
    ASSERT_EQ(e.at("cells").at("r").size(), 9u);
    double shares = 0.0;
    for (const auto &row : e.at("cells").at("share"))
      for (const auto &x : row)
        shares += x.get<double>();
    EXPECT_NEAR(shares, 1.0, 1e-12);
    ASSERT_EQ(e.at("largest").size(), 3u);
    EXPECT_GE(e.at("largest")[0].at("share").get<double>(), e.at("largest")[1].at("share").get<double>());
    std::ifstream v(dir / "vtu" / "rfm_solution.vtu");
    const std::string text((std::istreambuf_iterator<char>(v)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("Name=\"constitutive_error\""), std::string::npos);
  }

  // A numerical failure without --output writes the result, with status "failed", to stdout
  // as a success's would go (DESIGN.md 7: any partial history is still written). The
  // sphere asked for 1e-12 within p <= 4 gives up at once (the rate predicts a higher p).
  TEST(RfmSolveCli, NumericalFailureWritesTheResultToStdout)
  {
    const fs::path dir = scratch("failed_stdout");
    const fs::path in = dir / "problem.json", printed = dir / "stdout.json";
    std::ofstream(in) << sphere_with("/rfm", {{"tolerance", 1e-12}, {"max_degree", 4}});
    const Outcome o =
      axisym::testing::run_command("(" + std::string(RFM_SOLVE) + " " + in.string() + " > " + printed.string() + ")");
    EXPECT_EQ(o.status, 3) << o.err;
    EXPECT_NE(o.err.find("numerical failure"), std::string::npos) << o.err;
    std::ifstream f(printed);
    const nlohmann::json r = nlohmann::json::parse(f);
    EXPECT_EQ(r.at("diagnostics").at("status"), "failed");
    EXPECT_FALSE(r.at("diagnostics").at("message").get<std::string>().empty());
  }

  // A notch root (rfm.notch_roots) is listed in diagnostics.notch_roots with its columns; with
  // the option off it has none and is not listed.
  TEST(RfmSolveCli, NotchRootIsListedWithItsColumns)
  {
    const fs::path dir = scratch("notch");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    nlohmann::json problem = axisym::testing::grooved_shaft();
    std::ofstream(in) << problem;
    const Outcome o = run(in.string() + " --degree 6 --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    ASSERT_TRUE(r.at("diagnostics").contains("notch_roots"));
    const nlohmann::json &roots = r.at("diagnostics").at("notch_roots");
    ASSERT_EQ(roots.size(), 1u);
    EXPECT_NEAR(roots[0].at("r").get<double>(), 0.04, 1e-12);
    EXPECT_NEAR(roots[0].at("arc_radius").get<double>(), 0.01, 1e-12);
    EXPECT_GT(roots[0].at("columns").get<int>(), 0);
    EXPECT_EQ(r.at("discretization").at("vertex_columns").get<int>(), roots[0].at("columns").get<int>());
    problem["rfm"]["notch_roots"] = false;
    std::ofstream(in) << problem;
    const Outcome off = run(in.string() + " --degree 6 --output " + out.string());
    EXPECT_EQ(off.status, 0) << off.err;
    const nlohmann::json r_off = nlohmann::json::parse(std::ifstream(out));
    EXPECT_FALSE(r_off.at("diagnostics").contains("notch_roots"));
    EXPECT_EQ(r_off.at("discretization").at("vertex_columns").get<int>(), 0);
  }

  // A rough vertex (wedge_modes.h: rough_vertices) is listed in diagnostics.rough_vertices
  // with its exponents, and with the columns the model placed there where a traction jumps
  // (issue 24's hub: its inner arc's pressure ends at the bore); with rfm.rough_vertices off it
  // is listed without them.
  TEST(RfmSolveCli, RoughVertexIsListedWithItsColumns)
  {
    const fs::path dir = scratch("rough");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    nlohmann::json problem = axisym::testing::tapered_hub();
    // The vertices' discs and rough columns where a traction jumps only (the defaults before
    // session 82), as measured here; "all" would list the same vertex with the same columns.
    problem["rfm"] = {{"vertex_support", "section"}, {"rough_vertices", true}};
    std::ofstream(in) << problem;
    const Outcome o = run(in.string() + " --degree 6 --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    ASSERT_TRUE(r.at("diagnostics").contains("rough_vertices"));
    const nlohmann::json &rough = r.at("diagnostics").at("rough_vertices");
    ASSERT_EQ(rough.size(), 1u);
    EXPECT_NEAR(rough[0].at("r").get<double>(), 0.55, 1e-12);
    EXPECT_NEAR(rough[0].at("z").get<double>(), 0.5809475019311126, 1e-12);
    EXPECT_NEAR(rough[0].at("exponents")[0][0].get<double>(), 1.90475, 1e-4);
    ASSERT_FALSE(rough[0].at("enrichment").is_null());
    EXPECT_GT(rough[0].at("enrichment").at("modes").get<int>(), 0);
    EXPECT_GT(rough[0].at("enrichment").at("columns").get<int>(), 0);
    EXPECT_EQ(rough[0].at("enrichment").at("cutoff_radius").get<double>(),
              r.at("diagnostics").at("traction_jumps")[0].at("cutoff_radius").get<double>());
    // The jump's hoop shadow: rho^2 (V_0 + ln rho V_1), its collocation solved to rounding.
    const nlohmann::json &shadow = r.at("diagnostics").at("traction_jumps")[0].at("hoop_shadow");
    ASSERT_FALSE(shadow.is_null());
    EXPECT_EQ(shadow.at("log_levels").get<int>(), 2);
    EXPECT_LT(shadow.at("residual").get<double>(), 1e-10);
    // The 186-degree vertex between the outer arc and the taper has an arc face: its
    // intensity is given too (vertex_intensity.h), one K for lambda = 0.937.
    int curved = 0;
    for (const nlohmann::json &v : r.at("diagnostics").at("singular_vertices"))
      if (!v.at("enrichment").is_null() && v.at("enrichment").at("curved_faces").get<bool>())
        {
          ++curved;
          const nlohmann::json &k = v.at("enrichment").at("intensities");
          ASSERT_EQ(k.size(), 1u);
          EXPECT_NEAR(k[0].at("lambda")[0].get<double>(), 0.93678, 1e-4);
          EXPECT_TRUE(std::isfinite(k[0].at("K")[0].get<double>()));
          EXPECT_GT(std::abs(k[0].at("K")[0].get<double>()), 0.0);
        }
    EXPECT_EQ(curved, 1);
    problem["rfm"]["rough_vertices"] = false;
    std::ofstream(in) << problem;
    const Outcome off = run(in.string() + " --degree 6 --output " + out.string());
    EXPECT_EQ(off.status, 0) << off.err;
    const nlohmann::json r_off = nlohmann::json::parse(std::ifstream(out));
    ASSERT_TRUE(r_off.at("diagnostics").contains("rough_vertices"));
    EXPECT_TRUE(r_off.at("diagnostics").at("rough_vertices")[0].at("enrichment").is_null());
    EXPECT_LT(r_off.at("discretization").at("vertex_columns").get<int>(),
              r.at("discretization").at("vertex_columns").get<int>());
  }

  // At a resonant vertex the stress's rho ln rho term has the amplitude a = 2 E alpha g /
  // (pi (1 - nu)) of the local problem (g the temperature gradient across the symmetry line
  // into the body). Issue 24's hub under T = 100 r + 100 z K has four (z = 0 meets both arcs,
  // z = 1.6 the neck and the bore; g = 100 and -100 K/m): at p = 8 the solved amplitudes
  // are -0.13, 0.88, -1.4 and 6.8 times those (2.5 times at (0.8, 0) at p = 16), and
  // rfm_solve warns. The heated ring of verification/problems/heated_ring_axial_gradient.json
  // at p = 12 (ratios 0.95 and 1.00) does not.
  TEST(RfmSolveCli, ResonantVertexWithAnOffLogAmplitudeWarns)
  {
    const fs::path dir = scratch("resonant_amplitude");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    nlohmann::json problem = axisym::testing::tapered_hub();
    problem["boundary"].erase("inner_arc");
    problem["material"]["thermal_expansion"] = 1.2e-5;
    problem["loading"] = {{"temperature", {{"field", {0.0, 100.0, 100.0}}}}};
    // The vertices' discs (the defaults before session 82), where the ratios were measured.
    problem["rfm"] = {{"vertex_support", "section"}, {"rough_vertices", true}};
    std::ofstream(in) << problem;
    const Outcome o = run(in.string() + " --degree 8 --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    const double expected = 2.0 * 2.1e11 * 1.2e-5 * 100.0 / (3.14159265358979323846 * 0.7);
    const nlohmann::json &list = r.at("diagnostics").at("resonant_vertices");
    ASSERT_EQ(list.size(), 4u);
    int off = 0;
    for (const nlohmann::json &v : list)
      {
        const nlohmann::json &a = v.at("log_amplitude");
        const bool on_top = v.at("z").get<double>() > 1.0;
        EXPECT_NEAR(a.at("theory").get<double>(), on_top ? -expected : expected, 1e-9 * expected);
        EXPECT_NEAR(a.at("ratio").get<double>(), a.at("solution").get<double>() / a.at("theory").get<double>(), 1e-12);
        off += std::abs(a.at("ratio").get<double>() - 1.0) > 0.5;
      }
    EXPECT_GE(off, 1);
    EXPECT_EQ(r.at("diagnostics").at("status"), "warning");
    bool warned = false;
    for (const nlohmann::json &w : r.at("diagnostics").at("warnings"))
      warned |= w.at("check") == "resonant_log_amplitude";
    EXPECT_TRUE(warned);
    EXPECT_NE(o.err.find("rho ln rho term"), std::string::npos) << o.err;

    const nlohmann::json ring = axisym::testing::heated_ring_axial_gradient();
    std::ofstream(in) << ring;
    const Outcome ok = run(in.string() + " --degree 12 --output " + out.string());
    EXPECT_EQ(ok.status, 0) << ok.err;
    const nlohmann::json rr = nlohmann::json::parse(std::ifstream(out));
    ASSERT_EQ(rr.at("diagnostics").at("resonant_vertices").size(), 2u);
    for (const nlohmann::json &v : rr.at("diagnostics").at("resonant_vertices"))
      EXPECT_NEAR(v.at("log_amplitude").at("ratio").get<double>(), 1.0, 0.1);
    if (rr.at("diagnostics").contains("warnings"))
      {
        for (const nlohmann::json &w : rr.at("diagnostics").at("warnings"))
          EXPECT_NE(w.at("check"), "resonant_log_amplitude");
      }
  }

  // --ritz-bound (rfm.ritz_bound) adds the displacement space's own bound: on Lame's sphere
  // (a = 0.1, b = 0.2 m, 10 MPa inside only) at p = 6 both Phi_L's lie above the closed form's
  // Phi = -p u(a) a^2 / 2 = -4/21 J/rad (u(a) = p a^3 ((1 - 2 nu) a + (1 + nu) b^3 / (2 a^2))
  // / (E (b^3 - a^3))), the Ritz one not above Phi_L(u_h) (measured 8.6e-5 and 1.1e-4 from
  // it), and the indicator with it not above the other.
  TEST(RfmSolveCli, RitzBoundIsWrittenBesideTheFunctionals)
  {
    const fs::path dir = scratch("ritz");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << sphere_with("/samples", {{0.15, 0.0}});
    const Outcome o = run(in.string() + " --degree 6 --ritz-bound --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err;
    std::ifstream f(out);
    const nlohmann::json phi = nlohmann::json::parse(f).at("functionals");
    const double exact = -4.0 / 21.0, ritz = phi.at("lagrange_ritz").get<double>();
    EXPECT_GT(ritz, exact);
    EXPECT_LE(ritz, phi.at("lagrange").get<double>());
    EXPECT_LE(phi.at("indicator_ritz").get<double>(), phi.at("indicator").get<double>());
    // Without the flag, neither field.
    const Outcome plain = run(in.string() + " --degree 6 --output " + out.string());
    EXPECT_EQ(plain.status, 0) << plain.err;
    std::ifstream g(out);
    EXPECT_FALSE(nlohmann::json::parse(g).at("functionals").contains("lagrange_ritz"));
  }

  // A fixed degree whose indicator is above 1e-5 says so (status "warning", exit 0: not a
  // failure); one below it, or a degree chosen by rfm.tolerance, does not (issue 24 item 6).
  // The thick sphere: indicator 3.1e-3 at p = 4, 4.0e-8 at p = 10, 8.4e-5 at the p = 6 that
  // rfm.tolerance 1e-3 chooses (a tolerance run says nothing more: it asked for that).
  TEST(RfmSolveCli, FixedDegreeWithALargeIndicatorWarns)
  {
    const fs::path dir = scratch("fixed_degree");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << sphere_with("/samples", {{0.15, 0.0}});
    for (const auto &[args, status] : {std::pair{"--degree 4", "warning"}, std::pair{"--degree 10", "ok"},
                                       std::pair{"--tolerance 1e-3", "ok"}})
      {
        const Outcome o = run(in.string() + " " + args + " --output " + out.string());
        EXPECT_EQ(o.status, 0) << o.err;
        std::ifstream f(out);
        const nlohmann::json r = nlohmann::json::parse(f);
        EXPECT_EQ(r.at("diagnostics").at("status"), status) << args;
        if (std::string(status) == "warning")
          {
            EXPECT_NE(r.at("diagnostics").at("message").get<std::string>().find("fixed degree p = 4"),
                      std::string::npos);
            EXPECT_NE(o.err.find("warning"), std::string::npos);
          }
      }
  }

  // A sample on the axis where sigma_rr and sigma_tt differ by more than the tolerance
  // promises warns (issue 24 items 5 and 6): the indicator does not see r = 0. The thick
  // sphere's (0, 0.15): at the tolerance 1e-4 (p = 6, indicator 8.7e-5 < 1e-4) they differ by
  // 4.7 % of the scale (the energy's stress, 5.86 MPa) against the limit 2 sqrt(1e-4) = 2 %,
  // and sigma_rr is 6.7 % off Lame's hoop stress; at 1e-6 (p = 10) by 0.05 % against 0.2 %,
  // and both are within 0.03 % of the scale of Lame's.
  TEST(RfmSolveCli, AxisSampleWithUnequalNormalStressesWarns)
  {
    const fs::path dir = scratch("axis_sample");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << sphere_with("/samples", {{0.0, 0.15}});
    // Lame's sphere, a = 0.1 m, b = 0.2 m, inner pressure 10 MPa: on the axis at rho = 0.15 m
    // sigma_rr = sigma_tt = the hoop stress p a^3 / (b^3 - a^3) (1 + b^3 / (2 rho^3)).
    const double hoop = 1e7 * 1e-3 / 7e-3 * (1.0 + 8e-3 / (2.0 * 3.375e-3));
    for (const auto &[given, warns] : {std::pair{"1e-4", true}, std::pair{"1e-6", false}})
      {
        const double tolerance = std::stod(given);
        const Outcome o = run(in.string() + " --tolerance " + given + " --output " + out.string());
        ASSERT_EQ(o.status, 0) << o.err;
        const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
        const nlohmann::json &d = r.at("diagnostics");
        ASSERT_EQ(d.at("axis_samples").size(), 1u);
        const nlohmann::json &a = d.at("axis_samples")[0];
        const double relative = a.at("relative").get<double>(), limit = a.at("limit").get<double>(),
                     scale = a.at("scale").get<double>();
        EXPECT_NEAR(limit, 2.0 * std::sqrt(tolerance), 1e-15);
        const nlohmann::json &s = r.at("samples")[0];
        const double error = std::max(std::abs(s.at("sigma_rr").get<double>() - hoop),
                                      std::abs(s.at("sigma_tt").get<double>() - hoop)) / scale;
        if (warns)
          {
            EXPECT_GT(relative, limit);
            EXPECT_EQ(d.at("status"), "warning");
            EXPECT_NE(d.at("message").get<std::string>().find("on the axis sigma_rr = sigma_tt"), std::string::npos)
              << d.at("message");
            EXPECT_NE(o.err.find("warning"), std::string::npos);
            EXPECT_GT(error, 0.5 * limit);
          }
        else
          {
            // Quiet, and rightly: the exact error is below what the tolerance promises.
            EXPECT_LT(relative, limit);
            EXPECT_EQ(d.at("status"), "ok") << d.at("message");
            EXPECT_LT(error, 0.5 * limit);
          }
      }
  }

  // At a fixed degree a sample that moved since p - 2 by more than 2 sqrt(1e-5) of its scale
  // warns (issue 24 item 6), where neither the indicator nor the axis check does. The thick
  // sphere at p = 8 (indicator 1.8e-6, sigma_rr - sigma_tt on the axis below its 0.63 %): the
  // axis's (0, 0.15) moved 3.8 % of its scale (the energy's stress, 5.86 MPa) since p = 6 and
  // is 0.43 % off Lame's, above the sqrt(1e-5) = 0.32 % a fixed degree is allowed. The
  // equator's (0.15, 0) moved 2.1 % and is flagged too, though it is 0.22 % off: the change
  // measures p - 2's error more than p's, so the rule errs on the side of doubt. At p = 10
  // they moved 0.24 % and 0.45 % and are within 0.03 % of Lame's: quiet.
  TEST(RfmSolveCli, FixedDegreeWithAMovingSampleWarns)
  {
    const fs::path dir = scratch("moving_sample");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << sphere_with("/samples", {{0.15, 0.0}, {0.0, 0.15}});
    // Lame's sphere, a = 0.1 m, b = 0.2 m, inner pressure p = 10 MPa: at rho = 0.15 m the
    // radial and the hoop stress; on the equator sigma_zz is the hoop stress, on the axis
    // sigma_rr is.
    const double k = 1e7 * 1e-3 / 7e-3, b3 = 8e-3, rho3 = 3.375e-3;
    const double radial = k * (1.0 - b3 / rho3), hoop = k * (1.0 + b3 / (2.0 * rho3));
    const std::array<std::array<double, 4>, 2> lame{{{radial, hoop, hoop, 0.0}, {hoop, radial, hoop, 0.0}}};
    const double limit = 2.0 * std::sqrt(1e-5);
    for (const int p : {8, 10})
      {
        const Outcome o = run(in.string() + " --degree " + std::to_string(p) + " --output " + out.string());
        ASSERT_EQ(o.status, 0) << o.err;
        const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
        const nlohmann::json &d = r.at("diagnostics");
        const nlohmann::json &moved = d.at("check_at_lower_degree").at("samples");
        ASSERT_EQ(moved.size(), 2u);
        for (std::size_t i = 0; i < 2; ++i)
          {
            const nlohmann::json &s = r.at("samples")[i];
            double error = 0.0;
            int c = 0;
            for (const char *name : {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"})
              error = std::max(error, std::abs(s.at(name).get<double>() - lame[i][c++]));
            error /= moved[i].at("scale").get<double>();
            EXPECT_NEAR(moved[i].at("limit").get<double>(), limit, 1e-15);
            if (p == 8)
              {
                EXPECT_GT(moved[i].at("relative").get<double>(), limit) << i;
                // The axis sample rightly: its exact error is above what a fixed degree promises.
                if (i == 1)
                  {
                    EXPECT_GT(error, 0.5 * limit);
                  }
              }
            else
              {
                EXPECT_LT(moved[i].at("relative").get<double>(), limit) << i;
                EXPECT_LT(error, 0.5 * limit) << i;
              }
          }
        if (p == 8)
          {
            EXPECT_LT(r.at("functionals").at("indicator").get<double>(), 1e-5);
            EXPECT_LT(d.at("axis_samples")[0].at("relative").get<double>(), limit);
            EXPECT_EQ(d.at("status"), "warning");
            EXPECT_NE(d.at("message").get<std::string>().find("samples moved by more than"), std::string::npos)
              << d.at("message");
          }
        else
          {
            EXPECT_EQ(d.at("status"), "ok") << d.at("message");
          }
      }
  }

  // Where the tolerance path stops, each sample's change since p - 2, extrapolated at the rate
  // the indicator falls, estimates its error (issue 24 item 6). Lame's thick sphere (inner
  // pressure only) at five points, against the closed form: at the tolerance 1e-5 (p = 8) the
  // axis sample is estimated above 2 sqrt(t) and warns, and its exact error is above the
  // sqrt(t) the tolerance promises; at the default 1e-8 (p = 12) every estimate is within
  // 2 sqrt(t), and so is every exact error. (Measured: at 1e-5 the axis sample's estimate
  // 6.5e-3 of its scale against the limit 6.3e-3, its exact error 4.3e-3; at 1e-8 the estimates
  // 5.3e-6 to 3.9e-5 and the exact errors 2.9e-6 to 6.0e-5, against 2e-4.)
  TEST(RfmSolveCli, ToleranceWithAnUnsettledSampleWarns)
  {
    const fs::path dir = scratch("unsettled_sample");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    const std::vector<std::array<double, 2>> points{
      {0.15, 0.0}, {0.1, 0.1}, {0.0, 0.15}, {0.2, 0.0}, {0.17320508075688773, 0.1}};
    std::ofstream(in) << sphere_with("/samples", points);
    // sigma_rho = k (1 - b^3 / rho^3), sigma_phi = k (1 + b^3 / (2 rho^3)), k = p a^3 / (b^3 - a^3),
    // turned into (r, z) at the angle of the point.
    const double k = 1e7 * 1e-3 / 7e-3, b3 = 8e-3;
    const auto exact = [&](const double r, const double z) -> std::array<double, 4> {
      const double rho = std::hypot(r, z), c = r / rho, s = z / rho;
      const double radial = k * (1.0 - b3 / (rho * rho * rho)), hoop = k * (1.0 + b3 / (2.0 * rho * rho * rho));
      return {radial * c * c + hoop * s * s, radial * s * s + hoop * c * c, hoop, (radial - hoop) * c * s};
    };
    for (const double t : {1e-5, 1e-8})
      {
        const Outcome o = run(in.string() + (t == 1e-8 ? std::string() : " --tolerance 1e-5") + " --output " +
                              out.string());
        ASSERT_EQ(o.status, 0) << o.err;
        const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
        const nlohmann::json &d = r.at("diagnostics");
        const int p = r.at("discretization").at("degree");
        const nlohmann::json &check = d.at("check_at_lower_degree");
        EXPECT_EQ(check.at("degree"), p - 2);
        const double rate = std::sqrt(r.at("functionals").at("indicator").get<double>() /
                                      check.at("indicator").get<double>());
        EXPECT_NEAR(check.at("rate").get<double>(), rate, 1e-12 * rate);
        const nlohmann::json &list = check.at("samples");
        ASSERT_EQ(list.size(), points.size());
        const double limit = 2.0 * std::sqrt(t);
        std::vector<bool> warns(points.size());
        std::vector<double> error(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
          {
            const nlohmann::json &s = r.at("samples")[i];
            const auto e = exact(points[i][0], points[i][1]);
            int c = 0;
            for (const char *name : {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"})
              error[i] = std::max(error[i], std::abs(s.at(name).get<double>() - e[c++]));
            error[i] /= list[i].at("scale").get<double>();
            EXPECT_NEAR(list[i].at("limit").get<double>(), limit, 1e-15);
            EXPECT_NEAR(list[i].at("estimate").get<double>(),
                        list[i].at("relative").get<double>() * rate / (1.0 - rate), 1e-12);
            warns[i] = list[i].at("estimate").get<double>() > limit;
          }
        if (t == 1e-5)
          {
            EXPECT_EQ(p, 8);
            EXPECT_LT(r.at("functionals").at("indicator").get<double>(), t);
            EXPECT_TRUE(warns[2]);
            // Rightly: the axis sample is off by more than the tolerance promises.
            EXPECT_GT(error[2], std::sqrt(t));
            EXPECT_EQ(d.at("status"), "warning");
            EXPECT_NE(d.at("message").get<std::string>().find("(0, 0.15) m about"), std::string::npos)
              << d.at("message");
            // Listed with its check's key (diagnostics.warnings).
            bool listed = false;
            for (const nlohmann::json &w : d.at("warnings"))
              listed = listed || (w.at("check") == "samples_unsettled" &&
                                  w.at("message").get<std::string>().find("(0, 0.15) m about") != std::string::npos);
            EXPECT_TRUE(listed) << d.at("warnings");
          }
        else
          {
            EXPECT_EQ(p, 12);
            for (std::size_t i = 0; i < points.size(); ++i)
              {
                EXPECT_FALSE(warns[i]) << i;
                EXPECT_LT(error[i], limit) << i;
              }
            EXPECT_EQ(d.at("status"), "ok") << d.at("message");
            EXPECT_FALSE(d.contains("warnings"));
          }
      }
  }

  // A sample at a vertex where the stress has no value warns and is listed (issue 24 item 6),
  // whatever columns the discretization placed there; one beside it is not. The L-shaped
  // ring's re-entrant vertex (0.15, 0.1), free-free at 270 degrees (Re lambda = 0.5444837,
  // Williams), read sigma_zz = 0 there before; the pressure band's jump (0.5, 0.25), where the
  // pressure on the bore ends, sigma_rr = -5 MPa, the mean of the two sides' -10 and 0 MPa.
  TEST(RfmSolveCli, SampleAtASingularVertexOrATractionJumpWarns)
  {
    const fs::path dir = scratch("vertex_sample");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    // The jump also without its field (rfm.vertex_max_exponent 0), and a shear traction's,
    // which has none (a log term): the vertices are the problem's.
    nlohmann::json bare_band = axisym::testing::pressure_band();
    bare_band["rfm"]["vertex_max_exponent"] = 0;
    nlohmann::json shear_band = axisym::testing::pressure_band();
    shear_band["boundary"]["bore_loaded"] = {{"traction", {0.0, 1.0e6}}};
    const std::array<std::tuple<nlohmann::json, std::array<double, 2>, std::string>, 4> cases{
      {{axisym::testing::stepped_ring(), {0.15, 0.1}, "singular"},
       {axisym::testing::pressure_band(), {0.5, 0.25}, "traction_jump"},
       {bare_band, {0.5, 0.25}, "traction_jump"},
       {shear_band, {0.5, 0.25}, "traction_jump"}}};
    for (const auto &[problem, vertex, kind] : cases)
      for (const bool at_vertex : {true, false})
        {
          nlohmann::json j = problem;
          const std::array<double, 2> near{vertex[0] + 0.01, vertex[1] + 0.01};
          j["samples"] = {at_vertex ? vertex : near};
          std::ofstream(in) << j.dump();
          const Outcome o = run(in.string() + " --degree 4 --output " + out.string());
          ASSERT_EQ(o.status, 0) << o.err;
          const nlohmann::json d = nlohmann::json::parse(std::ifstream(out)).at("diagnostics");
          if (!at_vertex)
            {
              EXPECT_FALSE(d.contains("samples_at_vertices")) << kind;
              continue;
            }
          ASSERT_TRUE(d.contains("samples_at_vertices")) << kind;
          ASSERT_EQ(d.at("samples_at_vertices").size(), 1u);
          const nlohmann::json &s = d.at("samples_at_vertices")[0];
          EXPECT_EQ(s.at("kind"), kind);
          EXPECT_EQ(s.at("r").get<double>(), vertex[0]);
          if (kind == "singular")
            {
              EXPECT_NEAR(s.at("exponent").get<double>(), 0.5444837, 1e-6);
            }
          EXPECT_EQ(d.at("status"), "warning");
          EXPECT_NE(d.at("message").get<std::string>().find("the stress has no value there"), std::string::npos)
            << d.at("message");
        }
  }

  // A fixed degree is checked against p - 2 where its indicator is above 1e-8 (issue 24 item
  // 6). Issue 24's hub without its vertices' columns (rfm.vertex_max_exponent 0, no rough
  // vertices: the hub of the issue's first table) grows from p - 2 at p = 12 and at p = 16
  // (4.4e-4, 5.0e-4, 4.8e-4, 5.0e-4 at p = 10 to 16), with 2 more dependent stress
  // directions dropped at p = 16 than at 14, so both warn that it grows and why. The cylinder
  // clamped on its base (without the axis parity, the hoop shadow and the inner disc, local
  // stress columns of degree 4) converges there: p = 14 (1.0e-8, 2.5 times below p = 12's)
  // does not warn. (That cylinder grew from p = 14 to 16 with monomials for the local stress
  // columns, 9 more directions dropped; it falls to 5.5e-9 with VertexEnrichment's Legendre
  // polynomials, and now stops at p = 16 below the tolerance.)
  TEST(RfmSolveCli, FixedDegreeWithAGrowingIndicatorWarns)
  {
    const fs::path dir = scratch("growing");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    {
      std::ofstream(in) << R"({
        "rfm": {"axis_parity": false, "vertex_local_degree": 4, "vertex_shadow": false,
                "vertex_inner_disc": false},
        "geometry": {"outline": [
          {"start": [0.0, 0.0]}, {"line_to": [0.05, 0.0], "part": "base"},
          {"line_to": [0.05, 0.1], "part": "surface"}, {"line_to": [0.0, 0.1], "part": "end"},
          {"line_to": [0.0, 0.0], "part": "axis"}]},
        "boundary": {"base": {"displacement": [0.0, 0.0]}, "end": {"traction": [0.0, 1.0e7]}},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})";
      const Outcome o = run(in.string() + " --degree 14 --output " + out.string());
      EXPECT_EQ(o.status, 0) << o.err;
      std::ifstream f(out);
      const nlohmann::json r = nlohmann::json::parse(f);
      const nlohmann::json &d = r.at("diagnostics");
      EXPECT_EQ(d.at("check_at_lower_degree").at("degree"), 12);
      EXPECT_LT(r.at("functionals").at("indicator").get<double>(),
                0.5 * d.at("check_at_lower_degree").at("indicator").get<double>());
      EXPECT_EQ(d.at("status"), "ok") << d.at("message");
    }
    nlohmann::json hub = axisym::testing::tapered_hub();
    hub["rfm"] = {{"vertex_max_exponent", 0.0}, {"rough_vertices", false}};
#if defined(__SANITIZE_ADDRESS__)
    const int p = 12; // the Release run takes p = 16, where directions are dropped too
#else
    const int p = 16;
#endif
    std::ofstream(in) << hub.dump();
    const Outcome o = run(in.string() + " --degree " + std::to_string(p) + " --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err; // a fixed degree is not a numerical failure
    std::ifstream f(out);
    const nlohmann::json r = nlohmann::json::parse(f);
    const nlohmann::json &d = r.at("diagnostics");
    EXPECT_EQ(d.at("check_at_lower_degree").at("degree"), p - 2);
    EXPECT_GT(r.at("functionals").at("indicator").get<double>(),
              d.at("check_at_lower_degree").at("indicator").get<double>());
    EXPECT_EQ(d.at("status"), "warning");
    const std::string message = d.at("message").get<std::string>();
    EXPECT_NE(message.find("the indicator grows"), std::string::npos) << message;
    if (p == 16)
      {
        EXPECT_NE(message.find("more dependent directions"), std::string::npos) << message;
      }
    EXPECT_NE(o.err.find("grows"), std::string::npos);
  }

  // Phi_L - Phi_C is the constitutive-relation error E plus the stress's equilibrium defect
  // against u_h's fixed part (a traction jump's particular displacement, with rfm.jump_column
  // false: the default's column takes the defect away). On issue 24's hub
  // (its inner arc's pressure ends at the bore) the defect outweighs E from p = 18 on, so that
  // Phi_L lies below Phi_C: at p = 18 Phi_L - Phi_C = -0.58 E (E 8.87e-8 of |Phi_R|, the
  // indicator 5.15e-8, below the truth), at p = 20 -1.08 E (E 4.98e-8, the indicator 5.40e-8).
  // The run warns that the indicator crossed and names E. (The runs whose tests ask status
  // "ok" are the cases without the warning.)
  // The fixed degree's check reads the measure rfm.tolerance compares: E / |Phi_R| where that is
  // larger than the indicator. From p = 18 to 20 the indicator grew while E fell, and
  // rfm_solve warned that it grew (check "indicator_grows"); the measure falls (8.87e-8 ->
  // 5.40e-8): no such warning. One run at p = 20 checks both (about 80 s in Release; the
  // check at p = 18 inside it carries p = 18's indicator and E; not under ASan).
  TEST(RfmSolveCli, IndicatorCrossingAndTheFixedDegreeCheck)
  {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "p = 20 on the hub takes too long under ASan: the Release run checks it";
#endif
    const fs::path dir = scratch("measure");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    // Without the jump's column (rfm.jump_column) the stress's work defect against the jump's
    // fixed displacement makes Phi_L - Phi_C cross zero; with it the gap is E (the test
    // JumpColumnMakesTheGapTheConstitutiveError), and a crossing needs another fixed part.
    nlohmann::json hub = axisym::testing::tapered_hub();
    hub["rfm"]["jump_column"] = false;
    // The vertices' discs (the defaults before session 82), where the crossing was measured.
    hub["rfm"]["vertex_support"] = "section";
    hub["rfm"]["rough_vertices"] = true;
    std::ofstream(in) << hub.dump();
    const Outcome o = run(in.string() + " --degree 20 --output " + out.string());
    EXPECT_EQ(o.status, 0) << o.err;
    std::ifstream f(out);
    const nlohmann::json r = nlohmann::json::parse(f);
    const nlohmann::json &fn = r.at("functionals"), &d = r.at("diagnostics");
    const nlohmann::json &lower = d.at("check_at_lower_degree");
    ASSERT_EQ(lower.at("degree"), 18);
    const double indicator = fn.at("indicator").get<double>();
    const nlohmann::json &error = d.at("constitutive_error");
    const double e = error.at("relative").get<double>();
    // The crossing at p = 20: Phi_L below Phi_C, and the map's gap_minus_error is that gap less E.
    const double gap = (fn.at("lagrange").get<double>() - fn.at("castigliano").get<double>()) /
                       std::abs(fn.at("reissner").get<double>());
    EXPECT_LT(gap, 0.0);
    EXPECT_NEAR(error.at("gap_minus_error").get<double>(), gap - e, 1e-15);
    bool crossed = false;
    for (const nlohmann::json &w : d.value("warnings", nlohmann::json::array()))
      {
        crossed |= w.at("check") == "indicator_crossed";
        EXPECT_NE(w.at("check"), "indicator_grows") << w.at("message");
      }
    EXPECT_TRUE(crossed) << d.dump();
    EXPECT_EQ(d.at("status"), "warning");
    EXPECT_NE(o.err.find("Phi_L is below Phi_C"), std::string::npos) << o.err;
    // The check's premise: at p = 18 the indicator lies below E (its measure), the indicator
    // grows to p = 20 while E falls.
    ASSERT_GT(lower.at("error_measure").get<double>(), 1.001 * lower.at("indicator").get<double>());
    ASSERT_GT(indicator, lower.at("indicator").get<double>());
    ASSERT_LT(e, lower.at("error_measure").get<double>());
    ASSERT_LT(indicator, lower.at("error_measure").get<double>());
  }

  // A section with a re-entrant corner (a ring with a rectangular step, 270 degrees, free on
  // both faces) warns and lists the vertex with Williams' exponents (issue 24 item 6). (Its
  // indicator is 1.3e-2 at p = 24: rfm.tolerance 1e-3 is not reached, exit 3, and that
  // message names the vertex too.)
  // The stepped ring's 270-degree vertex carries its columns: listed with them, and no vertex
  // warning (the fixed degree's indicator, 2.2e-4 at p = 4 here, warns on its own; at p = 6 it
  // is 9.7e-6 since the modes' stresses carry their hoop term, 1.7e-5 before); with the columns
  // switched off the vertex warns.
  TEST(RfmSolveCli, SingularVertexWarnsWithoutItsColumns)
  {
    const fs::path dir = scratch("vertex");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    nlohmann::json problem = axisym::testing::stepped_ring();
    std::ofstream(in) << problem.dump();
    {
      const Outcome o = run(in.string() + " --degree 4 --output " + out.string());
      EXPECT_EQ(o.status, 0) << o.err;
      std::ifstream f(out);
      const nlohmann::json r = nlohmann::json::parse(f);
      const nlohmann::json &d = r.at("diagnostics");
      EXPECT_EQ(d.at("status"), "warning");
      EXPECT_NE(d.at("message").get<std::string>().find("the indicator"), std::string::npos);
      EXPECT_EQ(d.at("message").get<std::string>().find("singular"), std::string::npos);
      ASSERT_EQ(d.at("singular_vertices").size(), 1u);
      const nlohmann::json &v = d.at("singular_vertices")[0];
      EXPECT_NEAR(v.at("r").get<double>(), 0.15, 1e-12);
      EXPECT_NEAR(v.at("angle_degrees").get<double>(), 270.0, 1e-9);
      EXPECT_NEAR(v.at("exponents")[0][0].get<double>(), 0.5444837, 1e-7);
      EXPECT_NEAR(v.at("exponents")[1][0].get<double>(), 0.9085292, 1e-7);
      // The defaults: the modes with Re lambda < 3 and the local columns.
      ASSERT_FALSE(v.at("enrichment").is_null());
      EXPECT_GE(v.at("enrichment").at("modes").get<int>(), 2);
      EXPECT_GT(v.at("enrichment").at("cutoff_radius").get<double>(), 0.0);
      // The section is star-shaped about the vertex: its modes cover it (the default).
      EXPECT_EQ(v.at("enrichment").at("support"), "section");
      EXPECT_EQ(r.at("discretization").at("vertex_columns"), v.at("enrichment").at("columns"));
    }
    problem["rfm"] = {{"vertex_support", "local"}};
    std::ofstream(in) << problem.dump();
    {
      const Outcome o = run(in.string() + " --degree 6 --output " + out.string());
      EXPECT_EQ(o.status, 0) << o.err;
      std::ifstream f(out);
      const nlohmann::json r = nlohmann::json::parse(f);
      EXPECT_EQ(r.at("diagnostics").at("singular_vertices")[0].at("enrichment").at("support"), "local");
    }
    problem["rfm"] = {{"vertex_max_exponent", 0.0}};
    std::ofstream(in) << problem.dump();
    {
      const Outcome o = run(in.string() + " --degree 6 --output " + out.string());
      EXPECT_EQ(o.status, 0) << o.err;
      EXPECT_NE(o.err.find("singular"), std::string::npos) << o.err;
      std::ifstream f(out);
      const nlohmann::json r = nlohmann::json::parse(f);
      const nlohmann::json &d = r.at("diagnostics");
      EXPECT_EQ(d.at("status"), "warning");
      EXPECT_NE(d.at("message").get<std::string>().find("singular"), std::string::npos);
      EXPECT_TRUE(d.at("singular_vertices")[0].at("enrichment").is_null());
      EXPECT_EQ(r.at("discretization").at("vertex_columns"), 0);
    }
  }


  // A die on an outline part: the paper's die written as an outline (the half section, not
  // mirrored: its force is half the body's), solved on a given zone; the zone's search is
  // refused (exit 2) until the outline RFM has it.
  TEST(RfmSolveCli, OutlineDieOnAGivenZone)
  {
    const fs::path dir = scratch("outline_die");
    nlohmann::json j = axisym::testing::paper_die_outline();
    j["contact"] = {{"method", "fixed"}};
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << j.dump();
    Outcome o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    // The whole part in contact (c defaults to it): the paper's iteration 0, half of the FEM's
    // bilateral force 128728.67459 N (Q2, L = 5) on this half section.
    EXPECT_EQ(r.at("contact").at("part"), "outer");
    EXPECT_NEAR(r.at("contact").at("force").get<double>(), 0.5 * 128728.67459, 1e-8 * 64364.3);
    EXPECT_NEAR(r.at("contact").at("half_width").get<double>(), 0.2, 1e-15);
    // No free end, so no contact edge: a fixed degree is judged as without a die, and p = 8's
    // indicator (1.4e-5 when written) is above the 1e-5 a fixed degree is allowed.
    EXPECT_EQ(r.at("diagnostics").at("status"), "warning");
    EXPECT_EQ(r.at("diagnostics").at("warnings")[0].at("check"), "indicator");
    EXPECT_TRUE(r.at("diagnostics").contains("check_at_lower_degree"));
    EXPECT_EQ(r.at("dies").size(), 1u);
    EXPECT_EQ(r.at("contact").at("pressure").size(), 101u);

    // A zone that ends inside the part: solved with the edge modes, K reported (c = 0.1 m is
    // a little short of c*: K < 0); without the modes, with a warning.
    j["contact"]["half_width"] = 0.1;
    std::ofstream(in) << j.dump();
    o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    r = nlohmann::json::parse(std::ifstream(out));
    EXPECT_EQ(r.at("diagnostics").at("status"), "ok");
    EXPECT_LT(r.at("contact").at("edge_intensity").get<double>(), 0.0);
    j["rfm"]["edge_modes"] = 0;
    std::ofstream(in) << j.dump();
    o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    r = nlohmann::json::parse(std::ifstream(out));
    EXPECT_EQ(r.at("diagnostics").at("status"), "warning");
    EXPECT_TRUE(r.at("contact").at("edge_intensity").is_null());
    EXPECT_NE(o.err.find("edge_modes"), std::string::npos) << o.err;
    j["rfm"].erase("edge_modes");

    // The zone's search (the default, edge-intensity): against the finest FEM of the paper's
    // die (Q2, L = 5, reports/data/fem_convergence_die.json): c = 0.5192805 a = 0.1038561 m,
    // P = 192617.1 N for the whole body. Measured at p = 8 when written: c 2.8e-4 and P
    // 3.1e-5 from it (the rectangle model: 4.4e-4 and 6.8e-5).
    j.erase("contact");
    std::ofstream(in) << j.dump();
    o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    r = nlohmann::json::parse(std::ifstream(out));
    EXPECT_EQ(r.at("contact").at("method"), "edge-intensity");
    EXPECT_NEAR(r.at("contact").at("half_width").get<double>(), 0.1038561, 1e-3 * 0.1038561);
    EXPECT_NEAR(r.at("contact").at("force").get<double>(), 0.5 * 192617.1, 1e-4 * 96308.6);
    EXPECT_LT(std::abs(r.at("contact").at("edge_intensity").get<double>()), 1e3); // the root of K
  }

  // Samples on a die's zone (issue 24 item 6): the stress space's trace against the
  // consistent reactions. The references are the FEM's (fem_solve, Q2 graded meshes), an
  // independent solver: sigma_rr = -822870 Pa at (0.2, 0.05) for the paper's die by its
  // search (L = 4, die_paper_outline.json), -0.9153 MPa at (0.2, 0) of the same die on the
  // hollow-cylinder form by `iterate` (L = 4, die_unilateral.json), and for the bilateral zone
  // over the whole face -0.8044 MPa at (0.2, 0) (L = 3, 4 and 5 agree to 1e-4 MPa).
  TEST(RfmSolveCli, SampleOnAContactZoneWarns)
  {
    const fs::path dir = scratch("contact_samples");
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    nlohmann::json j = axisym::testing::paper_die_outline();
    j["samples"] = {{0.2, 0.05}, {0.15, 0.1}};
    std::ofstream(in) << j.dump();
    Outcome o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    // Measured when written: the trace 831958 Pa, 1.1 % off; the consistent 822955 Pa.
    const double fem = 822870.0;
    const nlohmann::json &on = r.at("samples")[0];
    EXPECT_NEAR(on.at("contact_pressure").get<double>(), fem, 1e-3 * fem);
    EXPECT_GT(std::abs(-on.at("sigma_rr").get<double>() - fem), 5e-3 * fem);
    EXPECT_FALSE(r.at("samples")[1].contains("contact_pressure"));
    ASSERT_EQ(r.at("diagnostics").at("contact_samples").size(), 1u);
    EXPECT_EQ(r.at("diagnostics").at("status"), "warning");
    EXPECT_EQ(r.at("diagnostics").at("warnings")[0].at("check"), "sample_on_contact_zone");

    // The bilateral zone over the whole face: the consistent form (a square-root fall at the
    // zone's end) does not apply, contact.pressure's p is the trace, and the sample where the
    // zone meets the free end face warns. Without a free end the fixed degree is judged as
    // without a die: the indicator (1.4e-5) and the samples' moves since p = 6 warn too
    // (measured: (0.2, 0) 0.8 %, where sigma_zz is -0.9436 MPa against the FEM's -0.9649).
    j["contact"] = {{"method", "fixed"}};
    j["samples"] = {{0.2, 0.0}, {0.2, 0.2}};
    std::ofstream(in) << j.dump();
    o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    r = nlohmann::json::parse(std::ifstream(out));
    const nlohmann::json &p0 = r.at("contact").at("pressure")[0];
    EXPECT_EQ(p0.at("p").get<double>(), p0.at("p_trace").get<double>());
    EXPECT_NEAR(p0.at("p").get<double>(), 0.8044e6, 1e-2 * 0.8044e6);
    EXPECT_FALSE(r.at("diagnostics").contains("contact_samples"));
    std::vector<std::string> checks;
    for (const nlohmann::json &w : r.at("diagnostics").at("warnings"))
      checks.push_back(w.at("check"));
    EXPECT_EQ(checks, (std::vector<std::string>{"samples_at_zone_ends", "indicator", "sample_moved"}));
    EXPECT_NE(o.err.find("(0.2, 0.2) m on part outer"), std::string::npos) << o.err;
    EXPECT_NEAR(r.at("samples")[0].at("sigma_zz").get<double>(), -0.9649e6, 3e-2 * 0.9649e6);

    // The hollow-cylinder form (its own branch of rfm_solve) gets the same check.
    const nlohmann::json legacy = {
      {"geometry", {{"inner_radius", 0.1}, {"outer_radius", 0.2}, {"length", 0.4}}},
      {"material", {{"youngs_modulus", 2.1e11}, {"poisson_ratio", 0.3}}},
      {"die", {{"indentation", 1.0e-6}, {"profile", "parabolic"}}},
      {"contact", {{"method", "iterate"}}},
      {"samples", {{0.2, 0.0}}}};
    std::ofstream(in) << legacy.dump();
    o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    r = nlohmann::json::parse(std::ifstream(out));
    const double fem_centre = 0.9153e6;
    EXPECT_NEAR(r.at("samples")[0].at("contact_pressure").get<double>(), fem_centre, 2e-3 * fem_centre);
    EXPECT_GT(std::abs(-r.at("samples")[0].at("sigma_rr").get<double>() - fem_centre), 2e-2 * fem_centre);
    EXPECT_EQ(r.at("diagnostics").at("warnings")[0].at("check"), "sample_on_contact_zone");
  }

  // The paper's iterations on the outline path (outline_contact.h): the same zone, the
  // record of every solve with its conditions, the bracket of c where they hold; not for a
  // zone with two free ends. (Its own test: the sanitizers' run stays short.)
  TEST(RfmSolveCli, IterateOnAnOutlineDie)
  {
    const fs::path dir = scratch("outline_iterate");
    nlohmann::json j = axisym::testing::paper_die_outline();
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    // p = 6 keeps it short under the sanitizers (measured: c 1.6e-5 from the FEM's, 27 solves).
    j["contact"] = {{"method", "iterate"}};
    j["rfm"]["degree"] = 6;
    std::ofstream(in) << j.dump();
    Outcome o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    const nlohmann::json &it = r.at("contact");
    EXPECT_EQ(it.at("method"), "iterate");
    EXPECT_EQ(it.at("part"), "outer");
    EXPECT_NEAR(it.at("half_width").get<double>(), 0.1038561, 1e-3 * 0.1038561);
    ASSERT_GE(it.at("iterations").size(), 3u);
    EXPECT_EQ(it.at("iterations")[0].at("half_width"), 0.2); // the paper's iteration 0: c = a
    EXPECT_FALSE(it.at("iterations")[0].at("condition_1_2_holds").get<bool>());
    const auto range = it.at("half_width_range").get<std::array<double, 2>>();
    EXPECT_LE(range[0], it.at("half_width").get<double>());
    EXPECT_GE(range[1], it.at("half_width").get<double>());
    EXPECT_TRUE(it.at("conditions").contains("max_penetration_relative"));
    EXPECT_EQ(r.at("dies").size(), 1u);

    // Not for a zone with two free ends (the die's centre inside its part): bad input.
    j["boundary"]["outer"]["die"]["center"] = {0.2, 0.1};
    std::ofstream(in) << j.dump();
    fs::remove(out);
    o = run(in.string() + " --output " + out.string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("contact.method"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("one free end"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(out));
  }

  // Several dies: every die in `dies` in the same form, `contact` the first; zones as given
  // with contact.method fixed (no local boxes: quick); iterate searches one die: bad input.
  TEST(RfmSolveCli, SeveralDiesAreAllInTheResult)
  {
    const fs::path dir = scratch("dies");
    nlohmann::json j = axisym::testing::cylinder_between_two_dies();
    j["rfm"]["local_levels"] = 0;
    j["contact"] = {{"method", "fixed"}, {"half_width", 0.005}};
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    std::ofstream(in) << j.dump();
    Outcome o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    ASSERT_EQ(r.at("dies").size(), 2u);
    EXPECT_EQ(r.at("dies")[0].at("part"), "bottom");
    EXPECT_EQ(r.at("dies")[1].at("part"), "top");
    EXPECT_EQ(r.at("contact"), r.at("dies")[0]);
    for (const nlohmann::json &die : r.at("dies"))
      {
        EXPECT_EQ(die.at("half_width"), 0.005);
        EXPECT_EQ(die.at("pressure").size(), 101u);
        EXPECT_TRUE(die.at("edge_intensity").is_number()); // one free end each
      }
    // Mirror images: the same force and K.
    EXPECT_NEAR(r.at("dies")[1].at("force").get<double>(), r.at("dies")[0].at("force").get<double>(),
                1e-9 * r.at("dies")[0].at("force").get<double>());
    EXPECT_NE(o.err.find("die on top"), std::string::npos) << o.err;

    j["contact"] = {{"method", "iterate"}};
    std::ofstream(in) << j.dump();
    fs::remove(out);
    o = run(in.string() + " --output " + out.string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("contact.method"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(out));
  }

  // --vtu DIR creates DIR (and its parents) and writes the fields with the FEM's names and
  // the displacement as one vector; a DIR that is a file is bad input.
  TEST(RfmSolveCli, VtuCreatesTheFolderAndWritesTheFields)
  {
    const fs::path dir = scratch("vtu");
    const fs::path in = dir / "problem.json", vtu = dir / "new" / "nested";
    std::ofstream(in) << valid().dump();
    Outcome o = run(in.string() + " --vtu " + vtu.string());
    EXPECT_EQ(o.status, 0) << o.err;
    std::ifstream f(vtu / "rfm_solution.vtu");
    ASSERT_TRUE(f) << o.err;
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    for (const char *name : {"\"u_r\"", "\"sigma_rr\"", "\"sigma_tt\"", "\"sigma_rz\"",
                             "Name=\"displacement\" NumberOfComponents=\"3\""})
      EXPECT_NE(text.find(name), std::string::npos) << name;
    EXPECT_NE(text.find("NumberOfPoints=\"20301\""), std::string::npos);

    o = run(in.string() + " --vtu " + in.string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("--vtu"), std::string::npos) << o.err;
  }

  // A contact zone the space does not resolve warns and says how far Phi_L and Phi_C are from
  // Phi_R: the rounded flat punch at its FEM's zone without local boxes (P 73 % off at p = 8;
  // measured here: indicator 13.3, Phi_L 11 and Phi_C 1.9 from Phi_R, so "the field"; with
  // the defaults' boxes 0.18, 0.0025: "the displacement field (Phi_L)").
  TEST(RfmSolveCli, AnUnresolvedZoneWarnsNamingTheField)
  {
    const fs::path dir = fs::temp_directory_path() / "rfm_cli_unresolved_zone";
    fs::create_directories(dir);
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    auto j = axisym::testing::punched_cylinder(); // flat_rounded_punch_indentation.json's section
    j["boundary"]["top"]["die"] = {
      {"indentation", 2e-6},
      {"profile", {{"shape", "flat_rounded"}, {"flat_radius", 5e-4}, {"edge_radius", 0.05}}}};
    j["contact"] = {{"method", "fixed"}, {"half_width", 0.747413e-3}};
    j["rfm"] = {{"local_levels", 0}};
    std::ofstream(in) << j.dump();
    const Outcome o = run(in.string() + " --output " + out.string());
    ASSERT_EQ(o.status, 0) << o.err;
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
    EXPECT_EQ(r.at("diagnostics").at("status"), "warning");
    const std::string message = r.at("diagnostics").at("message");
    EXPECT_NE(message.find("from Phi_R"), std::string::npos) << message;
    EXPECT_NE(message.find("field"), std::string::npos) << message;
    EXPECT_NE(o.err.find(message), std::string::npos) << o.err;
  }

  // A die pushed off by an outer pressure larger than its indentation can hold: K > 0 for
  // every zone down to 0.01 a, so the root of K(c) is not bracketed in (0, a]. A numerical
  // failure: exit 3, a message, and the result with the search history still written.
  TEST(RfmSolveCli, UnbracketedEdgeIntensityExitsWithStatus3AndWritesTheHistory)
  {
    const fs::path dir = fs::temp_directory_path() / "rfm_cli_unbracketed";
    fs::create_directories(dir);
    const fs::path in = dir / "problem.json", out = dir / "result.json";
    fs::remove(out);
    nlohmann::json j = valid();
    j["loading"] = {{"inner_pressure", 0.0}, {"outer_pressure", 2.0e6}};
    j["die"] = {{"indentation", 1.0e-6}};
    // p = 8: at p = 4 the outline model's K(c) changes sign near c = 0.01 a (a support of
    // 0.002 m against polynomials of degree 4 on 0.2 m), a spurious root.
    // No local boxes: the bracket walks c down to 0.01 a, where they would add four levels
    // to every solve (51 s instead of a few; with them, at the defaults, the same exit 3);
    // they are not what this test is about. Without them a zone of 0.01 a is not resolved,
    // and the edge modes times monomials of degree 4 (the default) then give K(c) a spurious
    // root at 0.012 a (measured); degree 2 does not.
    j["rfm"] = {{"degree", 8}, {"local_levels", 0}, {"edge_mode_degree", 2}};
    std::ofstream(in) << j.dump();
    const Outcome o = run(in.string() + " --output " + out.string());
    EXPECT_EQ(o.status, 3) << o.err;
    EXPECT_NE(o.err.find("not bracketed"), std::string::npos) << o.err;
    ASSERT_TRUE(fs::exists(out));
    std::ifstream f(out);
    const nlohmann::json r = nlohmann::json::parse(f);
    EXPECT_EQ(r.at("diagnostics").at("status"), "failed");
    ASSERT_GE(r.at("contact").at("iterations").size(), 3u);
    for (const auto &it : r.at("contact").at("iterations"))
      EXPECT_GT(it.at("edge_intensity").get<double>(), 0.0);
  }
} // namespace
