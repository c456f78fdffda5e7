// contact.method "max-force" (contact.h): Barber's principle.
#include "rfm/contact/contact_methods.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rfm::contact_methods
{
  // Barber's principle: golden-section maximization of P(c) on [0.05 a, a] (under force
  // control: minimization of delta(c)).
  void max_force(ZoneTrials &s)
  {
    const ContactOptions &options = s.options;
    ContactResult &result = s.result;
    const double a = s.extent;
    ContactIterate it;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    // The search variable: c itself, or log c when the tolerance is relative to c.
    auto to_c = [&](const double x) { return s.relative_to_c ? std::exp(x) : x; };
    auto to_x = [&](const double c) { return s.relative_to_c ? std::log(c) : c; };
    const double tol = s.relative_to_c ? options.tolerance : options.tolerance * a;
    double lo = to_x(s.c_low), hi = to_x(a);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    // The objective: P at the given delta, or -delta at the given P (contact_methods.h).
    auto value = [&](const ContactIterate &i) { return s.force_control ? -i.indentation : i.force; };
    ContactIterate i1, i2;
    if (!s.solve(to_c(x1), i1, "search") || !s.solve(to_c(x2), i2, "search"))
      return;
    int k = 2;
    while (hi - lo > tol)
      {
        if (++k > options.max_iterations)
          {
            result.message = "max-force search did not reach the tolerance in " +
                             std::to_string(options.max_iterations) + " solves";
            return;
          }
        if (value(i1) > value(i2))
          {
            hi = x2, x2 = x1, i2 = i1;
            x1 = hi - g * (hi - lo);
            if (!s.solve(to_c(x1), i1, "search"))
              return;
          }
        else
          {
            lo = x1, x1 = x2, i1 = i2;
            x2 = lo + g * (hi - lo);
            if (!s.solve(to_c(x2), i2, "search"))
              return;
          }
      }
    // Final solve at the maximizer, with the check of conditions 1.2 and 1.3.
    if (!s.solve(to_c(0.5 * (lo + hi)), it, "final"))
      return;
    result.success = true;
    const std::string found = s.force_control ? "minimum of delta(c) at the given force found"
                                              : "maximum of P(c) found";
    result.message = it.conditions_hold()
                       ? found + "; conditions 1.2 and 1.3 hold there"
                       : found + "; conditions 1.2/1.3 violated there beyond the tolerance (the "
                                 "objective is flat at its optimum: see `iterate`)";
  }
} // namespace rfm::contact_methods
