// The hollow cylinder's contact methods (contact.h, contact.method), one file each behind one
// interface: a method drives ZoneTrials (a solve at a trial half-width c with the check of
// conditions 1.2 and 1.3) and fills its ContactResult. `fixed` is a single trial
// (solve_contact in contact.cc). Internal to rfm/.
#pragma once

#include "rfm/contact/contact.h"

namespace rfm::contact_methods
{
  /// The solves of one search: each trial zone [0, c] on the outer side, checked and recorded
  /// in result.history (the last one also in result.final and result.model).
  struct ZoneTrials
  {
    const axisym::Problem &problem;
    const DiscretizationOptions &discretization;
    const ContactOptions &options;
    ContactResult &result;

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
