#include "problem/problem.h"

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
