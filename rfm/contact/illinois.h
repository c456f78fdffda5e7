// The Illinois method's bracket (regula falsi that halves the retained end's value when the
// same end is replaced twice running): superlinear on a nearly linear function, it never
// leaves the bracket. The zone searches of both contact paths (contact_edge_intensity.cc,
// outline_contact.cc) step K(c) with it; each keeps its own stopping rule.
#pragma once

#include <cmath>

namespace rfm
{
  struct IllinoisBracket
  {
    double a, f_a, b, f_b; ///< the ends and their values, of opposite signs
    int side = 0;          ///< +1: the last replacement was a, -1: b, 0: none yet

    /// The regula falsi point between the ends.
    double secant() const { return (a * f_b - b * f_a) / (f_b - f_a); }

    /// Replaces the end whose value has the sign of f_x by (x, f_x); halves the other end's
    /// value when the same end was replaced the time before.
    void replace(const double x, const double f_x)
    {
      if (std::signbit(f_x) == std::signbit(f_b))
        {
          b = x, f_b = f_x;
          if (side == -1)
            f_a *= 0.5;
          side = -1;
        }
      else
        {
          a = x, f_a = f_x;
          if (side == 1)
            f_b *= 0.5;
          side = 1;
        }
    }
  };
} // namespace rfm
