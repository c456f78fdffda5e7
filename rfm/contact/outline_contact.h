// Frictionless contact of a rigid die with a straight part of an outline section (DESIGN.md
// 4.4, 7.1): the zone is unknown. For a trial zone the bilateral problem is linear
// (OutlineModel with a DieZone and the contact edge's modes); the edge intensity K at the
// zone's free end, from the interaction integral, is < 0 when the zone is too short there and
// > 0 when it is too long, and changes sign linearly through the true end, where the pressure
// falls to zero like a square root. The zone's end is the root of K.
//
// Method ("edge-intensity", the default of contact.method): from where the die's surface
// reaches the undeformed part (g0(c) = delta: the zone of the overlapping shapes, above the
// true one; a die about the axis on an end face: from the contact radius of the half-space
// punch of its profile, half_space.h, with a first step of 1 %, three solves on Hertz and on
// the rounded punch instead of eight and nine), steps by a factor 1 + 2 first_step in the
// direction K asks for until K changes
// sign, each step after the first to the secant's root and a tenth beyond (a bracket), then the
// Illinois method until the bracket or its next step is below root_tolerance times c. A root
// not bracketed inside the part is a numerical failure. A zone with two free ends (the centre
// inside the part: a ring die on a shaft) has two unknowns and two intensities (K_lo, K_hi):
// Broyden's method from a finite-difference Jacobian (two extra solves), each step limited to a
// quarter of the zone's width, until both ends move, or the next step would move them, less
// than root_tolerance times the zone's half-width.
// A flat punch with a sharp edge keeps its face as the zone (one or two edges; K is the
// intensity of its singular edge pressure). The hollow-cylinder form's search (contact.h) also
// takes the stationary point of P(c) next to the root; on the outline path c is the root itself.
//
// Force control (boundary.PART.die.force P*): for a fixed zone the bilateral problem is linear
// in delta, so the force, the intensities and the fields are affine in delta. Two solves at
// delta_a = 0 and delta_b (the gap at the zone's end) give delta = delta_a + (P* - P_a) (delta_b
// - delta_a) / (P_b - P_a) and the intensities there: no outer iteration. The search starts
// (unless the half-space gives its first zone) from a zone of a tenth of the part, takes
// delta there, and then the zone of g0 = delta; the
// zone found is solved once more at its delta for the fields and functionals (the history's
// functionals of force-controlled steps are null: they are quadratic in delta).
//
// Local boxes (local_basis.h): every trial zone is solved with the boxes of the first estimate,
// so that the space does not change with the zone (K(c) stays smooth).
//
// One file per task: outline_contact.cc (one die's search and fixed zone), outline_dies.cc
// (several dies), outline_conditions.cc (iterate, max-force), outline_pressure.cc (the
// consistent pressure); the bilateral solves they share in outline_trials.h.
#pragma once

#include "rfm/contact/contact.h"
#include "rfm/outline_model.h"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rfm
{
  struct OutlineContactStep;
  struct OutlineDiesStep;

  struct OutlineContactOptions
  {
    /// Relative to c (the zone's half-width): the search stops when the zone's ends move less.
    /// It was relative to the part's extent: 0.23 % of the Hertz radius, 0.9 % of the ring
    /// die's zone on a 40 mm shaft.
    double root_tolerance = 1e-4;
    double first_step = 0.1;      ///< the first bracketing step: a factor 1 + 2 first_step
    int max_solves = 40;
    /// Search passes with the local boxes rebuilt about the zone found, until it is within
    /// 10 % of the zone the boxes were built from (at most 3; 1: the first estimate's boxes).
    int local_passes = 3;
    /// Called after every trial solve of one die's search (solve_outline_contact) or of
    /// several dies' (solve_outline_dies), in order: rfm_solve prints each as it comes (a
    /// ring die's search at the defaults takes minutes, about 100 s a solve).
    std::function<void(const OutlineContactStep &)> on_step;
    std::function<void(const OutlineDiesStep &)> on_dies_step;
  };

  /// One solve at a trial zone.
  struct OutlineContactStep
  {
    double half_width = 0.0;      ///< c [m], the centre to the farther free end
    std::array<double, 2> zone{{0.0, 0.0}}; ///< [s_lo, s_hi] [m] along the part
    double indentation = 0.0;     ///< delta [m] (found from the force under force control)
    double force = 0.0, force_trace = 0.0; ///< P [N]
    double edge_intensity = 0.0;  ///< K [Pa m^1/2] at the first free end
    std::vector<double> edge_intensities; ///< K at every free end, low end first
    double lagrange = 0.0, castigliano = 0.0, reissner = 0.0; ///< J per radian
    std::string phase;            ///< "bracket", "illinois", "jacobian", "broyden", "estimate"
  };

  struct OutlineContactResult
  {
    bool success = false;
    std::string message;
    DieZone zone;                        ///< the zone found (indentation: delta there)
    std::vector<OutlineContactStep> history;
    std::unique_ptr<OutlineModel> model; ///< the solve at the zone found
  };

  /// The zone of the problem's die (one die part, indentation or force; precondition: the
  /// parser's checks).
  OutlineContactResult solve_outline_contact(const axisym::Problem &problem,
                                             const DiscretizationOptions &discretization,
                                             const OutlineContactOptions &options = {});

  /// One solve of several dies (one zone per die part, in Body::die_parts() order).
  struct OutlineDiesStep
  {
    std::vector<DieZone> zones;          ///< each with its delta [m] (force control: found)
    std::vector<double> forces;          ///< P [N] per die (domain integral)
    std::vector<double> forces_trace;    ///< P [N] per die (trace integral)
    std::vector<double> edge_intensities; ///< K [Pa m^1/2] at every free end, in zone order, low end first
    std::string phase;                   ///< "fixed", "estimate", "jacobian", "broyden"
  };

  struct OutlineDiesResult
  {
    bool success = false;
    std::string message;
    std::vector<DieZone> zones; ///< the zones found (or given), with their delta
    std::vector<OutlineDiesStep> history;
    std::unique_ptr<OutlineModel> model; ///< the solve at `zones`
  };

  /// Several dies on their given zones (zones[i] on die part i, Body::die_parts() order):
  /// one bilateral solve, or under force control the linearity of the header's force
  /// control in every force-controlled die's delta at once (one solve per such die and one
  /// more: delta solves the small system of their forces), then the solve at those deltas.
  /// A singular system (the body held by force-controlled dies only: its translation is
  /// free) is a numerical failure.
  OutlineDiesResult solve_outline_dies_on_zones(const axisym::Problem &problem,
                                                const DiscretizationOptions &discretization,
                                                const std::vector<DieZone> &zones);

  /// Several dies' zones (contact.method "edge-intensity" with more than one die part): every
  /// free end of every zone is a root of its K, all at once. From each die's first estimate
  /// (as for one die: the zone where g0 = delta, under force control from zones of a tenth of
  /// each part first), Broyden's method on the vector of free ends against the vector of
  /// their K, the Jacobian first from finite differences (one solve per end), each step
  /// limited to a quarter of every zone's width, until every end moves less than
  /// root_tolerance times its zone's half-width; local boxes as for one die (built about
  /// half the first estimate, rebuilt about the zones found while they are 10 % off). A flat
  /// punch with a sharp edge keeps its face. Every trial solves all dies together.
  OutlineDiesResult solve_outline_dies(const axisym::Problem &problem,
                                       const DiscretizationOptions &discretization,
                                       const OutlineContactOptions &options = {});

  /// contact.method "iterate" or "max-force" (contact.h) for the problem's die on an outline
  /// part whose zone has one free end (its centre on the axis or a symmetry edge): the same
  /// methods as the hollow cylinder's, on trial zones of length c from the centre, each
  /// solved by solve_outline_zone (its own local boxes; under force control delta from the
  /// linearity) and checked by check_die_conditions with K from the interaction integral.
  /// The tolerance is options.tolerance times c (the hollow cylinder: times a); max-force
  /// searches log c in [1e-3 a, a], a the part's length from the centre, and under force
  /// control minimizes delta(c). ContactIterate::first_tension_z and penetration_end_z are
  /// distances from the centre. Throws axisym::InputError for a zone with two free ends or a
  /// flat punch with a sharp edge (its zone is its face). Precondition: one die part.
  ContactResult solve_outline_contact_by_conditions(const axisym::Problem &problem,
                                                    const DiscretizationOptions &discretization,
                                                    const ContactOptions &options = {},
                                                    const std::function<void(const ContactIterate &)> &on_step = {});

  /// The bilateral solve of the problem's die on the zone [s_lo, s_hi] along its part, by
  /// indentation or by force (the linearity above); the local boxes of that zone. The result
  /// holds one step and the model at the zone's delta.
  OutlineContactResult solve_outline_zone(const axisym::Problem &problem,
                                          const DiscretizationOptions &discretization,
                                          double s_lo, double s_hi);

  /// The contact pressure p(s) [Pa] of a die's zone as consistent reactions (Babuska and
  /// Miller; DESIGN.md 4.4; the hollow cylinder's form: consistent_contact_pressure in
  /// contact.h), at the distances `s` from the die's centre along its part (0 outside the
  /// zone). With x the zone's coordinate in [0, 1] (one free end: |s| / c) or [-1, 1] (two:
  /// from the zone's middle, h its half length), p = w(x) sum_j b_j X_j(x): w = sqrt(1 - x^2)
  /// and X_j the Chebyshev polynomials of the second kind U_j for a smooth edge (the pressure
  /// falls like a square root at a free end), w = 1 / sqrt(1 - x^2) and the first kind T_j for
  /// a flat punch's sharp edge (p is infinite there: +infinity at |x| = 1). One free end takes
  /// the even degrees 0, 2, .., 2 (n_moments - 1) (p is even about the axis or a symmetry
  /// edge), two free ends every degree up to that. A die about the axis on an end face (one
  /// free end, a smooth edge) takes X_0 = half_space::pressure_shape of its profile
  /// (half_space.h) instead of U_0: the rounded flat punch's pressure peaks at the flat's end,
  /// where g0'' jumps and p has an x log x term that the polynomials smooth out (measured on
  /// the finest FEM's p(s): that shape alone fits it to 0.6 % of its peak, sqrt(1 - x^2) times
  /// even polynomials to 11 %, 3.8 % and 2.9 % with 3, 6 and 9 terms); the paraboloid's is U_0
  /// times a constant. The b_j solve G b = m with the moments m_k
  /// of OutlineModel::die_moments for test fields phi_k (the .cc file: die_force's for k = 0,
  /// so the pressure carries P exactly, and bumps of the zone next to it beyond) and
  /// G_kj = int_zone w X_j phi_k r ds. Precondition: model.ok() solved on `zone`,
  /// n_moments >= 1. NaN at every s where the form does not apply to the zone
  /// (consistent_pressure_applies).
  std::vector<double> consistent_die_pressure(const OutlineModel &model, const axisym::Problem &problem,
                                              const DieZone &zone, const std::vector<double> &s,
                                              int n_moments);

  /// Whether consistent_die_pressure's form applies to the zone: each of its ends is a free
  /// end (DieFrame::free_low_end, free_high_end: the pressure falls as the square root of the
  /// distance there, which the form builds in) or the die's centre at its part's end (on the
  /// axis or a symmetry edge). A zone that runs to its part's end, such as a bilateral zone
  /// over the whole face, has a pressure that does not fall there: measured on
  /// die_bilateral.json (c = a) at p = 8, the form gave 0.735 MPa at the centre and 0 at the
  /// zone's end, the trace 0.807 and 1.818 MPa in tension, the FEM's L5 0.804 and 1.896 MPa.
  bool consistent_pressure_applies(const axisym::DieFrame &frame, const DieZone &zone);
} // namespace rfm
