// R-function geometry and solution structures (paper eqs. 2.1, 2.2) for any meridian
// section given as an outline of lines and arcs (problem/outline.h, DESIGN.md 7.1), with a
// condition on every part (problem/problem.h). Every boundary condition holds identically,
// for any coefficients.
//
// 1. Edge omegas (normalized: |grad omega| = 1 on the edge, omega > 0 inside). The carrier
//    of an edge is its line, f = -n . (x - x_start), or its circle,
//    f = +-(R^2 - |x - c|^2) / (2 R) (+ when the body is inside the circle: sweep > 0). Where
//    the carrier meets the closed section only along the edge (a convex side, an annulus'
//    arcs) omega = f: smooth and polynomial. Otherwise it is trimmed to the edge,
//    omega = sqrt(f^2 + ((sqrt(t^2 + f^4) - t) / 2)^2), with t >= 0 exactly on the edge's part
//    of the carrier (a line: the strip ((L/2)^2 - s^2) / L; an arc under 180 degrees: the
//    half-plane of its chord, on the arc's side). f and t enter in units of the section's
//    size l (the diagonal of its box: omega = l w(f / l, t / l)), because f^4 and t^2 are not
//    of one dimension: with them in metres the same problem given in millimetres had another
//    stress space (issue 24's hub at p = 16 with its lengths times 0.1, 1, 10: indicator
//    7.9e-5, 8.7e-5, 1.04e-4). Likewise the shear factor below takes its omegas over l. Now a
//    problem scaled in length gives the same indicator and stresses to rounding
//    (outline_model_test.cc: AProblemScaledInLengthGivesTheSameSolution).
//
// 2. Edge sets. S (stress): traction-free, pressure and traction edges, sigma . n = t;
//    Y (symmetry and axis): straight edges along r or z, u . n = 0 and sigma_rz = 0;
//    D (displacement): u = u_bar.
//
// 3. Structures. The S edges are of two kinds. A lone straight edge along z (normal +-e_r; a
//    chain of one) prescribes sigma_rr and sigma_rz only, one along r (normal +-e_z) sigma_zz
//    and sigma_rz: the other normal stress is free there, as in the structures of the paper's
//    rectangle. So do the edges of a straight chain, a line along r or z split into parts
//    with different tractions (a pressure on part of a bore): the line is one edge for the
//    structures, its chain's omega that of the segment from the first start to the last end
//    (not the conjunction below). Every other S edge (arcs, inclined lines, the edges of a
//    smooth chain of several) prescribes the whole traction, and its tangential normal
//    stress is left free by boundary columns B_e (the set G). With omega_T = prod over the
//    smooth chains C of S edges of omega_C, omega_rr (omega_zz) the same product without the
//    lone edges along r (along z), omega_Y = prod_{e in Y} omega_e and the transfinite weights
//    W_e = prod_{f != e} omega_f / sum_g prod_{h != g} omega_h over S (W_e = 1 on e, 0 on the
//    other S edges):
//
//      sigma_rr = s0_rr + omega_rr P_rr + sum_{e in G} B_e(xi_e) W_e T_e,rr
//      sigma_zz = s0_zz + omega_zz P_zz + sum_{e in G} B_e(xi_e) W_e T_e,zz
//      sigma_rz = s0_rz + omega_T omega_Y P_rz + sum_{e in G} B_e(xi_e) W_e T_e,rz
//      sigma_tt = P_tt
//      u_r = u0_r + omega_ur P_r,   u_z = u0_z + omega_uz P_z
//
//    s0_rz = sum_{e in S} W_e s0_e,rz; s0_rr (s0_zz) is the same blend over the S edges that
//    prescribe sigma_rr (sigma_zz) only, with the weights of that set. Why two kinds: at a
//    corner between a pressure edge along z and a free end along r, the blend of all S edges
//    is not smooth (the weights are homogeneous of degree 0 there) and the boundary column of
//    the end cannot make it so: the Lame cylinder's Phi_R converged algebraically (1.2e-9 at
//    p = 14, sigma_rr at the corner 0.26 % off), against rounding at p = 12 with the
//    component-wise blend, whose space is then the rectangle's.
//
//    P_c are the tensor Legendre polynomials of the bounding box; B_e are Legendre
//    polynomials in the edge coordinate xi_e (the projection on the edge's chord: linear,
//    monotone along the edge, in [-1, 1] over the bounding box); T_e = tau tau with tau the unit tangent field of e
//    (constant on a line; (-(z - z_c), r - r_c) / R on an arc, radial frame), so that on e
//    sigma . n = s0 . n and the tangential normal stress B_e is free. s0 = sum_e W_e s0_e
//    with s0_e = -p I (pressure) or t n + n t - (t . n) n n (traction) in the (r, z) plane.
//    Where T_e or s0_e has a shear component on Y edges (an arc whose center is off those
//    symmetry lines), their rz components take the factor omega_Ye / (omega_Ye + omega_e),
//    omega_Ye the product of the omegas of those Y edges only.
//    Even ends. Where an arc with boundary columns ends on a symmetry line or the axis that
//    passes through its centre (the arc meets the line at a right angle, and its mirror image
//    continues it smoothly), the exact sigma_ss is even in the angle about that end. xi_e
//    there is an even function of that angle phi, so that the end is an interior point of
//    the mirrored arc for the B_e and not an end of their interval, where a polynomial's
//    value is the least determined by a norm: with one even end xi_e = 2 (phi / phi_max)^2 - 1
//    (phi_max the largest angle from the end over the section, so that xi_e stays in [-1, 1]
//    there); with both ends even (a hollow sphere's arcs from the equator to the axis)
//    xi_e = -cos(pi phi / |sweep|). Measured on the tapered hub of issue 24 under
//    T = 100 r [K] at p = 16, sigma_zz at that vertex, (0.8, 0), against the FEM (-229.80 MPa):
//    off by -5.98 MPa with the monotone coordinate, +0.14 MPa with the even one (the largest
//    error within 1 cm of the vertex 5.98 -> 0.42 MPa; the indicator 1.20e-4 -> 1.09e-4). The
//    centre must lie outside the section, and the section within 0.95 pi of the even end
//    about it (the angle's branch cut); otherwise the monotone coordinate stays. The cost: a
//    stress peak at the end (a sharp groove's root) was resolved by the Legendre polynomials'
//    clustering at the end of their interval, and is now resolved as at an interior point
//    (the sharp groove's K_t at p = 24 +2.0 % -> +3.7 % off the FEM's; report 5.3).
//    omega_ur vanishes on the D edges and the Y edges with normal e_r (the axis, vertical
//    symmetry lines); omega_uz on the D edges and the Y edges with normal e_z. u0 is the
//    transfinite blend of the prescribed values over the same edges (0 on Y edges).
//
// Axis parity (OutlineModel, issue 24 item 5). On a section on the axis the structures can be
// made even in r across it, so that with coordinate functions in (r^2, z)
// (section_basis.h: even_in_r) sigma_rr, sigma_zz, sigma_tt and u_z are even and u_r and
// sigma_rz odd, as the smooth fields of a body of revolution are. The omega of the axis, r,
// is odd and stays; every other carrier and trimming function becomes even in r:
//   * a line along z at r = a > 0: f = +-(a^2 - r^2) / (2 a) (the cylinder r = a; unit
//     gradient on the edge, positive on the body's side for r >= 0);
//   * a trimmed line along r from r1 to r2: t = (r2^2 - r^2) / (2 r2) if r1 = 0, else the R0
//     conjunction of (r^2 - r1^2) / (2 r1) and (r2^2 - r^2) / (2 r2) (the two coaxial
//     cylinders, each normalized at its radius);
//   * the edge coordinate of a line along r: 2 r^2 / r_max^2 - 1 (monotone on r >= 0).
// Lines along r (z = c) and trimming in z are even already. axis_parity_obstacle() says what
// rules it out: arcs and inclined lines (cones and tori: not done), a die, a traction with
// a shear component (a constant sigma_rz blended up to the axis is not odd), a prescribed u_r
// other than 0. With the parity every S edge is a line along r or z, and a chain of several
// is a straight chain (section 3), so there are no boundary columns: the even edge coordinate
// serves EdgeOmega::edge_coordinate alone.
//
// A smooth chain is a run of S edges that follow one another with a continuous tangent
// (a circle split into two arcs, an arc running into a tangent line); a lone S edge is a
// chain of one. omega_C is the R0 conjunction of its edges' omegas, x + y - sqrt(x^2 + y^2)
// (but for a straight chain: its line's omega, section 3):
// zero on each edge with unit normal derivative, also at the join, where the stress does not
// vanish. The product of the edges' omegas vanishes to second order at the join and leaves
// the polynomial part unable to carry the field there (measured on the heated ring, two
// arcs of one circle: RFM against FEM at the FEM's Gauss-Lobatto points 1.8e-3 -> 3.0e-4 of
// max |sigma|, indicator at p = 12 8.2e-8 -> 1.9e-8). At a corner between S edges (convex,
// where the stresses vanish) the product stays.
//
// The B_e columns make the stress space complete on every traction edge of G (sigma_ss is
// free there), and they are independent of the polynomial columns: on e the polynomial columns
// vanish and the other W's are 0, so a combination that is zero forces B_e = 0 on [-1, 1].
#pragma once

#include "problem/problem.h"
#include "rfm/geometry/r_functions.h"
#include "rfm/material.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace rfm
{
  /// The omega of one outline edge and its carrier.
  class EdgeOmega
  {
  public:
    /// `one_sided` (a die part's sub-edges): a line trimmed at one end only, where its
    /// carrier goes on in the section, is a ray beyond the other end (t linear), smooth at a
    /// corner there instead of non-smooth.
    /// `even_in_r`: the even forms of the header's axis parity (lines along r or z only).
    EdgeOmega(const axisym::Outline &outline, int edge, bool one_sided = false,
              bool even_in_r = false);
    /// The same for a segment of the outline that is not one of its edges (the line on
    /// which a straight chain of edges lies, from its first start to its last end).
    EdgeOmega(const axisym::Outline &outline, const axisym::OutlineEdge &edge, bool one_sided,
              bool even_in_r);

    RValue operator()(double r, double z) const;
    /// The carrier function f (line or circle), normalized, positive on the body's side.
    RValue carrier(double r, double z) const;
    bool trimmed() const { return trimmed_; }
    const axisym::OutlineEdge &edge() const { return edge_; }
    /// The edge coordinate xi and its gradient, monotone along the edge and bounded in the
    /// section (so that the Legendre polynomials of the boundary columns do not grow like
    /// xi^p away from their edge):
    ///  * an arc whose center lies outside the section, with the section inside a sector of
    ///    under 0.95 pi either side of the arc's mid direction: the angle about the center,
    ///    xi = phi / (|sweep| / 2) relative to the mid direction (the arc is [-1, 1] exactly);
    ///  * otherwise the projection on the edge's chord, mapped so that the section's
    ///    bounding box projects onto [-1, 1] (the edge onto a part of it).
    RValue edge_coordinate(double r, double z) const;
    bool angular_coordinate() const { return angular_; }
    /// Unit tangent field: constant on a line; on an arc the rotated radius, which equals
    /// the edge's tangent (direction of travel) on the arc.
    std::array<double, 2> tangent(double r, double z) const;

  private:
    axisym::OutlineEdge edge_;
    bool trimmed_ = false;
    int trim_side_ = 0; ///< one_sided lines: +1 trimmed at the end only, -1 at the start only
    /// A die part's sub-edge trimmed at both ends (a zone inside its part): t is the R0
    /// conjunction of the distances to the two ends (linear growth away from the segment)
    /// instead of (L^2 / 4 - s^2) / L (quadratic growth, ~s^2 / L: for a zone 1/40 of its part
    /// omega reaches 40 section sizes at the part's end and the coordinate functions carry a
    /// 1 / s^2 factor).
    bool conjunction_ends_ = false;
    double sign_ = 1.0; ///< arcs: +1 when the body is inside the circle
    bool even_ = false;  ///< even in r (axis parity)
    double r_box_max_ = 1.0;
    double trim_length_ = 1.0; ///< l of the header: the section's size
    double s_min_ = 0.0, s_max_ = 1.0; ///< the box's extent along the chord from the start
    bool angular_ = false;
  };

  /// The structures' values at points, one row per point.
  struct OutlineStressValues
  {
    Eigen::MatrixXd omega; ///< n x 4: multipliers of the polynomial columns per component
    Eigen::MatrixXd s0;    ///< n x 4: particular stress
    /// Boundary columns: for component c, n x n_boundary_columns.
    std::array<Eigen::MatrixXd, 4> boundary;
  };
  struct OutlineDisplacementValues
  {
    Eigen::MatrixXd omega, omega_r, omega_z, u0, u0_r, u0_z; ///< n x 2 each: (u_r, u_z)
  };

  /// A die's contact zone for a bilateral solve (contact.method "fixed"; DESIGN.md 4, 7.1):
  /// the interval [s_lo, s_hi] along the die's part, measured from its centre
  /// (axisym::DieFrame), and the indentation delta [m]. In the zone the outward normal
  /// displacement is u.n = g0(|s|) - delta and the shear traction vanishes; the rest of the
  /// part is traction free.
  struct DieZone
  {
    std::string part;
    double s_lo = 0, s_hi = 0;
    double indentation = 0;
    /// Where the prescribed value's continuation off the zone fades [m] (0 < fade_start <
    /// fade_end; both 0: no fading). The structures need u.n = g0(|s|) - delta on the zone
    /// only; continued unchanged it is g0(|s|) - delta along the whole part and across the
    /// body, which for a die much smaller than the section is many times the field itself (a
    /// paraboloid's g0 at a part's end 40 zone widths away is ~10^3 delta), and the coordinate
    /// functions must cancel it to that many more digits. With fading the continuation is
    /// (g0(|s|) - delta) psi(|s|) psi(n), n the distance into the body from the part and psi
    /// the C2 quintic step from 1 at fade_start to 0 at fade_end: zero outside a box about the
    /// die's centre. OutlineModel fades from the zone's end (along the part) and from the part
    /// (into the body) to the side of one of its local boxes (local_basis.h): cell ends of its
    /// rule, where the local columns may kink.
    double fade_start = 0, fade_end = 0;
    /// The fade into the body, in n >= 0 (both 0: as along the part).
    double fade_normal_start = 0, fade_normal_end = 0;
  };

  class OutlineStructures
  {
  public:
    /// `degree`: the degree of the B_e Legendre polynomials. `zones`: one per die part of the
    /// body (a die part without a zone is refused). Each die part's edges are split at the
    /// zone's ends: the zone's sub-edges are Y edges with the prescribed normal displacement
    /// (u_r or u_z, a function of s), the others traction-free S edges; body() is the split
    /// body (the zone keeps the part's name, the free sub-edges are part "<part>#free").
    /// Throws InputError for conditions the structures do not support (a symmetry edge or a
    /// die part not along r or z, a die without a zone).
    /// `axis_parity`: the even forms of the header (precondition: axis_parity_obstacle(body)
    /// is empty, so no die; std::invalid_argument otherwise).
    OutlineStructures(const axisym::Body &body, int degree, const std::vector<DieZone> &zones = {},
                      bool axis_parity = false);

    /// Why the structures of `body` cannot be even in r (the header's axis parity): empty
    /// when they can, which needs an edge on the axis.
    static std::string axis_parity_obstacle(const axisym::Body &body);
    bool axis_parity() const { return axis_parity_; }

    OutlineStressValues stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                               const Eigen::Ref<const Eigen::VectorXd> &z) const;
    OutlineDisplacementValues displacement(const Eigen::Ref<const Eigen::VectorXd> &r,
                                           const Eigen::Ref<const Eigen::VectorXd> &z) const;

    Eigen::Index n_boundary_columns() const
    {
      return static_cast<Eigen::Index>(n_general_) * (degree_ + 1);
    }
    const axisym::Body &body() const { return body_; }
    const std::vector<EdgeOmega> &omegas() const { return omegas_; }
    /// The coordinate xi_e of edge e's boundary columns B_e at a point: its
    /// EdgeOmega::edge_coordinate, or on an arc with even ends the header's even form.
    double boundary_coordinate(int e, double r, double z) const;
    /// The traction t = sigma . n prescribed at a point of edge e (0 for a non-S edge).
    std::array<double, 2> prescribed_traction(int edge, double r, double z) const;
    /// Edge e of body() in a die's zone: the prescribed outward normal displacement
    /// u.n = g0(|s|) - delta at a point of it (s from the point's projection on the part).
    /// Precondition: in_die_zone(e).
    double die_normal_displacement(int edge, double r, double z) const;
    bool in_die_zone(int edge) const { return zone_of_edge_.at(edge) >= 0; }
    /// Sets the zones' indentations delta [m], in the order the zones were given: u0 is
    /// affine in them and nothing else depends on them. Throws std::invalid_argument when the
    /// count differs.
    void set_indentations(const std::vector<double> &delta);
    /// How far the polynomial degree of displacement component m (0: u_r, 1: u_z) is
    /// lowered in r and in z. Its omega is the product over the edges where u_m is
    /// constrained; an edge along z (r = const) has degree 1 in r, one along r degree 1 in
    /// z, an inclined line 1 in both, an arc 2 in both. Where that product has degree k > 1
    /// in a direction (two ends with u_z = 0: z (h - z)), e(u) would reach degree p + k - 1
    /// there while the normal stresses need not carry any omega in that direction: a
    /// strain the stresses cannot see (u_z = int P_{p+1}(z) dz made R12 lose rank on a slab
    /// with symmetry on both ends). The degree is lowered by k - 1.
    std::array<int, 2> displacement_degree_reduction(int m) const;

  private:
    /// How an S edge prescribes the stress: a lone straight edge along z (normal +-e_r)
    /// prescribes sigma_rr and sigma_rz only, one along r (normal +-e_z) sigma_zz and sigma_rz,
    /// and so do the edges of a straight chain; every other edge (arcs, inclined lines, edges
    /// of any other smooth chain of several) the whole traction, its tangential normal stress
    /// left to its boundary columns.
    enum class StressEdge
    {
      general,
      normal_r,
      normal_z
    };
    // The transfinite blend of the particular normal stress `component` (0: rr, 1: zz) over the
    // S edges not of kind `skip`, with w the edges' omegas at the point; `weight` receives the
    // weights.
    double blend_normal(const std::vector<double> &w, std::vector<double> &weight,
                        StressEdge skip, double r, double z, int component) const;
    // s0_e and T_e at one point, in (rr, zz, rz) order.
    std::array<double, 3> particular(int edge, double r, double z) const;
    std::array<double, 3> tangent_tensor(int edge, double r, double z) const;
    // sum_e v_e W_e over `edges` with values v_e, and its gradient.
    /// A prescribed displacement component on a constrained edge: a constant, or a die
    /// zone's normal displacement (times the normal's component).
    struct Prescribed
    {
      double constant = 0.0;
      int zone = -1; ///< index into zones_
    };
    RValue prescribed(const Prescribed &v, double r, double z) const;
    RValue blend(const std::vector<int> &edges, const std::vector<Prescribed> &values, double r,
                 double z) const;
    // The factor of the rz components of edge e at a point: omega_Ye / (omega_Ye + omega_e),
    // omega_Ye the product over the Y edges where T_e or s0_e has shear (1 if none), every
    // omega over the section's size (a product of two is not of omega_e's dimension).
    double shear_factor(int edge, double r, double z) const;
    /// The angle about an arc's centre from its even end (the start when both are), positive
    /// along the arc [rad].
    double angle_from_even_end(int e, double r, double z) const;

    axisym::Body body_;
    int degree_;
    bool axis_parity_ = false;
    std::vector<EdgeOmega> omegas_;
    std::vector<int> stress_edges_, symmetry_edges_, u_r_edges_, u_z_edges_;
    /// For each S edge (index into stress_edges_), its smooth chain: S edges that follow one
    /// another with a continuous tangent form one chain, whose factor in omega_T is the R0
    /// conjunction of their omegas (normalized on every edge, nonzero gradient at the join),
    /// not their product (which vanishes to second order at the join, where the stress does
    /// not); a straight chain's factor is its line's omega (chain_line_).
    std::vector<int> stress_chain_;
    int n_stress_chains_ = 0;
    std::vector<StressEdge> stress_kind_; ///< per S edge (index into stress_edges_)
    /// Per chain: the kind of its edge if it is a lone edge along r or z, else general (a
    /// lone edge's chain omega does not enter the omega of the component it leaves free).
    std::vector<StressEdge> chain_kind_;
    /// Per chain: the index into line_chain_omegas_ of a straight chain's omega, or -1.
    std::vector<int> chain_line_;
    std::vector<EdgeOmega> line_chain_omegas_;
    std::vector<int> boundary_slot_;      ///< per S edge: its block of boundary columns, or -1
    /// Per outline edge: the even ends of an arc with boundary columns (bit 0 its start, bit 1
    /// its end), and the largest angle from the even end over the section (with one even end
    /// the coordinate's scale).
    struct EvenArc
    {
      int ends = 0;
      double angle_max = 0.0;
    };
    std::vector<EvenArc> even_arcs_;
    int n_general_ = 0;                   ///< S edges with boundary columns
    std::vector<Prescribed> u_r_values_, u_z_values_;
    /// The zones: the die's frame and profile, delta, and the normal's component (0: r, 1: z)
    /// and sign.
    struct Zone
    {
      axisym::DieFrame frame;
      axisym::DieProfile profile;
      double indentation = 0;
      double fade_start = 0, fade_end = 0, fade_normal_start = 0, fade_normal_end = 0;
      int component = 0;
      double sign = 1;
    };
    std::vector<Zone> zones_;
    std::vector<int> zone_of_edge_; ///< per edge of body_: its zone, or -1
    std::vector<std::vector<int>> shear_y_edges_; ///< per edge (S edges only)
  };
} // namespace rfm
