// Samples at vertices where the stress has no value (sample_checks.h), on the test sections
// whose vertices wedge_modes_test.cc checks.
#include "problem/sample_checks.h"

#include "problem/problem.h"
#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace axisym
{
  namespace
  {
    Problem with_samples(nlohmann::json j, const nlohmann::json &samples)
    {
      j["samples"] = samples;
      return parse_problem(j);
    }
  } // namespace

  // The stepped ring's 270-degree step corner (0.15, 0.1) between two free faces (Williams:
  // 0.5444837); a sample 1 cm off it, one on its face and one at its right-angled corner
  // (0.2, 0.2), free against free, are not listed.
  TEST(SampleChecks, ASampleAtASingularVertex)
  {
    const Problem p = with_samples(testing::stepped_ring(), {{0.16, 0.11}, {0.15, 0.15}, {0.2, 0.2}, {0.15, 0.1}});
    const std::vector<SampleAtVertex> at = samples_at_vertices(p);
    ASSERT_EQ(at.size(), 1u);
    EXPECT_EQ(at[0].sample, 3u);
    EXPECT_EQ(at[0].kind, SampleAtVertex::Kind::singular);
    EXPECT_NEAR(at[0].exponent, 0.5444837, 1e-6);
    const nlohmann::json j = to_json(at);
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0].at("kind"), "singular");
    EXPECT_EQ(j[0].at("r").get<double>(), 0.15);
    EXPECT_EQ(j[0].at("z").get<double>(), 0.1);
    const std::string why = samples_at_vertices_warning(at);
    EXPECT_NE(why.find("(0.15, 0.1) m is a singular vertex (the stress grows like rho^-0.4555"), std::string::npos)
      << why;
    EXPECT_TRUE(samples_at_vertices_warning({}).empty());
    EXPECT_EQ(samples_with_a_value(p), (std::vector<bool>{true, true, true, false}));
  }

  // Where a traction ends on a straight face: the pressure band, and a shear traction in its
  // place. The shear's jump has no bounded field (a log term, which the RFM's particular
  // field refuses: rfm/spaces/traction_jump.h), and its sample is listed all the same.
  TEST(SampleChecks, ASampleWhereTheTractionJumps)
  {
    nlohmann::json shear = testing::pressure_band();
    shear["boundary"]["bore_loaded"] = {{"traction", {0.0, 1.0e6}}};
    for (const nlohmann::json &problem : {testing::pressure_band(), shear})
      {
        const Problem p = with_samples(problem, {{0.5, 0.25}, {0.5, 0.24}, {0.5, 0.0}});
        const std::vector<SampleAtVertex> at = samples_at_vertices(p);
        ASSERT_EQ(at.size(), 1u) << problem.dump();
        EXPECT_EQ(at[0].sample, 0u);
        EXPECT_EQ(at[0].kind, SampleAtVertex::Kind::traction_jump);
        EXPECT_EQ(to_json(at)[0].at("kind"), "traction_jump");
        EXPECT_NE(samples_at_vertices_warning(at).find("the traction jumps"), std::string::npos);
      }
    // Without samples, and with the pressure on the whole bore: nothing.
    nlohmann::json whole = testing::pressure_band();
    whole["boundary"]["bore_free"] = {{"pressure", 1.0e7}};
    EXPECT_TRUE(samples_at_vertices(parse_problem(testing::pressure_band())).empty());
    EXPECT_TRUE(samples_at_vertices(with_samples(whole, {{0.5, 0.25}})).empty());
  }
} // namespace axisym
