// contact.method "iterate" (contact.h): the paper's successive iterations.
#include "rfm/contact/contact_methods.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rfm::contact_methods
{
  // The paper's successive iterations, safeguarded by the bracket [lo, hi]: lo is a zone
  // known to be too short (penetration), hi one known too long (tension).
  void iterate(ZoneTrials &s)
  {
    const ContactOptions &options = s.options;
    ContactResult &result = s.result;
    const double a = s.extent;
    ContactIterate it;
    double lo = 0.0, hi = a, c = a;
    bool holds = false, last_too_long = false;
    int same_side = -1;
    int n_solves = 0;
    for (; n_solves < options.max_iterations && !holds; ++n_solves)
      {
        if (!s.solve(c, it, "iteration"))
          return;
        if (it.conditions_hold())
          {
            holds = true;
            break;
          }
        // Penetration outside the zone means the zone is too short, whatever the
        // pressure does: a too-long zone opens a gap beyond its edge. Tension together
        // with penetration is the oscillation of a compressive edge singularity that
        // the polynomial stresses cannot represent, not a sign of a too-long zone.
        // With the edge modes, the sign of K tells a too-long zone (tensile edge) from a
        // too-short one directly, and decides when both conditions fail (the violations
        // of a nearly right zone are then both at the noise level).
        const bool too_long = (it.tension && it.penetration && std::isfinite(it.edge_intensity))
                                ? it.edge_intensity > 0
                                : it.tension && !it.penetration;
        double proposal;
        if (too_long)
          hi = std::min(hi, c), proposal = it.first_tension_z;
        else
          lo = std::max(lo, c), proposal = it.penetration_end_z;
        if (hi - lo <= options.tolerance * s.length_scale(hi))
          break; // bracketed without a c where both hold: accept the bracket below
        // Keep the fixed-point step if it stays well inside the bracket and the zone
        // has not erred on the same side three times running: near c the fixed point
        // creeps (the penetrating interval beyond a zone slightly too short is short
        // too; measured at p = 10: 30 steps from 0.50 a to 0.516 a), bisection does not.
        same_side = (too_long == last_too_long) ? same_side + 1 : 0;
        last_too_long = too_long;
        const double margin = 0.01 * (hi - lo);
        c = (proposal > lo + margin && proposal < hi - margin && same_side < 2)
              ? proposal
              : 0.5 * (lo + hi);
      }
    if (!holds && hi - lo > options.tolerance * s.length_scale(hi))
      {
        result.message = "contact iteration did not converge in " +
                         std::to_string(options.max_iterations) + " solves";
        return;
      }

    // Refinement: at finite N the conditions hold on an interval of c, which shrinks to
    // the true c as N grows. Bisect for both ends: the largest c without tension and
    // the smallest c without penetration. The answer is the interval's midpoint; its
    // half-length is the discretization uncertainty of c at this N.
    double c_lo = holds ? c : lo, c_hi = holds ? c : hi;
    if (holds)
      {
        double bad = hi, good = c; // upper end: good holds 1.2, bad is tensile
        while (bad - good > options.tolerance * s.length_scale(good) &&
               n_solves++ < options.max_iterations)
          {
            const double mid = 0.5 * (good + bad);
            if (!s.solve(mid, it, "refinement"))
              return;
            (it.tension ? bad : good) = mid;
          }
        c_hi = good;
        bad = lo, good = c; // lower end: good holds 1.3, bad penetrates
        while (good - bad > options.tolerance * s.length_scale(good) &&
               n_solves++ < options.max_iterations)
          {
            const double mid = 0.5 * (good + bad);
            if (!s.solve(mid, it, "refinement"))
              return;
            (it.penetration ? bad : good) = mid;
          }
        c_lo = good;
      }
    if (!s.solve(0.5 * (c_lo + c_hi), it, "final"))
      return;
    result.half_width_range = {c_lo, c_hi};
    result.success = true;
    result.message = holds ? "conditions 1.2 and 1.3 hold for c in [" +
                               std::to_string(c_lo / a) + ", " + std::to_string(c_hi / a) +
                               "] a at this N; c is its midpoint"
                           : "zone bracketed to the tolerance without an iterate free of "
                             "violations (discretization noise at this N)";
  }
} // namespace rfm::contact_methods
