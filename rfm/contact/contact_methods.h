// The contact methods of a die with one free end (contact.h, contact.method), one file each
// behind one interface: a method drives ZoneTrials (a solve at a trial half-width c with the check of
// conditions 1.2 and 1.3) and fills its ContactResult: the hollow cylinder's (contact.cc) and
// a die on an outline part (outline_contact.cc). `fixed` is a single trial
// (solve_contact in contact.cc). Internal to rfm/.
#pragma once

#include "rfm/contact/contact.h"

#include <functional>
#include <memory>

namespace rfm::contact_methods
{
  /// The solves of one search: each trial zone of length c from the die's centre (the hollow
  /// cylinder: [0, c] on its outer side), checked and recorded in result.history (the last one
  /// also in result.final and result.model). The methods see only c in (0, extent].
  struct ZoneTrials
  {
    const axisym::Problem &problem;
    const DiscretizationOptions &discretization;
    const ContactOptions &options;
    ContactResult &result;
    double extent;  ///< a [m]: the zone's end runs over (0, a]
    /// The bilateral solve at c (may throw std::runtime_error on a numerical failure).
    std::function<std::unique_ptr<OutlineModel>(double c)> model_at;
    /// Its check: P, K, the functionals and conditions 1.2 and 1.3.
    std::function<ContactIterate(const OutlineModel &model)> check;
    /// max-force's objective: P at a given indentation; under force control the indentation,
    /// minimized (P(c; delta) is affine in delta, so the c of the largest P at a given delta
    /// is the c of the smallest delta at a given P).
    bool force_control = false;
    /// The searches' tolerance is options.tolerance times this length: the extent a (the
    /// hollow cylinder, whose zone is a good part of a), or c itself (a die on an outline
    /// part, whose zone may be 1/30 of its part: 5e-4 a would be 1.3 % of c).
    bool relative_to_c = false;
    /// max-force searches c in [c_low, extent]: linearly for the hollow cylinder, in log c
    /// when relative_to_c.
    double c_low = 0.0;

    /// Called after each solve with its iterate (progress output); may be empty.
    std::function<void(const ContactIterate &)> on_step = {};

    double length_scale(double c) const { return relative_to_c ? c : extent; }

    /// Solves at c; returns false (and sets result.message) on a numerical failure.
    bool solve(double c, ContactIterate &it, const char *phase);
  };

  /// contact_edge_intensity.cc: the root of K(c) and the stationary point of P(c) next to it.
  void edge_intensity(ZoneTrials &s);
  /// contact_iterate.cc: the paper's successive iterations in a bracket, then bisection for
  /// the interval of c on which both conditions hold.
  void iterate(ZoneTrials &s);
  /// contact_max_force.cc: golden-section search for the maximum of P(c).
  void max_force(ZoneTrials &s);
} // namespace rfm::contact_methods
