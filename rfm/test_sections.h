// Sections shared by the rfm unit tests: the paper's cylinder half-section with
// pressures, and with a die contact zone [0, c] on the outer side.
#pragma once

#include "rfm/section.h"

namespace rfm::testing
{
  inline constexpr double r1 = 0.1, r2 = 0.2, a = 0.2, c = 0.11;
  inline constexpr double p_in = 1e7, p_out = 3e6, delta = 1e-6;

  inline double u_star(double z) { return -delta * (1 - 2 * z * z / (a * a)); }
  inline double du_star(double z) { return 4 * delta * z / (a * a); }

  /// Lame half-section: inner and outer pressure, free end on top, symmetry at z = 0.
  inline Section lame_section(double inner = p_in, double outer = p_out)
  {
    Section s(r1, r2, 0.0, a);
    s.add_part({"inner", Side::inner, 0.0, a, Condition::traction, -inner, {}, {}});
    s.add_part({"outer", Side::outer, 0.0, a, Condition::traction, -outer, {}, {}});
    s.add_part({"symmetry", Side::bottom, r1, r2, Condition::symmetry, 0.0, {}, {}});
    s.add_part({"end", Side::top, r1, r2, Condition::traction, 0.0, {}, {}});
    return s;
  }

  /// Die half-section: contact on the outer side for z in [0, c], pressure beyond.
  inline Section die_section()
  {
    Section s(r1, r2, 0.0, a);
    s.add_part({"inner", Side::inner, 0.0, a, Condition::traction, -p_in, {}, {}});
    s.add_part({"contact", Side::outer, 0.0, c, Condition::contact, 0.0, u_star, du_star});
    s.add_part({"outer_free", Side::outer, c, a, Condition::traction, -p_out, {}, {}});
    s.add_part({"symmetry", Side::bottom, r1, r2, Condition::symmetry, 0.0, {}, {}});
    s.add_part({"end", Side::top, r1, r2, Condition::traction, 0.0, {}, {}});
    return s;
  }
} // namespace rfm::testing
