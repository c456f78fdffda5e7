// The bilateral solves behind the outline's contact searches (outline_contact.h): the die
// parts of a problem (DieInfo), the solves of all dies at given zones with the force
// control of every force-controlled die by linearity (DiesSolver), its one-die form for the
// one-die searches (ZoneSolver), and the first estimate of a zone (overlap_end). Internal to
// rfm/contact/: outline_contact.cc (one die), outline_dies.cc (several),
// outline_conditions.cc (iterate, max-force).
#pragma once

#include "rfm/contact/outline_contact.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfm::outline_trials
{
    inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

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

    inline std::vector<DieInfo> die_infos(const axisym::Problem &problem)
    {
      std::vector<DieInfo> out;
      for (const std::string &part : problem.body->die_parts())
        {
          DieInfo d;
          d.part = part;
          d.frame = axisym::die_frame(*problem.body, part);
          d.die = &problem.body->conditions.at(part).die;
          d.up = d.frame.runs_up(), d.down = d.frame.runs_down();
          d.extent = d.up && d.down ? std::min(d.frame.s_max, -d.frame.s_min)
                                    : (d.up ? d.frame.s_max : -d.frame.s_min);
          d.flat = d.die->profile.sharp_edge();
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
      /// Called with every step as it is recorded.
      void on_step(std::function<void(const OutlineDiesStep &)> f) { on_step_ = std::move(f); }

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
            std::unique_ptr<OutlineModel> base_model = make_model(z, delta);
            record(*base_model, base);
            std::vector<std::unique_ptr<OutlineModel>> unit_models;
            std::vector<double> unit_deltas;
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
                unit_models.push_back(make_model(z, dj));
                unit_deltas.push_back(db);
                record(*unit_models.back(), b);
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
            // The model at these deltas by the same linearity (no third solve: the Hertz
            // search's 8 steps took 24 solves before).
            std::vector<const OutlineModel *> others;
            std::vector<double> t;
            for (std::size_t j = 0; j < unit_models.size(); ++j)
              others.push_back(unit_models[j].get()), t.push_back(x[static_cast<Eigen::Index>(j)] / unit_deltas[j]);
            base_model->combine_indentations(others, t);
            result_.model = std::move(base_model);
          }
        step.zones = zones(z, delta);
        result_.zones = step.zones;
        result_.history.push_back(step);
        if (on_step_)
          on_step_(step);
        return step;
      }

      /// The model at the zones of the last solve (solve() leaves it; this builds it only when
      /// it is missing).
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
      std::function<void(const OutlineDiesStep &)> on_step_;
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
      /// Called with every step as it is recorded.
      void on_step(std::function<void(const OutlineContactStep &)> f) { on_step_ = std::move(f); }

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
        if (on_step_)
          on_step_(step);
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
      std::function<void(const OutlineContactStep &)> on_step_;
    };

    /// The distance from the centre where the die's surface reaches the undeformed part
    /// (g0(s) = delta), at least 2 % of the extent; half the extent if it does not.
    inline double overlap_end(const axisym::DieProfile &profile, const double delta, const double extent)
    {
      for (double s = 0.0; s < extent; s += 1e-3 * extent)
        if (profile.gap(s) >= delta)
          return std::max(s, 0.02 * extent);
      return 0.5 * extent;
    }
} // namespace rfm::outline_trials
