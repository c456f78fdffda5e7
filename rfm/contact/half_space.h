// A rigid axisymmetric punch of any profile g0 on an elastic half-space with a smooth edge at
// the contact radius a (Sneddon, Int. J. Engng Sci. 3 (1965) 47-57; Johnson, Contact
// Mechanics, 1985, section 5.2), E* = E / (1 - nu^2) for a rigid die:
//
//   psi(t)  = t int_0^(pi/2) g0'(t sin phi) dphi,
//   delta   = psi(a)                               (the pressure vanishes at r = a),
//   P       = 2 E* int_0^a (psi(a) - psi(t)) dt,
//   p(r)    = (E* / pi) int_r^a psi'(t) / sqrt(t^2 - r^2) dt,
//   psi'(t) = int_0^(pi/2) [g0'(v) + v g0''(v)] at v = t sin phi dphi.
//
// The paraboloid gives Hertz (psi = t^2 / R: delta = a^2 / R, P = 4 E* a^3 / 3 R, p = (2 E* /
// pi R) sqrt(a^2 - r^2)); the rounded flat punch psi = (t / rho) (sqrt(t^2 - b^2) - b arccos(b /
// t)) beyond its flat radius b. Only the profile's g0', g0'' and kinks enter (DieProfile): a
// new profile needs nothing here. The RFM reads it for a die about the axis on an end face
// (DieFrame::about_axis): the first estimate of the zone, and the shape of the consistent
// pressure's first function (outline_contact.h). A body of finite size changes a at third
// order in a / H under force control (the Hertz case of dies_on_parts, a / H = 0.043: the
// RFM's zone is 1.3e-5 and the FEM's -8.5e-5 from the half-space's a); under an indentation
// its own compression takes part of delta (the rounded punch there: a 0.4 % short).
//
// The integrals are Gauss-Legendre on pieces split at g0's kinks, with t = lo + (hi - lo) u^2
// where psi or psi' has a root singularity at a kink's lower end: to rounding for the
// paraboloid and the rounded punch (half_space_test.cc, against their closed forms).
#pragma once

#include "problem/problem.h"

#include <optional>

namespace rfm::half_space
{
  /// psi(t) [m] and psi'(t) [-] for t >= 0.
  double psi(const axisym::DieProfile &g0, double t);
  double psi_slope(const axisym::DieProfile &g0, double t);

  /// delta(a) [m] of a smooth edge at a: psi(a).
  double indentation(const axisym::DieProfile &g0, double a);
  /// P(a) [N] of a smooth edge at a, E* [Pa].
  double force(const axisym::DieProfile &g0, double a, double e_star);

  /// The contact radius a [m] of the die's indentation or force (exactly one set) on the
  /// half-space of E* [Pa], when it is below `limit` [m]; nullopt otherwise (also for a die
  /// with a sharp edge, whose zone is its face).
  std::optional<double> contact_radius(const axisym::DieCondition &die, double e_star, double limit);

  /// The pressure's shape p(x a) / ((E* / pi) sqrt(1 - x^2)) [-] for x in [0, 1]: bounded,
  /// psi'(a) at x = 1, 2 a / R for the paraboloid (constant). Throws std::invalid_argument for
  /// x outside [0, 1] or a <= 0.
  double pressure_shape(const axisym::DieProfile &g0, double a, double x);

  /// E* = E / (1 - nu^2) [Pa] of the problem's material (a rigid die).
  double contact_modulus(const axisym::Problem &problem);
} // namespace rfm::half_space
