// The outline of a meridian section (DESIGN.md section 7.1): one closed, simple,
// counter-clockwise loop of straight lines and circular arcs in the half-plane r >= 0 of the
// coordinates (r, z) [m], each edge naming the boundary part it belongs to.
//
// Conventions:
//  * Counter-clockwise = the body on the left of the direction of travel; the outward normal
//    is the right-hand normal n = (t_z, -t_r) of the unit tangent t.
//  * An arc runs from `start` to `end` around `center` the shorter way; its sweep is the signed
//    angle from start to end (+ = counter-clockwise), |sweep| < pi. It is parameterized by
//    angle: p(t) = center + R (cos(theta0 + t sweep), sin(theta0 + t sweep)), t in [0, 1].
//  * Tolerances are relative to size(), the diagonal of the bounding box (named below).
//  * Messages name the JSON entry: `<field>[0]` is the start point, edge i is `<field>[i + 1]`
//    (the entries `{"line_to": ...}` / `{"arc_to": ...}` follow `{"start": ...}`).
//
// Integrals are exact (to rounding): the signed area by the shoelace formula plus the circular
// segments, A = sum_edges (start x end) / 2 + sum_arcs R^2 (sweep - sin sweep) / 2; the moments
// int r^i z^j dr dz by Green's theorem, oint r^(i+1) z^j / (i+1) dz, Gauss-Legendre along each
// edge (exact for lines; for arcs the integrand is a trigonometric polynomial of degree
// i + j + 2 and the rule has 2 (i + j + 2) + 8 points, which reaches rounding for i + j <= 6).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace axisym
{
  /// A point of the meridian half-plane [m].
  struct Point
  {
    double r = 0, z = 0;
  };

  struct OutlineEdge
  {
    enum class Kind { line, arc };
    Kind kind = Kind::line;
    Point start, end;
    Point center;     ///< arcs only
    std::string part; ///< boundary part name

    /// Arcs: |start - center|; lines: 0.
    double radius() const;
    /// Line length |end - start|, arc length R |sweep|.
    double length() const;
    /// Arcs: signed angle from start to end about the center (+ = counter-clockwise),
    /// |sweep| < pi for a valid arc; lines: 0.
    double sweep() const;
    /// The point at t in [0, 1], uniform in length (arcs: in angle); t = 0 and t = 1 return
    /// start and end exactly.
    Point point_at(double t) const;
    /// Unit tangent in the direction of travel.
    Point tangent_at(double t) const;
    /// The right-hand normal (t_z, -t_r): outward for a counter-clockwise outline.
    Point outward_normal_at(double t) const;
    /// Distance from p to the edge as a curve (segment or arc) [m].
    double distance_to(Point p) const;
    /// A line with both ends at |r| <= tol (an edge on the axis of revolution).
    bool on_axis(double tol) const;
  };

  struct BoundingBox
  {
    double r_min = 0, r_max = 0, z_min = 0, z_max = 0;
  };

  class Outline
  {
  public:
    /// Relative tolerances (times size()). Two points closer than point_tolerance are the same
    /// point (closure, touching edges, axis edges); an edge must be longer than
    /// length_tolerance and r >= -length_tolerance everywhere; an arc's ends must be at the
    /// same distance from the center within radius_tolerance * R, and the center must be
    /// farther than radius_tolerance * R from the chord (else the shorter way is ambiguous).
    static constexpr double point_tolerance = 1e-9;
    static constexpr double length_tolerance = 1e-12;
    static constexpr double radius_tolerance = 1e-6;

    /// Builds the outline from the start point and the edges as read; each edge's `start` is
    /// ignored and set to the previous edge's end (the first to `start`). `field` is the JSON
    /// path used in messages. Throws InputError unless:
    ///  * there are at least 2 edges, each longer than length_tolerance * size();
    ///  * every point has r >= 0, including the interior of arcs;
    ///  * arcs: the ends are on one circle (radius_tolerance), the sweep is under 180 degrees
    ///    and not ambiguous;
    ///  * the last edge ends at the start point (point_tolerance);
    ///  * the loop is simple: edges meet only where consecutive edges share a vertex
    ///    (touching within point_tolerance counts; consecutive edges overlapping along a
    ///    stretch fail);
    ///  * the signed area is > 0 (counter-clockwise).
    /// Normalizations: the last end is set to `start` exactly, and an arc whose ends are not
    /// at equal distances from its center has the center moved (by at most about
    /// radius_tolerance * R) onto the perpendicular bisector of its chord, so that both ends
    /// lie on the circle to rounding.
    Outline(Point start, std::vector<OutlineEdge> edges,
            const std::string &field = "geometry.outline");

    const std::vector<OutlineEdge> &edges() const { return edges_; }
    /// Shoelace plus circular segments (closed form, see above) [m^2]; > 0.
    double signed_area() const { return area_; }
    /// Exact: the vertices and the points where arcs pass 0, 90, 180, 270 degrees.
    BoundingBox bounding_box() const { return box_; }
    /// Diagonal of the bounding box [m]: the scale of all tolerances.
    double size() const { return size_; }
    /// int r^i z^j dr dz over the section [m^(i+j+2)]; i, j >= 0. Rounding-exact for
    /// i + j <= 6 (see above).
    double moment(int i, int j) const;
    /// True if p is inside or within tol [m] of the boundary (ray crossing with half-open
    /// rules at vertices, arcs split where they are monotone in z).
    bool contains(Point p, double tol) const;
    /// min over edges of the distance from p to the edge [m]; optionally the index of the
    /// nearest edge (the first one on a tie).
    double distance_to_boundary(Point p, int *nearest_edge = nullptr) const;
    /// Part names in order of first appearance.
    std::vector<std::string> parts() const;
    /// Indices of the edges on the axis r = 0 (on_axis with point_tolerance * size()).
    std::vector<int> axis_edges() const;
    /// The edge that arrives at x and the one that leaves it (x within point_tolerance *
    /// size() of its end, of its start); nullptr where there is none. Both are set exactly
    /// when x is a vertex of the outline.
    std::pair<const OutlineEdge *, const OutlineEdge *> edges_at(Point x) const;

  private:
    std::vector<OutlineEdge> edges_;
    BoundingBox box_;
    double size_ = 0, area_ = 0;
  };
} // namespace axisym
