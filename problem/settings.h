// Solver settings a problem file carries ("contact", "rfm", "fem" objects, DESIGN.md
// section 7), and the one table of their admissible ranges. The parser, the settings'
// validate() and the drivers' command-line checks all read the ranges from here, so a
// value is accepted or refused the same way wherever it comes from.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace axisym
{
  /// An integer setting: its JSON path, its closed range and why the range is what it is.
  struct IntRange
  {
    const char *field;
    int lo, hi;
    const char *reason = "";

    bool contains(long long x) const { return x >= lo && x <= hi; }
    /// "an integer in [lo, hi] (reason)"
    std::string rule() const;
    /// Throws InputError "<shown_as> = <x>: must be <rule>" unless contains(x).
    void check(long long x, const std::string &shown_as) const;
    void check(long long x) const { check(x, field); }
  };

  namespace ranges
  {
    inline constexpr IntRange rfm_degree{"rfm.degree", 0, 40, "N = (p + 1)^2 per component"};
    inline constexpr IntRange rfm_extra_gauss_points{"rfm.extra_gauss_points", 1, 40};
    inline constexpr IntRange rfm_n_cells_r{"rfm.n_cells_r", 1, 64};
    inline constexpr IntRange rfm_n_cells_z{"rfm.n_cells_z", 1, 64};
    inline constexpr IntRange rfm_n_graded_layers{"rfm.n_graded_layers", 0, 40};
    inline constexpr IntRange rfm_edge_modes{"rfm.edge_modes", 0, 4,
                                             "the odd modes 1, 3, ..., 2k - 1; 0 is off"};
    inline constexpr IntRange rfm_edge_extra_points{"rfm.edge_extra_points", 0, 40};
    inline constexpr IntRange rfm_edge_mode_degree{
      "rfm.edge_mode_degree", 0, 6, "each edge mode times the monomials of this total degree"};
    inline constexpr IntRange rfm_vertex_mode_degree{
      "rfm.vertex_mode_degree", 0, 6, "each vertex mode times the monomials of this total degree"};
    inline constexpr IntRange rfm_vertex_local_degree{
      "rfm.vertex_local_degree", -1, 24, "the vertex's smooth stress columns; -1: none"};
    inline constexpr IntRange rfm_vertex_local_displacement_degree{
      "rfm.vertex_local_displacement_degree", -1, 12,
      "the vertex's smooth displacement columns, at most rfm.vertex_local_degree; -1: none"};
    inline constexpr IntRange rfm_resonant_displacement_degree{
      "rfm.resonant_displacement_degree", -1, 4,
      "the resonant vertices' log displacement columns times the monomials of this total degree; -1: none"};
    inline constexpr IntRange rfm_local_levels{
      "rfm.local_levels", -1, 8, "-1: as many as the zone's size asks for; 0: none"};
    inline constexpr IntRange rfm_local_degree{
      "rfm.local_degree", -1, 12,
      "per direction, in each local box; -1: 9 about a zone with one free end, 7 with two"};
    inline constexpr IntRange rfm_local_stress_degree{
      "rfm.local_stress_degree", -1, 12,
      "per direction, the stress-only columns in each local box; -1: none"};
    inline constexpr IntRange fem_degree{"fem.degree", 1, 4, "FE_Q(p)"};
    inline constexpr IntRange fem_refinements{
      "fem.refinements", 0, 8,
      "each level has 4 times the cells of the last; beyond level 6 (about 1e6 dofs on a "
      "small section) run fem_solve under mpirun"};
    inline constexpr IntRange contact_curve_points{"contact.curve_points", 0, 200};
    inline constexpr IntRange rfm_max_degree{"rfm.max_degree", 2, 40,
                                             "the last p tried to reach rfm.tolerance"};
  } // namespace ranges

  /// Discretization of the R-function solver (the "rfm" object).
  struct RfmSettings
  {
    int degree = 8;             ///< p: N = (p + 1)^2 functions per unknown component
    /// How p is chosen. `degree_given`: the file (or --degree) fixes p = degree. Otherwise p
    /// rises (2, 4, 6, ...) until the a-posteriori indicator |Phi_L - Phi_C| / |Phi_R| falls
    /// below `tolerance` (default_tolerance when none is given), up to max_degree. A die
    /// problem without either uses p = degree: the indicator does not see the contact-edge
    /// error, which decides its accuracy (DESIGN.md 4.4).
    bool degree_given = false;
    std::optional<double> tolerance;
    int max_degree = 24;
    static constexpr double default_tolerance = 1e-8; ///< about 1e-4 in stress (Lame)
    static constexpr double min_tolerance = 1e-14;    ///< the indicator's rounding floor
    /// The polynomials' degree along z over the degree p along r (r^2 with the axis parity):
    /// p_z = round(z_degree_ratio p), N = (p + 1)(p_z + 1) per component. 1: the same degree
    /// both ways (the paper's N = (p + 1)^2). A long section resolves z with fewer functions
    /// per unit length than r: on the stepped shaft (box 0.05 m x 0.2 m) ratio 2 at p = 12
    /// (N = 325) gave the indicator 1.7e-6 and sigma_zz on the axis 0.40 % from the FEM's,
    /// ratio 1 at p = 20 (N = 441) 1.8e-6 and 3.5 %. Not on every section: issue 24's hub
    /// (0.65 m x 1.6 m) at (12, 20) came out 3.4e-6 against 1.1e-6 at (16, 16) (README).
    double z_degree_ratio = 1.0;
    static constexpr double min_z_degree_ratio = 0.25, max_z_degree_ratio = 4.0;
    static constexpr int max_degree_z = 48;
    int degree_z() const { return static_cast<int>(std::lround(z_degree_ratio * degree)); }
    /// The larger of the two degrees: what the rules and the structures are sized for.
    int largest_degree() const { return std::max(degree, degree_z()); }
    int extra_gauss_points = 4; ///< Gauss points per direction and cell = p + this
    int n_cells_r = 1;          ///< uniform cells in r before splitting at break points
    int n_cells_z = 1;          ///< uniform cells in z before splitting at break points
    int n_graded_layers = 8;    ///< geometric layers toward each break point
    double grading_ratio = 0.35; ///< width ratio between successive graded layers
    /// Contact-edge enrichment (rfm/spaces/edge_modes.h): the odd modes n = 1, 3, ..., 2 k - 1 for
    /// k = edge_modes, added to both the stress and the displacement space at every
    /// contact edge; 0 switches it off.
    int edge_modes = 2;
    /// Cutoff radius rho_0 as a fraction of the largest admissible one,
    /// min(c - z_min, z_max - c, r_max - r_min) (the support must not reach another side).
    double edge_cutoff = 0.9;
    /// Gauss points per direction of the near-edge rule = p + extra_gauss_points + this.
    int edge_extra_points = 6;
    /// Each edge mode is multiplied by the monomials of the scaled offsets from the edge up
    /// to this total degree ((d + 1)(d + 2)/2 columns per mode; 0: the modes alone). 4 since
    /// session 14: with 2 the edge intensity K carried a bias of about -1e4 Pa m^1/2 at the
    /// true zone, and the searches' zones came out about 2e-4 too long. At the Hertz zone of
    /// the closed form (hertz_paraboloid_force.json, p = 8) K was -10240, -9454, -866, -853,
    /// -568 at degree 2 to 6; the Hertz search's radius +1.9e-4 -> +1.3e-6 from Hertz's, the
    /// rounded punch's +2.1e-4 -> +1.7e-5 from the FEM's, at no more time.
    int edge_mode_degree = 4;
    /// Vertex enrichment (rfm/spaces/vertex_enrichment.h): at every vertex between two
    /// straight parts, or traction parts of which one or both are arcs, where the field is singular (an exponent with Re lambda < 1), the
    /// wedge's modes with Re lambda < vertex_max_exponent (0: off), each times the monomials
    /// of the scaled offsets up to vertex_mode_degree, cut off at vertex_cutoff times the
    /// room around the vertex (degree 4 at least where the modes cover the section:
    /// vertex_support). The same cutoff places the loaded wedge's field at a traction
    /// jump (rfm/spaces/traction_jump.h). 0 switches both off.
    double vertex_max_exponent = 3.0;
    int vertex_mode_degree = 1;
    double vertex_cutoff = 1.0;
    /// The vertex's smooth stress columns: the cutoff times the monomials up to the degree
    /// floor(vertex_local_degree_ratio p), but at least vertex_local_displacement_degree and
    /// at most this, times the tensors that meet both faces' conditions (-1: none, and no
    /// smooth displacement columns either). vertex_local_stress_degree() says which.
    int vertex_local_degree = 8;
    /// The local stress columns' degree over p (above). 0.5 by default. Within a vertex's disc
    /// the polynomials times the structures cannot carry the smooth part of the field (the
    /// omegas are not smooth at the vertex), so these columns are all the stress space has
    /// there, and a disc as wide as the room around its vertex needs them of about the
    /// polynomials' degree: with 1 (and vertex_local_degree 24) the stepped ring's indicator
    /// at p = 16 fell from 1.5e-8 to 3.5e-9, issue 24's heated hub's from 1.0e-6 to 3.1e-7
    /// and its sample at (0.8, 0) from -0.82 % to -0.22 % off the FEM's, at 1.9 and 2.9 times
    /// the time (README, 'The vertex's local degree').
    double vertex_local_degree_ratio = 0.5;
    static constexpr double min_vertex_local_degree_ratio = 0.25, max_vertex_local_degree_ratio = 1.5;
    /// The local stress columns' degree at p (above), -1 where there are none.
    int vertex_local_stress_degree() const
    {
      if (vertex_local_degree < 0)
        return -1;
      const int grown = static_cast<int>(std::floor(vertex_local_degree_ratio * degree + 1e-9));
      const int least = std::min(vertex_local_displacement_degree, vertex_local_degree);
      return std::min(vertex_local_degree, std::max(least, grown));
    }
    /// The vertex's smooth displacement columns: the cutoff times the monomials up to this
    /// degree (at most vertex_local_degree) times the vectors that meet the faces' kinematic
    /// conditions (-1: none). Lower than the stress columns' degree on purpose: in the
    /// mixed principle the stress space must see the strains of the displacement space
    /// (vertex_enrichment.h). Indicator at p = 16, both at 4 / stresses at 8 and
    /// displacements at 4 / both at 8: the stepped ring 8.7e-6 / 1.6e-6 / 2.4e-6; the same
    /// ring moved to r = 10 m under an end traction 5.4e-5 / 1.5e-6 / 2.2e-5.
    int vertex_local_displacement_degree = 4;
    /// Resonant vertices (rfm/spaces/resonant_vertex.h: a symmetry line at a right angle to a
    /// traction part, a temperature gradient across the line): the log field's
    /// stress columns times the monomials up to the degree p / 4 within [1, 4], and its
    /// displacement columns times those up to this degree (at most the stresses'; -1: none).
    /// None by default: they restore exponential convergence where the rest of the section
    /// converges (a heated ring on a symmetry plane, indicator at p = 16 / 20: 1.3e-7 / 2.7e-8
    /// without the vertex's columns, 6.4e-8 / 1.2e-8 with the stress columns, 8.4e-9 /
    /// 4.6e-10 with displacement columns of degree 4 too), but where other vertices limit the
    /// section they gain nothing (issue 24's heated hub at p = 16, session 66: indicator 1.01e-6
    /// without, 1.05e-6 with displacement columns of degree 2, sigma_zz at the vertex -476.54 /
    /// -476.75 MPa against the FEM's -472.64; before session 51's arc modes 1.06e-4 / 1.61e-4).
    int resonant_displacement_degree = -1;
    /// Where a vertex's mode columns live (rfm/spaces/vertex_enrichment.h:
    /// set_section_support): `section` (default) on the whole section at a re-entrant vertex
    /// (interior angle above 180 degrees) about which the section is star-shaped, in a
    /// problem without a die, times factors that keep the other edges' conditions; elsewhere,
    /// and always with `local`, in the disc of the cutoff. Measured against the FEM's limit
    /// at p = 16, disc -> section: the stepped shaft's Phi_R 2.6e-5 -> 3.3e-6 and its
    /// indicator 2.5e-4 -> 1.3e-5; the stepped ring's indicator 1.6e-6 -> 3.5e-7. There the
    /// modes' multipliers take at least degree 4 (vertex_mode_degree is raised to it).
    /// `section` also puts a traction jump's field between two lines on the whole section
    /// (OutlineModel::traction_jumps): the pressure band's indicator at p = 16 1.94e-5 -> 2.5e-7.
    /// `blended` (the default since session 82): as `section`, and also at the re-entrant
    /// vertices that keep their disc there (the section not star-shaped about the vertex, or
    /// an arc face), with the columns integrated on the disc's rule blended with a rule over
    /// the section (rfm/outline_model.cc). Every singular vertex with Re lambda < 1 then takes
    /// the inner disc (OutlineModel::inner_disc_max_exponent otherwise). Only sections with
    /// such a vertex differ from `section` (of the verification problems, issue 24's two
    /// hubs), and there it costs four to seven times the time at the same p. On issue 24's
    /// heated hub (both re-entrant vertices so), section -> blended at p = 12 / 16 / 20:
    /// indicator 9.7e-6 / 8.7e-7 / 4.3e-7 -> 2.9e-7 / 1.4e-7 / 1.2e-7, sigma_zz at (0.8, 0)
    /// +0.15 / -0.68 / -0.28 % -> -0.41 / -0.11 / -0.05 % from the FEM's; with rough vertices
    /// everywhere (below, also the default) 9.8e-8 / 1.56e-8 / 8.3e-9, so that without
    /// --degree it reaches the default tolerance at p = 20 (with `section` it exits 3).
    enum class VertexSupport
    {
      local,
      section,
      blended
    };
    VertexSupport vertex_support = VertexSupport::blended;
    /// Axis parity (rfm/outline_model.h, issue 24 item 5): on a rectangular section on the
    /// axis, coordinate functions in (r^2, z) and structures even in r, so that values on the
    /// axis converge like the rest. Used where OutlineModel::axis_parity_obstacle finds
    /// nothing against it; false: never (the plain polynomials in r, as before).
    bool axis_parity = true;
    /// Axis coupling (rfm/outline_model.h, issue 24 item 5): on a section with an edge on the
    /// axis, sigma_tt = sigma_rr + (r / l) P_tt ((r / l)^2 with the axis parity) instead of a
    /// free P_tt, so that sigma_rr = sigma_tt on r = 0 for every coefficient, as the smooth
    /// fields of a body of revolution have it (the r-weighted functionals do not ask for it).
    /// The enrichment columns' sigma_tt takes their sigma_rr near the axis. Not with the die's
    /// local stress columns (rectangles with a die). Off by default: the smaller stress space
    /// costs the stepped shaft a fifth more energy error (Phi_R at p = 16 8.6e-7 -> 1.03e-6
    /// from the FEM's limit) and leaves its axis values as far off (the header of
    /// outline_model.h has the numbers), while the dies on the axis gain (report 7.1: the Hertz
    /// pressure 0.48 % -> 0.40 % off, its indicator 1.3e-3 -> 5.0e-4).
    bool axis_coupling = false;
    /// Local resolution at notch roots (problem/wedge_modes.h: notch_roots; issue 24 item
    /// 3): the vertex's smooth local columns (vertex_local_degree,
    /// vertex_local_displacement_degree) in a disc about every root of a concave arc of radius
    /// below a quarter of the section's size where it meets a symmetry line, without modes.
    /// Measured at p = 16 (indicator without -> with): the sharp-lipped grooved shaft
    /// 5.4e-3 -> 1.7e-5, the filleted groove 3.4e-6 -> 4.5e-7. Not at larger arcs: on the
    /// thick sphere (its inner arc's radius 0.35 of the section's size) the same columns took
    /// the indicator at p = 12 from 7e-10 to 1e-6 (their displacement columns; without them
    /// 5e-10), and the hubs of issue 24 (0.46) gained less than they cost.
    bool notch_roots = true;
    /// Rough vertices where a traction jumps (problem/wedge_modes.h: rough_vertices; issue
    /// 24 items 3 and 4): where the stress is bounded but its gradient is not (a non-integer
    /// exponent with 1 < Re lambda < 2) and the prescribed traction jumps, as where issue 24's
    /// hub's inner-arc pressure ends at its bore (133 degrees, lambda = 1.905 +- 0.388 i), the
    /// vertex's modes and smooth local columns as at a singular vertex, in a disc clear of the
    /// other vertices' discs; the jump's field takes the same disc, and the polynomials'
    /// products are taken on the disc's rule there too. Indicator of that hub at p = 8 / 12 /
    /// 16 / 20: 2.0e-3 / 2.8e-4 / 4.0e-5 / 1.2e-5 without, 4.9e-5 / 6.4e-6 / 1.1e-6 / 5.3e-7
    /// with them, falling at every even p. false: none (as before).
    bool rough_vertices = true;
    /// With rough_vertices, at every rough vertex, with or without a jump (JSON
    /// `"rough_vertices": "all"`, the default since session 82; `true`: where a traction
    /// jumps only). On issue 24's heated hub (its 133-degree vertex at the bore, free, no
    /// jump) they bought little with the vertices' discs (the comment in
    /// rfm/outline_model.cc: make_vertex_enrichments); with vertex_support `blended`, where
    /// that vertex then held most of the constitutive-relation error, the indicator at p = 12
    /// / 16 / 20 went 2.9e-7 / 1.4e-7 / 1.2e-7 -> 9.8e-8 / 1.56e-8 / 8.3e-9 (below the
    /// default tolerance). Of the verification problems only the two hubs have a rough
    /// vertex without a jump.
    bool rough_vertices_everywhere = true;
    /// The hoop shadow at singular vertices (rfm/spaces/wedge_shadow.h): each vertex mode's
    /// first axisymmetric correction rho^(lambda + 1) V(theta), from the hoop terms of the
    /// equations and the curvature of arc faces, as one more column per mode; its angular
    /// function solves the wedge's inhomogeneous problem (Chebyshev collocation). Not at rough
    /// vertices, nor where lambda + 1 lies within 0.1 of another exponent, nor at a re-entrant
    /// vertex between lines that keeps its disc (OutlineModel; README). Indicator at p = 16
    /// without -> with: the clamped cylinder 3.2e-9 -> 9.6e-10, the stepped ring 6.6e-8 ->
    /// 4.9e-8, the stepped shaft 4.4e-6 -> 3.6e-6.
    bool vertex_shadow = true;
    /// The traction jumps' fields as columns too (rfm/outline_model.h: n_jump_columns): each
    /// jump's particular field, fixed in the solution, also as one column with a free
    /// coefficient, so that the displacement space holds the direction of its displacement
    /// and the stress is in equilibrium against all of u_h; Phi_L - Phi_C is then the
    /// constitutive-relation error E (diagnostics.constitutive_error.gap_minus_error zero to
    /// rounding) and the indicator a measure of the error. Indicator at p = 8 / 12 / 16
    /// without -> with: the pressure band 3.5e-5 / 2.0e-6 / 1.9e-7 -> 1.5e-6 / 3.8e-8 /
    /// 3.9e-9 (E 1.6e-6 / 3.9e-8 / 3.9e-9 before: the indicator was the work defect); issue
    /// 24's pressed hub at p = 12 / 16 1.7e-6 / 8.0e-8 -> 7.3e-7 / 1.1e-7 (E 7.1e-7 / 1.1e-7
    /// before; at 16 Phi_L had come within 8e-8 of Phi_C by a defect of -3.2e-8). false: the
    /// fixed field alone (as before).
    bool jump_column = true;
    /// A second, concentric disc of stress columns at each singular vertex, of a fifth of the
    /// cutoff's radius and the local stress columns' degree (rfm/spaces/vertex_enrichment.h:
    /// set_inner_disc). Not at notch roots nor rough vertices. false: one disc (as before).
    bool vertex_inner_disc = true;
    /// A vertex whose faces include an arc and a rough vertex with curved faces where a
    /// traction jumps (issue 24's hub: its 186-degree vertex between the outer arc and the
    /// taper, 0.54 m from the 133-degree vertex where the inner arc's pressure ends) each take
    /// their whole room, and their discs may overlap: the two polar rules break at each
    /// other's rims, with twice the points where the rings cross them
    /// (OutlineModel::make_vertices). false:
    /// the discs are kept apart, the arc's vertex taking at least a quarter of the distance
    /// and the jump the rest (as before).
    bool vertex_disc_overlap = true;
    /// The displacement space's own upper bound of Phi beside Phi_L(u_h)
    /// (OutlineModel::ritz_lagrange; rfm_solve's functionals.lagrange_ritz and
    /// indicator_ritz): a displacement-only Ritz solve on the columns of u_h after the mixed
    /// one. Off by default: it costs about half an assembly (the stepped shaft at p = 16:
    /// 1.9 s beside 3.4 s).
    bool ritz_bound = false;
    /// Local resolution near a die's zone (rfm/spaces/local_basis.h): nested boxes of half sizes
    /// local_first_box c, twice that, ... up to local_max_box times the section's extent
    /// along the die's part (c the zone's extent from its centre), each with the tensor
    /// Legendre polynomials of degree local_degree times a cutoff (2 local_degree + 1 along
    /// the part in a box about a zone with two free ends, local_basis.h). -1: as many boxes
    /// as fit (none when the zone is comparable to the section, as the paper's die); 0: none;
    /// k > 0: at most k.
    int local_levels = -1;
    /// -1 (the default): 9 when every box is one-sided (a zone with one free end: measured at
    /// the finest FEM's zone of the rounded flat punch, P -1.6e-5 from the FEM's in 4.4 s,
    /// against -3.5e-3 in 1.9 s with degree 5 and the stress-only columns of degree 5, and
    /// -9.7e-5 in 15.5 s with both 9), 8 when a box is two-sided (2 d + 1 = 17 along the part).
    /// The ring die's search (ring_die_shaft.json, edge_mode_degree 4; session 14), c at both
    /// ends from the FEM's and P: degree 7 +0.087 %, -1.5e-4 in about 200 s and 2.4 GB; 8
    /// +0.041 %, -6.9e-5 in 365 s and 3.4 GB; 9 (edge_mode_degree 2) +0.028 %, -5e-5 in 647 s
    /// and 4.8 GB. (With edge_mode_degree 2, degree 7 gave +0.21 %.)
    int local_degree = -1;
    /// The degree local_degree stands for (two_sided: some die's zone has two free ends).
    int resolved_local_degree(const bool two_sided) const
    {
      return local_degree >= 0 ? local_degree : two_sided ? 8 : 9;
    }
    /// The stress-only local columns (outline_model.h): in each box, per stress component,
    /// the tensor Legendre polynomials of this degree on the box, without the cutoff (-1: none,
    /// the default since session 13: at local degree 9 they moved the rounded punch's P from
    /// -1.6e-5 to -9.7e-5 of the FEM's and took 3.5 times as long, and at 7 the ring die's from
    /// -9.4e-5 to -1.4e-4 in twice the time and 2.7 times the memory; they lower the indicator,
    /// 0.18 -> 0.004 on the rounded punch, by matching the displacement columns' strains, not
    /// the force. With degree 5 they were needed: P -4.6e-4 with them, -6.6e-4 without).
    int local_stress_degree = -1;
    double local_first_box = 2.0;
    double local_max_box = 0.6;

    /// Throws InputError naming the field, the value and the rule.
    void validate() const;
  };

  /// The FEM reference's settings that a problem file carries (the "fem" object).
  struct FemSettings
  {
    int degree = 2;
    int refinements = 4;
    /// "fem.refinement": {"strategy": "adaptive", "tolerance": t, "max_dofs": n} (issue 25):
    /// from the mesh of level `refinements`, cycles of Kelly-estimated refinement until the
    /// estimate or the energy's change between cycles is below t (relative) or the next
    /// cycle would pass n DoFs. "uniform" (the default): the L global refinements alone.
    bool adaptive = false;
    double adaptive_tolerance = 1e-6;
    long adaptive_max_dofs = 1000000;
    /// "goal": "energy" (default) or "samples" (refine for the stresses at the samples).
    bool adaptive_goal_samples = false;
  };

  /// The "contact" object of a die problem.
  struct ContactSettings
  {
    /// "edge-intensity" (default: the root of K(c)), "fixed", "iterate" or "max-force"
    std::string method = "edge-intensity";
    std::optional<double> half_width; ///< c [m] for "fixed"; default a
    int curve_points = 0;             ///< extension: sample P(c) at this many c in (0, a]
  };
} // namespace axisym
