// The generalized stress intensities at a singular vertex of the section (issue 24 item 3):
// the coefficients K of the wedge's singular modes in a field, from the axisymmetric
// interaction integral with the dual modes as auxiliary fields, for any field (the RFM's, or
// the FEM's sampled at the rule's points). A post-processing of fields, as the contact edge's
// intensity (interaction_integral.h).
//
// The modes. Near a vertex of interior angle 2 alpha the field is u(vertex) plus
// sum_i K_i rho^lambda_i F_i(theta) plus smoother terms (problem/wedge_modes.h: plane strain,
// theta = 0 on the bisector). K_i is reported in the normalization of the notch literature
// (Gross and Mendelson; for the crack the usual K_I and K_II): the mode is scaled so that
// sqrt(2 pi) rho^(1 - lambda) s_thth(rho, 0) = 1 on the bisector, or s_rhotheta where that is
// the larger one there (an antisymmetric mode), so that s_thth(rho, 0) = K / sqrt(2 pi)
// rho^(lambda - 1) for a symmetric mode. Units: Pa m^(1 - lambda). For a complex lambda the
// real field is Re(K rho^lambda F) and K is complex.
//
// The integral. For the field (u_h, s_h) and a dual mode (u*, s*) (exponent -lambda_j, plane
// strain, s*_tt = nu (s*_rr + s*_zz)), W = r (s_h u* - s* u~) with u~ = u_h - u_h(vertex)
// satisfies, by the axisymmetric equilibrium of s_h and the plane one of s*,
//
//   div W = u*_r s_h,tt + u_r s*_tt - u~ . (s*_rr, s*_rz) - r f . u* - r alpha T tr s*,
//
// (f the body force, alpha T the free thermal strain). With a weight q(rho) = 1 at the vertex
// and 0 at rho_1 (1 - 3 t^2 + 2 t^3, t = rho / rho_1), Green's theorem on the sector rho < rho_1
// gives the contour integral about the vertex, r_v sum_i K_i B(F_i, G_j), as
//
//   - int (q div W + W . grad q) dr dz + int_faces q r t_h . u* ds,
//
// the face term only where a face carries a traction t_h (on free faces s* n = 0; on clamped
// and symmetry faces both fields' constrained parts vanish).
//
// A face that is an arc (a traction-free, pressure or traction part) bounds the sector where
// it runs, not its tangent at the vertex: the sector is the body within rho_1 (the frame's
// rule, wedge_frame.h), the duals are taken at the polar angle from the bisector also where
// the arc leaves the straight wedge (their angular functions are analytic), and the face
// term on the arc is W . n = r (t_h . u* - t* . u~): the dual is traction free on the
// tangent, not on the arc, where t* = s* n ~ rho^(-lambda) / R (R the arc's radius), which
// is integrable against u~ ~ rho^lambda. Without that term K depended on rho_1 by O(rho_1 / R).
//
// The terms u_r s*_tt and - r alpha T tr s* of div W and the faces' t_h . u* go like
// rho^(-Re lambda) drho at the vertex, integrable, but for lambda near 1 a fixed share of them
// lies below any radius that points in (r, z) resolve (13 % below 1e-14 rho_1 at lambda =
// 0.9375, the 186-degree free wedge, where a rule alone gave K 3.8 % low). Their parts with
// the vertex's values (u_r(v), r_v alpha T(v), r_v t_h(v)) are q rho^mu times a function of
// the angle, integrated in closed form in rho and by Gauss in the angle (and over the slivers
// between an arc and its tangent); the rules take the rest, which is regular.
//
// B is the plane Betti form of
// two wedge fields on a circle about the vertex (independent of its radius, zero between
// modes of different exponents), so the K_i are the solution of one small linear system. The
// integrand is integrable for Re lambda < 1 (the singular modes; the hoop and load terms are
// O(rho / r_v) beside the rest).
#pragma once

#include "problem/problem.h"
#include "rfm/fields/solution.h"
#include "rfm/quadrature/quadrature.h"
#include "rfm/spaces/vertex_enrichment.h"

#include <nlohmann/json.hpp>

#include <complex>
#include <vector>

namespace rfm
{
  struct VertexIntensity
  {
    std::complex<double> lambda;
    std::complex<double> value; ///< K [Pa m^(1 - Re lambda)]; real for a real lambda
  };

  /// The rule of vertex_intensities about the vertex of `frame` (a vertex of `problem`'s
  /// outline): the points at which `field` is asked for values, in this order, followed by the
  /// vertex alone. First the sector rho < rho_1 of the body (the near-vertex rule at radius
  /// rho_1, the frame's where a face is an arc; weights dr dz), then the points of the faces
  /// that are arcs within rho_1 (weights ds).
  Quadrature2D vertex_interaction_quadrature(const VertexEnrichment &frame, const axisym::Problem &problem,
                                             double rho_1);

  /// The intensities of the modes of `frame` with Re lambda < 1 (one per real exponent and mode,
  /// one complex one per complex exponent) in `field`, the vertex of `frame` a vertex of
  /// `problem`'s outline between two parts that are lines, or arcs that carry a traction (none,
  /// a pressure or a traction); loads (tractions of the two parts, body force, temperature)
  /// from `problem`. rho_1 > 0: the sector must lie in the body (the enrichment's cutoff radius
  /// does). Throws std::invalid_argument otherwise.
  std::vector<VertexIntensity> vertex_intensities(const FieldEvaluator &field,
                                                  const VertexEnrichment &frame,
                                                  const axisym::Problem &problem, double rho_1);

  /// [{"lambda": [re, im], "K": [re, im]}, ...]: the result JSON's form (rfm_solve, drivers).
  nlohmann::json to_json(const std::vector<VertexIntensity> &intensities);
} // namespace rfm
