// Several dies on outline parts (outline_contact.h): all zones solved and searched together.
#include "rfm/contact/outline_contact.h"

#include "rfm/contact/outline_trials.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfm
{
  using namespace outline_trials;

  OutlineDiesResult solve_outline_dies_on_zones(const axisym::Problem &problem,
                                                const DiscretizationOptions &discretization,
                                                const std::vector<DieZone> &zones)
  {
    OutlineDiesResult result;
    const std::vector<DieInfo> dies = die_infos(problem);
    if (zones.size() != dies.size())
      throw std::invalid_argument("solve_outline_dies_on_zones: one zone per die part");
    DiesSolver solver(problem, discretization, dies, result);
    try
      {
        std::vector<std::array<double, 2>> z;
        for (const DieZone &zone : zones)
          z.push_back({zone.s_lo, zone.s_hi});
        solver.fix_local_basis(z);
        solver.solve(z, "fixed");
        solver.finish();
        result.success = true;
        result.message = "the zones as given";
      }
    catch (const std::runtime_error &e)
      {
        result.success = false;
        result.message = e.what();
      }
    return result;
  }

  OutlineDiesResult solve_outline_dies(const axisym::Problem &problem,
                                       const DiscretizationOptions &discretization,
                                       const OutlineContactOptions &options)
  {
    OutlineDiesResult result;
    const std::vector<DieInfo> dies = die_infos(problem);
    const std::size_t n = dies.size();
    DiesSolver solver(problem, discretization, dies, result);
    solver.on_step(options.on_dies_step);
    // The unknowns: every free end of every zone but a sharp punch's, in the model's order of
    // zone ends (zone order, low end first), and which die each belongs to.
    struct End
    {
      std::size_t die;
      bool upper; ///< the zone's upper end (s_hi), else its lower end
    };
    std::vector<End> ends;
    for (std::size_t d = 0; d < n; ++d)
      if (!dies[d].flat)
        {
          if (dies[d].down)
            ends.push_back({d, false});
          if (dies[d].up)
            ends.push_back({d, true});
        }
    const auto n_x = static_cast<Eigen::Index>(ends.size());
    auto zones_at = [&](const Eigen::VectorXd &x, const std::vector<double> &c_fixed) {
      std::vector<std::array<double, 2>> z;
      for (std::size_t d = 0; d < n; ++d)
        z.push_back(dies[d].zone_of(c_fixed[d]));
      for (Eigen::Index k = 0; k < n_x; ++k)
        z[ends[static_cast<std::size_t>(k)].die][ends[static_cast<std::size_t>(k)].upper ? 1 : 0] = x[k];
      return z;
    };
    // The K of the unknown ends among all zone ends of a solve (a sharp punch's are skipped).
    auto residual = [&](const OutlineDiesStep &step, const std::vector<std::array<double, 2>> &z) {
      Eigen::VectorXd k(n_x);
      std::size_t e = 0;
      Eigen::Index i = 0;
      for (std::size_t d = 0; d < n; ++d)
        for (const bool upper : {false, true})
          {
            const bool free = upper ? dies[d].frame.free_high_end(z[d][1]) : dies[d].frame.free_low_end(z[d][0]);
            if (!free)
              continue;
            if (e >= step.edge_intensities.size())
              throw std::runtime_error("a zone end without its edge intensity");
            if (!dies[d].flat)
              k[i++] = step.edge_intensities[e];
            ++e;
          }
      if (i != n_x)
        throw std::runtime_error("the zones' free ends do not match the unknowns");
      return k;
    };
    try
      {
        if (discretization.edge_modes == 0)
          throw std::runtime_error("the search needs the edge modes (rfm.edge_modes > 0): K "
                                   "locates the zones' ends");
        // The sharp punches' faces, and the first estimates of the others (under force
        // control: delta from zones of a tenth of each part first).
        std::vector<double> c_fixed(n), c_first(n), delta(n, 0.0);
        bool any_force = false;
        for (std::size_t d = 0; d < n; ++d)
          {
            c_fixed[d] = dies[d].flat ? dies[d].die->profile.radius : 0.1 * dies[d].extent;
            if (dies[d].die->indentation)
              delta[d] = *dies[d].die->indentation;
            else
              any_force = true;
          }
        if (any_force)
          {
            std::vector<std::array<double, 2>> z;
            for (std::size_t d = 0; d < n; ++d)
              z.push_back(dies[d].zone_of(c_fixed[d]));
            solver.fix_local_basis(z);
            const OutlineDiesStep est = solver.solve(z, "estimate");
            for (std::size_t d = 0; d < n; ++d)
              {
                delta[d] = est.zones[d].indentation;
                if (!(delta[d] > 0.0))
                  throw std::runtime_error("the force of the die on part " + dies[d].part +
                                           " gives no indentation (delta = " + std::to_string(delta[d]) +
                                           " m) at zones of a tenth of the parts");
              }
          }
        for (std::size_t d = 0; d < n; ++d)
          c_first[d] = dies[d].flat ? c_fixed[d]
                                    : std::min(overlap_end(dies[d].die->profile, delta[d], dies[d].extent),
                                               0.9 * dies[d].extent);
        for (std::size_t d = 0; d < n; ++d)
          if (dies[d].flat)
            c_fixed[d] = c_first[d];
        auto half_width = [&](const std::size_t d, const std::vector<std::array<double, 2>> &z) {
          return dies[d].up && dies[d].down ? 0.5 * (z[d][1] - z[d][0]) : std::max(z[d][1], -z[d][0]);
        };
        Eigen::VectorXd x(n_x);
        {
          std::vector<std::array<double, 2>> z;
          for (std::size_t d = 0; d < n; ++d)
            z.push_back(dies[d].zone_of(c_first[d]));
          for (Eigen::Index k = 0; k < n_x; ++k)
            x[k] = z[ends[static_cast<std::size_t>(k)].die][ends[static_cast<std::size_t>(k)].upper ? 1 : 0];
        }
        auto broyden = [&](Eigen::VectorXd x) -> Eigen::VectorXd {
          auto z = zones_at(x, c_fixed);
          Eigen::VectorXd k = residual(solver.solve(z, "broyden"), z);
          Eigen::MatrixXd jac(n_x, n_x);
          for (Eigen::Index i = 0; i < n_x; ++i)
            {
              const End &e = ends[static_cast<std::size_t>(i)];
              const double h = 0.05 * half_width(e.die, z) * (e.upper ? 1.0 : -1.0);
              Eigen::VectorXd xi = x;
              xi[i] += h;
              const auto zi = zones_at(xi, c_fixed);
              jac.col(i) = (residual(solver.solve(zi, "jacobian"), zi) - k) / h;
            }
          bool solved_at_x = false; // the last solve was at x (not at a Jacobian's column)
          auto below_tolerance = [&](const Eigen::VectorXd &step) {
            for (Eigen::Index i = 0; i < n_x; ++i)
              if (!(std::abs(step[i]) < options.root_tolerance * half_width(ends[static_cast<std::size_t>(i)].die, z)))
                return false;
            return true;
          };
          while (true)
            {
              if (static_cast<int>(result.history.size()) >= options.max_solves * static_cast<int>(n))
                throw std::runtime_error("the zones' ends did not converge in " +
                                         std::to_string(result.history.size()) + " solves");
              Eigen::VectorXd dx = jac.fullPivLu().solve(-k);
              double scale = 1.0;
              for (Eigen::Index i = 0; i < n_x; ++i)
                {
                  const std::size_t d = ends[static_cast<std::size_t>(i)].die;
                  scale = std::max(scale, std::abs(dx[i]) / (0.25 * (z[d][1] - z[d][0])));
                }
              dx /= scale;
              Eigen::VectorXd x_new = x + dx;
              for (Eigen::Index i = 0; i < n_x; ++i)
                {
                  const DieInfo &d = dies[ends[static_cast<std::size_t>(i)].die];
                  x_new[i] = std::clamp(x_new[i], d.frame.s_min * (1 - 1e-3), d.frame.s_max * (1 - 1e-3));
                }
              dx = x_new - x;
              // The next step is below the tolerance: x, solved last, is the answer (without
              // the solve that would only confirm it; outline_contact.cc stops one die alike).
              if (solved_at_x && below_tolerance(dx))
                return x;
              const auto z_new = zones_at(x_new, c_fixed);
              for (std::size_t d = 0; d < n; ++d)
                if (!(z_new[d][1] - z_new[d][0] > 1e-3 * dies[d].extent))
                  throw std::runtime_error("the zone on part " + dies[d].part + " vanished (s = " +
                                           std::to_string(z_new[d][0]) + ", " +
                                           std::to_string(z_new[d][1]) + " m)");
              const Eigen::VectorXd k_new = residual(solver.solve(z_new, "broyden"), z_new);
              if (dx.norm() > 0.0)
                jac += ((k_new - k) - jac * dx) * dx.transpose() / dx.squaredNorm();
              x = x_new, k = k_new, z = z_new;
              solved_at_x = true;
              if (below_tolerance(dx))
                return x;
            }
        };
        // Passes with the local boxes about half the first estimate, then about the zones
        // found while they are more than 10 % off (as for one die).
        std::vector<double> c_box(n);
        for (std::size_t d = 0; d < n; ++d)
          c_box[d] = dies[d].flat ? c_first[d] : 0.5 * c_first[d];
        const int max_passes = std::max(1, options.local_passes);
        for (int pass = 0;; ++pass)
          {
            std::vector<std::array<double, 2>> zb;
            for (std::size_t d = 0; d < n; ++d)
              zb.push_back(dies[d].zone_of(c_box[d]));
            solver.fix_local_basis(zb);
            if (n_x > 0)
              x = broyden(x);
            else
              solver.solve(zones_at(x, c_fixed), "fixed");
            const auto z = zones_at(x, c_fixed);
            bool near = true;
            for (std::size_t d = 0; d < n; ++d)
              {
                const double c = half_width(d, z);
                near = near && std::abs(c - c_box[d]) <= 0.1 * c;
                c_box[d] = c;
              }
            if (!solver.has_local_boxes() || near || pass + 1 == max_passes)
              break;
          }
        solver.finish();
        result.success = true;
        result.message = "every free end is a root of its K to " + std::to_string(options.root_tolerance) +
                         " of its zone's half-width (" + std::to_string(result.history.size()) +
                         " solves of all dies, Broyden)";
      }
    catch (const std::runtime_error &e)
      {
        result.success = false;
        result.message = e.what();
      }
    return result;
  }

} // namespace rfm
