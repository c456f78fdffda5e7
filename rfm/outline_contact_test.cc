#include "rfm/outline_contact.h"

#include "problem/test_problems.h"

#include <gtest/gtest.h>

namespace rfm
{
  using axisym::testing::paper_die_outline;

  // The search: K changes sign across the bracket, the Illinois steps close it, and the end
  // found is where K vanishes (|K| small against the bracket's), near the finest FEM's c =
  // 0.1038561 m (Q2, L = 5; measured 2.8e-4 from it at p = 8).
  TEST(OutlineContact, FindsTheRootOfTheEdgeIntensity)
  {
    const axisym::Problem p = axisym::parse_problem(paper_die_outline());
    const OutlineContactResult r = solve_outline_contact(p, p.rfm);
    ASSERT_TRUE(r.success) << r.message;
    ASSERT_GE(r.history.size(), 3u);
    double k_max = 0;
    for (const OutlineContactStep &s : r.history)
      k_max = std::max(k_max, std::abs(s.edge_intensity));
    EXPECT_LT(std::abs(r.history.back().edge_intensity), 1e-2 * k_max);
    EXPECT_NEAR(r.zone.s_hi, 0.1038561, 1e-3 * 0.1038561);
    EXPECT_EQ(r.zone.s_lo, 0.0);
    ASSERT_TRUE(r.model);
    EXPECT_TRUE(r.model->ok());
  }

  // Without the edge modes there is no K to search with; a zone with two free ends and a
  // force are refused (the search takes one end and an indentation so far).
  TEST(OutlineContact, RefusesWhatItCannotSearch)
  {
    auto j = paper_die_outline();
    j["rfm"]["edge_modes"] = 0;
    const axisym::Problem no_modes = axisym::parse_problem(j);
    const OutlineContactResult r = solve_outline_contact(no_modes, no_modes.rfm);
    EXPECT_FALSE(r.success);
    EXPECT_NE(r.message.find("edge modes"), std::string::npos) << r.message;

    j = paper_die_outline();
    j["boundary"]["outer"]["die"]["center"] = {0.2, 0.1};
    const axisym::Problem two_ends = axisym::parse_problem(j);
    EXPECT_THROW(solve_outline_contact(two_ends, two_ends.rfm), axisym::InputError);

    j = paper_die_outline();
    j["boundary"]["outer"]["die"].erase("indentation");
    j["boundary"]["outer"]["die"]["force"] = 1e5;
    const axisym::Problem force = axisym::parse_problem(j);
    EXPECT_THROW(solve_outline_contact(force, force.rfm), axisym::InputError);
  }
} // namespace rfm
