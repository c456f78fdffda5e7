// Frictionless contact of the outer side r = R2 with a smooth rigid die (paper sections
// 1, 2 and 4; DESIGN.md section 4.2): the contact half-width c is unknown.
//
// For a fixed c the bilateral problem is linear (u_r = u_r* on |z| <= c, free
// beyond). Its contact pressure is p(z) = -sigma_rr(R2, z); the structure forces p(c) = 0
// at the zone edge, so a wrong c shows up as
//   * condition 1.2 violated: tensile pressure p < 0 inside the zone (c too long), or
//   * condition 1.3 violated: penetration u_r > u_r* outside the zone (c too short).
// Both are checked on a fine grid of points along the outer side.
//
// Four ways to fix c (problem file: contact.method; one file per method behind
// contact_methods.h: contact_edge_intensity.cc, contact_iterate.cc, contact_max_force.cc):
//   edge-intensity (default): the zone where the edge intensity K(c) changes sign
//              (DESIGN.md 4.4). The enriched bilateral solve at a trial c gives
//              K = sqrt(2 pi) a_1 from the coefficient of the n = 1 edge mode: K < 0 when
//              the zone is too short (compressive rho^-1/2 pressure at the edge), K > 0 when
//              it is too long, and K changes sign linearly through the true c while P(c) is
//              stationary there. From c = a/2 a secant step on K finds a bracket and the
//              Illinois method closes it to root_tolerance. The root of the coefficient
//              carries the leakage of unresolved edge terms into a_1 (0.5-0.8 % above the
//              FEM's c at p = 8-14, moving with the cutoff radius), while the discrete P, a
//              domain integral, is stationary within 0.05 % of it: c is the stationary point
//              of P next to the root, by successive parabolic interpolation over the solves
//              (stationary_step), and the last solve checks conditions 1.2 and 1.3. If K < 0
//              up to the end of the side, c = a (full contact) is accepted when it has no
//              tension; otherwise the root is not bracketed in (0, a]: a numerical failure.
//   fixed:     the given c (c = a is the paper's iteration 0); gives P(c).
//   iterate:   the paper's successive iterations, from c = a: remove the points where the
//              pressure is tensile (c <- first zero of p), add the points that penetrate
//              (c <- end of the penetrating interval), until both conditions hold. When
//              both are violated, the sign of K decides (with the edge modes), else
//              penetration (the zone is too short). Each
//              step is kept inside the bracket [too short, too long] found so far; a step
//              that leaves it is replaced by a bisection step (the raw fixed-point
//              iteration can overshoot and cycle). At finite N both conditions may hold on
//              an interval of c (without the edge modes the structures force p(c) = 0 and
//              cannot represent the singularity that flags a slightly wrong c; with them the
//              interval closes and the bracket ends at noise-level violations); bisection then finds
//              both ends and c is the midpoint, the half-length its uncertainty.
//   max-force: Barber's principle: the true zone maximizes P(c). Golden-section search
//              on P(c), then conditions 1.2 and 1.3 checked at the maximizer. P(c) is flat
//              at its maximum, so c is located less sharply than by `iterate`.
//
// Contact force P (full 360 degrees, N): the die's force, OutlineModel::die_force on part
// `outer`: `force` is the domain integral -2 pi [int s . e(v) r dr dz - int_St t . v r ds]
// with v = ((r - R1)/(R2 - R1), 0) (energetically consistent; DESIGN.md section 4.3);
// `force_trace` is eq. 4.6, -2 pi R2 int (sigma_rr(R2, z) + p_out) dz over the outer side.
// (Up to issue 23 both counted an outer pressure on the free part in P too.)
//
// Every solve is the outline model (outline_model.h) of the problem's body (axisym::
// legacy_body: the half section, mirrored) with the zone [0, c] on the part `outer`.
#pragma once

#include "rfm/fields/interaction_integral.h"
#include "rfm/outline_model.h"

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace rfm
{
  struct ContactOptions
  {
    int max_iterations = 60;     ///< solves in `iterate` / `max-force`
    double tolerance = 5e-4;     ///< on c / a: bracket width at which a search stops
    int n_check_points = 2001;   ///< grid along the outer side for conditions 1.2, 1.3
    /// A tension (condition 1.2) counts when it exceeds this fraction of the peak pressure:
    /// discretization noise below it is not a violation.
    double violation_tolerance = 1e-4;
    /// A penetration (condition 1.3) counts when it exceeds this fraction of the
    /// indentation delta. Smaller than the tension's: a zone too short by dc penetrates by
    /// only O(dc^2) (the edge term's sqrt(z - c) against the die's gap, linear in z - c),
    /// while the discretization error of u_r vanishes at the edge, where u_r is prescribed.
    /// Measured with `iterate` at p = 8 (14): 1e-4 gives c 0.56 % (0.47 %) below the FEM's,
    /// 1e-5 0.14 % (0.17 %); 1e-6 is below the noise at p = 14 (no c free of violations).
    double penetration_tolerance = 1e-5;
    /// edge-intensity: stop when a secant step moves c by less than this times a.
    double root_tolerance = 1e-3;
    /// edge-intensity: the stationary point of P(c) next to the root of K is searched within
    /// h = this times a of the solves so far, to h / 100; 0 takes the root of K itself.
    double stationary_step = 1e-2;
  };

  /// One solve at a fixed c, with its check of conditions 1.2 and 1.3.
  struct ContactIterate
  {
    double half_width = 0.0;                          ///< c [m]
    double force = 0.0, force_trace = 0.0;            ///< P [N]
    double lagrange = 0.0, castigliano = 0.0, reissner = 0.0; ///< J per radian
    double peak_pressure = 0.0;   ///< max p inside the zone [Pa]
    double max_tension = 0.0;     ///< max(-p)+ inside the zone [Pa] (condition 1.2)
    double max_penetration = 0.0; ///< max(u_r - u_r*)+ outside the zone [m] (condition 1.3)
    /// K [Pa m^1/2] from the axisymmetric interaction integral (edge_intensity_interaction,
    /// on the half disc of radius interaction_radius(c)); NaN without the edge modes or at
    /// c = a.
    double edge_intensity = 0.0;
    /// K from the n = 1 coefficient of the stress space (sqrt(2 pi) times it): a
    /// pointwise quantity into which the unresolved edge terms leak (its root lies 0.4-0.8 %
    /// above the FEM's c at p = 8-16, against 0.04-0.08 % for the interaction integral).
    double edge_intensity_coefficient = 0.0;
    /// K from the plane-strain contour form (edge_intensity_reciprocal_work) at rho_1 = 0.05
    /// rho_0 (NaN where not applicable). Its value drifts about linearly with rho_1 (the hoop
    /// terms the plane-strain identity leaves out): measured at p = 8 it is within 4 % of K
    /// at c = 0.45 a (rho_1 -> 0.03 rho_0: 0.6 %) and 1.6 % at 0.6 a.
    double edge_intensity_reciprocal_work = 0.0;
    /// First zero of p where it turns tensile [m] (or c): on a die part other than the hollow
    /// cylinder's, the distance from the die's centre along the part toward the free end.
    double first_tension_z = 0.0;
    double penetration_end_z = 0.0; ///< end of the penetrating interval beyond c [m] (or c), as above
    double indentation = 0.0; ///< delta [m] of the solve (under force control: found from P)
    double extent = 0.0;      ///< a [m]: the zone's end runs over (0, a] (the hollow cylinder: L/2)
    bool tension = false, penetration = false; ///< violations above the tolerances
    /// "fixed", "iteration", "refinement", "search", "bracket", "secant" or "final"
    std::string phase;
    double assembly_s = 0.0, solve_s = 0.0;
    bool conditions_hold() const { return !tension && !penetration; }
  };

  struct ContactResult
  {
    bool success = false;
    std::string message;
    std::string method;
    std::vector<ContactIterate> history; ///< every solve, in order
    ContactIterate final;                ///< the accepted iterate
    /// iterate: the interval of c on which 1.2 and 1.3 hold at this N (c is its midpoint);
    /// edge-intensity: the last bracket of the root of K(c)
    std::optional<std::pair<double, double>> half_width_range;
    /// edge-intensity: the root of K(c) [m] (c itself is the stationary point of P next to it)
    std::optional<double> edge_intensity_root;
    std::unique_ptr<OutlineModel> model; ///< the model at the accepted c (zone [0, c] on `outer`)
  };

  /// Solves at c and checks the conditions (precondition: problem.die set, 0 < c <= a).
  /// Sets `model` to the solved model; on a numerical failure returns success = false.
  ContactResult solve_contact(const axisym::Problem &problem, const DiscretizationOptions &discretization,
                              const ContactOptions &options);

  /// The check of one fixed c (used by solve_contact and the verification drivers): the
  /// functionals, P, the three edge intensities, and conditions 1.2 and 1.3 on a grid of
  /// n_check_points along r = R2 with points graded toward c (check_die_conditions). The
  /// conditions are checked on the discrete field with its edge term recovered: the n = 1
  /// amplitude of both spaces replaced by the interaction integral's (the coefficients carry
  /// the unresolved edge field, and the traces' sign at the edge is that amplitude's). Measured at p = 8, nu =
  /// 0.3: `iterate` then finds c 0.14 % from the FEM's (0.80 % on the raw traces), and
  /// both conditions hold at the default method's c (both were violated on the raw traces).
  ContactIterate check_contact(const axisym::Problem &problem, const OutlineModel &model,
                               const ContactOptions &options);
  /// Conditions 1.2 and 1.3 for a zone with one free end on any straight part: the zone
  /// model.zones()[0] of its part's die in `body` (the problem's, not the model's split body),
  /// its centre on the axis or a symmetry edge, c its length. On n_check_points along the
  /// free side of the part from the centre, with c and points c (1 + 10^-k), k = 2..6, among
  /// them (and c (1 - 10^-k) when the grid is coarser than c / 1000), the pressure
  /// p = -sigma_nn must be >= 0 inside the zone (1.2: a tension above violation_tolerance
  /// p_peak counts) and the part must not enter the die beyond it:
  /// (delta - g0(s)) + u . n <= 0, n the outward normal (1.3: above penetration_tolerance
  /// delta). The traces carry the edge term recovered from k_edge (K [Pa m^1/2]; NaN: as
  /// solved): the n = 1 amplitude of both spaces replaced by K / sqrt(2 pi). Fills the
  /// condition fields of `it` (peak_pressure to penetration_end_z, indentation, extent);
  /// half_width, P, K and the functionals are the caller's. Precondition: model.ok(), one die
  /// zone with one free end.
  void check_die_conditions(const OutlineModel &model, const axisym::Body &body, double k_edge,
                            const ContactOptions &options, ContactIterate &it);
  /// The hollow cylinder's bilateral solve at c: the outline model of the problem's body with
  /// the zone [0, c] on the part `outer` (the legacy die's part).
  std::unique_ptr<OutlineModel> solve_cylinder_zone(const axisym::Problem &problem,
                                                    const DiscretizationOptions &discretization,
                                                    double c, const SolverOptions &solver = {});
  /// The zone's half-width c of such a solve (its first zone's end).
  double zone_half_width(const OutlineModel &model);

  /// One iterate as JSON (result files and drivers): c [m], c/a, P and P trace [N], the
  /// functionals [J/rad], the violations (absolute and relative to the peak pressure and
  /// to delta), the two conditions, the phase and the time [s].
  nlohmann::json to_json(const ContactIterate &it, const axisym::Problem &problem);

  /// A contact solve as JSON: the `contact` object of rfm_solve's result file (DESIGN.md 7;
  /// its keys are a public contract), from which the verification drivers take their run
  /// records. `method`, `message` and every iterate in order (`iterations`, as above); on
  /// success also c [m] (`half_width`), c/a, P and its trace [N], K [Pa m^1/2] (`edge_intensity`,
  /// null when not computed), the last bracket of c [m] (`half_width_range`, when the method
  /// has one), the root of K [m] (`edge_intensity_root`, edge-intensity), the accepted iterate
  /// (`conditions`), and for pressure_points > 0 the pressure at that many z in [0, c]
  /// (`pressure`: `z`, the trace `p` and, when c < a, the consistent reactions
  /// `p_consistent`). Precondition: result.model set when result.success and
  /// pressure_points > 0.
  nlohmann::json to_json(const ContactResult &result, const axisym::Problem &problem,
                         int pressure_points);

  /// Contact pressure p(z) = -sigma_rr(R2, z) for z in [0, c] at n points (the trace of
  /// the stress field, with the edge modes).
  std::vector<std::pair<double, double>> contact_pressure(const OutlineModel &model, double c, int n);

  /// Edge intensity from a reciprocal-work (Betti) integral with the n = -1 edge mode
  /// (u*, s*), independent of the n = 1 coefficient: on the half circle rho = rho_1 about the
  /// edge (R2, c),
  ///   a_1 C = int_0^pi (s e_rho . u~ * ... ) = J(rho_1) + int_0^rho_1 s*_rr(x) (u_r(x) - u_r*(c)) dx,
  /// J(rho) = int_0^pi (s e_rho . u* - s* e_rho . u~) rho dtheta, u~ = u - (u_r*(c), 0)
  /// (a rigid translation that removes the die's value at the edge), the face integral is the
  /// work of s* on the prescribed u_r along the contact face, and C is the same J for the
  /// n = 1 mode itself. Exact for plane-strain fields with a traction-free free face; in the
  /// axisymmetric body the hoop terms make it approximate, to O(rho_1 / R2).
  /// Returns K = sqrt(2 pi) a_1 [Pa m^1/2]. Precondition: model.ok(), 0 < c < a, the free
  /// part unloaded, 0 < rho_1 < min(c, a - c, R2 - R1).
  double edge_intensity_reciprocal_work(const OutlineModel &model, const axisym::Problem &problem, double c,
                                        double rho_1);

  /// Edge intensity from the axisymmetric interaction integral (a domain form of Betti's
  /// theorem with the n = -1 edge mode (u*, s*) as auxiliary field; DESIGN.md 4.4). With
  /// W = r (s_h u* - s* u~), u~ = u_h - u_h(edge), the axisymmetric equilibrium
  /// d_j(r s_ij) = s_tt delta_ir and Hooke's law give
  ///   div W = s_tt u*_r + s*_tt u_r - s*_rr u~_r - s*_rz u~_z
  /// (integrable at the edge), and for the smoothstep weight q = 1 - 3 t^2 + 2 t^3,
  /// t = rho / rho_1, on the half disc rho < rho_1 (q = 1 and dq/drho = 0 at the edge,
  /// q = 0 and dq/drho = 0 at rho_1)
  ///   R2 a_1 C = int_faces q W_r dz - int (q div W + W . grad q) dr dz,
  /// C the plane-strain contour integral of mode 1 against mode -1. The face terms are known
  /// data: the prescribed u_r on the contact face, the outer pressure on the free face.
  /// Unlike the n = 1 coefficient (a pointwise quantity), the domain integral weights the
  /// field error smoothly, and unlike the contour form it keeps the hoop terms.
  /// Returns K = sqrt(2 pi) a_1 [Pa m^1/2]. Precondition: model.ok(), 0 < c < a, no body
  /// loads, 0 < rho_1 < min(c, a - c, R2 - R1).
  double edge_intensity_interaction(const OutlineModel &model, const axisym::Problem &problem,
                                    double c, double rho_1);

  /// The same integral for any field (u and sigma; the strain is not used), e.g. the FEM's
  /// sampled at the rule's points (the verification drivers): `field` is
  /// called once at the points of interaction_quadrature(geometry, c, rho_1) and once at
  /// the edge point (R2, c).
  double edge_intensity_interaction(const FieldEvaluator &field, const axisym::Problem &problem,
                                    double c, double rho_1);
  /// The half-disc rule of edge_intensity_interaction (polar, rho = rho_1 s^2).
  Quadrature2D interaction_quadrature(const axisym::Geometry &geometry, double c, double rho_1);

  // The same integral at a contact edge of any straight part, for any field:
  // rfm/fields/interaction_integral.h.

  /// The radius of the interaction integral's half disc used by check_contact:
  /// 0.9 min(c, a - c, R2 - R1) (the largest that keeps the other sides out; the root of K
  /// moves by 2.6e-4 c between 0.5 and 0.9 of that bound at p = 8).
  double interaction_radius(const axisym::Geometry &geometry, double c);

  /// Contact pressure as consistent reactions (Babuska and Miller; DESIGN.md 4.4). With the
  /// test fields V_k = (U_2k(z/c) psi(r), 0), psi = (r - R1)/(R2 - R1) (U the Chebyshev
  /// polynomials of the second kind, continued by U_2k(1) beyond the zone), weak equilibrium
  /// gives the moments
  ///   m_k = int_{-c}^{c} p(z) U_2k(z/c) R2 dz = W_t(V_k) - int s_h . e(V_k) r dr dz
  /// (per radian, both halves; W_t the work of the prescribed tractions), whose error is of
  /// the order of the energy error times the approximation error of V_k, far below that of
  /// the trace. With p(z) = sqrt(1 - z^2/c^2) sum_k b_k U_2k(z/c) (the square-root fall of
  /// the true edge) the U_2k are orthogonal and b_k = 2 m_k / (pi R2 c). k = 0 gives the
  /// domain-integral force: P = 2 pi m_0. Returns (z, p) at n points of [0, c].
  /// Precondition: model.ok(), 0 < c < a, n_moments >= 1.
  std::vector<std::pair<double, double>> consistent_contact_pressure(const OutlineModel &model,
                                                                     const axisym::Problem &problem,
                                                                     double c, int n, int n_moments);
  /// Moments used by default: 3 (the pressure is sqrt(1 - z^2/c^2) times a polynomial of
  /// degree 4). Higher moments of the mixed stress carry more of its error than the shape
  /// needs: against the finest FEM, max |p - p_FEM| / p_FEM(0) is 1.8 % with 2-9 moments at
  /// p = 8, but 3.4 % (5 moments) and 11 % (9) at p = 16, 1.7 % with 3.
  inline constexpr int default_pressure_moments = 3;
} // namespace rfm
