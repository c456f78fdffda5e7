// The particular stress of a traction jump at a vertex (issue 24 item 4).
//
// Where the prescribed traction of two traction parts (free, pressure, traction) differs at
// their common vertex v so that no constant stress meets both (a pressure ending at a free
// face at any angle but 90 degrees; a pressure on part of a straight face), the stress near v
// has a term of degree 0 in rho: bounded, but with a value that depends on the direction from
// v. The structures' transfinite blend s0 = sum_e W_e s0_e meets both faces' conditions with
// another direction dependence, and the polynomial columns times omega vanish at v, so the
// difference stays in the error and the Reissner indicator stalls (issue 24's hub: 4-6e-4 at
// p = 8-20, while with the pressure continued over the vertex it falls to 8e-6).
//
// The term is the plane wedge's (Williams 1952; Timoshenko and Goodier, section 45): with
// theta measured from the leaving face (theta = 0) into the body to the arriving face
// (theta = beta, the interior angle), the Airy function rho^2 f(theta),
//   f = A + B cos 2 theta + C sin 2 theta + D theta,
//   sigma_rhorho = 2 f + f'',  sigma_thth = 2 f,  sigma_rhoth = -f',
// equilibrated and with the faces' tractions t_0 (theta = 0) and t_1 (theta = beta) at v
// when (A, B, C, D) solve a 4 x 4 system. The system is singular where tan 2 beta = 2 beta
// (beta = 257.5 degrees: the field then has a log rho term) and, at beta = 180 degrees, for
// two different shear tractions; there it has no solution and no field is made.
//
// Faces that are arcs. The straight wedge meets an arc's condition only at v. The field is
// therefore taken at the mapped angle theta' of wedge_frame.h and turned by its a, S(x) =
// Q(a) S_wedge(theta') Q(a)^T: that meets the arc's traction for a pressure (t turns with n)
// and for a free face; an arc carrying a fixed traction vector is left out. On lines the
// wedge's field exactly.
//
// The model (outline_model.h) adds chi(rho) (S - s0) to the particular stress, with chi the
// C2 cutoff of edge_modes.h (1 at v, 0 from rho_0 on), so that the structures stay
// boundary-exact (S and s0 meet the same conditions on both faces) and the stress near v is
// S plus terms that vanish at v. Between two lines, on a section star-shaped about v without
// a die, the model takes the whole section instead (OutlineModel::traction_jumps; session
// 79): chi becomes F = 1 - (1 - G)^4 per component, G the product of the other edges'
// omegas where the component enters their condition, 1 at v, so that F (S - s0) meets every
// edge's condition, F - 1 = O(rho^4) at v, and no rim is left. On the pressure band the
// indicator at p = 12 / 16 / 20 went from 1.06e-4 / 1.94e-5 / 5.6e-6 to 2.2e-6 / 2.5e-7 /
// 3.5e-8: the rim, below, was the limit. The quintic's C2 join at rho_0 leaves the polynomials a
// remainder they resolve algebraically there (the pressure band's sample on the cutoff's rim
// is 7e-4 of max |sigma| off at p = 20 against 2e-4 elsewhere); a C-infinity cutoff
// (exp(-1/x) blend) was steeper inside and worse everywhere (Phi_R 1.5e-5 against 3.5e-6).
// The largest room helps most: the band's indicator at p = 20 is 1.8e-5 with the whole room,
// 7.9e-5 with half of it and 7.9e-4 with a quarter. The hoop component of S is
// nu (S_rr + S_zz), as in plane strain; the model adds Hooke's hoop stress of the field's own
// displacement, E u_r / r (OutlineModel::jump_fields; the rho ln rho term's hoop strain, which
// P_tt could carry only algebraically). Its products are integrated on near_rule, a polar rule
// about v that follows curved faces (for each radius the angles between the faces).
//
// The hoop shadow. Off the axis, the body of revolution adds to the plane field the terms of
// wedge_shadow.h: the D term's hoop strain h = u_r / r_v (with its rho ln rho) puts lambda_L h
// into the in-plane stresses, and (S_rr - S_tt) / r_v, S_rz / r_v enter the equilibrium. The
// answer is a displacement u1 = rho^2 (V_0 + ln rho V_1 + ...) with stresses of degree 1 and
// logs, free on both faces (LogSeriesShadow; at 180 degrees 2 is an exponent of the half
// plane and the log's level carries the resonant mode). The polynomials carry it only
// algebraically: without it the pressure band's Castigliano functional stalled near -4e-6
// (relative) while the Lagrange one converged. stress() and displacement() include it, for
// the D term alone (the uniform part's displacement is linear and its shadow a polynomial
// away from resonance). On an arc it is taken at the mapped angle and turned like the rest,
// which keeps the faces' conditions exact; the arc's own first-order term (wedge_shadow.h's
// L) is not added. Measured at p = 12 / 16 / 20: the band's indicator 1.79e-4 / 4.31e-5 /
// 1.63e-5 without, 1.06e-4 / 1.94e-5 / 5.61e-6 with; the hub's 4.48e-6 / 7.65e-7 / 2.29e-7
// without, 1.30e-6 / 6.65e-8 / 2.02e-8 with.
#pragma once

#include "problem/outline.h"
#include "problem/problem.h"
#include "rfm/quadrature/quadrature.h"
#include "rfm/spaces/wedge_frame.h"
#include "rfm/spaces/wedge_shadow.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace rfm
{
  class TractionJump
  {
  public:
    /// The traction at the vertex of one face: t [Pa] there; `follows_normal`: t = -p n
    /// (a pressure) or 0, which an arc may carry.
    struct FaceLoad
    {
      std::array<double, 2> traction{{0.0, 0.0}};
      bool follows_normal = true;
    };

    /// The field at the vertex where `arriving` ends and `leaving` starts (a counter-clockwise
    /// outline, the body on the left), cut off at cutoff_radius > 0. std::nullopt, with the
    /// reason in *why, when there is no jump (a constant stress meets both faces' tractions),
    /// when the wedge has no field of degree 0 (see above), or when an arc carries a fixed
    /// traction vector. With `hoop_shadow` and v off the axis, the D term's hoop shadow (the
    /// header) is part of stress() and displacement().
    static std::optional<TractionJump> make(const axisym::OutlineEdge &arriving, const FaceLoad &on_arriving,
                                            const axisym::OutlineEdge &leaving, const FaceLoad &on_leaving,
                                            double cutoff_radius, double poisson_ratio,
                                            bool hoop_shadow = true, std::string *why = nullptr);

    const axisym::Point &vertex() const { return frame_.vertex(); }
    double cutoff_radius() const { return cutoff_radius_; }
    /// The interior angle beta [rad].
    double angle() const { return frame_.angle(); }
    /// Whether stress() and displacement() carry the hoop shadow (make's hoop_shadow, v off the
    /// axis, and the collocation's self-check passed), and the shadow itself.
    bool has_hoop_shadow() const { return has_shadow_; }
    const LogSeriesShadow &hoop_shadow() const { return shadow_; }

    /// S at points, n x 4 in StressComponent order (rr, zz, tt, rz) [Pa], without the cutoff.
    /// At the vertex itself (no direction) the value on the bisector.
    Eigen::MatrixXd stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                           const Eigen::Ref<const Eigen::VectorXd> &z) const;
    /// The displacement of the wedge's D term [m] for the shear modulus mu (plane strain),
    /// n x 2 (u_r, u_z), without the cutoff, mapped like the stress:
    ///   2 mu u_rho = (kappa - 1) D theta rho,   2 mu u_th = -(kappa + 1) D rho ln(rho / rho_0),
    /// kappa = 3 - 4 nu (the stresses 2 D theta, 2 D theta, -D). It rotates like ln rho, which
    /// polynomials resolve no better than the stress's jump. The A, B and C terms are a
    /// uniform stress, whose displacement is linear: the polynomials carry it, and cut off it
    /// would only leave a strain of the field's size in the cutoff's annulus (measured: the
    /// pressure band's indicator at p = 8 went from 1.6e-3 to 2.0e-2 with them).
    Eigen::MatrixXd displacement(const Eigen::Ref<const Eigen::VectorXd> &r,
                                 const Eigen::Ref<const Eigen::VectorXd> &z, double mu) const;
    /// chi(rho) at points.
    Eigen::VectorXd cutoff(const Eigen::Ref<const Eigen::VectorXd> &r,
                           const Eigen::Ref<const Eigen::VectorXd> &z) const;

    /// The body within rho_0 of the vertex (WedgeFrame::near_rule; OutlineModel chooses rho_0
    /// below the faces' lengths and the distance to every other edge).
    Quadrature2D near_rule(int n_radial, int n_angular, int n_layers = 8,
                           const std::vector<Circle> &rims = {},
                           int n_beyond_rims = 0) const;

  private:
    TractionJump() = default;
    /// The straight wedge's stress (rr, zz, rz) in the (r, z) frame at the angle theta.
    std::array<double, 3> wedge_stress(double theta) const;
    /// The hoop shadow of the D term (the header), for D / mu = 1.
    void make_shadow();
    WedgeFrame frame_;
    LogSeriesShadow shadow_;
    bool has_shadow_ = false;
    std::array<double, 4> coefficients_{{0, 0, 0, 0}}; ///< A, B, C, D
    double cutoff_radius_ = 0.0;
    double poisson_ratio_ = 0.0;
  };

  /// The traction of edge e's part at its point t in [0, 1] (problem/wedge_modes.h:
  /// edge_traction) as a face load; std::nullopt where the part prescribes none (a symmetry
  /// line, a prescribed displacement).
  std::optional<TractionJump::FaceLoad> face_load(const axisym::Body &body, const axisym::OutlineEdge &e,
                                                  double t);

  /// The outline's vertices off the axis where the prescribed traction jumps
  /// (axisym::traction_jump_vertices: no constant stress meets the two faces' loads) and
  /// TractionJump::make has the field: for each, the index i of the arriving edge (the vertex
  /// is edges[i + 1].start, cyclically). Independent of the discretization (OutlineModel
  /// places the field at these vertices where there is room). A shear traction ending on a
  /// straight face jumps but has no field here (a log term).
  std::vector<std::size_t> traction_jump_vertices(const axisym::Body &body, double poisson_ratio);
} // namespace rfm
