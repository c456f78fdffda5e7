// The one-die zone search on an outline part and its fixed-zone solve (outline_contact.h).
#include "rfm/contact/outline_contact.h"

#include "rfm/contact/half_space.h"
#include "rfm/contact/illinois.h"
#include "rfm/contact/outline_trials.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace rfm
{
  using namespace outline_trials;

  OutlineContactResult solve_outline_contact(const axisym::Problem &problem,
                                             const DiscretizationOptions &discretization,
                                             const OutlineContactOptions &options)
  {
    const std::vector<std::string> parts = problem.body->die_parts();
    const std::string &part = parts.at(0);
    const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
    const axisym::DieCondition &die = problem.body->conditions.at(part).die;
    const bool up = f.runs_up(), down = f.runs_down(), two_ends = up && down;
    const axisym::DieProfile &profile = die.profile;
    const bool flat = profile.sharp_edge();
    // The extent: the part's length from the centre on the free side(s).
    const double extent = two_ends ? std::min(f.s_max, -f.s_min) : (up ? f.s_max : -f.s_min);
    auto zone_of = [&](const double c) {
      return two_ends ? std::array<double, 2>{-c, c}
                      : (up ? std::array<double, 2>{0.0, c} : std::array<double, 2>{-c, 0.0});
    };

    OutlineContactResult result;
    ZoneSolver solver(problem, discretization, part, result);
    solver.on_step(options.on_step);
    try
      {
        if (discretization.edge_modes == 0)
          throw std::runtime_error("the search needs the edge modes (rfm.edge_modes > 0): K "
                                   "locates the zone's end");
        // A flat punch with a sharp edge keeps its face as the zone (the edge pressure is
        // singular there; K is its intensity).
        if (flat)
          {
            const auto z = zone_of(profile.radius);
            solver.fix_local_basis({part, z[0], z[1], 0.0});
            solver.solve(z[0], z[1], "flat face");
            solver.finish();
            result.success = true;
            result.message = "a flat punch with a sharp edge: the zone is its face";
            return result;
          }
        // 0. The first estimate. A die about the axis on an end face: the half-space's
        //    contact radius for its indentation or force (half_space.h): 1.3e-5 from the zone
        //    found for Hertz by force, 0.4 % short for the rounded punch by indentation (the
        //    column's own compression takes part of delta). Otherwise the zone where g0 =
        //    delta (under force control, delta from a zone of a tenth of the extent first),
        //    about twice the zone.
        const std::optional<double> c_half_space =
          f.about_axis() && !two_ends
            ? half_space::contact_radius(die, half_space::contact_modulus(problem), 0.9 * extent)
            : std::nullopt;
        double delta = die.indentation ? *die.indentation : 0.0;
        if (!die.indentation && !c_half_space)
          {
            const auto z = zone_of(0.1 * extent);
            solver.fix_local_basis({part, z[0], z[1], 0.0});
            delta = solver.solve(z[0], z[1], "estimate").indentation;
            if (!(delta > 0.0))
              throw std::runtime_error("the force gives no indentation (delta = " +
                                       std::to_string(delta) + " m) at a zone of a tenth of the part");
          }
        const double c_first =
          c_half_space ? *c_half_space : std::min(overlap_end(profile, delta, extent), 0.9 * extent);
        // The search from a zone (its ends, or its extent c) with the boxes fixed; returns the
        // zone found.
        auto search_two_ends = [&](Eigen::Vector2d x) -> Eigen::Vector2d {
          // Broyden on (s_lo, s_hi) -> (K_lo, K_hi).
          auto k_of = [&](const Eigen::Vector2d &s, const std::string &phase) {
            const OutlineContactStep st = solver.solve(s[0], s[1], phase);
            if (st.edge_intensities.size() != 2)
              throw std::runtime_error("a zone with two free ends gave " +
                                       std::to_string(st.edge_intensities.size()) + " intensities");
            return Eigen::Vector2d(st.edge_intensities[0], st.edge_intensities[1]);
          };
          Eigen::Vector2d k = k_of(x, "bracket");
          Eigen::Matrix2d jac;
          const double h = 0.05 * (x[1] - x[0]);
          for (int i = 0; i < 2; ++i)
            {
              Eigen::Vector2d xi = x;
              xi[i] += i == 0 ? -h : h;
              jac.col(i) = (k_of(xi, "jacobian") - k) / (xi[i] - x[i]);
            }
          bool solved_at_x = false; // the last solve was at x (not at a Jacobian's column)
          while (true)
            {
              if (static_cast<int>(result.history.size()) >= options.max_solves)
                throw std::runtime_error("the zone's ends did not converge in " +
                                         std::to_string(options.max_solves) + " solves");
              Eigen::Vector2d dx = jac.fullPivLu().solve(-k);
              const double width = x[1] - x[0], limit = 0.25 * width;
              const double scale = std::max({1.0, std::abs(dx[0]) / limit, std::abs(dx[1]) / limit});
              dx /= scale;
              const Eigen::Vector2d x_new(std::max(x[0] + dx[0], f.s_min * (1 - 1e-3)),
                                          std::min(x[1] + dx[1], f.s_max * (1 - 1e-3)));
              dx = x_new - x;
              // The next step is below the tolerance: x, solved last, is the answer (as the
              // one-end search stops), without a solve that would only confirm it (the ring
              // die's last step was 5e-6 of its half-width: one solve of nine, 40 s).
              if (solved_at_x && dx.cwiseAbs().maxCoeff() < options.root_tolerance * 0.5 * width)
                return x;
              if (!(x_new[1] - x_new[0] > 1e-3 * extent))
                throw std::runtime_error("the zone's ends crossed (s = " + std::to_string(x_new[0]) +
                                         ", " + std::to_string(x_new[1]) + " m)");
              const Eigen::Vector2d k_new = k_of(x_new, "broyden");
              if (dx.norm() > 0.0)
                jac += ((k_new - k) - jac * dx) * dx.transpose() / dx.squaredNorm();
              x = x_new, k = k_new;
              solved_at_x = true;
              if (dx.cwiseAbs().maxCoeff() < options.root_tolerance * 0.5 * (x[1] - x[0]))
                return x;
            }
        };
        auto search_one_end = [&](double c_a, const double first_step) -> double {
          // 1. Bracket: from c_a toward the root until K changes sign. K(c) is nearly linear
          //    about the root: after the first step (a factor 1 + 2 first_step) each step goes
          //    to the secant's root through the last two points and a tenth of the step beyond,
          //    at least that factor and at most a factor 2 (the first estimate of the Hertz
          //    zone is 2.3 times it: six factor steps of 1.2 before).
          auto k_of = [&](const double c, const std::string &phase) {
            const auto z = zone_of(c);
            return solver.solve(z[0], z[1], phase).edge_intensity;
          };
          double k_a = k_of(c_a, "bracket");
          const double factor = 1.0 + 2.0 * first_step;
          double c_b = c_a, k_b = k_a, c_p = nan, k_p = nan;
          while (std::signbit(k_b) == std::signbit(k_a))
            {
              c_p = c_a, k_p = k_a, c_a = c_b, k_a = k_b;
              const bool grow = k_a < 0; // K < 0: the zone too short
              c_b = grow ? c_a * factor : c_a / factor;
              if (std::isfinite(k_p) && k_p != k_a && c_p != c_a)
                {
                  const double root = c_a - k_a * (c_a - c_p) / (k_a - k_p);
                  const double beyond = c_a + 1.1 * (root - c_a);
                  if (grow && beyond > c_b)
                    c_b = std::min(beyond, 2.0 * c_a);
                  else if (!grow && beyond < c_b)
                    c_b = std::max(beyond, 0.5 * c_a);
                }
              if (!(c_b > 1e-3 * extent && c_b < extent * (1 - 1e-3)) ||
                  static_cast<int>(result.history.size()) >= options.max_solves)
                throw std::runtime_error("the root of K is not bracketed inside the part (K = " +
                                         std::to_string(k_a) + " Pa m^1/2 at c = " +
                                         std::to_string(c_a) + " m)");
              k_b = k_of(c_b, "bracket");
            }
          // 2. Illinois on [c_a, c_b], until the bracket or the next step is below
          //    root_tolerance c (the last solve is then the answer).
          IllinoisBracket br{c_a, k_a, c_b, k_b};
          double c_last = c_b;
          while (std::abs(br.b - br.a) > options.root_tolerance * std::max(br.a, br.b))
            {
              if (static_cast<int>(result.history.size()) >= options.max_solves)
                throw std::runtime_error("the root of K did not converge in " +
                                         std::to_string(options.max_solves) + " solves");
              const double c = br.secant();
              if (std::abs(c - c_last) <= options.root_tolerance * c)
                break;
              const double k = k_of(c, "illinois");
              c_last = c;
              br.replace(c, k);
              if (k == 0.0)
                break;
            }
          const OutlineContactStep &last = result.history.back();
          return last.half_width;
        };
        // Passes: the local boxes are those of the zone the pass starts from; when the zone
        // found is more than 10 % off that one, the boxes are rebuilt about it and the search
        // goes on from there (a first estimate of twice the zone put the boxes' first side at
        // 4.6 times the Hertz contact radius: a 3.6 % short one).
        // The first estimate g0 = delta overshoots: 2.3 times the Hertz radius under force,
        // 2.2 times the ring die's zone: the first pass's boxes are built about half of it.
        // The half-space's is close: the boxes about it, and a first step of 1 %.
        double c_box = c_half_space ? c_first : 0.5 * c_first;
        const double bracket_step = c_half_space ? 0.005 : options.first_step;
        Eigen::Vector2d x(-c_first, c_first);
        const int max_passes = std::max(1, options.local_passes);
        for (int pass = 0;; ++pass)
          {
            {
              const auto z = zone_of(c_box);
              solver.fix_local_basis({part, z[0], z[1], 0.0});
            }
            double c_found;
            if (two_ends)
              {
                x = search_two_ends(x);
                c_found = std::max(-x[0], x[1]);
              }
            else
              c_found = search_one_end(pass == 0 ? c_first : c_box, pass == 0 ? bracket_step : 0.02);
            if (!solver.has_local_boxes() || std::abs(c_found - c_box) <= 0.1 * c_found ||
                pass + 1 == max_passes)
              break;
            c_box = c_found;
          }
        solver.finish();
        result.success = true;
        result.message = two_ends ? "both ends are roots of their K to " +
                                      std::to_string(options.root_tolerance) + " of the zone's half-width (" +
                                      std::to_string(result.history.size()) + " solves, Broyden)"
                                  : "c is the root of K to " + std::to_string(options.root_tolerance) +
                                      " of c (" +
                                      std::to_string(result.history.size()) + " solves)";
      }
    catch (const std::runtime_error &e)
      {
        result.success = false;
        result.message = e.what();
      }
    return result;
  }

  OutlineContactResult solve_outline_zone(const axisym::Problem &problem,
                                          const DiscretizationOptions &discretization,
                                          const double s_lo, const double s_hi)
  {
    const std::string part = problem.body->die_parts().at(0);
    OutlineContactResult result;
    ZoneSolver solver(problem, discretization, part, result);
    try
      {
        solver.fix_local_basis({part, s_lo, s_hi, 0.0});
        solver.solve(s_lo, s_hi, "fixed");
        solver.finish();
        result.success = true;
        result.message = "the zone as given";
      }
    catch (const std::runtime_error &e)
      {
        result.success = false;
        result.message = e.what();
      }
    return result;
  }
} // namespace rfm
