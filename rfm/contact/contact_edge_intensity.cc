// contact.method "edge-intensity" on the hollow cylinder (contact.h): the root of K(c), then the
// stationary point of P(c) next to it.
#include "rfm/contact/contact_methods.h"
#include "rfm/contact/illinois.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rfm::contact_methods
{
  // The root of the edge intensity K(c).
  void edge_intensity(ZoneTrials &s)
  {
    const DiscretizationOptions &discretization = s.discretization;
    const ContactOptions &options = s.options;
    ContactResult &result = s.result;
    const double a = s.extent;
    ContactIterate it;
    if (discretization.edge_modes < 1)
      {
        result.message = "contact.method edge-intensity needs the n = 1 edge mode "
                         "(rfm.edge_modes >= 1)";
        return;
      }
    const double tol = options.root_tolerance * a;
    int n_solves = 0;
    auto solve_k = [&](const double c, const char *phase) {
      ++n_solves;
      if (!s.solve(c, it, phase))
        return false;
      if (!std::isfinite(it.edge_intensity))
        {
          result.message = "no edge intensity at c = " + std::to_string(c) + " m";
          return false;
        }
      return true;
    };
    // 2a. Bracket: K < 0 at lo (too short), K > 0 at hi (too long). Secant steps,
    //     each kept within a factor of the distance to the ends of (0, a).
    double c0 = 0.5 * a;
    if (!solve_k(c0, "bracket"))
      return;
    double k0 = it.edge_intensity;
    double c1 = k0 < 0 ? 0.6 * a : 0.4 * a;
    if (!solve_k(c1, "bracket"))
      return;
    double k1 = it.edge_intensity;
    const double c_min = 0.01 * a, c_max = a * (1.0 - 0.01);
    while ((k0 < 0) == (k1 < 0) && k1 != 0.0)
      {
        if (n_solves >= options.max_iterations)
          {
            result.message = "edge intensity: no sign change of K found in " +
                             std::to_string(n_solves) + " solves";
            return;
          }
        if (k1 < 0 && c1 >= c_max)
          {
            // K < 0 up to the end of the side: the zone reaches it (full contact) if
            // the pressure is compressive there.
            if (!s.solve(a, it, "final"))
              return;
            if (!it.tension)
              {
                result.success = true;
                result.message = "K(c) < 0 up to c = 0.99 a and no tension at c = a: full "
                                 "contact";
                result.half_width_range = {a, a};
                return;
              }
            result.message = "edge intensity: the root of K(c) is not bracketed in (0, a] "
                             "(K < 0 up to 0.99 a, tension at c = a)";
            return;
          }
        if (k1 > 0 && c1 <= c_min)
          {
            result.message = "edge intensity: the root of K(c) is not bracketed in (0, a] "
                             "(K > 0 down to c = 0.01 a)";
            return;
          }
        double next = k1 != k0 ? c1 - k1 * (c1 - c0) / (k1 - k0) : c1;
        if (k1 < 0)
          next = std::clamp(next, c1 + 0.05 * (a - c1), c1 + 0.5 * (a - c1));
        else
          next = std::clamp(next, 0.5 * c1, c1 - 0.05 * c1);
        next = std::clamp(next, c_min, c_max);
        c0 = c1, k0 = k1, c1 = next;
        if (!solve_k(c1, "bracket"))
          return;
        k1 = it.edge_intensity;
      }
    // 2b. Illinois on [lo, hi] (K < 0 at lo, K > 0 at hi).
    IllinoisBracket br{k0 < 0 ? c0 : c1, k0 < 0 ? k0 : k1, k0 < 0 ? c1 : c0, k0 < 0 ? k1 : k0};
    double c = k1 == 0.0 ? c1 : 0.0;
    double c_prev = c1;
    while (k1 != 0.0)
      {
        c = br.secant();
        if (std::abs(c - c_prev) < tol || br.b - br.a < tol)
          break;
        if (n_solves >= options.max_iterations)
          {
            result.message = "edge intensity: the secant iteration did not converge in " +
                             std::to_string(n_solves) + " solves";
            return;
          }
        if (!solve_k(c, "secant"))
          return;
        const double k = it.edge_intensity;
        c_prev = c;
        if (k == 0.0)
          break;
        br.replace(c, k);
      }
    const double lo = br.a, hi = br.b;

    // 2c. P(c) is stationary where K changes sign (DESIGN.md 4.4). The two are
    //     independent domain integrals of the discrete field (measured at p = 8, nu =
    //     0.3: the root of K +0.08 %, the stationary point of P +0.04 % from the FEM's
    //     c); c is the stationary point, found by successive parabolic interpolation of P
    //     over the solves so far (the three with the largest P), each vertex solved,
    //     until the vertex is within h / 100 of the best solve; a vertex is kept within h
    //     of those three points.
    result.edge_intensity_root = c;
    bool stationary = false;
    const double h = options.stationary_step * a;
    if (h > 0.0)
      {
        for (int round = 0; round < 6; ++round)
          {
            std::vector<const ContactIterate *> best;
            for (const ContactIterate &done : result.history)
              if (std::none_of(best.begin(), best.end(), [&](const ContactIterate *b) {
                    return std::abs(b->half_width - done.half_width) <= 1e-9 * a;
                  }))
                best.push_back(&done);
            if (best.size() < 3)
              break;
            std::partial_sort(best.begin(), best.begin() + 3, best.end(),
                              [](const ContactIterate *x, const ContactIterate *y) {
                                return x->force > y->force;
                              });
            const double x0 = best[0]->half_width, x1 = best[1]->half_width,
                         x2 = best[2]->half_width;
            const double f0 = best[0]->force, f1 = best[1]->force, f2 = best[2]->force;
            // Vertex of the parabola through the three points (Newton's divided
            // differences); it must open downwards.
            const double d01 = (f1 - f0) / (x1 - x0), d12 = (f2 - f1) / (x2 - x1);
            const double curvature = (d12 - d01) / (x2 - x0);
            if (!(curvature < 0.0))
              break; // no maximum near the root: keep the root of K
            double vertex = 0.5 * (x0 + x1) - 0.5 * d01 / curvature;
            const double lo3 = std::min({x0, x1, x2}), hi3 = std::max({x0, x1, x2});
            vertex = std::clamp(vertex, std::max(lo3 - h, c_min), std::min(hi3 + h, c_max));
            if (std::abs(vertex - x0) < 1e-2 * h)
              {
                c = x0; // the best solve is the stationary point to the tolerance
                stationary = true;
                break;
              }
            ContactIterate probe;
            if (!s.solve(vertex, probe, "stationary"))
              return;
            c = vertex;
            stationary = true;
          }
      }
    // 2d. The answer: a final solve at c, with the check of 1.2 and 1.3 (the last solve
    //     when it is at c).
    if (std::abs(result.history.back().half_width - c) <= 1e-12 * a)
      {
        result.history.back().phase = result.final.phase = "final";
        it = result.history.back();
      }
    else if (!s.solve(c, it, "final"))
      return;
    result.half_width_range = {lo, hi};
    result.success = true;
    result.message = (stationary ? std::string("stationary point of P(c) at c = ") +
                                     std::to_string(c / a) + " a, next to the root of the "
                                     "edge intensity K(c) at " +
                                     std::to_string(*result.edge_intensity_root / a) + " a ("
                                 : std::string("root of the edge intensity K(c) at c = ") +
                                     std::to_string(c / a) + " a (") +
                     std::to_string(result.history.size()) +
                     " solves); conditions 1.2 and 1.3 " +
                     (it.conditions_hold() ? "hold there" : "are violated there beyond the tolerance");
  }
} // namespace rfm::contact_methods
