// The asymptotic field at a contact edge: where the condition on r = R2 switches from
// frictionless bilateral contact (|z| < c) to a free surface (|z| > c) (DESIGN.md 4.4).
//
// Local frame at the edge (R2, c): x = c - z (positive inside the zone), y = R2 - r
// (positive into the body), polar (rho, theta) with x = rho cos theta, y = rho sin theta,
// theta in [0, pi]: theta = 0 is the contact face, theta = pi the free face. Locally plane
// strain, kappa = 3 - 4 nu, mu = E / (2 (1 + nu)). Mode n (h = n/2, s = (-1)^n) with unit
// amplitude:
//
//   u_x      = rho^h / (2 mu) [ (kappa + h + s) cos(h theta) - h cos((h - 2) theta) ]
//   u_y      = rho^h / (2 mu) [ (kappa - h - s) sin(h theta) + h sin((h - 2) theta) ]
//   sigma_xx = h rho^(h-1) [ (2 + h + s) cos((h - 1) theta) - (h - 1) cos((h - 3) theta) ]
//   sigma_yy = h rho^(h-1) [ (2 - h - s) cos((h - 1) theta) + (h - 1) cos((h - 3) theta) ]
//   sigma_xy = h rho^(h-1) [ -(h + s) sin((h - 1) theta) + (h - 1) sin((h - 3) theta) ]
//
// Every mode is in equilibrium, satisfies Hooke's law in plane strain, u_y = sigma_xy = 0
// on theta = 0 and sigma_yy = sigma_xy = 0 on theta = pi (tested). In the meridian plane:
// u_r = -u_y, u_z = -u_x, sigma_rr = sigma_yy, sigma_zz = sigma_xx, sigma_rz = sigma_xy,
// sigma_tt = nu (sigma_xx + sigma_yy) (the plane-strain out-of-plane stress). Strains map
// like stresses: e_rr = eps_yy, e_zz = eps_xx, gamma_rz = gamma_xy; e_tt = u_r / r.
//
// On the contact face an odd mode's pressure is p(x) = -sigma_yy(x, 0) = -n x^(n/2 - 1)
// (even modes are polynomial fields without pressure there):
// n = 1 is the rho^(-1/2) singularity of a wrong zone; the edge intensity of a field with
// amplitude a_1 is K = sqrt(2 pi) a_1 [Pa m^1/2]: K < 0 (compressive singular pressure)
// means the zone is too short, K > 0 (tension) too long.
//
// Enrichment columns multiply a mode by the cutoff chi(rho) = 1 - 10 t^3 + 15 t^4 - 6 t^5,
// t = rho / rho_0 (chi = 0 for rho >= rho_0; C2 at rho_0), a polynomial in rho so that the
// near-edge rule in rho = rho_0 s^2 integrates it exactly, and by the monomials xi^i eta^j
// (i + j <= d) of the scaled offsets xi = (z - c) / rho_0, eta = (r - R2) / rho_0. Any
// scalar factor keeps both face conditions pointwise, so the structures stay boundary-exact
// when rho_0 < min(c, a - c, R2 - R1) keeps the support away from every other side. The
// multiplied modes carry what the modes alone leave to polynomials times omega near the
// edge (the rho^(5/2) terms and the O(rho / R2) hoop corrections of the axisymmetric body):
// at p = 8 the error of P at the true zone falls from 3.7e-4 (d = 0) to 7e-5 (d = 2).
#pragma once

#include "rfm/material.h"

#include <Eigen/Core>

#include <array>
#include <limits>
#include <vector>

namespace rfm
{
  /// One mode (unit amplitude, no cutoff) at one point, in the meridian frame.
  struct EdgeModeValue
  {
    double u_r = 0.0, u_z = 0.0; ///< [m per unit amplitude]
    /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) and the strains e(u) of the mode's own
    /// displacement (e_rr, e_zz, e_tt, gamma_rz).
    Eigen::Vector4d sigma = Eigen::Vector4d::Zero(), strain = Eigen::Vector4d::Zero();
  };

  /// The local frame of a contact edge on any straight part: the edge point (r, z), the unit
  /// vector t along the part into the zone (x) and the unit normal n into the body (y). Any
  /// orthonormal pair will do (a reflection leaves the plane-strain modes valid). The legacy
  /// outer side r = R2 with the zone at z < c is outer_side(R2, c): t = -e_z, n = -e_r.
  struct EdgeFrame
  {
    double r = 0.0, z = 0.0;
    std::array<double, 2> t{{0.0, -1.0}}, n{{-1.0, 0.0}};

    static EdgeFrame outer_side(double r_edge, double z_edge)
    {
      return {r_edge, z_edge, {{0.0, -1.0}}, {{-1.0, 0.0}}};
    }
    /// The meridian point at local (x, y).
    std::array<double, 2> point(double x, double y) const
    {
      return {r + x * t[0] + y * n[0], z + x * t[1] + y * n[1]};
    }
  };

  /// Mode n (n >= 1; n = -1 is allowed for extraction) at (r, z) in the edge's frame,
  /// rotated into the meridian components: u = u_x t + u_y n, sigma = sigma_xx t t +
  /// sigma_xy (t n + n t) + sigma_yy n n, strains alike (engineering shear), sigma_tt and
  /// e_tt = u_r / r as above. At the edge point itself (rho = 0) the singular terms have no
  /// value: the terms with a negative power of rho are returned as 0 there.
  EdgeModeValue edge_mode(int n, double r, double z, const EdgeFrame &frame,
                          const Material &material);
  /// The legacy outer side: edge_mode(n, r, z, EdgeFrame::outer_side(r_edge, z_edge), material).
  EdgeModeValue edge_mode(int n, double r, double z, double r_edge, double z_edge,
                          const Material &material);

  /// The cutoff chi(rho) and d chi / d rho.
  struct Cutoff
  {
    double value, derivative;
  };
  Cutoff edge_cutoff(double rho, double cutoff_radius);

  /// Enrichment columns at points, one column per mode:
  /// stress[c](k, j) = chi sigma_c of mode j at point k (c = rr, zz, tt, rz);
  /// u[m](k, j) = chi u_m (m = r, z); strain[c](k, j) = e_c(chi u) (c = rr, zz, tt, rz).
  struct EdgeColumns
  {
    Eigen::MatrixXd stress[4], u[2], strain[4];

    /// n_points x n_columns zeros in every block.
    static EdgeColumns zero(Eigen::Index n_points, Eigen::Index n_columns)
    {
      EdgeColumns c;
      for (auto *m : {&c.stress[0], &c.stress[1], &c.stress[2], &c.stress[3], &c.u[0], &c.u[1],
                      &c.strain[0], &c.strain[1], &c.strain[2], &c.strain[3]})
        m->setZero(n_points, n_columns);
      return c;
    }
    /// Copies `part` into the columns [at, at + part's columns).
    void set_columns(Eigen::Index at, const EdgeColumns &part)
    {
      const Eigen::Index w = part.u[0].cols();
      for (int k = 0; k < 4; ++k)
        stress[k].middleCols(at, w) = part.stress[k], strain[k].middleCols(at, w) = part.strain[k];
      for (int m = 0; m < 2; ++m)
        u[m].middleCols(at, w) = part.u[m];
    }
    /// The columns with a nonzero entry in any of the ten matrices. Columns cut off at a
    /// disc are exactly zero beyond it (their evaluate() writes nothing there), so the
    /// products over points away from a vertex need only the columns that live there.
    std::vector<Eigen::Index> nonzero_columns() const;
    /// The columns with a nonzero displacement or strain: the others are stresses alone (a
    /// vertex's local and inner-disc stress columns, DESIGN.md 4.5), whose products with
    /// strains and displacements vanish.
    std::vector<Eigen::Index> displacement_columns() const;
    /// The columns `which`, in that order.
    EdgeColumns columns(const std::vector<Eigen::Index> &which) const;
    /// Keeps the nonzero_columns() alone and returns their indices before (ascending).
    std::vector<Eigen::Index> drop_zero_columns();
  };

  /// The modes at one contact edge, cut off at rho_0.
  class EdgeEnrichment
  {
  public:
    /// Precondition: cutoff_radius > 0, every mode odd and >= 1, multiplier_degree >= 0.
    /// Each mode is multiplied by the monomials xi^i eta^j, i + j <= multiplier_degree, of
    /// the scaled offsets xi = (z - z_edge) / rho_0, eta = (r - r_edge) / rho_0 (a scalar
    /// factor keeps both face conditions, and the products carry the higher terms of the
    /// edge expansion that polynomials times omega cannot: DESIGN.md 4.4).
    ///
    /// With a traction-free end z = end_z (+inf: none) the support may cross it, clipped
    /// there: the displacement columns need no condition on that end, and the stress
    /// columns are multiplied by g = (end_z - z) / (end_z - z_edge), which is 1 at the edge
    /// and makes their traction vanish on the end.
    EdgeEnrichment(double r_edge, double z_edge, double cutoff_radius, std::vector<int> modes,
                   const Material &material, int multiplier_degree = 0,
                   double end_z = std::numeric_limits<double>::infinity());
    /// At an edge of any straight part: the modes in `frame`. With a traction-free end at the
    /// distance end_distance beyond the edge (across the part's line at a right angle, at x =
    /// -end_distance; +inf: none) the support may cross it, clipped, and the stress columns
    /// are multiplied by g = 1 + x / end_distance (x along frame.t), as above.
    EdgeEnrichment(const EdgeFrame &frame, double cutoff_radius, std::vector<int> modes,
                   const Material &material, int multiplier_degree = 0,
                   double end_distance = std::numeric_limits<double>::infinity());
    const EdgeFrame &frame() const { return frame_; }

    double r_edge() const { return r_edge_; }
    double z_edge() const { return z_edge_; }
    double cutoff_radius() const { return cutoff_radius_; }
    /// The end where the support is clipped (+inf when it is not): its z (the legacy form)
    /// and its distance from the edge along -t.
    double end_z() const { return end_z_; }
    double end_distance() const { return end_distance_; }
    const std::vector<int> &modes() const { return modes_; }
    int multiplier_degree() const { return multiplier_degree_; }
    /// Columns: for each mode (in the given order) every monomial xi^i eta^j, i + j <= d,
    /// ordered by i + j, then by j.
    /// Columns: for each mode (in the given order) every monomial xi^i eta^j, i + j <= d,
    /// ordered by i + j, then by j.
    Eigen::Index columns_per_mode() const
    {
      return (multiplier_degree_ + 1) * (multiplier_degree_ + 2) / 2;
    }
    Eigen::Index n_columns() const
    {
      return static_cast<Eigen::Index>(modes_.size()) * columns_per_mode();
    }
    /// Column of mode 1 with the constant multiplier (whose coefficient gives K), or -1 if it
    /// is not enriched.
    Eigen::Index singular_column() const;

    EdgeColumns evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;

  private:
    EdgeFrame frame_;
    double r_edge_, z_edge_, cutoff_radius_;
    std::vector<int> modes_;
    Material material_;
    int multiplier_degree_;
    double end_z_, end_distance_;
  };
} // namespace rfm
