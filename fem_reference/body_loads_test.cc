// The pointwise body loads against DESIGN.md 7.1 written out by hand.
#include "fem_reference/body_loads.h"

#include "problem/test_problems.h"

#include <gtest/gtest.h>

namespace fem
{
  namespace
  {
    nlohmann::json sphere_with(const nlohmann::json &loading)
    {
      nlohmann::json j = axisym::testing::thick_sphere();
      j["material"]["density"] = 7850.0;
      j["material"]["thermal_expansion"] = 1.2e-5;
      j["loading"] = loading;
      return j;
    }
  } // namespace

  TEST(BodyLoadField, RotationGravityAndTemperatureAsInDesign71)
  {
    const axisym::Problem p = axisym::parse_problem(
      sphere_with({{"angular_velocity", 300.0},
                   {"gravity", 9.81},
                   {"temperature", {{"field", {50.0, -200.0, 100.0}}}}}));
    const BodyLoadField loads(p);
    EXPECT_TRUE(loads.has_force());
    EXPECT_TRUE(loads.has_thermal_strain());
    const double r = 0.15, z = 0.05;
    const std::array<double, 2> f = loads.force(r, z);
    EXPECT_DOUBLE_EQ(f[0], 7850.0 * 300.0 * 300.0 * r); // centrifugal, along +e_r
    EXPECT_DOUBLE_EQ(f[1], -7850.0 * 9.81);             // weight, along -e_z
    EXPECT_DOUBLE_EQ(loads.thermal_strain(r, z), 1.2e-5 * (50.0 - 200.0 * r + 100.0 * z));
  }

  // Without loads (and for the legacy form, which cannot state them) every value is an exact
  // zero: the FEM's numbers without body loads stay what they were.
  TEST(BodyLoadField, NoLoadsGiveExactZeros)
  {
    for (const axisym::Problem &p :
         {axisym::parse_problem(axisym::testing::thick_sphere()),
          axisym::parse_problem(sphere_with({{"gravity", 0.0}})),
          axisym::parse_problem(nlohmann::json::parse(R"({
            "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
            "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
            "loading": {"inner_pressure": 1.0e7}})"))})
      {
        const BodyLoadField loads(p);
        EXPECT_FALSE(loads.any());
        EXPECT_EQ(loads.force(0.2, 0.1)[0], 0.0);
        EXPECT_EQ(loads.force(0.2, 0.1)[1], 0.0);
        EXPECT_EQ(loads.thermal_strain(0.2, 0.1), 0.0);
      }
    // Only a thermal load: no force; only gravity: no thermal strain.
    const BodyLoadField thermal(
      axisym::parse_problem(sphere_with({{"temperature", {{"field", {0.0, 0.0, 1.0}}}}})));
    EXPECT_FALSE(thermal.has_force());
    EXPECT_TRUE(thermal.has_thermal_strain());
    const BodyLoadField weight(axisym::parse_problem(sphere_with({{"gravity", 9.81}})));
    EXPECT_TRUE(weight.has_force());
    EXPECT_FALSE(weight.has_thermal_strain());
  }

  // A Problem assembled by hand without the constant its load needs: bad input, naming it.
  TEST(BodyLoadField, MissingMaterialConstantIsAnInputError)
  {
    axisym::Problem p = axisym::parse_problem(axisym::testing::thick_sphere());
    p.body_loads.angular_velocity = 10.0;
    try
      {
        BodyLoadField loads(p);
        ADD_FAILURE() << "accepted a rotation without material.density";
      }
    catch (const axisym::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find("material.density"), std::string::npos) << e.what();
      }
    p = axisym::parse_problem(axisym::testing::thick_sphere());
    p.body_loads.temperature[0] = 10.0;
    EXPECT_THROW(BodyLoadField{p}, axisym::InputError);
  }
} // namespace fem
