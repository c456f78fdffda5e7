// The polar frame of a vertex of the outline with faces that may be arcs: the geometry that
// the traction jump's particular field (traction_jump.h) and the resonant vertex's columns
// (resonant_vertex.h) share.
//
// With the outline counter-clockwise (the body on its left), theta is the polar angle about
// the vertex v from the direction of the face that leaves v (theta = 0) into the body to the
// face that arrives (theta = beta, the interior angle). A field made for the straight wedge
// meets a condition on an arc only at v; it is therefore taken at a mapped angle and turned:
// with phi_f(x) the angle about the arc's centre from v to x (0 for a line), a point of face f
// is seen from v at the polar angle of the chord, theta_f + phi_f / 2, and the face's normal
// there is turned by phi_f, so
//   w = (theta - phi_0 / 2) / (beta + phi_1 / 2 - phi_0 / 2)          (0 on face 0, 1 on face 1)
//   theta' = theta - (1 - w) phi_0 / 2 - w phi_1 / 2,   a = (1 - w) phi_0 + w phi_1,
//   S(x) = Q(a) S_wedge(theta') Q(a)^T
// puts every point of a face at the straight wedge's face angle, and Q(a) turns the wedge's
// face normal into the arc's: S n = Q(a) (S_wedge n_f). A traction that turns with the normal
// (a pressure, none) is met on the arc exactly. On lines a = 0 and theta' = theta.
#pragma once

#include "problem/outline.h"
#include "rfm/quadrature/quadrature.h"

#include <array>
#include <vector>

namespace rfm
{
  /// A circle of the section: another rule's disc, across whose rim the integrands have a
  /// kink (a cutoff's third derivative, the partition of unity's shares).
  struct Circle
  {
    axisym::Point centre;
    double radius;
  };

  /// The components (xx, yy, xy) along the fixed axes of a symmetric plane tensor whose
  /// components along the axes turned by phi from them are (a11, a22, a12), with c = cos phi
  /// and s = sin phi: Q S Q^T, Q the rotation by phi. Polar components (rho rho, theta theta,
  /// rho theta) at the polar angle phi give Cartesian ones; the turn Q(a) of the mapped angle
  /// below is the same operation. A strain with engineering shear g takes a12 = g / 2 and
  /// gives twice the third component. T: double or std::complex<double>.
  template <typename T>
  std::array<T, 3> turned_tensor(const T &a11, const T &a22, const T &a12, const double c, const double s)
  {
    return {a11 * c * c + a22 * s * s - 2.0 * a12 * c * s, a11 * s * s + a22 * c * c + 2.0 * a12 * c * s,
            (a11 - a22) * c * s + a12 * (c * c - s * s)};
  }

  class WedgeFrame
  {
  public:
    WedgeFrame() = default;
    /// The vertex where `arriving` ends and `leaving` starts.
    WedgeFrame(const axisym::OutlineEdge &arriving, const axisym::OutlineEdge &leaving);

    const axisym::Point &vertex() const { return at_; }
    /// The direction of the leaving face at v in the (r, z) plane [rad] (theta = 0).
    double leaving_direction() const { return gamma_; }
    /// The interior angle beta [rad], in (0, 2 pi].
    double angle() const { return beta_; }

    /// Whether face f (0 leaving, 1 arriving) is an arc, and its centre and radius [m].
    bool face_is_arc(const int f) const { return faces_[f].sweep_sign != 0; }
    const axisym::Point &face_center(const int f) const { return faces_[f].center; }
    double face_radius(const int f) const { return faces_[f].radius; }
    bool curved() const { return face_is_arc(0) || face_is_arc(1); }

    /// The polar angle of x about v from the leaving face's direction, in
    /// [beta / 2 - pi, beta / 2 + pi).
    double polar_angle(double r, double z) const;
    /// phi_f(x): the angle about face f's centre (0 leaving, 1 arriving) from v to x; 0 for a
    /// line.
    double arc_angle(int face, double r, double z) const;
    /// The mapped angle theta' and the rotation a at x; (beta / 2, 0) within rho_min of v.
    std::array<double, 2> mapped_angle(double r, double z, double rho_min) const;

    /// The body within rho_0 of v, polar: radially in geometric layers toward v (ratio 0.2,
    /// n_layers of them, the innermost with rho = rho_in s^2), n_radial points each; at each
    /// radius the angles between the two faces (the chord angle of an arc), in panels of at
    /// most pi / 2 broken where a face's line continues into the body, n_angular points each.
    /// Plain area weights dr dz. Precondition: rho_0 below the faces' lengths and the distance
    /// to every other edge.
    /// `rims`: other discs that may overlap this one (their centres outside it). Each ring is
    /// broken in angle where it crosses a rim, and the radial layers where the rings start
    /// and stop crossing it (at |c - v| -+ R), so that the other disc's cutoff and share,
    /// whose third derivatives jump on its rim, are integrated piecewise smoothly; from the
    /// first ring that crosses a rim outward, n_beyond_rims points a direction where that
    /// is more.
    /// `n_outer`: the outermost layer, [0.2 rho_0, rho_0], takes at least that many points a
    /// direction, radially and in angle (VertexEnrichment::near_rule says why).
    Quadrature2D near_rule(double rho_0, int n_radial, int n_angular, int n_layers,
                           const std::vector<Circle> &rims = {}, int n_beyond_rims = 0, int n_outer = 0) const;

  private:
    axisym::Point at_;
    double gamma_ = 0.0, beta_ = 0.0;
    /// Faces: 0 leaving, 1 arriving; an arc's centre, radius, sweep sign (0 for a line).
    struct Face
    {
      axisym::Point center;
      double radius = 0.0;
      int sweep_sign = 0;
    };
    std::array<Face, 2> faces_;
  };
} // namespace rfm
