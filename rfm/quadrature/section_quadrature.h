// A quadrature rule over a whole outline section (lines and circular arcs): nodes inside the
// section, positive plain area weights dr dz, exact for polynomials on straight triangles and
// exponentially convergent on curved ones.
//
// Construction:
//  1. Polygon: the outline's vertices plus the points splitting every arc into m equal sub-arcs,
//     m = ceil(|sweep| / max_arc_angle) (at least 2 per arc if the polygon would otherwise have
//     fewer than 3 vertices, e.g. a lens of two arcs).
//  2. Triangulation by ear clipping; among all valid ears (strictly convex, no other vertex in
//     the closed triangle) the one with the largest minimum angle is cut first. O(N^3) for N
//     polygon vertices (N is tens to a few hundred here).
//  3. Curved triangles: with barycentric coordinates lambda_0 = 1 - x - y, lambda_1 = x,
//     lambda_2 = y on the reference triangle {x, y >= 0, x + y <= 1} and vertices V_k (counter-
//     clockwise), the blending map (Gordon-Hall transfinite blending for triangles in the form
//     used in hp finite elements, e.g. Szabo & Babuska, "Finite Element Analysis", 1991)
//        X(x, y) = sum_k lambda_k V_k
//                + sum_{curved edges V_i -> V_j} lambda_i lambda_j phi_e(s) / (s (1 - s)),
//        s = (1 + lambda_j - lambda_i) / 2,
//     where phi_e(s) = gamma_e(s) - [(1 - s) V_i + s V_j] is the deviation of the sub-arc
//     gamma_e (uniform in angle) from its chord. On edge i -> j, s is the chord parameter and X
//     is the arc; on the other edges the term vanishes; so every number of curved edges (one,
//     two at the tip of a lens, three for a triangle of three arcs) is supported. For a circle,
//     phi_e(s) / (s (1 - s)) is an entire function of s, evaluated by power series without
//     cancellation; the map is analytic on the closed triangle.
//  4. On each triangle (split into 4^n_refinements congruent sub-triangles in the reference
//     coordinates) the collapsed (Duffy) rule x = s (1 - t), y = t, dx dy = (1 - t) ds dt, with
//     n x n Gauss-Legendre points in (s, t) on [0, 1]^2, collapsed at V_2. Weights are
//     w_s w_t (1 - t) det(dX/d(x, y)) times the sub-triangle's area ratio.
//
// Exactness: on a straight triangle p(X(s (1 - t), t)) (1 - t) has degree d in s and d + 1 in
// t for a polynomial p of total degree d, so the rule is exact for total degree d <= 2n - 2 in
// (r, z) (and in general not for 2n - 1: the t-direction would need Gauss-Jacobi). On curved
// triangles the integrand is analytic, not polynomial, and the error decays exponentially in n;
// with sub-arcs of at most 15 degrees and n = 10 moments of degree <= 8 are exact to rounding.
//
// Validity: the blending correction is of the size of the sub-arc's sagitta R (1 - cos(m / 2))
// (sweep m) throughout the triangle, so a triangle thinner than about the sagitta folds over
// (Jacobian <= 0). This happens in thin walls (an annulus of thickness 1% of its radius with
// 15-degree sub-arcs) and in fan triangles from a long straight edge without vertices to many
// sub-arc points. It is detected at every node; the arcs of the failing triangles then get
// their sub-arcs halved and the section is retriangulated (at most max_arc_bisections times),
// which repairs thin walls. If the polygon of vertices and sub-arc points is not simple (an
// edge within a sub-arc's sagitta of an arc) ear clipping finds no ear, and all arcs are
// halved likewise. No points are added on straight edges: fans that stay too thin must be
// fixed in the outline (vertices on the long edges).
#pragma once

#include "problem/outline.h"
#include "rfm/quadrature/quadrature.h"

#include <array>
#include <vector>

namespace rfm
{
  struct SectionQuadratureOptions
  {
    int n_points = 10;           ///< Gauss points per direction in each (curved) triangle
    double max_arc_angle = 0.26; ///< arcs are split into sub-arcs of at most this sweep [rad]
                                 ///< (about 15 deg)
    int n_refinements = 0;       ///< each triangle split into 4 this many times (for large
                                 ///< sections / high degree)
    int max_arc_bisections = 4;  ///< on a non-positive Jacobian, the sub-arcs of the arcs
                                 ///< concerned are halved and the section retriangulated, at
                                 ///< most this many times (0: throw at once)

    static constexpr int max_n_points = 100;
    static constexpr int max_n_refinements = 8; ///< 4^8 = 65536 sub-triangles per triangle
    static constexpr int max_max_arc_bisections = 6; ///< ear clipping is O(N^3)

    /// Throws std::invalid_argument ("Violated constraint: ...") unless
    /// 1 <= n_points <= max_n_points, 0 < max_arc_angle <= pi,
    /// 0 <= n_refinements <= max_n_refinements and
    /// 0 <= max_arc_bisections <= max_max_arc_bisections.
    void validate() const;
  };

  /// The rule described above: (number of triangles) x 4^n_refinements x n_points^2 nodes, all
  /// strictly inside the section (tested, not proven: the Jacobian is checked at the nodes
  /// only), with positive plain area weights dr dz (the r of the axisymmetric measure is not
  /// included). Throws std::invalid_argument for invalid options, or if after
  /// max_arc_bisections halvings of the arcs concerned ear clipping still finds no ear or a
  /// curved triangle's Jacobian is still not positive at every node (the message names the
  /// triangle and its curved outline edges, 0-based indices into Outline::edges()).
  Quadrature2D section_gauss(const axisym::Outline &outline,
                             const SectionQuadratureOptions &options = {});

  /// The cells of a tensor rule on a rectangular section.
  struct RectangleCells
  {
    int n_uniform_r = 1, n_uniform_z = 1; ///< uniform cells before splitting
    int n_graded_layers = 8;              ///< geometric layers toward each break point
    double grading_ratio = 0.35;          ///< width ratio between successive layers
    /// Vertices inside a side toward whose side the cells are graded across it too, in
    /// n_normal_layers layers (traction jumps: the particular stress depends on the direction
    /// from the vertex there, and a cell that spans the section across the side resolves
    /// that only as its Gauss points allow). Points not inside a side are ignored.
    std::vector<axisym::Point> graded_across;
    int n_normal_layers = 3;
  };

  /// True if every edge of the outline is a line on its bounding box, i.e. the section is
  /// a rectangle with sides along r and z (its sides may be split into several edges).
  bool is_axis_aligned_rectangle(const axisym::Outline &outline);

  /// The tensor Gauss rule of such a rectangle: n_points x n_points points on every cell of
  /// section_cells (quadrature.h) in r and in z, split and graded (cells) at every vertex
  /// inside a side, where a boundary condition changes (a contact zone's end). For polynomials
  /// of degree <= p in each variable (the coordinate functions), n_points = p + 4 integrates
  /// their products times r and the structures' low-degree factors exactly on every cell with
  /// (p + 4)^2 points instead of the triangles' 2 (2 p + 4)^2. `extra_ends`: more cell ends
  /// in r and in z, not graded (the sides of local boxes, local_basis.h; those outside the
  /// section are ignored). `even_in_r` (the axis parity, coordinate functions polynomial in
  /// r^2): Gauss in r^2 on the cells in r (quadrature.h: gauss_in_square_on_cells), exact for
  /// their products with the same n_points. Precondition: is_axis_aligned_rectangle(outline),
  /// n_points >= 1, r >= 0.
  Quadrature2D rectangle_gauss(const axisym::Outline &outline, int n_points,
                               const RectangleCells &cells = {},
                               const std::array<std::vector<double>, 2> &extra_ends = {},
                               bool even_in_r = false);
} // namespace rfm
