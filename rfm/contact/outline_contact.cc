#include "rfm/contact/outline_contact.h"

#include "rfm/contact/contact_methods.h"
#include "rfm/contact/illinois.h"
#include "rfm/quadrature/quadrature.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfm
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// A die part of a problem with several: its frame and what is free about its zone.
    struct DieInfo
    {
      std::string part;
      axisym::DieFrame frame;
      const axisym::DieCondition *die = nullptr;
      bool up = false, down = false; ///< the part runs on beyond the centre upward / downward
      double extent = 0.0;           ///< the part's length from the centre on the free side(s)
      bool flat = false;             ///< a flat punch with a sharp edge: its face is the zone

      /// The zone of extent c from the centre (one free end) or [-c, c] (two).
      std::array<double, 2> zone_of(const double c) const
      {
        return up && down ? std::array<double, 2>{-c, c}
                          : (up ? std::array<double, 2>{0.0, c} : std::array<double, 2>{-c, 0.0});
      }
    };

    std::vector<DieInfo> die_infos(const axisym::Problem &problem)
    {
      std::vector<DieInfo> out;
      const double tol = 1e-9 * problem.body->outline.size();
      for (const std::string &part : problem.body->die_parts())
        {
          DieInfo d;
          d.part = part;
          d.frame = axisym::die_frame(*problem.body, part);
          d.die = &problem.body->conditions.at(part).die;
          d.up = d.frame.s_max > tol, d.down = d.frame.s_min < -tol;
          d.extent = d.up && d.down ? std::min(d.frame.s_max, -d.frame.s_min)
                                    : (d.up ? d.frame.s_max : -d.frame.s_min);
          d.flat = d.die->profile.shape == axisym::DieProfile::Shape::flat;
          out.push_back(d);
        }
      return out;
    }

    /// The bilateral solves of several dies: zones in, P per die, K at every free end and the
    /// deltas of the force-controlled dies out (solve_outline_dies_on_zones).
    class DiesSolver
    {
    public:
      DiesSolver(const axisym::Problem &problem, const DiscretizationOptions &discretization,
                 std::vector<DieInfo> dies, OutlineDiesResult &result)
        : problem_(problem), options_(discretization), dies_(std::move(dies)), result_(result)
      {}

      void fix_local_basis(const std::vector<std::array<double, 2>> &estimates)
      {
        local_ = die_local_basis(problem_, zones(estimates, std::vector<double>(dies_.size(), 0.0)),
                                 options_);
      }
      bool has_local_boxes() const { return local_ && !local_->empty(); }

      OutlineDiesStep solve(const std::vector<std::array<double, 2>> &z, const std::string &phase)
      {
        const std::size_t n = dies_.size();
        std::vector<double> delta(n, 0.0);
        std::vector<std::size_t> by_force;
        for (std::size_t d = 0; d < n; ++d)
          if (dies_[d].die->indentation)
            delta[d] = *dies_[d].die->indentation;
          else
            by_force.push_back(d);
        OutlineDiesStep step;
        step.phase = phase;
        if (by_force.empty())
          {
            auto model = make_model(z, delta);
            record(*model, step);
            result_.model = std::move(model);
          }
        else
          {
            // Affine in the force-controlled deltas: a solve at 0 and one per such die.
            OutlineDiesStep base;
            record(*make_model(z, delta), base);
            const auto n_f = static_cast<Eigen::Index>(by_force.size());
            const auto n_k = static_cast<Eigen::Index>(base.edge_intensities.size());
            Eigen::MatrixXd dp(static_cast<Eigen::Index>(n), n_f), dpt(static_cast<Eigen::Index>(n), n_f),
              dk(n_k, n_f);
            for (Eigen::Index j = 0; j < n_f; ++j)
              {
                const std::size_t d = by_force[static_cast<std::size_t>(j)];
                const double c = std::max(std::abs(z[d][0]), std::abs(z[d][1]));
                const double db = std::max(dies_[d].flat ? 1e-6 * problem_.body->outline.size()
                                                         : dies_[d].die->profile.gap(c),
                                           1e-6 * problem_.body->outline.size());
                std::vector<double> dj = delta;
                dj[d] = db;
                OutlineDiesStep b;
                record(*make_model(z, dj), b);
                for (std::size_t i = 0; i < n; ++i)
                  {
                    dp(static_cast<Eigen::Index>(i), j) = (b.forces[i] - base.forces[i]) / db;
                    dpt(static_cast<Eigen::Index>(i), j) = (b.forces_trace[i] - base.forces_trace[i]) / db;
                  }
                for (Eigen::Index i = 0; i < n_k; ++i)
                  dk(i, j) = (b.edge_intensities[static_cast<std::size_t>(i)] -
                              base.edge_intensities[static_cast<std::size_t>(i)]) / db;
              }
            Eigen::MatrixXd a(n_f, n_f);
            Eigen::VectorXd rhs(n_f);
            for (Eigen::Index i = 0; i < n_f; ++i)
              {
                const std::size_t d = by_force[static_cast<std::size_t>(i)];
                rhs[i] = *dies_[d].die->force - base.forces[d];
                for (Eigen::Index j = 0; j < n_f; ++j)
                  a(i, j) = dp(static_cast<Eigen::Index>(d), j);
              }
            const Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
            if (lu.rank() < n_f || lu.rcond() < 1e-12)
              throw std::runtime_error(
                "the dies' forces do not fix their indentations (rcond " + std::to_string(lu.rcond()) +
                "): a body held by force-controlled dies alone is free to translate; give one die "
                "an indentation, or a symmetry edge that holds the body");
            const Eigen::VectorXd x = lu.solve(rhs);
            for (Eigen::Index j = 0; j < n_f; ++j)
              delta[by_force[static_cast<std::size_t>(j)]] = x[j];
            step.forces = base.forces, step.forces_trace = base.forces_trace;
            for (std::size_t i = 0; i < n; ++i)
              {
                step.forces[i] += dp.row(static_cast<Eigen::Index>(i)).dot(x);
                step.forces_trace[i] += dpt.row(static_cast<Eigen::Index>(i)).dot(x);
              }
            step.edge_intensities = base.edge_intensities;
            for (Eigen::Index i = 0; i < n_k; ++i)
              step.edge_intensities[static_cast<std::size_t>(i)] += dk.row(i).dot(x);
            result_.model.reset();
          }
        step.zones = zones(z, delta);
        result_.zones = step.zones;
        result_.history.push_back(step);
        return step;
      }

      /// The model at the zones of the last solve (force control: one more solve).
      void finish()
      {
        if (result_.model)
          return;
        std::vector<std::array<double, 2>> z;
        std::vector<double> delta;
        for (const DieZone &zone : result_.zones)
          z.push_back({zone.s_lo, zone.s_hi}), delta.push_back(zone.indentation);
        result_.model = make_model(z, delta);
      }

    private:
      std::vector<DieZone> zones(const std::vector<std::array<double, 2>> &z,
                                 const std::vector<double> &delta) const
      {
        std::vector<DieZone> out;
        for (std::size_t d = 0; d < dies_.size(); ++d)
          out.push_back(DieZone{dies_[d].part, z[d][0], z[d][1], delta[d]});
        return out;
      }
      std::unique_ptr<OutlineModel> make_model(const std::vector<std::array<double, 2>> &z,
                                               const std::vector<double> &delta) const
      {
        auto model = std::make_unique<OutlineModel>(problem_, options_, SolverOptions{},
                                                    zones(z, delta), local_);
        if (!model->ok())
          throw std::runtime_error("the solve of the dies' zones failed: " + model->summary().message);
        return model;
      }
      void record(const OutlineModel &model, OutlineDiesStep &step) const
      {
        step.forces.clear(), step.forces_trace.clear();
        for (const DieInfo &d : dies_)
          {
            const OutlineModel::DieForce f = model.die_force(d.part);
            step.forces.push_back(f.domain), step.forces_trace.push_back(f.trace);
          }
        step.edge_intensities.clear();
        for (std::size_t i = 0; i < model.n_zone_edges(); ++i)
          step.edge_intensities.push_back(model.edge_intensity(i));
      }

      const axisym::Problem &problem_;
      DiscretizationOptions options_;
      std::vector<DieInfo> dies_;
      OutlineDiesResult &result_;
      std::optional<LocalBasis> local_;
    };

    /// The bilateral solves of one problem's die (DiesSolver with one die): a zone [s_lo,
    /// s_hi] in, P, K at the free ends and delta out, by indentation or by force (the header's
    /// linearity), as the steps of the one-die search.
    class ZoneSolver
    {
    public:
      ZoneSolver(const axisym::Problem &problem, const DiscretizationOptions &discretization,
                 const std::string &part, OutlineContactResult &result)
        : part_(part), result_(result), dies_(problem, discretization, one_die(problem, part), solves_)
      {}

      /// The local boxes every later solve uses (those of `estimate`).
      void fix_local_basis(const DieZone &estimate) { dies_.fix_local_basis({{estimate.s_lo, estimate.s_hi}}); }
      bool has_local_boxes() const { return dies_.has_local_boxes(); }

      OutlineContactStep solve(const double s_lo, const double s_hi, const std::string &phase)
      {
        const OutlineDiesStep d = dies_.solve({{s_lo, s_hi}}, phase);
        OutlineContactStep step;
        step.zone = {s_lo, s_hi};
        step.half_width = std::max(std::abs(s_lo), std::abs(s_hi));
        step.phase = phase;
        step.indentation = d.zones[0].indentation;
        step.force = d.forces[0], step.force_trace = d.forces_trace[0];
        step.edge_intensities = d.edge_intensities;
        step.edge_intensity = step.edge_intensities.empty() ? nan : step.edge_intensities[0];
        step.lagrange = step.castigliano = step.reissner = nan; // quadratic in delta
        if (solves_.model)
          {
            const Functionals phi = solves_.model->functionals();
            step.lagrange = phi.lagrange, step.castigliano = phi.castigliano,
            step.reissner = phi.reissner;
          }
        result_.model = std::move(solves_.model);
        result_.zone = d.zones[0];
        result_.history.push_back(step);
        return step;
      }

      /// The model at the zone found, at its delta (force control: one more solve).
      void finish()
      {
        if (result_.model)
          return;
        dies_.finish();
        result_.model = std::move(solves_.model);
      }

    private:
      static std::vector<DieInfo> one_die(const axisym::Problem &problem, const std::string &part)
      {
        std::vector<DieInfo> all = die_infos(problem);
        all.erase(std::remove_if(all.begin(), all.end(), [&](const DieInfo &d) { return d.part != part; }),
                  all.end());
        return all;
      }

      std::string part_;
      OutlineContactResult &result_;
      OutlineDiesResult solves_;
      DiesSolver dies_;
    };

    /// The distance from the centre where the die's surface reaches the undeformed part
    /// (g0(s) = delta), at least 2 % of the extent; half the extent if it does not.
    double overlap_end(const axisym::DieProfile &profile, const double delta, const double extent)
    {
      for (double s = 0.0; s < extent; s += 1e-3 * extent)
        if (profile.gap(s) >= delta)
          return std::max(s, 0.02 * extent);
      return 0.5 * extent;
    }
  } // namespace

  OutlineContactResult solve_outline_contact(const axisym::Problem &problem,
                                             const DiscretizationOptions &discretization,
                                             const OutlineContactOptions &options)
  {
    const std::vector<std::string> parts = problem.body->die_parts();
    const std::string &part = parts.at(0);
    const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
    const axisym::DieCondition &die = problem.body->conditions.at(part).die;
    const double tol = 1e-9 * problem.body->outline.size();
    const bool up = f.s_max > tol, down = f.s_min < -tol, two_ends = up && down;
    const axisym::DieProfile &profile = die.profile;
    const bool flat = profile.shape == axisym::DieProfile::Shape::flat;
    // The extent: the part's length from the centre on the free side(s).
    const double extent = two_ends ? std::min(f.s_max, -f.s_min) : (up ? f.s_max : -f.s_min);
    auto zone_of = [&](const double c) {
      return two_ends ? std::array<double, 2>{-c, c}
                      : (up ? std::array<double, 2>{0.0, c} : std::array<double, 2>{-c, 0.0});
    };

    OutlineContactResult result;
    ZoneSolver solver(problem, discretization, part, result);
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
        // 0. The first estimate: g0 = delta (under force control, delta from a zone of a tenth
        //    of the extent first).
        double delta = die.indentation ? *die.indentation : 0.0;
        if (!die.indentation)
          {
            const auto z = zone_of(0.1 * extent);
            solver.fix_local_basis({part, z[0], z[1], 0.0});
            delta = solver.solve(z[0], z[1], "estimate").indentation;
            if (!(delta > 0.0))
              throw std::runtime_error("the force gives no indentation (delta = " +
                                       std::to_string(delta) + " m) at a zone of a tenth of the part");
          }
        const double c_first = std::min(overlap_end(profile, delta, extent), 0.9 * extent);
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
              if (!(x_new[1] - x_new[0] > 1e-3 * extent))
                throw std::runtime_error("the zone's ends crossed (s = " + std::to_string(x_new[0]) +
                                         ", " + std::to_string(x_new[1]) + " m)");
              const Eigen::Vector2d k_new = k_of(x_new, "broyden");
              if (dx.norm() > 0.0)
                jac += ((k_new - k) - jac * dx) * dx.transpose() / dx.squaredNorm();
              x = x_new, k = k_new;
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
        // The first estimate (g0 = delta) overshoots: 2.3 times the Hertz radius under force,
        // 2.2 times the ring die's zone: the first pass's boxes are built about half of it.
        double c_box = 0.5 * c_first;
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
              c_found = search_one_end(pass == 0 ? c_first : c_box, pass == 0 ? options.first_step : 0.02);
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
    const double tol = 1e-9 * problem.body->outline.size();
    DiesSolver solver(problem, discretization, dies, result);
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
            const bool free = upper ? z[d][1] < dies[d].frame.s_max - tol : z[d][0] > dies[d].frame.s_min + tol;
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
              bool done = true;
              for (Eigen::Index i = 0; i < n_x; ++i)
                done = done && std::abs(dx[i]) < options.root_tolerance *
                                                   half_width(ends[static_cast<std::size_t>(i)].die, z);
              if (done)
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

  ContactResult solve_outline_contact_by_conditions(const axisym::Problem &problem,
                                                    const DiscretizationOptions &discretization,
                                                    const ContactOptions &options,
                                                    const std::function<void(const ContactIterate &)> &on_step)
  {
    const std::string part = problem.body->die_parts().at(0);
    const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
    const axisym::DieCondition &die = problem.body->conditions.at(part).die;
    const double tol = 1e-9 * problem.body->outline.size();
    const bool up = f.s_max > tol, down = f.s_min < -tol;
    const std::string field = "contact.method";
    if (up && down)
      throw axisym::InputError(
        field + " = \"" + problem.contact.method + "\": it searches a zone with one free end, and " +
        "the die on part " + part + " has two (its centre is inside the part, not on the axis or a " +
        "symmetry edge); use \"edge-intensity\" (the default) or \"fixed\"");
    if (die.profile.shape == axisym::DieProfile::Shape::flat)
      throw axisym::InputError(field + " = \"" + problem.contact.method +
                               "\": a flat punch with a sharp edge (boundary." + part +
                               ".die.profile.shape = \"flat\") has its face as the zone; use "
                               "\"edge-intensity\" (the default) or \"fixed\"");
    const double extent = up ? f.s_max : -f.s_min;
    ContactResult result;
    result.method = problem.contact.method;
    contact_methods::ZoneTrials trials{
      problem, discretization, options, result, extent,
      [&](const double c) {
        OutlineContactResult r =
          up ? solve_outline_zone(problem, discretization, 0.0, c)
             : solve_outline_zone(problem, discretization, -c, 0.0);
        if (!r.success || !r.model)
          throw std::runtime_error(r.message);
        return std::move(r.model);
      },
      [&](const OutlineModel &model) {
        ContactIterate it;
        const DieZone &zone = model.zones().at(0);
        it.half_width = up ? zone.s_hi : -zone.s_lo;
        const OutlineModel::DieForce force = model.die_force(part);
        it.force = force.domain, it.force_trace = force.trace;
        const Functionals phi = model.functionals();
        it.lagrange = phi.lagrange, it.castigliano = phi.castigliano, it.reissner = phi.reissner;
        it.assembly_s = model.assembly_seconds(), it.solve_s = model.solve_seconds();
        it.edge_intensity = it.edge_intensity_coefficient = nan;
        it.edge_intensity_reciprocal_work = nan;
        if (model.n_zone_edges() > 0)
          {
            it.edge_intensity = model.edge_intensity(0);
            const EdgeEnrichment &e = model.zone_edge_enrichment(0);
            if (e.singular_column() >= 0)
              it.edge_intensity_coefficient =
                std::sqrt(2.0 * M_PI) * model.edge_column_coefficients(0, e.singular_column())[0];
          }
        check_die_conditions(model, *problem.body, it.edge_intensity, options, it);
        return it;
      },
      !die.indentation.has_value(), true, 1e-3 * extent};
    trials.on_step = on_step;
    if (problem.contact.method == "iterate")
      contact_methods::iterate(trials);
    else if (problem.contact.method == "max-force")
      contact_methods::max_force(trials);
    else
      throw std::invalid_argument("solve_outline_contact_by_conditions: contact.method " +
                                  problem.contact.method);
    return result;
  }

  std::vector<double> consistent_die_pressure(const OutlineModel &model, const axisym::Problem &problem,
                                              const DieZone &zone, const std::vector<double> &s,
                                              const int n_moments)
  {
    if (n_moments < 1)
      throw std::invalid_argument("consistent_die_pressure: n_moments must be >= 1");
    const axisym::DieFrame frame = axisym::die_frame(*problem.body, zone.part);
    const bool sharp =
      problem.body->conditions.at(zone.part).die.profile.shape == axisym::DieProfile::Shape::flat;
    const double tol = 1e-9 * problem.body->outline.size();
    const bool two_ends = frame.s_max > tol && frame.s_min < -tol;
    // The zone's coordinate x(s): one free end x = |s| / h, two x = (s - mid) / h.
    const double mid = two_ends ? 0.5 * (zone.s_lo + zone.s_hi) : 0.0;
    const double h = two_ends ? 0.5 * (zone.s_hi - zone.s_lo) : std::max(zone.s_hi, -zone.s_lo);
    const int n_phi = two_ends ? 2 * n_moments - 1 : n_moments;
    auto degree = [two_ends](int k) { return two_ends ? k : 2 * k; };
    const int m_max = degree(n_phi - 1);
    // T_m or U_m at x in [-1, 1] (X_{m+1} = 2 x X_m - X_{m-1}, X_1 = x (T) or 2 x (U)).
    auto chebyshev = [&](double x, std::vector<double> &v) {
      v.assign(m_max + 1, 0.0);
      v[0] = 1.0;
      if (m_max >= 1)
        v[1] = (sharp ? 1.0 : 2.0) * x;
      for (int m = 1; m < m_max; ++m)
        v[m + 1] = 2.0 * x * v[m] - v[m - 1];
    };
    std::vector<double> v;
    // The test fields: V_0 = (1 - d / D) n (die_force's: m_0 = P / 2 pi), and for k >= 1 the
    // bumps (1 - x^2)^3 x^e of the zone (C2, zero at its ends and beyond; e = 2 (k - 1) with
    // one free end, k - 1 with two) times the C2 quintic step from 1 at d = 0 to 0 at
    // d = h / 2: supported next to the zone, where the local columns resolve the field, and
    // flat at the zone's ends, where the stresses carry the edge modes' residual singular
    // term. Measured against the finest FEM at p = 8 and three moments, max |p - p_FEM| /
    // p_max on the RFM's points at the searches' zones: Hertz 0.96 % (its peak -0.09 % from
    // Hertz's p0; at the FEM's zone 0.47 % on the FEM's points, the trace 61 % there), the
    // rounded flat punch 11 %, the sharp flat punch 2.4 % of p(0) inside 0.9 b. C1 bumps
    // (1 - x^2)^2 gave 2.1 % (peak +1.9 %), 11.4 % and 3.7 %; (1 - x^2)^4 gave 1.4 % (peak
    // -1.4 %) and 10.8 % on the first two; fading into the body over h instead of h / 2,
    // 2.5 % and 13 %. The hollow cylinder's tests (continued by their
    // end value along the part and linearly through the body, contact.h) gave 5.9 % on Hertz,
    // 37 % with six moments: they kink at the zone's end and vary on the zone's scale across
    // the whole section.
    const double depth = model.die_depth(frame);
    const double ell = 0.5 * h;
    const Eigen::VectorXd moments =
      model.die_moments(frame, [&](const Eigen::VectorXd &sq, const Eigen::VectorXd &dq) {
        Eigen::MatrixXd out = Eigen::MatrixXd::Zero(sq.size(), 3 * n_phi);
        for (Eigen::Index q = 0; q < sq.size(); ++q)
          {
            out(q, 0) = 1.0 - dq[q] / depth, out(q, 2 * n_phi) = -1.0 / depth;
            const double x = two_ends ? (sq[q] - mid) / h : std::abs(sq[q]) / h;
            const double dx_ds = two_ends ? 1.0 / h : (sq[q] < 0.0 ? -1.0 : 1.0) / h;
            const double y = dq[q] / ell;
            if (std::abs(x) >= 1.0 || y >= 1.0)
              continue;
            const double yc = std::max(y, 0.0);
            const double chi = 1.0 - yc * yc * yc * (10.0 - 15.0 * yc + 6.0 * yc * yc);
            const double dchi = -30.0 * yc * yc * (1.0 - yc) * (1.0 - yc) / ell;
            const double w2 = (1.0 - x * x) * (1.0 - x * x), bump = w2 * (1.0 - x * x),
                         dbump = -6.0 * x * w2;
            for (int k = 1; k < n_phi; ++k)
              {
                const int e = two_ends ? k - 1 : 2 * (k - 1);
                const double xe = std::pow(x, e), dxe = e > 0 ? e * std::pow(x, e - 1) : 0.0;
                out(q, k) = bump * xe * chi;
                out(q, n_phi + k) = (dbump * xe + bump * dxe) * dx_ds * chi;
                out(q, 2 * n_phi + k) = bump * xe * dchi;
              }
          }
        return out;
      });
    // G_kj = int_zone w X_j phi_k r ds by Gauss-Legendre in theta, x = sin theta: w dx =
    // cos^2 theta d theta (U) or d theta (T), smooth; s = mid + h x (two ends) or on the
    // zone's side of the centre (one).
    const double side = two_ends || zone.s_hi > tol ? 1.0 : -1.0;
    const double theta_a = two_ends ? -0.5 * M_PI : 0.0, theta_b = 0.5 * M_PI;
    const GaussRule1D rule = gauss_legendre(2 * m_max + 24);
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n_phi, n_phi);
    for (Eigen::Index i = 0; i < rule.nodes.size(); ++i)
      {
        const double theta = theta_a + 0.5 * (rule.nodes[i] + 1.0) * (theta_b - theta_a);
        const double x = std::sin(theta), wx = sharp ? 1.0 : std::cos(theta) * std::cos(theta);
        const double r = frame.point_at(two_ends ? mid + h * x : side * h * x).r;
        chebyshev(x, v);
        const double weight = 0.5 * (theta_b - theta_a) * rule.weights[i] * wx * h * r *
                              (model.mirrored() ? 2.0 : 1.0);
        for (int k = 0; k < n_phi; ++k)
          {
            const int e = two_ends ? k - 1 : 2 * (k - 1);
            const double test = k == 0 ? 1.0 : std::pow(1.0 - x * x, 3) * std::pow(x, e);
            for (int j = 0; j < n_phi; ++j)
              g(k, j) += weight * test * v[degree(j)];
          }
      }
    const Eigen::VectorXd b = g.partialPivLu().solve(moments);
    std::vector<double> p(s.size(), 0.0);
    for (std::size_t i = 0; i < s.size(); ++i)
      {
        const double x = two_ends ? (s[i] - mid) / h : side * s[i] / h;
        if (x < (two_ends ? -1.0 : 0.0) - 1e-12 || x > 1.0 + 1e-12)
          continue;
        const double xc = std::clamp(x, -1.0, 1.0);
        chebyshev(xc, v);
        double sum = 0.0;
        for (int k = 0; k < n_phi; ++k)
          sum += b[k] * v[degree(k)];
        const double root = std::sqrt(std::max(0.0, 1.0 - xc * xc));
        p[i] = sharp ? (root > 0.0 ? sum / root : std::numeric_limits<double>::infinity()) : root * sum;
      }
    return p;
  }
} // namespace rfm
