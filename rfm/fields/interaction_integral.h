// The edge intensity of a contact edge from the axisymmetric interaction integral: a domain
// form of Betti's theorem with the n = -1 edge mode as auxiliary field (DESIGN.md 4.4), for
// any field (the RFM's, or the FEM's sampled at the rule's points). A post-processing of
// fields: the contact searches (rfm/contact/) and the model's edge_intensity use it.
#pragma once

#include "rfm/fields/solution.h"
#include "rfm/material.h"
#include "rfm/quadrature/quadrature.h"
#include "rfm/spaces/edge_modes.h"

#include <functional>
#include <utility>

namespace rfm
{
  /// The axisymmetric interaction integral (DESIGN.md 4.4; the derivation with the hollow
  /// cylinder's form in contact.h) at a contact edge of any straight part (the frame of
  /// edge_modes.h: t into the zone along the part, n into the body), for any field:
  /// `contact_u(x)` is the
  /// prescribed outward normal displacement on the contact face at the distance x >= 0 from the
  /// edge, `free_pressure` the pressure on the free face. u~ = u_h - u_bar with u_bar's normal
  /// component contact_u(0) and its tangential one the field's at the edge; the faces are the
  /// part's line, W . n_out = -r s*_nn u~_n (contact) and -r p u*_n (free); divided by the edge's
  /// radius. The hollow cylinder's form (contact.h) is this with EdgeFrame::outer_side(R2, c),
  /// contact_u(x) = u_r*(c - x) and the outer pressure. Returns K = sqrt(2 pi) a_1 [Pa m^1/2]
  /// (K < 0: compressive, the zone too short, or a flat punch's edge).
  double edge_intensity_interaction(const FieldEvaluator &field, const EdgeFrame &frame,
                                    const Material &material, double rho_1,
                                    const std::function<double(double)> &contact_u,
                                    double free_pressure = 0.0);
  Quadrature2D interaction_quadrature(const EdgeFrame &frame, double rho_1);

  /// The interaction integrals' weight q(rho) = 1 - 3 t^2 + 2 t^3, t = rho / rho_1, and
  /// dq / drho: 1 at the edge or vertex and flat there, where the discrete field is least
  /// accurate, 0 and flat at rho_1.
  inline std::pair<double, double> interaction_weight(const double rho, const double rho_1)
  {
    const double t = rho / rho_1;
    return {1.0 - t * t * (3.0 - 2.0 * t), 6.0 * t * (t - 1.0) / rho_1};
  }
} // namespace rfm
