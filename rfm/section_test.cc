#include "rfm/section.h"

#include "rfm/test_sections.h"

#include <gtest/gtest.h>

namespace rfm
{
  using namespace rfm::testing;

  TEST(Section, PartOmegaVanishesOnItsPartOnlyAndIsPositiveInside)
  {
    const Section s = die_section();
    s.validate();
    for (const BoundaryPart &p : s.parts())
      {
        SCOPED_TRACE(p.name);
        const bool radial = p.side == Side::inner || p.side == Side::outer;
        for (int k = 0; k <= 20; ++k)
          {
            const double t = p.begin + (p.end - p.begin) * k / 20.0;
            double r = 0, z = 0;
            switch (p.side)
              {
                case Side::inner: r = r1, z = t; break;
                case Side::outer: r = r2, z = t; break;
                case Side::bottom: r = t, z = 0.0; break;
                case Side::top: r = t, z = a; break;
              }
            EXPECT_NEAR(s.part_omega(p, r, z).value, 0.0, 1e-15);
          }
        // Interior points are positive.
        for (double r : {0.11, 0.15, 0.19})
          for (double z : {0.01, 0.1, 0.19})
            EXPECT_GT(s.part_omega(p, r, z).value, 0.0);
        // Normalized: |grad| = 1 on the part away from its ends (one-sided, inside).
        const double mid = 0.5 * (p.begin + p.end);
        const RValue w = radial ? s.part_omega(p, p.side == Side::inner ? r1 + 1e-9 : r2 - 1e-9, mid)
                                : s.part_omega(p, mid, p.side == Side::bottom ? 1e-9 : a - 1e-9);
        EXPECT_NEAR(std::hypot(w.d_r, w.d_z), 1.0, 1e-6);
      }
    // The contact part's omega is positive on the free part of the outer side.
    const BoundaryPart &contact = s.parts()[1];
    EXPECT_GT(s.part_omega(contact, r2, 0.15).value, 0.0);
    EXPECT_EQ(s.z_breaks(), std::vector<double>({c, c}));
  }

  TEST(Section, ValidateRejectsGapsAndMisplacedConditions)
  {
    Section gap(r1, r2, 0.0, a);
    gap.add_part({"inner", Side::inner, 0.0, 0.1, Condition::traction, 0.0, {}, {}});
    EXPECT_THROW(gap.validate(), std::invalid_argument);

    Section bad = lame_section();
    bad.add_part({"extra", Side::outer, 0.0, a, Condition::symmetry, 0.0, {}, {}});
    EXPECT_THROW(bad.validate(), std::invalid_argument);
    EXPECT_THROW(Section(0.2, 0.1, 0.0, 1.0), std::invalid_argument);
  }
} // namespace rfm
