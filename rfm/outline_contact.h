// Frictionless contact of a rigid die with a straight part of an outline section (DESIGN.md
// 4.4, 7.1): the zone is unknown. For a trial zone the bilateral problem is linear
// (OutlineModel with a DieZone and the contact edge's modes); the edge intensity K at the
// zone's free end, from the interaction integral, is < 0 when the zone is too short there and
// > 0 when it is too long, and changes sign linearly through the true end, where the pressure
// falls to zero like a square root. The zone's end is the root of K.
//
// Method ("edge-intensity", the default of contact.method): from where the die's surface
// reaches the undeformed part (g0(c) = delta: the zone of the overlapping shapes, above the
// true one), steps by a factor 1 + 2 first_step in the direction K asks for until K changes
// sign (a bracket), then the Illinois method to root_tolerance times the part's extent. A root
// not bracketed inside the part is a numerical failure. One free end (the centre on a
// symmetry edge or the axis) so far. A flat punch with a sharp edge keeps its face as the zone
// (one or two edges; K is the intensity of its singular edge pressure). The hollow-cylinder
// form's search (contact.h) also takes the stationary point of P(c) next to the root; on the
// outline path c is the root itself.
#pragma once

#include "rfm/outline_model.h"

#include <memory>
#include <string>
#include <vector>

namespace rfm
{
  struct OutlineContactOptions
  {
    double root_tolerance = 1e-4; ///< on c / extent: the Illinois method stops below it
    double first_step = 0.1;      ///< bracketing steps, times the extent
    int max_solves = 40;
  };

  /// One solve at a trial zone.
  struct OutlineContactStep
  {
    double half_width = 0.0;      ///< c [m], the centre to the free end
    double force = 0.0, force_trace = 0.0; ///< P [N]
    double edge_intensity = 0.0;  ///< K [Pa m^1/2]
    double lagrange = 0.0, castigliano = 0.0, reissner = 0.0; ///< J per radian
    std::string phase;            ///< "bracket" or "illinois"
  };

  struct OutlineContactResult
  {
    bool success = false;
    std::string message;
    DieZone zone;                        ///< the zone found
    std::vector<OutlineContactStep> history;
    std::unique_ptr<OutlineModel> model; ///< the solve at the zone found
  };

  /// The zone of the problem's die (one die part, indentation given; precondition: the
  /// parser's checks). Throws InputError for what it does not handle (a zone with two free
  /// ends, a force).
  OutlineContactResult solve_outline_contact(const axisym::Problem &problem,
                                             const DiscretizationOptions &discretization,
                                             const OutlineContactOptions &options = {});
} // namespace rfm
