// The RFM on any meridian section (DESIGN.md 7.1): the outline structures
// (outline_structures.h), the polynomials of degree <= p in r and z orthonormal on the
// section (section_basis.h), the curved-triangle quadrature of the section (section_quadrature.h), the resolving system of
// Reissner's functional (assembly.h, same blocks) and its solution.
//
// A mirrored body (axisym::Body::mirrored, the legacy hollow cylinder's half z >= 0) counts
// every integral twice, so that functionals refer to the whole body, and is evaluated at z < 0
// by mirroring.
//
// Unknowns: q_s = (q_rr, q_zz, q_tt, q_rz, q_b): N each and the boundary columns B_e last;
// q_u = (q_r, q_z), N each.
//
// Body loads (DESIGN.md 7.1): the body force f enters p_u (- int f . Phi) and W(u); the
// thermal strain e_th = alpha T (1, 1, 1, 0) enters p_s (int X . (e(u0) - C s0 - e_th)) and
// the functionals: Phi_L = 1/2 int (e - e_th) . D (e - e_th) - W, Phi_C = -1/2 int s . C s
// - int s . e_th + int_{S_u} (s n) . u*, Phi_R = int [s . (e - e_th) - 1/2 s . C s] - W, so
// that all three are the same number at the exact solution. The stress is the total stress.
//
// Conditioning. The tensor Legendre polynomials of the bounding box are nearly dependent on a
// section that fills only part of the box (the quarter annulus: condition number of their
// r-weighted values 1.3e12 at p = 16), so the coordinate functions are the same polynomials
// orthonormalized on the section itself (section_basis.h). The structures' omegas, the
// coupling of the components through C and the boundary columns still make the stress
// columns' Gram matrix far from I (Jacobi-scaled l_min / l_max about 2e-8 on the sphere at
// p = 20), so the system is solved in a basis orthonormal in its own norms: with G the Gram
// matrix of the stress columns in the compliance norm (G = -R11) and D G D = V L V^T (D its
// Jacobi scaling), the columns D V_j / sqrt(l_j) with l_j > 1e-14 max l are kept; likewise
// per displacement component with the Gram matrix of values and gradients. With the box's
// Legendre basis this step dropped directions (203 of 1806 at p = 20 on the sphere) and the
// sphere's stress error flattened near 5e-5 from p = 14; with the section basis it keeps
// them all there. The transform costs three symmetric eigendecompositions (5 of the 6 s of a
// p = 20 solve on the rectangle), so a system is first solved as assembled, and transformed
// only when the rcond estimate of its scaled M or K falls below raw_min_rcond (or a
// displacement component is reduced in degree).
//
// Coordinate functions and quadrature: the polynomials orthonormal on the section and its
// curved-triangle rule; on a rectangle with sides along r and z the tensor Legendre
// polynomials of the box (orthogonal there, with no N x N transform to evaluate them) and
// the tensor rule with p + extra_gauss_points points per direction on cells graded toward
// the zones' ends (section_quadrature.h): the same functions and points as the rectangle
// stack had, a quarter of the triangles' points and a third of the time at p = 20.
//
// Axis parity (issue 24 item 5; rfm.axis_parity, default on). Values on the axis r = 0 are
// where polynomials in r projected in r-weighted norms are weakest (section_basis.h). On a
// rectangle along r and z with an edge on the axis, and nothing against it
// (axis_parity_obstacle), the coordinate functions are the polynomials of degree <= p in r^2
// and <= p in z (the same count, (p + 1)^2: the tensor Legendre polynomials in
// 2 (r / r_max)^2 - 1 and z, orthogonal in the r-weighted measure, or where a displacement
// degree is lowered the ones orthonormal on the section), the structures are even in r
// (outline_structures.h), the tensor rule is Gauss in r^2 in r (quadrature.h:
// gauss_in_square_on_cells, exact for their r-weighted products with the plain rule's
// points), and the near-vertex rules are sized for the degree 2 p in r. Measured on a
// spinning solid cylinder with free ends (b = 0.2 m, h = 0.1 m, 500 rad/s), the largest
// stress error at the axis point of the free end, (0, 0.1), against p = 24:
// 9.2e-2, 4.7e-2, 1.6e-2 MPa at p = 8, 12, 16 with polynomials in r, 3.1e-3, 5.7e-4, 8.2e-5
// with the parity; the indicator 1.2e-8, 5.2e-10, 2.3e-11 against 1.3e-9, 1.6e-11, 1.8e-13.
// Not on other sections yet: their recurrence in r^2 is too noisy beyond p = 16
// (section_basis.h), and arcs and inclined lines would need even omegas (tori, cones).
//
// Axis coupling (issue 24 item 5; rfm.axis_coupling, default off). The smooth fields of a
// body of revolution have sigma_rr = sigma_tt on r = 0, which the r-weighted functionals do
// not ask for (the hoop stress is free of every boundary condition). With the option, on a
// section with an edge on the axis (without the die's local stress columns), the polynomial
// column (rr, j) carries sigma_tt = sigma_rr too and the hoop block is omega_tt P_tt with
// omega_tt = r / l ((r / l)^2 with the parity; l the section's size): sigma_tt = sigma_rr +
// omega_tt P_tt, the same number of columns. In the assembly this is the change of variables
// T (the blocks' components to the stress's; assembly.h: block_compliance): C becomes
// T^T C T between polynomial blocks and the rr block pairs with e_rr + e_tt and with the
// thermal strain twice. The particular stress and the boundary columns B_e take sigma_tt =
// sigma_rr (structure_stress), and the enrichment columns, given as whole fields, sigma_tt +
// h (sigma_rr - sigma_tt) with h = 1 - S(r / rho) (couple_at_axis; S the quintic
// smoothstep, rho half the smallest radius of an enrichment's centre, so that a vertex's own
// field is untouched). Measured on the stepped shaft, sigma_zz(0, 0) against the FEM's
// 3.607754 MPa at p = 8 / 12 / 16 / 20: -36 % / -11 % / -5.1 % / -2.2 % free, -21 % / -16 %
// / -5.9 % / -1.5 % coupled; the indicator 1.5e-4 / 1.0e-5 / 2.5e-6 / 9.7e-7 -> 2.1e-4 /
// 9.4e-6 / 2.2e-6 / 8.7e-7, Phi_R's error at p = 16 8.6e-7 -> 1.03e-6 (the smaller stress
// space), sigma_rr - sigma_tt at (0, 0) up to 0.3 MPa free, 0 coupled. So the free hoop
// stress on the axis is not what holds the axis back. Off by default: the report's gates of
// the stepped shaft (Phi_R at p = 16 within 1e-6; with p_z = 2 p the axis within 0.5 % at p =
// 16: 0.54 %) fail with it, while the dies on the axis gain (the Hertz pressure 0.48 % ->
// 0.40 % off, its indicator 1.3e-3 -> 5.0e-4) and the thick sphere's largest stress error
// moves by up to a quarter either way (p = 8 8.5e-3 -> 6.2e-3, p = 10 1.46e-3 -> 1.65e-3).
#pragma once

#include "problem/problem.h"
#include "rfm/assembly/assembly.h"
#include "rfm/degree_sequence.h"
#include "rfm/fields/solution.h"
#include "rfm/quadrature/quadrature.h"
#include "rfm/solve/saddle_point_solver.h"
#include "rfm/spaces/basis.h"
#include "rfm/spaces/edge_modes.h"
#include "rfm/spaces/local_basis.h"
#include "rfm/spaces/section_basis.h"
#include "rfm/spaces/traction_jump.h"
#include "rfm/spaces/resonant_vertex.h"
#include "rfm/spaces/vertex_enrichment.h"
#include "rfm/structures/outline_structures.h"

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <variant>

namespace rfm
{
  /// Points on the edges: (r, z), r ds weights, outward unit normal and the edge index.
  struct EdgeQuadrature
  {
    Eigen::VectorXd r, z, weights, n_r, n_z;
    std::vector<int> edge;
  };

  /// The smallest rcond estimate of the scaled M and K at which OutlineModel solves the
  /// system as assembled, without the orthonormalizing transform. 1e-10 until session 15:
  /// the edge modes' richer multipliers (session 14) put the paper's die at p = 16 at
  /// 6.4e-11, onto the transform (one search 1.97 -> 4.4 s). At 1e-12 the raw and the
  /// transformed solves gave the same c to 2e-9 and P to 2e-12 there (p = 14 and 16); every
  /// test and report gate passed, every report number but the timings within 2e-5 (the
  /// residual K at a zone found, a number near zero, moved 1.3 %), and the p = 16 search took
  /// 2.2 s.
  inline constexpr double raw_min_rcond = 1e-12;

  /// Why OutlineModel does not use axis parity (the header) for `problem`: empty when it
  /// does (a die's zone lies on a die part, which OutlineStructures::axis_parity_obstacle
  /// names).
  std::string axis_parity_obstacle(const axisym::Problem &problem, const DiscretizationOptions &options);

  class OutlineModel
  {
  public:
    /// The inner disc (rfm.vertex_inner_disc) goes to singular vertices whose leading
    /// exponent's real part is below this: the stronger the singularity, the rougher the
    /// field that its modes leave near the vertex. Indicator without -> with, and the time
    /// of rfm_solve --degree p (one thread): at lambda = 0.544 (the stepped ring's 270
    /// degrees) 1.6e-7 -> 9.5e-8 at p = 12 (2.6 -> 3.7 s), 4.9e-8 -> 1.5e-8 at p = 16 (7.2
    /// -> 10.6 s); at 0.711 (the clamped cylinder's 90 degrees) 3.0e-9 -> 5.8e-10 (0.5 ->
    /// 0.8 s), 9.6e-10 -> 3.1e-11 (1.6 -> 2.9 s). At issue 24's hubs (0.937 at 186 degrees,
    /// 0.827 at 199 degrees) it bought less than a higher degree: heated, 1.0e-5 -> 6.2e-6
    /// at p = 12 (3.3 -> 6.6 s) and 1.0e-6 -> 6.3e-7 at p = 16 (21 -> 31 s); pressed, 6.4e-6
    /// -> 6.0e-6 (4.6 -> 8.3 s) and 1.13e-6 -> 1.02e-6 (26 -> 38 s).
    static constexpr double inner_disc_max_exponent = 0.8;
    /// Points per block where fields are evaluated at many points (and the vertices' near
    /// points assembled): bounds the matrices of points by columns.
    static constexpr Eigen::Index evaluation_block = 2048;

    /// Builds, assembles and solves at options.degree. `zones`: one per die part, the contact
    /// zone of a bilateral solve (OutlineStructures). `local`: the local boxes' columns
    /// (local_basis.h; default: die_local_basis of the zones; a search passes the boxes of its
    /// first estimate to every trial zone, so that the space does not jump with the zone).
    /// Local columns need the tensor rule of a rectangle with sides along r and z; on other
    /// sections they are left out. Throws InputError for sections the structures do not
    /// support. Numerical failure: ok() false, summary().message.
    OutlineModel(const axisym::Problem &problem, const DiscretizationOptions &options,
                 const SolverOptions &solver_options = {}, const std::vector<DieZone> &zones = {},
                 const std::optional<LocalBasis> &local = std::nullopt);

    bool ok() const { return summary_.success; }
    const SolveSummary &summary() const { return summary_; }
    double assembly_seconds() const { return assembly_s_; }
    /// The Ritz solve and the stress projection made with rfm.ritz_bound (stress_space_gap).
    double ritz_seconds() const { return ritz_s_; }
    double solve_seconds() const { return solve_s_; }
    /// Coordinate functions per component: the global polynomials, then the local ones.
    Eigen::Index n_basis_functions() const;
    /// The global polynomials' degree along z (rfm.z_degree_ratio).
    int degree_z() const
    {
      return std::visit([](const auto &b) { return b.degree_z(); }, basis_);
    }
    Eigen::Index n_local_functions() const { return local_.n_basis_functions(); }
    const LocalBasis &local_basis() const { return local_; }
    Eigen::Index n_boundary_columns() const { return structures_.n_boundary_columns(); }
    /// Whether the coordinate functions and structures are even in r (the header's axis
    /// parity), and if not, why (axis_parity_obstacle).
    bool axis_parity() const { return structures_.axis_parity(); }
    const std::string &axis_parity_obstacle() const { return axis_parity_obstacle_; }
    /// Whether sigma_tt = sigma_rr + omega_tt P_tt (rfm.axis_coupling; problem/settings.h):
    /// a section with an edge on the axis, without the die's local stress columns.
    bool axis_coupling() const { return hoop_coupled_; }
    /// The stress-only local columns (all four components; 0 without local boxes).
    Eigen::Index n_local_stress_columns() const { return n_local_stress_; }
    Eigen::Index n_quadrature_points() const { return quadrature_.n_points(); }
    /// Unknowns after the orthonormalization (stress, displacement).
    std::array<Eigen::Index, 2> n_kept_unknowns() const { return n_kept_; }
    /// The directions the orthonormalizing transform dropped as dependent (eigenvalue of the
    /// Jacobi-scaled Gram matrix below 1e-14 of its largest), stresses and displacements:
    /// {0, 0} on the raw path. Not the same as unknowns - n_kept_unknowns(), which counts
    /// the lowered displacement degrees and the vertices' stress-only columns (whose
    /// displacement columns are zero) too.
    std::array<Eigen::Index, 2> n_dropped_directions() const { return n_dropped_; }

    /// Fields at points of the section, and of its image z < 0 when the body is mirrored
    /// (axisym::Body::mirrored: the legacy hollow cylinder's half section). Precondition: ok().
    FieldValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;
    Functionals functionals() const;

    /// Where the indicator's gap lies. The constitutive-relation error (Ladeveze) of the
    /// solution (u_h, s_h), per radian [J/rad]:
    ///
    ///   E = 1/2 int d . D d  r dr dz,    d = C s_h - (e(u_h) - e_th),
    ///
    /// the energy of the disagreement between the stress and the displacement's elastic
    /// strain, >= 0 at every point. Phi_L - Phi_C - E = int s_h . e(u_h) - W(u_h) -
    /// int_{S_u, S_c} (s_h n) . u* ds, which the mixed solution's equation for u_h makes zero
    /// (to the rules' rounding) when u_h has no fixed part: every prescribed displacement
    /// homogeneous (symmetry planes, the axis, clamped parts) and no traction jump's
    /// particular displacement (traction_jump.h). Then E = Phi_L - Phi_C. Otherwise the
    /// difference is the stress's equilibrium defect against that fixed part (issue 24's
    /// pressed hub at p = 16: Phi_L - Phi_C = 0.58 E). `total` is integrated as
    /// functionals_at does (the polynomial part on the section's rule, what the enrichment
    /// adds on the near-edge rules). That difference is no density of its own (the
    /// polynomial part alone is far off inside a disc, and the two rules' small difference on
    /// it is not), so the map takes the whole field's density times psi on the near rules
    /// and times 1 - psi on the section's, psi = 1 - prod_i S(rho_i^2 / rho_0,i^2) over the
    /// near rules' discs (S their partition step: psi is 1 at each centre, where the
    /// section's rule does not resolve the density, 0 beyond every rim, where the near rules
    /// end, and smooth between), binned into n_r x n_z equal cells of the section's box
    /// (cells(i, j): r in the i-th, z in the j-th interval) [J/rad]. The cells' sum and
    /// `total` differ by the rules' errors (issue 24's heated hub at p = 12: by 13 % with the
    /// default rules, 0.4 % with rfm.edge_extra_points 12). Precondition: ok(),
    /// n_r, n_z >= 1.
    struct ErrorMap
    {
      double total = 0.0;      ///< E [J/rad]
      axisym::BoundingBox box; ///< the section's box, split into the cells
      Eigen::MatrixXd cells;   ///< n_r x n_z [J/rad]
      /// The edges of the cells: r of the i-th (i = 0..n_r), z of the j-th (j = 0..n_z) [m].
      double r_edge(const Eigen::Index i) const { return box.r_min + (box.r_max - box.r_min) * i / cells.rows(); }
      double z_edge(const Eigen::Index j) const { return box.z_min + (box.z_max - box.z_min) * j / cells.cols(); }
      /// The k cells with the largest values, largest first: their (i, j).
      std::vector<std::array<Eigen::Index, 2>> largest(std::size_t k) const;
    };
    ErrorMap constitutive_error_map(int n_r, int n_z) const;
    /// The density 1/2 d . D d at points (r, z) of the section [J/m^3], of the fields f there
    /// (evaluate(r, z)).
    Eigen::VectorXd constitutive_error_density(const Eigen::Ref<const Eigen::VectorXd> &r,
                                               const Eigen::Ref<const Eigen::VectorXd> &z,
                                               const FieldValues &f) const;

    /// The Lagrange functional's least value over the displacement space (the columns of u_h:
    /// the polynomial ones times the structures, and every enrichment's; the lowered degree of
    /// a displacement component is not applied) [J/rad]: Phi_L at the Ritz solution of that
    /// space, a displacement-only solve beside the mixed one. Like Phi_L(u_h) it is an upper
    /// bound of the exact Phi (a kinematically admissible field), and never above Phi_L(u_h)
    /// (u_h is in the space). Why: in the mixed principle u_h is the multiplier of
    /// equilibrium, not the space's best approximation in energy, and where the stress
    /// space cannot see part of the displacement space's strains (vertex enrichment, arcs)
    /// Phi_L(u_h) falls far behind what the space holds (the header of vertex_enrichment.h;
    /// issue 24). Precondition: ok(), no die zone. Its cost: the stiffness matrix of the
    /// displacement columns on the assembly's rules and a Cholesky factorization.
    double ritz_lagrange() const;

    /// Whether the stress space or the pairing holds the mixed solution back (issue 24), with
    /// u_R the Ritz solution of ritz_lagrange(), per radian [J/rad]: `ritz` the constitutive-
    /// relation error E (constitutive_error_map) of (s_h, u_R), `projected` that of
    /// (P s_R, u_R), P s_R the stress space's best approximation of s_R = D (e(u_R) - e_th)
    /// in the compliance norm (the mixed solution's stress equation with u_R in place of u_h:
    /// s_h is P of D (e(u_h) - e_th) in the same way). So projected <= ritz, and
    /// sqrt(2 projected) is the stress space's distance from s_R: within sqrt(2 (Phi_L(u_R) -
    /// Phi)) (the Ritz solution's own error) of its distance from the exact stress. Where
    /// projected comes near the mixed solution's E, a better displacement cannot help: the
    /// stress space is the limit. Measured on the stepped ring: E of the mixed solution 6.4e-9
    /// and 2.8e-9 J/rad at p = 16 and 20, projected 4.9e-9 and 2.4e-9, with the Ritz
    /// solution within 3e-10 of the FEM's limit there. Precondition: ok(), built with
    /// rfm.ritz_bound (the projection needs the assembled system; without it: logic_error).
    /// `lagrange`: Phi_L at u_R, ritz_lagrange() from the same pass as `ritz`.
    struct StressSpaceGap
    {
      double ritz = 0.0, projected = 0.0, lagrange = 0.0;
    };
    StressSpaceGap stress_space_gap() const;

    /// The force of the die on `part` [N, the whole body of revolution] (DESIGN.md 4.3), as
    /// a domain integral, P = -2 pi [int s . e(v) - int f . v] r dr dz + 2 pi int_St t . v r ds
    /// with v = psi n (n the part's outward normal, psi = 1 - d / D, d the distance from the
    /// part's line into the body and D its largest value over the section, so that v vanishes
    /// at the far side; exact for the exact solution when v . n = 0 on every support), and as
    /// the trace -2 pi int (sigma_nn - t* . n) r ds over the part (t* the prescribed traction
    /// of a loaded free part beyond the zone). The die's force alone: the hollow cylinder's
    /// form (contact.h) counted the outer pressure on the free part in P as well (the same
    /// when it is 0, as in every problem of the paper). Precondition: ok(), a zone on `part`.
    struct DieForce
    {
      double domain = 0.0, trace = 0.0;
    };
    DieForce die_force(const std::string &part) const;

    /// Moments of the die's contact pressure p on the part of `frame` (consistent reactions,
    /// Babuska and Miller; DESIGN.md 4.4): for m scalar test functions phi_k(s, d) of the
    /// distance s from the frame's centre along the part and d into the body from its line,
    ///   m_k = int_zone p phi_k r ds = W_t(V_k) - int [s_h . e(V_k) - f . V_k] r dr dz
    /// (per radian; twice for a mirrored body) with V_k = phi_k n, n the part's outward normal
    /// (phi = 1 - d / die_depth gives P / 2 pi: die_force's domain integral). V_k must vanish
    /// where the displacement along n is prescribed off the zone. The error of m_k is of the
    /// order of the stress error times how well the displacement space approximates V_k,
    /// far below that of the trace for smooth V_k. `phi(s, d)` returns n x 3 m: phi_k in
    /// columns 0..m-1, d phi_k / ds in m..2 m-1, d phi_k / dd in 2 m..3 m-1.
    /// Precondition: ok(), `frame` a die frame of the problem's part (straight).
    using DieTestFields = std::function<Eigen::MatrixXd(const Eigen::VectorXd &, const Eigen::VectorXd &)>;
    Eigen::VectorXd die_moments(const axisym::DieFrame &frame, const DieTestFields &phi) const;
    /// D: the largest distance into the body from the line of `frame`'s part [m].
    double die_depth(const axisym::DieFrame &frame) const;
    /// The body is mirrored in z = 0 (its integrals count the image as well).
    bool mirrored() const { return mirrored_; }

    /// Contact-edge enrichment (DESIGN.md 4.4, edge_modes.h) at every free end of a zone: the
    /// odd modes 1, 3, ... (rfm.edge_modes) times the monomials up to rfm.edge_mode_degree, in
    /// the frame of the end (t into the zone, n into the body), cut off at rho_0 =
    /// rfm.edge_cutoff times the room around the end (the zone's length, the part beyond the
    /// end, the distance to every other edge), as extra columns of both spaces; their products
    /// are integrated on a polar rule over the support's half disc, and the traces on the
    /// zone's edge on a rule graded toward the end. n_zone_edges() such ends, in zone order
    /// (low end first).
    std::size_t n_zone_edges() const { return enrichments_.size(); }
    Eigen::Index n_edge_columns() const;
    /// Vertex enrichment (vertex_enrichment.h; issue 24 item 3): at every vertex of the
    /// outline off the axis between two straight parts, or parts of which the arcs carry a
    /// traction (VertexEnrichment::set_curved_faces), without a die where the field is
    /// singular (singular_vertices: Re lambda < 1), the wedge's modes with Re lambda <
    /// rfm.vertex_max_exponent times the monomials up to rfm.vertex_mode_degree, and the
    /// smooth local columns of degree floor(rfm.vertex_local_degree_ratio p) within
    /// [rfm.vertex_local_displacement_degree, rfm.vertex_local_degree] (stresses) and
    /// rfm.vertex_local_displacement_degree (displacements, at most rfm.vertex_local_degree), cut
    /// off at rfm.vertex_cutoff times the room (each face, half of it where its other end is
    /// singular too; the distance to every other edge; clear of the contact edges' supports), as
    /// extra columns of both spaces after the edge modes; their products are integrated on the
    /// near-vertex rules (VertexEnrichment::near_rule). With rfm.notch_roots, every notch root
    /// (axisym::notch_roots) gets the smooth local columns alone, in the same form (no modes).
    /// With rfm.rough_vertices, every rough vertex (axisym::rough_vertices) where a traction
    /// jumps gets the modes and local columns as a singular vertex, its disc also clear of
    /// the other vertices' discs; there the polynomials' products are taken on the disc's
    /// rule too, blended with the section's (blend_disc_rules, quadrature.h).
    const std::vector<VertexEnrichment> &vertex_enrichments() const { return vertices_; }
    /// The vertex enrichment at x (within tol of its vertex), or nullptr.
    const VertexEnrichment *vertex_enrichment_at(const axisym::Point &x, double tol) const
    {
      for (const VertexEnrichment &e : vertices_)
        if (std::hypot(e.vertex().r - x.r, e.vertex().z - x.z) <= tol)
          return &e;
      return nullptr;
    }
    /// Traction jumps (traction_jump.h; issue 24 item 4): at every vertex of the outline off
    /// the axis between two traction parts (free, pressure, traction; no die) whose tractions
    /// no constant stress meets, the loaded wedge's stress S of degree 0, added as
    /// chi (S - s0) to the particular stress, and the displacement of its log term as chi u_D
    /// to the particular displacement, cut off at rfm.vertex_cutoff times the room (each face,
    /// half of it where its other end has a jump too; the distance to every other edge; clear
    /// of the other enrichments' supports; a singular vertex's own cutoff when the vertex has
    /// modes too). Their products are integrated on the jump's polar rule (the vertex's when
    /// it has modes), like the enrichment columns'.
    /// With rfm.vertex_support `section` (the default), a jump between two lines with its own
    /// rule, about which the section is star-shaped, in a problem without a die, takes the
    /// whole section instead of the disc: the field is F_c (S - s0) per stress component c and
    /// F u_D, F = 1 - (1 - G)^4 with G the product of the other edges' omegas where the
    /// component enters their condition, 1 at the vertex (vertex_enrichment.h's section
    /// factors; traction_jump.h says why), on a polar rule about the vertex over the section,
    /// which then takes every volume integral.
    const std::vector<TractionJump> &traction_jumps() const { return jumps_; }
    /// Whether jump i's field covers the section (above).
    bool traction_jump_on_section(std::size_t i) const { return jump_sections_.at(i).has_value(); }
    /// Resonant vertices (resonant_vertex.h): at every vertex of axisym::resonant_vertices (a
    /// symmetry line meets a traction part at a right angle and the loads are not symmetric
    /// about the line; no die), the log field's stress and displacement columns times the
    /// monomials up to rfm.vertex_mode_degree, cut off at rfm.vertex_cutoff times the room
    /// (each face, half of it where its other end is resonant too; the distance to every other
    /// edge; clear of the other enrichments' and jumps' supports), after the vertex
    /// enrichments' columns, on their own polar rules.
    const std::vector<ResonantVertex> &resonant_vertices() const { return resonances_; }
    /// At each resonant vertex (in resonant_vertices()' order): the amplitude a [Pa/m] of the
    /// stress's rho ln rho term in the solved field (its first column's coefficient: no other
    /// column has that term) and the one the local problem gives
    /// (ResonantVertex::theory_amplitude). A check of the field near the vertex against an
    /// independent asymptotic result. Precondition: ok().
    struct LogAmplitude
    {
      double solution, theory;
    };
    std::vector<LogAmplitude> resonant_log_amplitudes() const;
    /// One column per jump with rfm.jump_column (none without): the jump's field (the
    /// stress, displacement and strain of jump_fields for that jump alone) with a free
    /// coefficient, beside its fixed copy. The displacement space then holds the direction of
    /// the fixed displacement u_j, so that the stress is in equilibrium against all of u_h in
    /// the weak sense and Phi_L - Phi_C is the constitutive-relation error E (without it,
    /// E plus the stress's work defect against u_j, of either sign). They come after the
    /// vertices' columns and before the resonant vertices'.
    Eigen::Index n_jump_columns() const;
    /// The vertex enrichments', the jumps' (n_jump_columns) and the resonant vertices' columns.
    Eigen::Index n_vertex_columns() const;
    /// The edge intensity K = sqrt(2 pi) a_1 [Pa m^1/2] at zone end i by the interaction
    /// integral (contact.h) on the half disc of radius 0.9 times the end's room. K < 0: the
    /// zone is too short there (compressive singular pressure), K > 0: too long.
    double edge_intensity(std::size_t i) const;
    /// The die part whose zone ends at zone end i.
    const std::string &zone_edge_part(std::size_t i) const { return edges_.at(i).zone.part; }
    /// The contact zones of the solve, as given.
    const std::vector<DieZone> &zones() const { return zones_; }
    /// The solution at other indentations by linearity. `others` are models of the same
    /// problem, options and zones (the same local boxes) that differ from this one only in
    /// their zones' indentations: this model becomes the one at delta = delta_0 + sum_j t_j
    /// (delta_j - delta_0), with coefficients q = q_0 + sum_j t_j (q_j - q_0). Exact up to
    /// rounding: the system's matrix and the orthonormalizing transform do not depend on
    /// delta, its right-hand side and u0 are affine in it. Throws std::invalid_argument when
    /// the models' zones or unknowns differ. Precondition: every model ok().
    void combine_indentations(const std::vector<const OutlineModel *> &others,
                              const std::vector<double> &t);
    /// The enrichment at zone end i (its frame, cutoff and columns).
    const EdgeEnrichment &zone_edge_enrichment(std::size_t i) const { return enrichments_.at(i); }
    /// The coefficients (in q_s, in q_u) of column j of the enrichment at zone end i.
    std::array<double, 2> edge_column_coefficients(std::size_t i, Eigen::Index j) const;

    /// int g(f, r, z) r dr dz over the section (per radian; twice for a mirrored body) on the
    /// assembly's rules: g of the polynomial part on the section's rule plus g(all) -
    /// g(polynomial part) on the near-edge rules, so exact in the assembly's sense for g
    /// linear in the fields. g returns n_points x m (m integrands at once); the result has m
    /// entries. Precondition: ok().
    using Integrand = std::function<Eigen::MatrixXd(const FieldValues &, const Eigen::VectorXd &,
                                                    const Eigen::VectorXd &)>;
    Eigen::VectorXd integrate(const Integrand &g) const;
    /// int_{S_t} t . V_k r ds over the traction edges (per radian; twice for a mirrored body)
    /// for m test fields: v(r, z) returns n_points x 2 m, the r and z components of field k
    /// in columns 2 k and 2 k + 1; the result has m entries.
    Eigen::VectorXd traction_work(
      const std::function<Eigen::MatrixXd(const Eigen::VectorXd &, const Eigen::VectorXd &)> &v) const;

    /// The split body the structures and the rules work on (OutlineStructures::body()).
    const axisym::Body &body() const { return structures_.body(); }

  private:
    /// The system (R11: its lower triangle; the enrichment's displacement Gram matrix in
    /// gram_e_).
    ReissnerSystem assemble();
    /// The stress structures' values with the stress-only local columns appended to the
    /// boundary columns: per component k, omega_k times LocalBasis::piecewise_values (the
    /// component's own omega keeps every traction condition exact).
    OutlineStressValues stress_values(const Eigen::Ref<const Eigen::VectorXd> &r,
                                      const Eigen::Ref<const Eigen::VectorXd> &z) const;
    /// The stress columns beyond the 4 N polynomial ones: the structures' boundary columns and
    /// the stress-only local columns.
    Eigen::Index n_stress_border() const { return structures_.n_boundary_columns() + n_local_stress_; }
    /// The Gram matrices of the displacement columns (values and gradients, per component)
    /// for the basis transform.
    std::array<Eigen::MatrixXd, 2> displacement_grams() const;
    /// The fields, without the enrichment's part when !with_enrichment (no mirroring), in
    /// blocks of at most evaluation_block points.
    /// `q_u`: displacement coefficients in place of u_h's (nullptr: u_h's).
    /// `polynomial` (with_enrichment only; nullptr: not wanted): also the fields without the
    /// enrichment's part, from the same basis values (the near rules' sums take both, and the
    /// basis is the evaluation's cost: half of the pressed hub's run at p = 16 in long double).
    /// `q_s`: stress coefficients in place of s_h's (nullptr: s_h's).
    FieldValues evaluate_parts(const Eigen::Ref<const Eigen::VectorXd> &r,
                               const Eigen::Ref<const Eigen::VectorXd> &z, bool with_enrichment,
                               const Eigen::VectorXd *q_u = nullptr,
                               FieldValues *polynomial = nullptr,
                               const Eigen::VectorXd *q_s = nullptr) const;
    FieldValues evaluate_block(const Eigen::Ref<const Eigen::VectorXd> &r,
                               const Eigen::Ref<const Eigen::VectorXd> &z, bool with_enrichment,
                               const Eigen::VectorXd *q_u = nullptr,
                               FieldValues *polynomial = nullptr,
                               const Eigen::VectorXd *q_s = nullptr) const;
    /// functionals() with the displacement coefficients q_u and the stress coefficients q_s
    /// (nullptr: u_h's, s_h's).
    Functionals functionals_at(const Eigen::VectorXd *q_u, const Eigen::VectorXd *q_s = nullptr) const;
    /// The Ritz solution's coefficients (ritz_lagrange()), in q_u's layout.
    Eigen::VectorXd ritz_coefficients() const;
    /// With rfm.ritz_bound: ritz_q_ and projected_q_s_ (stress_space_gap()) from the
    /// assembled system; `s_map` the orthonormalizing transform of the stresses (nullptr: the
    /// system was solved as assembled).
    void project_ritz_stress(const ReissnerSystem &sys, const Eigen::MatrixXd *s_map);
    /// int_{S_t} t . Phi r ds of every displacement column Phi (the polynomial ones, u_r's
    /// then u_z's, and the enrichment's): the prescribed tractions' work, 2 N + n_e.
    Eigen::VectorXd columns_traction_work() const;
    /// The enrichment columns (the tail of q_s and q_u): every zone end's, then every
    /// vertex's.
    Eigen::Index n_enrichment_columns() const { return n_edge_columns() + n_vertex_columns(); }
    EdgeColumns enrichment_columns(const Eigen::Ref<const Eigen::VectorXd> &r,
                                   const Eigen::Ref<const Eigen::VectorXd> &z) const;
    /// The mode columns of the vertices with the section support, in the enrichment's order,
    /// then the columns of the jumps with it (jump_columns): the only enrichment columns that
    /// are nonzero beyond every disc.
    EdgeColumns section_mode_columns(const Eigen::Ref<const Eigen::VectorXd> &r,
                                     const Eigen::Ref<const Eigen::VectorXd> &z) const;
    /// Builds jumps_ (after vertices_); jump_rules_[i]: jump i has a near rule of its own
    /// (false where it shares a vertex enrichment's).
    void make_traction_jumps(const axisym::Problem &problem, const DiscretizationOptions &options);
    /// Builds resonances_ (after jumps_).
    void make_resonant_vertices(const axisym::Problem &problem, const DiscretizationOptions &options);
    /// Sums over the jumps (only >= 0: jump `only` alone) at points (zero beyond their
    /// supports): sigma = chi (S - s0) (the
    /// particular stress's change), u = chi u_D (the particular displacement's: no condition
    /// on u holds within the support) and its strain (fourth-order central differences with
    /// steps of 1e-3 times the distance to the vertex: truncation about 1e-12 and rounding
    /// about 1e-13 of the strain).
    FieldValues jump_fields(const Eigen::Ref<const Eigen::VectorXd> &r,
                            const Eigen::Ref<const Eigen::VectorXd> &z, int only = -1) const;
    /// Those columns at points; `on_section_only`: only the jumps with section support (the
    /// columns that live beyond every disc, after the modes in section_mode_columns).
    EdgeColumns jump_columns(const Eigen::Ref<const Eigen::VectorXd> &r,
                             const Eigen::Ref<const Eigen::VectorXd> &z, bool on_section_only = false) const;
    /// The jumps' terms of p_s and p_u: - int X . (C sigma_j - e(u_j)) and + int sigma_j . e(Phi)
    /// on the near rules.
    void add_jump_terms(ReissnerSystem &sys) const;
    /// Fields on the near rules beyond the polynomial part: enrichment columns or jumps.
    bool has_near_fields() const { return n_enrichment_columns() > 0 || !jumps_.empty(); }
    /// Builds vertices_ (after enrichments_) and grades the edge rule toward each vertex.
    void make_vertex_enrichments(const axisym::Problem &problem,
                                 const DiscretizationOptions &options, std::vector<int> &graded);
    /// Gives `vertex` (at the vertex between the edges `arriving` and `leaving` of the body's
    /// outline) the section support of its mode columns (VertexEnrichment::
    /// set_section_support) with the reach (VertexEnrichment::has_section_rule) when both
    /// faces are lines and the section is star-shaped about it, or, with `blended`, also
    /// otherwise without the reach (the disc's rule blended with one over the section);
    /// returns whether it did (false: the disc stays).
    bool set_section_support(VertexEnrichment &vertex, const axisym::Body &body, int arriving,
                             int leaving, bool blended = false);
    /// Builds enrichments_ and edges_; returns, per edge of the split body, which of its ends
    /// (bit 1 start, bit 2 end) is a zone end (the edge rule is graded there).
    std::vector<int> make_enrichments(const axisym::Problem &problem,
                                      const std::vector<DieZone> &zones,
                                      const DiscretizationOptions &options);

    std::vector<DieZone> zones_;
    LocalBasis local_; ///< the local boxes' columns after the global ones
    int local_stress_degree_ = -1; ///< of the stress-only local columns (-1: none)
    Eigen::Index n_local_stress_ = 0;
    Material material_;
    axisym::BodyLoads loads_; ///< body force in p_u and W, thermal strain in p_s and the functionals
    bool mirrored_ = false;   ///< integrals twice (the section and its image in z = 0)
    std::string axis_parity_obstacle_;
    /// The axis coupling: sigma_tt = sigma_rr + omega_tt P_tt with omega_tt = r (r^2 with
    /// the axis parity), on a section with an edge on the axis (assembly.h).
    bool hoop_coupled_ = false;
    /// The union of the near-edge rules' discs (the whole section when a vertex's rule
    /// covers it): where constitutive_error_map takes the near rules instead of the section's.
    std::vector<VertexEnrichment::Circle> near_discs_;
    bool near_covers_section_ = false;
    double axis_coupling_radius_ = 0.0; ///< where the enrichment columns' sigma_tt is coupled
    OutlineStructures structures_;
    /// With the axis coupling: the enrichment columns' sigma_tt += h (sigma_rr - sigma_tt)
    /// near the axis (the header).
    void couple_at_axis(EdgeColumns &e, const Eigen::Ref<const Eigen::VectorXd> &r) const;
    /// The structures' stress values, with the axis coupling applied to omega_tt, s0 and the
    /// boundary columns (their sigma_tt takes their sigma_rr).
    OutlineStressValues structure_stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                                         const Eigen::Ref<const Eigen::VectorXd> &z) const;
    /// The coordinate functions: the tensor Legendre polynomials of the box on a rectangle
    /// with sides along r and z (orthogonal there; their values cost no N x N transform; in
    /// r^2 with the axis parity) when no displacement component is reduced in degree, else the
    /// polynomials orthonormal on the section.
    std::variant<TensorLegendreBasis, SectionPolynomialBasis> basis_;
    /// The global and the local coordinate functions side by side.
    BasisValues basis_values(const Eigen::Ref<const Eigen::VectorXd> &r,
                             const Eigen::Ref<const Eigen::VectorXd> &z) const;
    Quadrature2D quadrature_;
    EdgeQuadrature edge_quadrature_;
    Eigen::VectorXd q_s_, q_u_;
    /// With rfm.ritz_bound: the Ritz solution's coefficients and P s_R's (stress_space_gap).
    Eigen::VectorXd ritz_q_, projected_q_s_;
    SolveSummary summary_;
    double assembly_s_ = 0.0, solve_s_ = 0.0, ritz_s_ = 0.0;
    std::array<Eigen::Index, 2> n_kept_{0, 0};
    std::array<Eigen::Index, 2> n_dropped_{0, 0};
    std::vector<EdgeEnrichment> enrichments_;
    /// Per enrichment: its zone, the end's s along the part, the direction into the zone
    /// (+1: increasing s) and the room around the end [m].
    struct ZoneEdge
    {
      DieZone zone;
      double s = 0, into = 1, room = 0;
    };
    std::vector<ZoneEdge> edges_;
    std::vector<VertexEnrichment> vertices_;
    std::vector<bool> rough_; ///< per vertices_: a rough vertex (make_vertex_enrichments)
    std::vector<TractionJump> jumps_;
    std::vector<ResonantVertex> resonances_;
    /// For each jump: its section support (make_traction_jumps), a vertex without modes or
    /// local columns whose factors and section rule the jump's field takes; none: the disc.
    std::vector<std::optional<VertexEnrichment>> jump_sections_;
    std::vector<bool> jump_rules_;
    bool jump_columns_ = true; ///< rfm.jump_column (n_jump_columns)
    Quadrature2D near_;      ///< the near-edge and near-vertex rules of all enrichments
    /// The first n_near_in_discs_ points of near_ lie in some rule's disc (all of them
    /// without a section rule); beyond them only section_mode_columns are nonzero.
    Eigen::Index n_near_in_discs_ = 0;
    Eigen::MatrixXd gram_e_; ///< Gram matrix of the enrichment's displacement columns
    /// With a vertex's section support: the Gram matrices of the polynomial displacement
    /// columns (u_r's, then u_z's) on the near rules, against themselves and against the
    /// enrichment's columns (values / l^2 and strains, as gram_e_), and the polynomial part
    /// of the kept vertex columns in the solve's basis.
    Eigen::MatrixXd gram_pp_, gram_pe_, vertex_projection_;
    /// A vertex's mode columns cover the section (VertexEnrichment::section_support).
    bool section_support() const
    {
      for (const VertexEnrichment &v : vertices_)
        if (v.section_support())
          return true;
      for (const std::optional<VertexEnrichment> &j : jump_sections_)
        if (j)
          return true;
      return false;
    }
  };

  /// Peak memory of one OutlineModel solve at options.degree [bytes], estimated before any
  /// allocation: the quadrature points (the body's rule, with the cells or triangles one zone's
  /// end adds per die part) times the basis size for the ~14 dense point-by-function matrices
  /// of assembly, the near-edge rules' ~20 matrices of all stress columns (two free ends per
  /// die part at most), and the saddle-point matrices with the transform's eigenvectors (R11,
  /// R12, their factors, the Schur complement), with the vertices' columns (vertex_columns_bound)
  /// in both spaces and their blocks of near points. Boundary columns are left out (a few per
  /// edge). (Before the vertices were counted, the stepped ring at p = 16 peaked at 0.51 GiB
  /// against 0.22 GiB estimated, issue 24's pressed hub at 0.84 against 0.42 GiB.)
  double estimate_memory_bytes(const axisym::Problem &problem, const DiscretizationOptions &options);
  /// An upper bound of OutlineModel::n_vertex_columns() at options (every singular, rough and
  /// notch vertex counted, with the most stress families a vertex can have), for the estimate.
  double vertex_columns_bound(const axisym::Problem &problem, const DiscretizationOptions &options);

  /// The local boxes of the zones (local_basis.h): per zone, with c its extent from the die's
  /// centre (the farther end), boxes of half size h_l = local_first_box c 2^l about the centre,
  /// t along the part (away from the section when the centre is at the part's end: one-sided
  /// boxes), n into the body, as long as h_l <= local_max_box times the extent of the
  /// section's box along t, at most local_levels of them (-1: no limit), with local_degree
  /// (LocalBasis::t_degree along t). Empty for sections that are not rectangles with sides
  /// along r and z.
  LocalBasis die_local_basis(const axisym::Problem &problem, const std::vector<DieZone> &zones,
                             const DiscretizationOptions &options);

  /// rfm.tolerance for an outline problem (degree_sequence.h).
  DegreeSequence<OutlineModel> solve_outline_to_tolerance(const axisym::Problem &problem,
                                                          const DiscretizationOptions &options,
                                                          double tolerance);
} // namespace rfm
