// The local fields at a vertex of the section (DESIGN.md 4.5; issue 24 item 2): the
// plane-strain eigenfunctions of an elastic wedge with a condition on each face.
//
// Why. Where the boundary turns inward or its condition changes (shoulders, grooves, clamped
// ends, the contact edge) the field has terms rho^lambda F(theta) with non-integer, possibly
// complex lambda; the global polynomials converge slowly there (the hub section of issue 24
// stalls near 5e-4 in the indicator). This file finds the exponents and the modes; the
// enrichment (columns, near-vertex rule, intensities) is built on it.
//
// The wedge. Polar coordinates (rho, theta) about the vertex, theta = 0 on the bisector, the
// body in |theta| <= alpha (interior angle 2 alpha in (0, 2 pi]). Williams (1952): the Airy
// function Phi = rho^(lambda + 1) f(theta),
//
//   f = a1 cos((lambda + 1) theta) + a2 sin((lambda + 1) theta)
//     + a3 cos((lambda - 1) theta) + a4 sin((lambda - 1) theta),
//
// gives sigma_thth = rho^(lambda - 1) lambda (lambda + 1) f, sigma_rhoth = -rho^(lambda - 1)
// lambda f' and sigma_rhorho = rho^(lambda - 1) ((lambda + 1) f + f''), and in plane strain
// (kappa = 3 - 4 nu)
//
//   2 mu u_rho = rho^lambda [-(lambda + 1)(a1 c_+ + a2 s_+) + (kappa - lambda)(a3 c_- + a4 s_-)],
//   2 mu u_th  = rho^lambda [ (lambda + 1)(a1 s_+ - a2 c_+) + (kappa + lambda)(a3 s_- - a4 c_-)],
//
// c_+- = cos((lambda +- 1) theta), s_+- = sin((lambda +- 1) theta). Each face gives two rows:
// free (or loaded: the homogeneous part) f = f' = 0; clamped u_rho = u_th = 0; symmetry or a
// die zone (normal displacement given, shear free) u_th = f' = 0. The exponents are the roots
// of det M(lambda) = 0 for the 4 x 4 matrix M of those rows, found by Newton's method in the
// complex plane from a grid of starts with 0 < Re lambda <= max_real_part, polished, and
// counted with the dimension of M's null space (the crack's lambda = 1/2 is double: a
// symmetric and an antisymmetric mode). Integer exponents are left out: their fields are
// polynomials, which the coordinate functions carry, and the Airy basis degenerates at
// lambda = 1 (sin(0 theta)), where det M vanishes whatever the faces.
#pragma once

#include "problem/problem.h"

#include <Eigen/Core>

#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace axisym
{
  enum class WedgeFace
  {
    free,     ///< traction free (or a given traction: its homogeneous part)
    clamped,  ///< u = 0
    symmetry  ///< u . n = 0 and no shear (a symmetry line, a die zone)
  };

  /// One mode rho^lambda F(theta): the exponent and the Airy coefficients (a1..a4, complex
  /// for a complex lambda; the real fields are its real and imaginary parts).
  struct WedgeMode
  {
    std::complex<double> lambda;
    Eigen::Vector4cd a;
  };

  /// Stresses (rho rho, theta theta, rho theta) and displacements (rho, theta) of a mode at
  /// (rho, theta), complex; displacements for the shear modulus mu = 1 (they scale as 1 / mu).
  struct WedgeFieldValues
  {
    std::complex<double> s_rr, s_tt, s_rt, u_r, u_t;
  };

  class Wedge
  {
  public:
    /// Interior angle 2 alpha [rad] in (0, 2 pi]; the face at theta = -alpha and the one at
    /// +alpha; Poisson's ratio in (-1, 0.5). Throws std::invalid_argument otherwise.
    Wedge(double angle, WedgeFace face_minus, WedgeFace face_plus, double poisson_ratio);

    /// The non-integer exponents with 0 < Re lambda <= max_real_part and Im lambda >= 0 (the
    /// conjugate of a complex one is a root too and gives the same real fields), ascending in
    /// Re lambda, each with its modes (one per dimension of M's null space).
    std::vector<WedgeMode> modes(double max_real_part) const;

    /// det M(lambda): the function whose roots are the exponents.
    std::complex<double> characteristic(std::complex<double> lambda) const;
    /// The modes at a given root lambda of det M, any sign of Re lambda (one per dimension of
    /// M's null space, the largest Airy coefficient 1); empty where M is not singular. The
    /// exponents come in pairs lambda, -lambda (det M is even in lambda): the mode at -lambda
    /// is the dual of the mode at lambda in the interaction integral of the vertex
    /// intensities (rfm/fields/vertex_intensity.h).
    std::vector<WedgeMode> modes_at(std::complex<double> lambda) const;
    /// The mode's fields at a point.
    WedgeFieldValues evaluate(const WedgeMode &mode, double rho, double theta) const;
    double half_angle() const { return alpha_; }
    WedgeFace face_minus() const { return minus_; }
    WedgeFace face_plus() const { return plus_; }

  private:
    /// modes() without the memo.
    std::vector<WedgeMode> find_modes(double max_real_part) const;
    Eigen::Matrix4cd matrix(std::complex<double> lambda) const;
    double alpha_, kappa_;
    WedgeFace minus_, plus_;
  };

  /// A vertex of a section's outline off the axis with the wedge it makes (the interior
  /// angle, the faces from the two parts' conditions) and its non-integer exponents with
  /// Re lambda < 1 (the stress is singular there).
  struct SingularVertex
  {
    Point at;
    double angle = 0; ///< interior angle [rad]
    std::string part_before, part_after;
    std::vector<WedgeMode> modes;
  };

  /// The face of a part's condition at a vertex (the homogeneous part of the condition):
  /// free for traction-free, pressure, traction and die parts (a die zone that reaches its
  /// part's corner is not known before the solve; the zone's own ends are contact edges,
  /// edge_modes.h), clamped for a prescribed displacement, symmetry for a symmetry line.
  WedgeFace wedge_face(const PartCondition &condition);

  /// Every vertex of the body's outline off the axis where the elastic field is singular
  /// (Re lambda < 1 for some exponent of its wedge), in the outline's order. Where a traction
  /// jumps at a vertex the particular field has logarithms this does not see (issue 24 item 4).
  std::vector<SingularVertex> singular_vertices(const Body &body, double poisson_ratio);

  /// Every vertex of the body's outline off the axis where the stress is bounded but not
  /// smooth: not singular, with a non-integer exponent of its wedge with Re lambda below
  /// rough_vertex_max_exponent, in the outline's order; each with those exponents' modes. The
  /// stress there has a term rho^(lambda - 1) whose gradient is unbounded, which global
  /// polynomials resolve only at an algebraic rate. Free faces meeting at an obtuse angle
  /// (from about 126 degrees to 180) are such vertices, e.g. issue 24's hub where the inner
  /// arc's pressure ends at the bore (133 degrees, lambda = 1.905 +- 0.388 i); a free face
  /// meeting a symmetry line at a right angle, or two free faces at one, is not (its exponents
  /// are integers, or 2.74 +- 1.12 i).
  std::vector<SingularVertex> rough_vertices(const Body &body, double poisson_ratio);
  inline constexpr double rough_vertex_max_exponent = 2.0;

  /// A notch root: a vertex off the axis where a concave arc (the body outside its circle)
  /// that carries a traction (free, pressure, traction) meets a symmetry line, with the arc's
  /// radius below notch_root_max_radius times the section's size (the diagonal of its box).
  /// The field is smooth there (its mirror image is a smooth notch), but it concentrates on
  /// the scale of the radius, below what global polynomials of moderate degree resolve
  /// (issue 24 item 3: local resolution; rfm.notch_roots).
  struct NotchRoot
  {
    Point at;
    double angle = 0;  ///< interior angle [rad]
    double radius = 0; ///< the arc's [m]
  };
  inline constexpr double notch_root_max_radius = 0.25;

  /// The notch roots of the body's outline, in the outline's order.
  std::vector<NotchRoot> notch_roots(const Body &body);

  /// The traction [Pa] that a traction part (traction free, pressure, traction) prescribes on
  /// edge e at its parameter t (a pressure p: -p n with n the outward normal there); nothing
  /// for any other condition.
  std::optional<Point> edge_traction(const Body &body, const OutlineEdge &e, double t);

  /// Every vertex of the outline off the axis between two traction parts (traction free,
  /// pressure, traction) whose tractions there no constant stress meets: with the faces'
  /// outward normals n_a, n_b and tractions t_a, t_b at the vertex, n_b . t_a != n_a . t_b
  /// (S n_a = t_a and S n_b = t_b need n_b . S n_a = n_a . S n_b), or, where the boundary runs
  /// straight on (n_a = n_b), t_a != t_b. The stress there has a term of degree 0 in rho
  /// whose value depends on the direction, and the displacement a rho log rho term
  /// (rfm/spaces/traction_jump.h): not singular in the sense above, but no smoother than
  /// lambda = 1. Relative tolerance 1e-9 of the larger traction.
  std::vector<Point> traction_jump_vertices(const Body &body);
  /// Every vertex of the outline off the axis where a symmetry line meets a traction part
  /// (traction free, pressure, traction) at a right angle and a temperature gradient crosses
  /// the line (n . grad T != 0, n the line's normal). The wedge's exponents there are
  /// integers (mirrored it is a half plane), and the temperature's mirror has a kink that
  /// resonates with lambda = 2: the field has a rho^2 log rho displacement
  /// (rfm/spaces/resonant_vertex.h). Left out: a gravity across the line (its mirror jumps,
  /// and resonates too, but weakly: on a hollow column standing on a frictionless plane the
  /// log stress columns took the indicator at p = 8, 12, 16 from 3.3e-7, 2.1e-8, 3.0e-9 to
  /// 2.4e-7, 1.3e-8, 1.5e-9 and the reaction on the plane, exact to 1e-14 with the
  /// polynomials alone, to 3.4e-5, 1.0e-5, 2.2e-6 of the weight: the weak equilibrium holds
  /// the polynomial resultant of each section z = const exactly, not one with the columns'
  /// log terms), and the axisymmetric terms at a symmetry line r = const, which no case has.
  struct ResonantSite
  {
    Point at;
    std::string symmetry_part, traction_part;
  };
  std::vector<ResonantSite> resonant_vertices(const Body &body, const BodyLoads &loads);
} // namespace axisym
