// contact.method "max-force" on the hollow cylinder (contact.h): Barber's principle.
#include "rfm/contact/contact_methods.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rfm::contact_methods
{
  // Barber's principle: golden-section maximization of P(c) on [0.05 a, a].
  void max_force(ZoneTrials &s)
  {
    const axisym::Problem &problem = s.problem;
    const ContactOptions &options = s.options;
    ContactResult &result = s.result;
    const double a = problem.geometry.half_length();
    ContactIterate it;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = 0.05 * a, hi = a;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    ContactIterate i1, i2;
    if (!s.solve(x1, i1, "search") || !s.solve(x2, i2, "search"))
      return;
    int k = 2;
    while (hi - lo > options.tolerance * a)
      {
        if (++k > options.max_iterations)
          {
            result.message = "max-force search did not reach the tolerance in " +
                             std::to_string(options.max_iterations) + " solves";
            return;
          }
        if (i1.force > i2.force)
          {
            hi = x2, x2 = x1, i2 = i1;
            x1 = hi - g * (hi - lo);
            if (!s.solve(x1, i1, "search"))
              return;
          }
        else
          {
            lo = x1, x1 = x2, i1 = i2;
            x2 = lo + g * (hi - lo);
            if (!s.solve(x2, i2, "search"))
              return;
          }
      }
    // Final solve at the maximizer, with the check of conditions 1.2 and 1.3.
    if (!s.solve(0.5 * (lo + hi), it, "final"))
      return;
    result.success = true;
    result.message = it.conditions_hold()
                       ? "maximum of P(c) found; conditions 1.2 and 1.3 hold there"
                       : "maximum of P(c) found; conditions 1.2/1.3 violated there beyond the "
                         "tolerance (P is flat at its maximum: see `iterate`)";
  }
} // namespace rfm::contact_methods
