// The log columns of a resonant vertex (issue 24): a right angle between a symmetry line and
// a traction face where the loads are not symmetric about the line.
//
// Why. At a 90-degree vertex between a symmetry line (u . n = 0, no shear) and a traction face
// (free, pressure) the wedge's exponents are integers (mirrored about the line it is a half
// plane), so wedge_modes.h finds none and the field is smooth when the loads mirror smoothly.
// A temperature that varies across the line (T_z at a symmetry line z = const) does not: the
// mirrored eigenstrain has a kink, and the field a term rho^2 log rho in the displacement,
// rho log rho in the stress (a gravity across the line too, which the model leaves out:
// axisym::resonant_vertices says why). On
// issue 24's heated hub (T = 100 r + 100 z K, symmetry on z = 0 and z = 1.6) sigma_zz at the
// vertex (0.8, 0) read -391.0, -492.2, -484.5 MPa at p = 8, 12, 16 against the graded FEM's
// -472.65 (polynomials resolve rho log rho no better than a traction jump's stress jump); with
// the stress columns below -476.9 at p = 16 and -472.69 at p = 20.
//
// The field. In the frame (x, y) with x along the symmetry line from the vertex v and y along
// the traction face (the body in x > 0, y > 0; psi = atan2(y, x)), the half plane x > 0 with
// the normal edge load sigma_xx(0, y) = (pi / 2) |y| and no shear has the Airy function
// (pi / 2) c (4 x^3 log rho - psi (6 x^2 y + 2 y^3) - 2 x^3 - 2 x y^2), c = -1 / (6 pi):
//
//   sigma_xx = x + y psi,   sigma_yy = -2 x log rho - 2 x / 3 + y psi,   sigma_xy = -x psi,
//   12 mu u_x = (3 - 4 nu) x^2 + 6 (1 - 2 nu) x y psi - 4 (1 - nu) y^2 + 6 (nu x^2 + (1 - nu) y^2) log rho,
//   12 mu u_y = (6 nu - 9) x^2 psi + (5 - 8 nu) x y + (3 - 6 nu) y^2 psi - 12 (1 - nu) x y log rho
//
// (plane strain; even in y, so u_y = 0 and sigma_xy = 0 on the line y = 0). Its stress less
// the uniform-gradient field sigma_xx = (pi / 2) y is traction free on x = 0, and that
// difference is the stress column; the displacement column is u. They are independent
// columns of the mixed principle's two spaces (the stress space's columns need the traction
// conditions only, the displacement's the symmetry line's), so the solve finds the
// amplitude, and the remainder of the exact field is smooth: the mirrored kink's free-space
// field is polynomial in the quarter plane, and its traction on the face is what the
// half plane's load cancels. (The half plane with the eigenstrain k |y| I: free-space
// sigma_xx = -E' k |y|, cancelled on the face by this load; E' = E / (1 - nu^2).)
// Coordinates are scaled by rho_0 (log rho_0 only adds the polynomial field sigma_yy ~ x).
//
// Columns: g (stress column, with sigma_tt = nu (sigma_rr + sigma_zz) + E u_r / r_v as the
// vertex modes' hoop term) and g u, g = chi(rho) m(r, z) with chi the C2 cutoff of
// edge_modes.h (1 at v, 0 from rho_0 on) and m the monomials xi^i eta^j (i + j <= d) of the
// offsets scaled by rho_0, which carry the next terms of the expansion (rho^3 log rho). A
// scalar factor keeps both faces' conditions. A traction face that is an arc: the stress is
// taken at wedge_frame.h's mapped angle and turned, which keeps it traction free on the arc;
// the displacement needs no map (its condition is on the line). The displacement columns may
// stop at a lower degree than the stress columns (the model takes none by default,
// rfm.resonant_displacement_degree; problem/settings.h says why).
#pragma once

#include "problem/outline.h"
#include "rfm/material.h"
#include "rfm/quadrature/quadrature.h"
#include "rfm/spaces/edge_modes.h"
#include "rfm/spaces/wedge_frame.h"

#include <Eigen/Core>

#include <array>

namespace rfm
{
  class ResonantVertex
  {
  public:
    /// The vertex where `arriving` ends and `leaving` starts (a counter-clockwise outline),
    /// one of them the symmetry line (`symmetry_leaves`: the leaving one), the other the
    /// traction face, at a right angle; off the axis. Cutoff radius rho_0 > 0 (below both
    /// faces' lengths and the distance to every other edge), multiplier degree d >= 0 of the
    /// stress columns, and of the displacement columns in [-1, d] (-1: none; the columns
    /// beyond it have a zero displacement part). Throws std::invalid_argument otherwise.
    ResonantVertex(const axisym::OutlineEdge &arriving, const axisym::OutlineEdge &leaving,
                   bool symmetry_leaves, double cutoff_radius, const Material &material,
                   int multiplier_degree, int displacement_degree);

    const axisym::Point &vertex() const { return frame_.vertex(); }
    double cutoff_radius() const { return cutoff_radius_; }
    Eigen::Index n_columns() const { return (degree_ + 1) * (degree_ + 2) / 2; }
    /// The columns with a displacement part (the first ones).
    Eigen::Index n_displacement_columns() const
    {
      return (displacement_degree_ + 1) * (displacement_degree_ + 2) / 2;
    }

    /// The columns at points (zero outside the support), ordered by i + j, then by j.
    EdgeColumns evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;

    /// The amplitude a [Pa/m] of the log field that the local problem gives (the header's
    /// half plane, its load (pi / 2) a |y| cancelling the mirrored free-space stress
    /// -E alpha g |y| / (1 - nu)): a = 2 E alpha g / (pi (1 - nu)), with alpha the material's
    /// thermal expansion (0 if it has none) and g = grad T . e_y the temperature gradient
    /// [K/m] across the symmetry line into the body. Along the line the
    /// stress then has the term -2 a x ln x in sigma_yy (x the distance from v), whose
    /// coefficient no polynomial changes. Plane strain holds at that order: the hoop strain's
    /// part of the field is of order rho^2 ln rho / r_v.
    double theory_amplitude(const std::array<double, 2> &temperature_gradient) const;
    /// The amplitude [Pa/m] of the same term in a field whose coefficient of the first column
    /// (degree 0) is q: the column is the field at the offsets over rho_0, so a = q / rho_0.
    double amplitude_of(double first_column_coefficient) const
    {
      return first_column_coefficient / cutoff_radius_;
    }

    /// The half plane's field of the header (not less the uniform gradient) at the point
    /// (x, y) of its frame: (sigma_xx, sigma_yy, sigma_xy) and (u_x, u_y) for mu = 1. The
    /// columns take it at the offsets over rho_0.
    struct FrameField
    {
      double s[3], u[2];
    };
    static FrameField frame_field(double x, double y, double nu);

    /// The body within rho_0 of v (WedgeFrame::near_rule).
    Quadrature2D near_rule(int n_radial, int n_angular, int n_layers,
                           const std::vector<Circle> &rims = {},
                           int n_beyond_rims = 0) const;

  private:
    WedgeFrame frame_;
    bool symmetry_leaves_;
    double cutoff_radius_;
    Material material_;
    int degree_;
    int displacement_degree_; ///< at most degree_
    /// Unit vectors of the frame in the (r, z) plane: x along the symmetry line, y along the
    /// straight traction face.
    std::array<double, 2> ex_, ey_;
  };
} // namespace rfm
