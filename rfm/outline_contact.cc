#include "rfm/outline_contact.h"

#include <cmath>
#include <limits>

namespace rfm
{
  OutlineContactResult solve_outline_contact(const axisym::Problem &problem,
                                             const DiscretizationOptions &discretization,
                                             const OutlineContactOptions &options)
  {
    const std::vector<std::string> parts = problem.body->die_parts();
    const std::string &part = parts.at(0);
    const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
    const axisym::DieCondition &die = problem.body->conditions.at(part).die;
    if (!die.indentation)
      throw axisym::InputError("boundary." + part + ".die.force: the RFM takes an indentation on "
                               "an outline part so far (fem_solve takes a force)");
    const double tol = 1e-9 * problem.body->outline.size();
    const bool up = f.s_max > tol, down = f.s_min < -tol;
    const axisym::DieProfile &profile = die.profile;
    const bool flat = profile.shape == axisym::DieProfile::Shape::flat;
    if (up && down && !flat)
      throw axisym::InputError("boundary." + part + ".die.center: the RFM's search takes a zone "
                               "with one free end (the centre at the part's end on a symmetry "
                               "edge or the axis) so far; give contact.method \"fixed\" with "
                               "half_width, or use fem_solve");
    const double extent = up ? f.s_max : -f.s_min;
    const double delta = *die.indentation;

    OutlineContactResult result;
    auto solve = [&](double c, const std::string &phase) -> double {
      const DieZone zone{part, up ? 0.0 : -c, up ? c : 0.0, delta};
      auto model = std::make_unique<OutlineModel>(problem, discretization, SolverOptions{},
                                                  std::vector<DieZone>{zone});
      if (!model->ok())
        throw std::runtime_error("the solve at c = " + std::to_string(c) +
                                 " m failed: " + model->summary().message);
      OutlineContactStep step;
      step.half_width = c;
      step.phase = phase;
      const OutlineModel::DieForce force = model->die_force(part);
      step.force = force.domain, step.force_trace = force.trace;
      step.edge_intensity = model->n_zone_edges() > 0 ? model->edge_intensity(0)
                                                             : std::numeric_limits<double>::quiet_NaN();
      const Functionals phi = model->functionals();
      step.lagrange = phi.lagrange, step.castigliano = phi.castigliano, step.reissner = phi.reissner;
      result.history.push_back(step);
      result.zone = zone;
      result.model = std::move(model);
      return step.edge_intensity;
    };

    try
      {
        if (discretization.edge_modes == 0)
          throw std::runtime_error("the search needs the edge modes (rfm.edge_modes > 0): K "
                                   "locates the zone's end");
        // A flat punch with a sharp edge keeps its face as the zone (the edge pressure is
        // singular there; K is its intensity).
        if (flat)
          {
            const double b = profile.radius;
            if (up && down)
              {
                const DieZone zone{part, -b, b, delta};
                result.model = std::make_unique<OutlineModel>(problem, discretization,
                                                              SolverOptions{},
                                                              std::vector<DieZone>{zone});
                if (!result.model->ok())
                  throw std::runtime_error("the solve on the punch's face failed: " +
                                           result.model->summary().message);
                result.zone = zone;
              }
            else
              solve(b, "flat face");
            result.success = true;
            result.message = "a flat punch with a sharp edge: the zone is its face";
            return result;
          }
        // 1. Bracket: from where the die's surface reaches the undeformed part (g0 = delta,
        //    an upper bound of Hertz's zone) steps by a factor toward the root until K changes
        //    sign.
        double c_a = 0.5 * extent;
        for (double s = 0.0; s < extent; s += 1e-3 * extent)
          if (profile.gap(s) >= delta)
            {
              c_a = std::max(s, 0.02 * extent);
              break;
            }
        double k_a = solve(c_a, "bracket");
        const double factor = 1.0 + 2.0 * options.first_step;
        double c_b = c_a, k_b = k_a;
        while (std::signbit(k_b) == std::signbit(k_a))
          {
            c_a = c_b, k_a = k_b;
            c_b = k_a < 0 ? c_a * factor : c_a / factor; // K < 0: the zone too short
            if (!(c_b > 1e-3 * extent && c_b < extent * (1 - 1e-3)) ||
                static_cast<int>(result.history.size()) >= options.max_solves)
              throw std::runtime_error("the root of K is not bracketed inside the part (K = " +
                                       std::to_string(k_a) + " Pa m^1/2 at c = " +
                                       std::to_string(c_a) + " m)");
            k_b = solve(c_b, "bracket");
          }
        // 2. Illinois on [c_a, c_b].
        int side = 0;
        while (std::abs(c_b - c_a) > options.root_tolerance * extent)
          {
            if (static_cast<int>(result.history.size()) >= options.max_solves)
              throw std::runtime_error("the root of K did not converge in " +
                                       std::to_string(options.max_solves) + " solves");
            const double c = (c_a * k_b - c_b * k_a) / (k_b - k_a);
            const double k = solve(c, "illinois");
            if (std::signbit(k) == std::signbit(k_b))
              {
                c_b = c, k_b = k;
                if (side == -1)
                  k_a *= 0.5;
                side = -1;
              }
            else
              {
                c_a = c, k_a = k;
                if (side == 1)
                  k_b *= 0.5;
                side = 1;
              }
            if (k == 0.0)
              break;
          }
        result.success = true;
        result.message = "c is the root of K to " + std::to_string(options.root_tolerance) +
                         " of the part's extent (" + std::to_string(result.history.size()) +
                         " solves)";
      }
    catch (const std::runtime_error &e)
      {
        result.success = false;
        result.message = e.what();
      }
    return result;
  }
} // namespace rfm
