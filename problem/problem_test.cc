#include "problem/problem.h"
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <cmath>

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

  // rfm.vertex_support takes "blended" (the default) beside "local" and "section", and
  // rfm.rough_vertices "all" (the default) beside true (where a traction jumps) and false.
  TEST(Problem, VertexSupportAndRoughVerticesSettings)
  {
    nlohmann::json j = testing::tapered_hub();
    const Problem defaults = parse_problem(j);
    EXPECT_EQ(defaults.rfm.vertex_support, RfmSettings::VertexSupport::blended);
    EXPECT_TRUE(defaults.rfm.rough_vertices);
    EXPECT_TRUE(defaults.rfm.rough_vertices_everywhere);
    j["rfm"] = {{"vertex_support", "section"}, {"rough_vertices", true}};
    const Problem jumps = parse_problem(j);
    EXPECT_EQ(jumps.rfm.vertex_support, RfmSettings::VertexSupport::section);
    EXPECT_TRUE(jumps.rfm.rough_vertices);
    EXPECT_FALSE(jumps.rfm.rough_vertices_everywhere);
    j["rfm"] = {{"vertex_support", "blended"}, {"rough_vertices", "all"}};
    const Problem all = parse_problem(j);
    EXPECT_EQ(all.rfm.vertex_support, RfmSettings::VertexSupport::blended);
    EXPECT_TRUE(all.rfm.rough_vertices);
    EXPECT_TRUE(all.rfm.rough_vertices_everywhere);
    j["rfm"] = {{"vertex_support", "local"}, {"rough_vertices", false}};
    const Problem none = parse_problem(j);
    EXPECT_EQ(none.rfm.vertex_support, RfmSettings::VertexSupport::local);
    EXPECT_FALSE(none.rfm.rough_vertices);
    EXPECT_FALSE(none.rfm.rough_vertices_everywhere);
    j["rfm"] = {{"rough_vertices", "some"}};
    EXPECT_THROW(parse_problem(j), InputError);
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
    expect_error(j, {"die", "hollow-cylinder", "boundary.PART.die"});
  }

  // A die on a straight part (DESIGN.md 7.1): its frame and default centre.
  TEST(ProblemDie, ParsesADieOnAPartWithItsFrame)
  {
    const Problem p = parse_problem(testing::punched_cylinder());
    ASSERT_EQ(p.body->die_parts(), std::vector<std::string>{"top"});
    const DieCondition &die = p.body->conditions.at("top").die;
    EXPECT_EQ(p.body->conditions.at("top").kind, PartCondition::Kind::die);
    ASSERT_TRUE(die.force.has_value());
    EXPECT_FALSE(die.indentation.has_value());
    EXPECT_EQ(*die.force, 2000.0);
    // Default centre: the end of `top` on the axis.
    EXPECT_EQ(die.center.r, 0.0);
    EXPECT_EQ(die.center.z, 0.02);
    const DieFrame f = die_frame(*p.body, "top");
    // `top` runs from (0.02, 0.02) to (0, 0.02): tangent -e_r, outward normal +e_z.
    EXPECT_DOUBLE_EQ(f.tangent.r, -1.0);
    EXPECT_DOUBLE_EQ(f.normal.z, 1.0);
    EXPECT_NEAR(f.s_min, -0.02, 1e-15);
    EXPECT_NEAR(f.s_max, 0.0, 1e-15);
    EXPECT_NEAR(f.coordinate({0.005, 0.02}), -0.005, 1e-15);
    EXPECT_DOUBLE_EQ(die.profile.gap(0.01), 0.01 * 0.01 / 0.2);

    // A part whose ends meet neither a symmetry edge nor the axis: the midpoint.
    auto j = testing::punched_cylinder();
    j["boundary"]["bottom"] = {{"displacement", {0.0, 0.0}}};
    j["boundary"]["side"] = j["boundary"]["top"];
    j["boundary"].erase("top");
    const Problem q = parse_problem(j);
    EXPECT_NEAR(q.body->conditions.at("side").die.center.r, 0.02, 1e-15);
    EXPECT_NEAR(q.body->conditions.at("side").die.center.z, 0.01, 1e-15);
    // With bottom a symmetry plane, the side's end on it.
    j["boundary"]["bottom"] = {{"symmetry", true}};
    EXPECT_NEAR(parse_problem(j).body->conditions.at("side").die.center.z, 0.0, 1e-15);
    // A centre given on the part.
    j["boundary"]["side"]["die"]["center"] = {0.02, 0.015};
    EXPECT_NEAR(parse_problem(j).body->conditions.at("side").die.center.z, 0.015, 1e-15);
  }

  TEST(ProblemDie, ProfilesGiveTheirGaps)
  {
    DieProfile flat_rounded;
    flat_rounded.shape = DieProfile::Shape::flat_rounded;
    flat_rounded.flat_radius = 2.0, flat_rounded.edge_radius = 4.0;
    EXPECT_EQ(flat_rounded.gap(1.5), 0.0);
    EXPECT_DOUBLE_EQ(flat_rounded.gap(3.0), 1.0 / 8.0);
    DieProfile flat;
    flat.shape = DieProfile::Shape::flat;
    flat.radius = 2.0;
    EXPECT_EQ(flat.gap(2.0), 0.0);
    EXPECT_TRUE(std::isinf(flat.gap(2.0001)));
    EXPECT_EQ(flat.extent(), 2.0);
  }

  // The legacy die is the paraboloid R = a^2 / (4 delta) centred on the mid-plane: the
  // normal displacement into the body, delta - g0(z), is -u_r*(z) of paper eq. 4.1.
  TEST(ProblemDie, LegacyDieIsTheParaboloidOnTheOuterPart)
  {
    auto j = valid();
    j["die"] = {{"indentation", 1e-6}};
    const Problem p = parse_problem(j);
    const PartCondition &outer = p.body->conditions.at("outer");
    ASSERT_EQ(outer.kind, PartCondition::Kind::die);
    EXPECT_EQ(outer.die.center.r, 0.2);
    EXPECT_EQ(outer.die.center.z, 0.0);
    for (const double z : {0.0, 0.05, 0.13, 0.2})
      EXPECT_NEAR(*outer.die.indentation - outer.die.profile.gap(z),
                  -die_u_r(*p.die, p.geometry, z), 1e-22)
        << z;
  }

  // The bad-input list of DESIGN.md 7.1 for dies: each names the field.
  // A die by indentation on an end face holds the body in z (it prescribes u_z on its zone):
  // a cylinder between two dies needs no symmetry plane. Under force alone it would be free
  // to translate.
  TEST(ProblemDie, AnIndentationHoldsTheBody)
  {
    auto j = testing::cylinder_between_two_dies();
    const Problem p = parse_problem(j);
    EXPECT_EQ(p.body->die_parts(), (std::vector<std::string>{"bottom", "top"}));
    j["boundary"]["top"]["die"].erase("indentation");
    j["boundary"]["top"]["die"]["force"] = 1e5;
    EXPECT_NO_THROW(parse_problem(j));
    j["boundary"]["bottom"]["die"].erase("indentation");
    j["boundary"]["bottom"]["die"]["force"] = 1e5;
    expect_error(j, {"boundary", "translation in z"});
  }

  TEST(ProblemDie, RejectsBadDiesNamingTheField)
  {
    auto j = testing::punched_cylinder();
    j["boundary"]["side"] = {{"die", {{"indentation", 1e-6},
                                      {"profile", {{"shape", "paraboloid"}, {"radius", 0.1}}}}}};
    j["geometry"]["outline"][2] = {{"arc_to", {0.0, 0.02}}, {"center", {0.0, 0.0}}, {"part", "side"}};
    j["geometry"]["outline"].erase(3);
    j["boundary"].erase("top");
    expect_error(j, {"boundary.side.die", "arc"});

    j = testing::punched_cylinder();
    j["boundary"]["top"]["die"]["center"] = {0.01, 0.019};
    expect_error(j, {"boundary.top.die.center", "0.019", "on part top"});
    j["boundary"]["top"]["die"]["center"] = {0.03, 0.02};
    expect_error(j, {"boundary.top.die.center", "on part top"});

    j = testing::punched_cylinder();
    j["boundary"]["top"]["die"]["indentation"] = 1e-6;
    expect_error(j, {"boundary.top.die", "exactly one of indentation"});
    j["boundary"]["top"]["die"].erase("indentation");
    j["boundary"]["top"]["die"].erase("force");
    expect_error(j, {"boundary.top.die", "exactly one of indentation"});

    j = testing::punched_cylinder();
    j["boundary"]["top"]["die"]["force"] = -5.0;
    expect_error(j, {"boundary.top.die.force", "-5", "> 0"});
    j = testing::punched_cylinder();
    j["boundary"]["top"]["die"].erase("force");
    j["boundary"]["top"]["die"]["indentation"] = 0.0;
    expect_error(j, {"boundary.top.die.indentation", "0", "small strain"});

    j = testing::punched_cylinder();
    j["boundary"]["top"]["die"]["profile"]["radius"] = 0.0;
    expect_error(j, {"boundary.top.die.profile.radius", "0", "> 0"});
    j["boundary"]["top"]["die"]["profile"] = {{"shape", "flat_rounded"}, {"flat_radius", 0.005},
                                              {"edge_radius", -1.0}};
    expect_error(j, {"boundary.top.die.profile.edge_radius", "-1", "> 0"});
    j["boundary"]["top"]["die"]["profile"] = {{"shape", "flat_rounded"}, {"radius", 0.005}};
    expect_error(j, {"boundary.top.die.profile.radius", "unknown key"});
    j["boundary"]["top"]["die"]["profile"] = {{"shape", "cone"}, {"radius", 0.005}};
    expect_error(j, {"boundary.top.die.profile.shape", "cone", "paraboloid"});
    j["boundary"]["top"]["die"]["profile"] = {{"shape", "flat"}, {"radius", 0.03}};
    expect_error(j, {"boundary.top.die.profile.radius", "0.03", "end on part top"});
    j["boundary"]["top"]["die"].erase("profile");
    expect_error(j, {"boundary.top.die.profile", "missing"});

    j = testing::punched_cylinder();
    j["boundary"]["top"] = {{"pressure", 1e6}};
    j["contact"] = {{"method", "iterate"}};
    expect_error(j, {"contact", "only with a die"});
  }
} // namespace axisym
