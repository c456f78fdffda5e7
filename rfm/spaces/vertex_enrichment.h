// Vertex enrichment (issue 24 item 3): the wedge modes of a singular vertex of the section
// (wedge_modes.h) times a cutoff, as extra columns of both spaces, in the column form of the
// contact-edge modes (edge_modes.h: EdgeColumns).
//
// At a vertex v where two parts meet at the interior angle 2 alpha (lines; an arc face that
// carries a traction takes the mapped stresses of set_curved_faces below), polar
// coordinates (rho, theta) about v with theta = 0 on the bisector and theta = -alpha on the
// face of the part that leaves v (the outline runs counter-clockwise, the body on its left),
// theta = +alpha on the face of the part that arrives. Each mode rho^lambda F(theta) gives,
// for a complex lambda, two real columns (its real and imaginary parts), for a real one one.
// A column is g(r, z) times the mode's plane-strain field in the meridian components:
//
//   stress:       g (sigma_rr, sigma_zz, sigma_tt, sigma_rz), sigma_tt = nu (sigma_rr + sigma_zz)
//                 + E u_r / (mu r_v) (the out-of-plane stress of plane strain, as the edge
//                 modes, and the hoop term below);
//   displacement: g u / mu, strains e(g u / mu) with e_tt = g u_r / (mu r);
//
// g = chi(rho) m(r, z): chi the C2 quintic cutoff of edge_modes.h (1 at v, 0 from rho_0 on)
// and m one of the monomials xi^i eta^j (i + j <= d) of the scaled offsets xi = (r - r_v) /
// rho_0, eta = (z - z_v) / rho_0, which carry the hoop terms O(rho / r) and the higher terms
// of the vertex expansion that the modes alone leave to polynomials times omega. A scalar
// factor keeps the face conditions of every mode (traction free, clamped, symmetry), so the
// structures stay boundary-exact when the support, the disc of radius rho_0 about v, meets
// the boundary only on the two faces (rho_0 below the faces' lengths and the distance to every
// other edge; OutlineModel chooses it). (With the section support, below, the factors of
// VertexFactors take chi's place: per stress component in the first term, the displacement's
// in the hoop term and the displacement.)
//
// The hoop term. Hooke's law gives sigma_tt = nu (sigma_rr + sigma_zz) + E e_tt exactly, and
// the mode's own hoop strain e_tt = u_r / r ~ rho^lambda U_r(theta) / r_v does not vanish at
// the vertex's order: it adds to sigma_tt a term rho^lambda (not smooth for lambda < 1) whose
// angular function U_r is not among the stress columns' (the multipliers give nu (F_rr +
// F_zz) times cos and sin). Without it the stress side stalled: on the stepped ring Phi_C was
// 1.9e-6, 6.3e-7, 2.8e-7, 1.9e-7 from the FEM's limit at p = 8, 12, 16, 20 while Phi_L came
// within 9e-9, and the largest stress errors were in sigma_tt on the faces next to the vertex
// (1.4 % of the pressure at rho = 2.5 mm, p = 20). With E times each column's own u_r over
// r_v: 2.3e-7, 1.1e-7, 7.0e-8, 5.4e-8. It is 1 / r_v, not 1 / r: the difference is of the
// next order, which the multipliers carry, and 1 / r put E u_r / r of a section-wide mode on
// the axis, where the r-weighted norms do not see it (sigma_tt 3e9 Pa at the stepped shaft's
// axis sample). sigma_tt takes no boundary condition: the columns stay boundary-exact.
//
// Local columns (local_degree >= 0). At a re-entrant vertex the structures' omegas of the
// trimmed faces behave like rho, and the polynomial stress columns can neither represent nor
// see the smooth part of the field there: with the modes alone the stepped ring's Phi_R came
// within 4e-6 of the FEM's limit at p = 16 but Phi_L stayed 4.8e-4 off. So each vertex also
// gets chi q T, q a polynomial of degree <= local_degree (products of Legendre polynomials in
// the offsets along and across the bisector: the .cc's WedgeLegendre) and T one of the smooth tensor families
// that meet both faces' conditions (l_0 l_1 E, l_1 A_0, l_0 A_1 and the hoop stress, with l_f
// the face's line function, 1 for a clamped face, and A_f the tensors its condition allows:
// t t free, t t and n n symmetry, all clamped), and chi q V, V = e_r, e_z times l_f of the
// faces where u is constrained (and a symmetry face's tangent), q a monomial of the offsets
// there (the cut of their orthonormalization was set on those). Stress columns alone made the
// stress worse (Phi_R 4.4e-6 -> 2.9e-5 off at p = 16, far samples 0.9 % -> 3.8 % at p = 12):
// the displacement columns give them equilibrium.
// With both, Phi_L is 2.3e-5 off at p = 12 and the far samples 0.6 % at p = 8 (4.4 % without).
// But the displacement columns must stay of lower degree than the stress columns
// (local_displacement_degree; OutlineModel takes rfm.vertex_local_displacement_degree for
// them and floor(rfm.vertex_local_degree_ratio p), p / 2 by default, up to rfm.vertex_local_degree
// for the stresses): in the mixed principle the displacement is the multiplier of equilibrium, and
// where the stress space cannot see a displacement column's strains the mixed solution's
// displacement falls behind what its own space holds. Measured at p = 16 against the FEM's limit,
// with a displacement-only Ritz solve on the same displacement space beside it (an experiment, not in
// the code): on the stepped ring with both degrees 4, Phi_L of the mixed solution 7.7e-6 off,
// of the Ritz solution 6.4e-7; with stresses of degree 8 or 12 over displacements of degree 4,
// the mixed Phi_L 1.5e-6 and 1.2e-6. The same ring moved to r = 10 m (plane strain, no hoop
// terms) under an end traction: both 4, mixed 5.2e-5 and Ritz 2.6e-7; stresses 8 over
// displacements 4, mixed 1.6e-6; both 8, mixed 2.5e-5 while the Ritz one was 3e-8.
// The stress families outnumber the displacement ones: the surplus columns pair with a zero
// displacement column, which the basis transform drops (so the system is always solved in the
// transformed basis when a vertex has local columns).
#pragma once

#include "rfm/material.h"
#include "rfm/quadrature/quadrature.h"
#include "rfm/spaces/edge_modes.h"
#include "rfm/spaces/wedge_frame.h"
#include "rfm/spaces/wedge_shadow.h"
#include "problem/wedge_modes.h"

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <functional>
#include <optional>
#include <vector>

namespace rfm
{
  // The wedge analysis lives in the problem layer (both solvers read it: the FEM grades its
  // mesh toward the same vertices).
  using axisym::rough_vertices;
  using axisym::singular_vertices;
  using axisym::SingularVertex;
  using axisym::Wedge;
  using axisym::WedgeFace;
  using axisym::wedge_face;
  using axisym::WedgeFieldValues;
  using axisym::WedgeMode;

  /// One real part (part 0: real, 1: imaginary) of a wedge field's values v, scaled by
  /// `scale`, in meridian components at the point in direction phi from the vertex:
  /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) [Pa], sigma_tt = nu (sigma_rr + sigma_zz) (plane
  /// strain), and (u_r, u_z) [m] for the shear modulus mu (v's displacements are for mu = 1).
  struct MeridianWedgeField
  {
    double s[4], u[2];
  };
  inline MeridianWedgeField meridian_wedge_field(const WedgeFieldValues &v, const std::complex<double> scale,
                                                 const int part, const double phi, const double mu,
                                                 const double nu)
  {
    auto take = [&](const std::complex<double> x) { return part == 0 ? (scale * x).real() : (scale * x).imag(); };
    const double s_pp = take(v.s_rr), s_qq = take(v.s_tt), s_pq = take(v.s_rt);
    const double u_p = take(v.u_r), u_q = take(v.u_t);
    const double c = std::cos(phi), s = std::sin(phi);
    MeridianWedgeField f;
    const std::array<double, 3> t = turned_tensor(s_pp, s_qq, s_pq, c, s);
    f.s[rr] = t[0], f.s[zz] = t[1], f.s[rz] = t[2];
    f.s[tt] = nu * (f.s[rr] + f.s[zz]);
    f.u[0] = (u_p * c - u_q * s) / mu;
    f.u[1] = (u_p * s + u_q * c) / mu;
    return f;
  }

  /// The factors of a vertex's mode columns on the whole section (VertexEnrichment::
  /// set_section_support) at points, one row per point: per stress component (rr, zz, tt, rz)
  /// a scalar that vanishes on every edge other than the vertex's faces where that component
  /// enters the edge's condition, and one scalar for both displacement components that
  /// vanishes on every other edge where the displacement is constrained, with its gradient.
  /// All are 1 at the vertex.
  struct VertexFactors
  {
    Eigen::MatrixXd stress;  ///< n x 4
    Eigen::VectorXd u, u_r, u_z;
  };
  using VertexFactorFunction = std::function<VertexFactors(const Eigen::Ref<const Eigen::VectorXd> &,
                                                           const Eigen::Ref<const Eigen::VectorXd> &)>;

  class VertexEnrichment
  {
  public:
    /// The vertex at `at` (off the axis, r > 0: the hoop term divides by r_v), the unit
    /// direction of the face of the part leaving it (theta = -alpha), the wedge (its angle
    /// and faces, face_minus that of the leaving part), the modes to enrich with
    /// (Wedge::modes), the cutoff radius rho_0 > 0, the multiplier degree d >= 0 and the
    /// local columns' degrees (stresses; displacements, at most the former; -1: none).
    VertexEnrichment(axisym::Point at, std::array<double, 2> leaving_direction, const Wedge &wedge,
                     std::vector<WedgeMode> modes, double cutoff_radius, const Material &material,
                     int multiplier_degree = 0, int local_degree = -1,
                     int local_displacement_degree = -1);

    const axisym::Point &vertex() const { return at_; }
    double cutoff_radius() const { return cutoff_radius_; }
    const Wedge &wedge() const { return wedge_; }
    /// The direction of the wedge's bisector in the (r, z) plane [rad] (theta = 0).
    double bisector_angle() const { return beta_; }
    const Material &material() const { return material_; }
    const std::vector<WedgeMode> &modes() const { return modes_; }
    int multiplier_degree() const { return multiplier_degree_; }
    /// The real fields: one per real exponent, two per complex one (real, imaginary part).
    Eigen::Index n_fields() const;
    Eigen::Index columns_per_field() const
    {
      return (multiplier_degree_ + 1) * (multiplier_degree_ + 2) / 2 + (shadows_.empty() ? 0 : 1);
    }
    /// Columns: for each field (modes in order; real part, then imaginary part) every
    /// monomial, ordered by i + j, then by j, and last its hoop shadow (set_hoop_shadow).
    Eigen::Index n_mode_columns() const { return n_fields() * columns_per_field(); }
    /// The local stress columns after the modes' (local_degree >= 0): chi q T with T one of
    /// the smooth tensor families that meet both face conditions. For each polynomial q of
    /// degree i + j <= local_degree (ordered by i + j, then j) a block of the full families;
    /// for i + j <= local_displacement_degree the first of them pair with the smooth
    /// displacement columns chi m V (m the monomial xi^i eta^j, V a constant vector times the
    /// line functions of the faces where the displacement is constrained), the others have a
    /// zero displacement column. After all blocks the reduced families (a face's own tensors
    /// on a line face, Family::own_face), each with the polynomials along its face up to
    /// local_degree, stresses alone.
    Eigen::Index n_local_columns() const;
    /// The stress families with a column per polynomial of the disc, and the reduced ones.
    Eigen::Index n_full_families() const;
    Eigen::Index n_reduced_families() const;
    /// The inner disc's stress columns after the local ones (set_inner_disc).
    Eigen::Index n_inner_columns() const;
    Eigen::Index n_columns() const { return n_mode_columns() + n_local_columns() + n_inner_columns(); }

    /// The inner disc's radius over the cutoff radius: the first layer of near_rule() and of
    /// section_rule()'s disc ends there, so that the rules of this vertex integrate the inner
    /// cutoff's products (its third derivative jumps at the rim) as they do the outer's.
    static constexpr double inner_disc_ratio = 0.2;
    /// Stress columns on a second, concentric disc of radius inner_disc_ratio rho_0 (degree
    /// >= 0; -1: none): chi_in q T as the local stress columns (q the monomials up to
    /// `degree` of the offsets over the inner radius, T the same families), each with a zero
    /// displacement column. Why: at a vertex the mixed solution is limited by its stress
    /// space, not its displacement space. On the stepped shaft (p_z = 2 p, p = 12) the Ritz
    /// solve on the mixed solution's displacement space came within 6.6e-8 of the FEM's
    /// limit while Phi_C stayed 1.0e-6 off, and 65 % of the stress error lay within half of
    /// rho_0 of the vertex, where one disc's local columns of degree p / 2 resolve the rest
    /// of the field too coarsely (what they miss was not separated further: the modes'
    /// higher axisymmetric corrections, the omegas' kinks). A nested disc is the hp remedy
    /// (geometric refinement toward the vertex). Indicator at p = 12 / 16 without -> with: the stepped
    /// ring 1.6e-7 / 4.9e-8 -> 9.5e-8 / 1.5e-8 (p = 20 without: 3.2e-8), the clamped
    /// cylinder 3.0e-9 / 9.6e-10 -> 5.8e-10 / 3.1e-11. A third disc at 0.04 rho_0 gained
    /// nothing (the shaft 9.2e-7 -> 9.0e-7 at p = 12), and displacement columns in it did
    /// no better than stresses alone.
    void set_inner_disc(int degree);
    int inner_degree() const { return inner_degree_; }

    /// The columns at points (zero outside the support). At the vertex itself the singular
    /// terms have no value: stresses and strains with Re lambda < 1 are returned as 0 there.
    /// `modes_only`: the mode columns alone (n_mode_columns(), the first ones).
    EdgeColumns evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z, bool modes_only = false) const;

    /// The near-vertex rule: the sector of the support in the body, polar about the vertex,
    /// in angular panels of at most pi / 2 with n_angular Gauss points each, and radially in
    /// geometric layers toward the vertex (ratio 0.2, n_layers of them, n_radial points each;
    /// the innermost layer with rho = rho_in s^2), so that the products of two singular
    /// columns (rho^(2 Re lambda - 2), integrable) and of a column with the polynomials are
    /// integrated to the assembly's accuracy. Plain area weights dr dz.
    /// `rims`: other discs overlapping this one, on curved faces only (the frame's rule,
    /// WedgeFrame::near_rule; a vertex between lines keeps its disc clear of the others).
    /// `n_outer`: the outermost layer, [0.2 rho_0, rho_0], takes at least that many points a
    /// direction, radially and in angle. There the columns and the polynomials vary over the
    /// whole disc, as in a cell of the section's rule, and where the model takes the
    /// polynomials' products on this rule (a rough vertex's disc) they have their full degree
    /// 2 p there. OutlineModel passes the section rule's count. Measured at p = 16 with
    /// n_outer 0 against 8 and 16 more points than n_radial: Phi_R of issue 24's pressed hub
    /// moved 5.7e-8 of it (the two within 5e-9), of the heated hub 8.6e-8 (within 1e-8).
    Quadrature2D near_rule(int n_radial, int n_angular, int n_layers = 8, const std::vector<Circle> &rims = {},
                           int n_beyond_rims = 0, int n_outer = 0) const;

    /// Section support of the mode columns (rfm.vertex_support "section"; OutlineModel decides
    /// where: re-entrant vertices about which the section is star-shaped, no die). Each mode
    /// column is then f_c(r, z) m(r, z) sigma_c of the mode for stresses and f_u m u for
    /// displacements, without the cutoff: f from `factors` (VertexFactors), m the monomials
    /// of the offsets scaled by `length_scale` (the farthest point of the outline seen from
    /// this one). The factors keep every other edge's condition, and the faces' conditions
    /// hold as before where the faces are lines along r or z (a factor per stress component
    /// scales each face's traction components apart); OutlineModel gives one common stress
    /// factor otherwise. The local columns keep the disc. `reach(phi)` is the distance from
    /// the vertex to the outline in the direction phi of the (r, z) plane, and `ray_breaks`
    /// the directions where it or the integrands have a kink (the outline's vertices). An
    /// empty `reach` (the section not star-shaped about the vertex, or a curved face; a
    /// vertex with curved faces takes no other): no section_rule(), the model integrates
    /// the columns on near_rule() blended with a rule over the section
    /// (rfm.vertex_support `blended`).
    /// Why: with the cutoff the polynomials must carry the smooth remainder of the modes,
    /// whose flank is as steep as rho_0 is small (the stepped shaft's indicator at p = 16
    /// was 6.0e-3, 1.1e-3, 2.5e-4 with rho_0 at 0.5, 0.75, 1 of the room).
    void set_section_support(VertexFactorFunction factors, std::function<double(double)> reach,
                             std::vector<double> ray_breaks, double length_scale);
    bool section_support() const { return static_cast<bool>(factors_); }
    /// Whether section_rule() can be built: section support with a reach (the section
    /// star-shaped about the vertex). Without it the model integrates the columns on the
    /// disc's near_rule() blended with the section's own rule.
    bool has_section_rule() const { return section_support() && static_cast<bool>(reach_); }
    /// The factors of set_section_support (empty without it); OutlineModel's traction jumps
    /// on the section take them too.
    const VertexFactorFunction &section_factors() const { return factors_; }

    /// Faces that are arcs (a traction-free, pressure or traction part on either side; before
    /// set_section_support, and then without a reach). The straight wedge's stresses meet an arc's
    /// condition only at the vertex, so the mode columns' stresses are taken at the mapped angle of
    /// wedge_frame.h and turned by its rotation a, S(x) = Q(a) S_wedge(rho, theta') Q(a)^T, which
    /// meets a free arc's condition exactly (S n = Q(a) S_wedge n_f = 0); their displacements stay
    /// the straight wedge's (a free face constrains none) with the exact strains of that
    /// displacement. The local stress families take the arc's circle function (R^2 - |x - c|^2) /
    /// (2 R) in place of the line function and the tangent dyad of the circle through x about c in
    /// place of t t. near_rule() is then the frame's rule, which follows the curved faces.
    /// Precondition: `frame` is that of this vertex and no curved face is clamped or a symmetry
    /// line.
    void set_curved_faces(const WedgeFrame &frame);
    bool curved() const { return frame_.has_value(); }

    /// The hoop shadow (wedge_shadow.h): each field gets one more column after its
    /// monomials', its first axisymmetric correction u1 ~ rho^(lambda + 1) V(theta) (the
    /// hoop terms, and the faces' curvature where they are arcs: set_curved_faces first, or
    /// again after it) times the cutoff or the section support's factors; its stresses are
    /// traction free on the faces like the mode's. A zero column where lambda + 1 lies near
    /// another exponent of the wedge (WedgeShadow::valid), none at all if that holds for
    /// every mode (hoop_shadow() false then).
    void set_hoop_shadow(bool on);
    bool hoop_shadow() const { return !shadows_.empty(); }

    /// A circle of the section (another rule's disc) across which the integrands that the
    /// section rule takes have a kink (the partition of unity's shares).
    using Circle = rfm::Circle;
    /// The rule for the section support: near_rule's disc, and beyond it rays out to the
    /// outline (reach), in angular panels between the ray breaks and the circles' tangent
    /// directions of at most pi / 8 with n_angular Gauss points each (halved where the reach
    /// is steep, see the .cc), radially in pieces of ratio at most 3, broken where a ray
    /// crosses a circle, with n_radial points each. Plain area weights dr dz.
    /// Precondition: section_support().
    /// `n_outer`: as near_rule's, for the disc.
    Quadrature2D section_rule(int n_radial, int n_angular, const std::vector<Circle> &circles = {},
                              int n_layers = 8, int n_outer = 0) const;

  private:
    /// The ends of the angular panels in theta, from -alpha to alpha: split at the faces'
    /// lines continued (reflex vertices) and at extra_breaks inside the wedge, gaps below
    /// min_gap dropped, each piece at most max_width wide.
    std::vector<double> angular_panels(const std::vector<double> &extra_breaks, double max_width,
                                       double min_gap) const;

    axisym::Point at_;
    double beta_; ///< the bisector's angle in the (r, z) plane
    Wedge wedge_;
    std::vector<WedgeMode> modes_;
    std::vector<WedgeMode> column_modes_; ///< modes_ as the columns take them (the constructor)
    double cutoff_radius_;
    Material material_;
    int multiplier_degree_;
    int local_degree_;
    int local_displacement_degree_; ///< at most local_degree_
    int inner_degree_ = -1;         ///< set_inner_disc
    VertexFactorFunction factors_;              ///< set: section support
    std::function<double(double)> reach_;
    std::vector<double> ray_breaks_;
    double length_scale_ = 1.0;
    /// A smooth stress family: (rr, zz, rz) tensor constants, the faces whose line function
    /// multiplies it (bit 1: the leaving face, bit 2: the arriving face), or the hoop stress.
    struct Family
    {
      std::array<double, 3> tensor{{0, 0, 0}};
      int factors = 0;
      bool hoop = false;
      int tangent_of = -1; ///< the face whose tangent dyad this is (per point on an arc)
      /// l_other A_f: a tensor that meets face f's condition, times the other face's function.
      /// If face f is a line (reduced()), q l_other A_f with q = l_f q' is q' l_0 l_1 A_f, of the
      /// first families' span already; so q runs over the polynomials of the coordinate along
      /// face f alone (degree <= d: d + 1 columns instead of (d + 1)(d + 2) / 2), the same span.
      int own_face = -1;
    };
    std::vector<Family> families_;
    /// Whether fam's columns are the reduced ones (Family::own_face): its face is a line.
    bool reduced(const Family &fam) const { return fam.own_face >= 0 && !(frame_ && frame_->face_is_arc(fam.own_face)); }

    /// A smooth displacement family: a constant vector times the line functions of `factors`.
    struct VectorFamily
    {
      std::array<double, 2> vector{{0, 0}};
      int factors = 0;
    };
    std::vector<VectorFamily> vector_families_;
    std::array<double, 2> normal_[2]; ///< unit normals of the leaving, arriving face
    std::optional<WedgeFrame> frame_;  ///< set: a face is an arc
    std::vector<WedgeShadow> shadows_; ///< per column mode (set_hoop_shadow)
  };
} // namespace rfm
