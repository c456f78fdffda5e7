// fem_solve through its command line (FEM_SOLVE is the path of the executable under test):
// an outline problem end to end, --vtu into a directory that does not exist yet, and the
// input errors of the outline path (exit 2, message naming the field, nothing written).
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <unistd.h>

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
    const fs::path dir =
      fs::temp_directory_path() / ("fem_cli_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
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
    EXPECT_EQ(r.at("discretization").at("refinements"), 1);
    EXPECT_GT(r.at("discretization").at("base_cells").get<int>(), 0);
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

  TEST(FemSolveCli, BodyLoadsOnAnOutlineExitWith2BeforeAnyWork)
  {
    const fs::path dir = scratch("body_loads");
    const fs::path in = dir / "sphere.json", out = dir / "result.json";
    nlohmann::json j = sphere();
    j["material"]["density"] = 7850;
    j["loading"] = {{"angular_velocity", 100.0}};
    std::ofstream(in) << j.dump();
    const Outcome o = run(in.string() + " --output " + out.string() + " --vtu " +
                          (dir / "vtu").string());
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("loading: body loads are not applied by fem_solve yet"),
              std::string::npos)
      << o.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir / "vtu"));
    fs::remove_all(dir);
  }

  TEST(FemSolveCli, StructuredMeshOnAnOutlineExitsWith2)
  {
    const fs::path dir = scratch("structured");
    const fs::path in = dir / "sphere.json";
    std::ofstream(in) << sphere().dump();
    const Outcome o = run(in.string() + " --mesh structured");
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("--mesh"), std::string::npos) << o.err;
    fs::remove_all(dir);
  }
} // namespace
