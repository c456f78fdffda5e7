#include "problem/problem.h"
#include "problem/test_problems.h"

#include <gtest/gtest.h>

namespace axisym
{
  namespace
  {
    nlohmann::json valid()
    {
      return nlohmann::json::parse(R"({
        "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
        "loading": {"inner_pressure": 1.0e7, "outer_pressure": 0.0},
        "samples": [[0.15, 0.0], [0.2, -0.2]],
        "rfm": {"degree": 7}
      })");
    }

    // The message must name the field, and mention the value and the rule.
    void expect_error(const nlohmann::json &j, const std::vector<std::string> &fragments)
    {
      try
        {
          parse_problem(j);
          ADD_FAILURE() << "accepted: " << j.dump();
        }
      catch (const InputError &e)
        {
          for (const auto &f : fragments)
            EXPECT_NE(std::string(e.what()).find(f), std::string::npos)
              << "message '" << e.what() << "' lacks '" << f << "'";
        }
    }
  } // namespace

  TEST(Problem, ParsesTheDesignExample)
  {
    const Problem p = parse_problem(valid());
    EXPECT_DOUBLE_EQ(p.geometry.half_length(), 0.2);
    EXPECT_DOUBLE_EQ(p.material.poisson_ratio, 0.3);
    ASSERT_TRUE(p.loading.has_value());
    EXPECT_DOUBLE_EQ(p.loading->inner_pressure, 1e7);
    EXPECT_FALSE(p.die.has_value());
    EXPECT_EQ(p.samples.size(), 2u);
    EXPECT_EQ(p.rfm.degree, 7);
  }

  TEST(Problem, RejectsBadInputNamingFieldValueAndRule)
  {
    auto j = valid();
    j["geometry"]["inner_radius"] = 0.3;
    expect_error(j, {"geometry.outer_radius", "0.2", "must exceed"});

    j = valid();
    j["geometry"]["inner_radius"] = -0.1;
    expect_error(j, {"geometry.inner_radius", "-0.1", "> 0"});

    j = valid();
    j["material"]["poisson_ratio"] = 0.5;
    expect_error(j, {"material.poisson_ratio", "0.5", "(-1, 0.5)"});

    j = valid();
    j["material"]["youngs_modulus"] = "steel";
    expect_error(j, {"material.youngs_modulus", "\"steel\"", "must be a number"});

    j = valid();
    j["geometry"]["radius"] = 1.0;
    expect_error(j, {"unknown key", "geometry.radius"});

    j = valid();
    j.erase("loading");
    expect_error(j, {"loading", "die"});

    j = valid();
    j["samples"] = {{0.05, 0.0}};
    expect_error(j, {"samples[0]", "0.05", "section"});

    j = valid();
    j["rfm"]["degree"] = 2.5;
    expect_error(j, {"rfm.degree", "2.5", "integer"});

    j = valid();
    j["die"] = {{"indentation", 0.01}};
    expect_error(j, {"die.indentation", "0.01", "small strain"});

    j = valid();
    j["contact"] = {{"method", "guess"}};
    expect_error(j, {"contact.method", "\"guess\"", "\"iterate\""});

    j = valid();
    j.erase("material");
    expect_error(j, {"material"});
  }

  TEST(Problem, MissingAndMalformedFiles)
  {
    EXPECT_THROW(read_problem_file("/nonexistent/problem.json"), InputError);
  }
} // namespace axisym

namespace axisym
{
  namespace
  {
    // The thick spherical shell of DESIGN.md 7.1 (a quarter annulus touching the axis).
    nlohmann::json sphere()
    {
      nlohmann::json j = testing::thick_sphere();
      j["samples"] = {{0.1, 0.05}, {0.0, 0.15}};
      return j;
    }
  } // namespace

  TEST(ProblemOutline, ParsesTheSphereOfTheDesign)
  {
    const Problem p = parse_problem(sphere());
    EXPECT_FALSE(p.legacy_cylinder);
    ASSERT_TRUE(p.body);
    const Body &b = *p.body;
    EXPECT_FALSE(b.mirrored);
    ASSERT_EQ(b.outline.edges().size(), 4u);
    EXPECT_EQ(b.conditions.at("equator").kind, PartCondition::Kind::symmetry);
    EXPECT_EQ(b.conditions.at("outer").kind, PartCondition::Kind::traction_free);
    EXPECT_EQ(b.conditions.at("axis").kind, PartCondition::Kind::axis);
    EXPECT_EQ(b.conditions.at("inner").kind, PartCondition::Kind::pressure);
    EXPECT_EQ(b.conditions.at("inner").pressure, 1e7);
    EXPECT_EQ(b.condition_of_edge(3).kind, PartCondition::Kind::pressure);
    EXPECT_NEAR(b.outline.signed_area(), M_PI * (0.04 - 0.01) / 4, 1e-15);
    EXPECT_EQ(p.samples.size(), 2u);
    EXPECT_FALSE(p.body_loads.any());
  }

  // The legacy form becomes the half section [R1, R2] x [0, a], mirrored.
  TEST(ProblemOutline, LegacyCylinderBecomesARectangleOutline)
  {
    nlohmann::json j = nlohmann::json::parse(R"({
      "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "die": {"indentation": 1e-6}})");
    const Problem p = parse_problem(j);
    EXPECT_TRUE(p.legacy_cylinder);
    ASSERT_TRUE(p.body);
    EXPECT_TRUE(p.body->mirrored);
    EXPECT_NEAR(p.body->outline.signed_area(), 0.1 * 0.2, 1e-17);
    EXPECT_EQ(p.body->conditions.at("outer").kind, PartCondition::Kind::die);
    EXPECT_EQ(p.body->conditions.at("inner").kind, PartCondition::Kind::traction_free);
    EXPECT_EQ(p.body->conditions.at("mid_plane").kind, PartCondition::Kind::symmetry);
    EXPECT_EQ(p.body->conditions.at("end").kind, PartCondition::Kind::traction_free);
  }

  TEST(ProblemOutline, ParsesConditionsAndBodyLoads)
  {
    auto j = sphere();
    j["boundary"]["outer"] = {{"traction", {1.0, -2.0}}};
    j["material"]["density"] = 7850;
    j["material"]["thermal_expansion"] = 1.2e-5;
    j["loading"] = nlohmann::json::parse(
      R"({"angular_velocity": 100, "gravity": 9.81, "temperature": {"field": [10, 0, 50]}})");
    const Problem p = parse_problem(j);
    EXPECT_EQ(p.body->conditions.at("outer").kind, PartCondition::Kind::traction);
    EXPECT_EQ(p.body->conditions.at("outer").traction[1], -2.0);
    EXPECT_TRUE(p.body_loads.any());
    EXPECT_EQ(p.body_loads.temperature[2], 50.0);
    EXPECT_EQ(*p.material.density, 7850.0);
  }

  // DESIGN.md 7.1's list of bad input, each naming the field.
  TEST(ProblemOutline, RejectsBadInputNamingTheField)
  {
    auto j = sphere();
    j["geometry"]["outline"][4]["arc_to"] = {0.1, 0.01};
    expect_error(j, {"geometry.outline"});

    j = sphere(); // clockwise: the same loop backwards
    j["geometry"]["outline"] = nlohmann::json::parse(R"([
      {"start": [0.1, 0.0]}, {"arc_to": [0.0, 0.1], "center": [0.0, 0.0], "part": "inner"},
      {"line_to": [0.0, 0.2], "part": "axis"},
      {"arc_to": [0.2, 0.0], "center": [0.0, 0.0], "part": "outer"},
      {"line_to": [0.1, 0.0], "part": "equator"}])");
    expect_error(j, {"geometry.outline", "counter-clockwise"});

    j = sphere();
    j["geometry"]["outline"][0]["start"] = {-0.1, 0.0};
    j["geometry"]["outline"][4]["arc_to"] = {-0.1, 0.0};
    expect_error(j, {"geometry.outline"});

    j = sphere();
    j["geometry"]["outline"][2]["center"] = {0.0, 0.01};
    expect_error(j, {"geometry.outline[2]"});

    j = sphere();
    j["boundary"]["hole"] = {{"pressure", 1.0}};
    expect_error(j, {"boundary.hole", "no such part", "equator"});

    j = sphere();
    j["boundary"]["axis"] = {{"pressure", 1.0}};
    expect_error(j, {"boundary.axis", "axis"});

    j = sphere();
    j["boundary"]["outer"] = {{"symmetry", true}};
    expect_error(j, {"boundary.outer.symmetry", "arc"});

    j = sphere();
    j["boundary"]["outer"] = {{"pressure", 1.0}, {"traction", {0.0, 0.0}}};
    expect_error(j, {"boundary.outer", "exactly one"});

    j = sphere();
    j["samples"] = {{0.05, 0.05}};
    expect_error(j, {"samples[0]", "0.05", "inside geometry.outline"});

    j = sphere();
    j["loading"] = {{"angular_velocity", 10.0}};
    expect_error(j, {"loading.angular_velocity", "material.density"});

    j = sphere();
    j["loading"] = {{"temperature", {{"field", {1.0, 0.0, 0.0}}}}};
    expect_error(j, {"loading.temperature", "material.thermal_expansion"});

    j = sphere();
    j["material"]["density"] = -1.0;
    expect_error(j, {"material.density", "-1", "> 0"});

    j = sphere();
    j["boundary"].erase("equator");
    expect_error(j, {"boundary", "translation in z"});

    j = sphere();
    j["geometry"]["outline"][1]["part"] = "axis";
    expect_error(j, {"geometry.outline[1].part", "axis"});

    j = sphere();
    j["die"] = {{"indentation", 1e-6}};
    expect_error(j, {"die", "hollow-cylinder"});
  }
} // namespace axisym
