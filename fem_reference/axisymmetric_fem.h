// deal.II finite-element reference for the axisymmetric problems of DESIGN.md sections 4 and
// 7.1. Plain structs only (no deal.II headers), so drivers and tests compile fast; all deal.II
// code lives in the axisymmetric_fem*.cc units (axisymmetric_solver.h).
//
// Model (DESIGN.md sections 1 and 6): dim = 2 with x = r, y = z, one geometry path (DESIGN.md
// 8): every problem is the section given by an outline with a condition per part
// (problem.body). The hollow cylinder of the legacy form (problem.legacy_cylinder) is its
// half section r in [R1, R2], z in [0, a] as an outline (parts mid_plane: symmetry, outer,
// end, inner), mirrored (Body::mirrored: the section and its image in z = 0 are the body),
// its die a die on part `outer` (the paraboloid R = a^2 / (4 delta) centred at (R2, 0),
// which is u_r* = -delta (1 - 2 z^2/a^2) of paper eq. 4.1).
// Q_p x Q_p Lagrange elements, strain e(u) = (du_r/dr, du_z/dz, u_r/r, du_r/dz + du_z/dr),
// s = D e, bilinear form int e(v).D e(u) r dr dz, pressures as int t.v r ds.
//
//  * Mesh: the gmsh base mesh of fem_reference/outline_mesh.h (all quadrilaterals, base size
//    h0 = shortest edge / outline_cells_on_shortest_edge, boundary id = 1 + part index), then
//    L = refinements global refinements. Every boundary face carries the manifold of its
//    outline edge (PolarManifold about the center for an arc, flat for a line) and every cell
//    a TransfiniteInterpolationManifold, so new vertices land on the arcs and the interior
//    stays untangled; the mapping is MappingQ(p) (cached), so the curved boundary is
//    represented at the element degree and Q_p keeps its order (MappingQ1 on a polygon:
//    every cell is then the bilinear image of its vertices).
//  * Conditions per part: pressure (t = -p n with n the normal of the mapped face at each
//    quadrature point) and traction (t_r, t_z) as int t.v r ds; displacement (u_r, u_z),
//    axis (u_r = 0; sigma_rz = 0 is natural) and symmetry (u.n = 0 with n the normal of the
//    straight edge) as constraints on the boundary nodes: u_r = 0 or u_z = 0 when n is along
//    e_r or e_z, else the line n_r u_r + n_z u_z = 0 on the larger component. Where parts
//    meet, a node collects the conditions of all its faces (displacement before axis before
//    symmetry and a prescribed die zone); two independent ones fix both components. The hoop
//    strain u_r/r is formed at quadrature points only (never on r = 0); at r = 0 (samples, VTU
//    points) it is du_r/dr, its limit.
//  * Mirrored bodies: every integral reported (functionals, energies, forces, the L2 error
//    norms) is the whole body's, twice the section's; a sample at z < 0 is the mirror image
//    of (r, -z) (u_z and sigma_rz change sign); no support reactions (the mid-plane is no
//    support of the body).
//  * Functionals (J per radian) with s_h = D (e(u_h) - e_th):
//      lagrange = U_h - W(u_h), castigliano = -U_h + int_{S_u} (s_h n).u* r ds,
//      reissner = U_h - W(u_h) - int_{S_u} (s_h n).(u_h - u*) r ds,
//    S_u the displacement parts and the die zones (the prescribed zone, or the active points
//    of the penalty: there u.n = t, u* = t n); symmetry and axis parts add nothing (u*.n = 0
//    there and u_h.n = 0 exactly). s_h n is the element trace. For pure traction problems the
//    three are -U_h; with a prescribed zone and p >= 2 u_h = u* on S_u exactly, so reissner ==
//    lagrange. The penalty energy 1/2 kappa int_A g^2 r ds is reported apart (penalty_energy),
//    not in lagrange.
//  * Body loads (DESIGN.md 7.1; pointwise in fem_reference/body_loads.h): the body force
//    f = (density omega^2 r, -density g) enters as int f.v r dr dz, the thermal strain
//    e_th = alpha T (1, 1, 1, 0), T = T0 + T_r r + T_z z, as an initial strain:
//    int e(v).D e(u) r = int f.v r + int_St t.v r ds + int e(v).D e_th r. Every stress the
//    FEM reports (samples, VTU, error norms, element traces in the functionals) is the total
//    stress s_h = D (e(u_h) - e_th). With them the functionals are (per radian)
//      U_h        = 1/2 int (e(u_h) - e_th).D (e(u_h) - e_th) r dr dz   (strain_energy)
//      W(u_h)     = int f.u_h r dr dz + int_St t.u_h r ds               (external_work)
//      lagrange    = U_h - W(u_h)
//      castigliano = -U_h - int s_h.e_th r dr dz + int_{S_u} (s_h n).u* r ds
//      reissner    = U_h - W(u_h) - int_{S_u} (s_h n).(u_h - u*) r ds
//    (Reissner's int [s.e(u) - 1/2 s.C s - s.e_th] is U_h at s = s_h). All three equal the
//    potential energy at the exact solution; without body loads they are the formulas above.
//  * Reactions: the force each symmetry or displacement part exerts on the body (N, full
//    360 degree body), from the residual of the discrete equilibrium at the dofs it holds
//    (PartReaction), in the conforming basis (hanging nodes distributed to their masters).
//  * Dies (boundary.PART.die on a straight part; DESIGN.md 7.1; the legacy die), with the
//    outward normal n of the part and the target outward displacement u.n = g0(s) - delta (s
//    the distance from the die's centre along the part; no die surface beyond a flat
//    punch's edge). Every die part is its own contact set; several dies are solved together.
//    - contact.method "fixed" (bilateral): the zone is prescribed, [-c, c] about the centre
//      clipped to the part (c = contact.half_width; the whole part without it; the legacy
//      die: [0, c] from the mid-plane, one free end), u.n = g0 - delta strongly at the nodes
//      of its faces, traction free beyond. Each free end of the zone is made a mesh vertex
//      (the nearest boundary vertex of the part is moved onto it after the refinement below).
//      P = -2 pi R.n summed over the zone's constrained dofs (R the residual of the discrete
//      equilibrium: the consistent reaction, the legacy domain integral -2 pi int s_h.e(v) r
//      with v = (psi, 0) for the hollow cylinder); pressure = the trace -n.s_h n. A force-
//      controlled die cannot have a prescribed zone (InputError).
//    - "iterate" / "max-force" / none (unilateral): penalty at the face points of the part,
//      kappa int_A (u.n - t) v.n r ds over the active set A = {u.n - t > 0}; the active-set
//      (semi-smooth Newton) loop starts from the estimated or previous zone and stops when A
//      repeats its previous state. The contact points are the p + 1 Gauss-Lobatto points of
//      each face (the nodes of FE_Q(p) for p <= 2): a nodal, lumped penalty with one
//      constraint per node; more points over-constrain the trace (with p = 1 and 3 points
//      the active set never settles). kappa = penalty_factor * E / h_min, h_min the smallest
//      face on the die parts. The force on a die is the penalty reaction P = 2 pi int_A kappa
//      (u.n - g0 + delta) r ds (consistent: it is the residual of the discrete equilibrium
//      at the die's dofs). The zone is the interval of active points around the centre; each
//      free end c is bracketed by the last point with positive gap and the next one, and
//      located inside the bracket by the square-root law p^2 ~ (c - s) of a smooth contact
//      edge (half_width) or by linear interpolation of the gap (half_width_gap).
//      Force control (die.force = P): for a fixed active set the solution is affine in the
//      indentations, u = u_0 + sum_k delta_k u_k (one factorization, one solve per force-
//      controlled die), and the deltas that give the asked forces follow from a small linear
//      system at every active-set step: no outer iteration.
//    force_trace = -2 pi int (n.s_h n) r ds over the part in both modes.
//    Mesh (every problem): after the L global refinements, the cells at each singular
//    vertex of the outline are graded toward it (FemOptions::grade_toward_vertices), and
//    so are those at every traction jump (axisym::traction_jump_vertices, as lambda = 1) and
//    every resonant vertex (axisym::resonant_vertices, as lambda = 1).
//    Mesh (dies): after the L global refinements, the cells within half the zone's length of the
//    zone are refined until they are die_zone_cells * 2^L across the zone (unless the global
//    mesh already has at least half that density there), then the cells at each free end of
//    the zone die_edge_refinements times more (hanging nodes constrained). Unilateral: pass 0
//    refines around an estimate of the zone (indentation: where g0 < delta; force: Hertz's
//    radius, or the flat face), each edge-fitting pass around the zone of the previous pass;
//    with n passes in all, pass k runs on level max(0, L - (n-1-k)).
//  MPI (issue 25): when the process runs under MPI (fem_solve started by mpirun; MpiSession),
//    the same solver runs on a parallel::distributed::Triangulation (p4est): every rank
//    refines, assembles, evaluates and estimates its own cells into Trilinos matrices, and
//    sums, extrema, samples and contact points are combined over the ranks, so that every
//    rank holds the whole result. Linear solves: MUMPS (Amesos) up to
//    FemOptions::mpi_direct_max_dofs, CG with ML algebraic multigrid beyond (near-null space:
//    the constant modes of u_r and u_z). The active set is decided per contact point by the
//    rank that owns the point's face. A prescribed zone (contact.method = "fixed") moves mesh
//    vertices onto the zone's ends and is not distributed (InputError under MPI).
#pragma once

#include "problem/problem.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fem
{
  /// Options of the FEM reference that the problem file does not carry.
  struct FemOptions
  {
    int degree = 2;      ///< p of FE_Q(p); default from problem.fem.degree
    int refinements = 4; ///< mesh level L: L global refinements of the gmsh base mesh
    enum class LinearSolver
    {
      direct, ///< SparseDirectUMFPACK
      cg      ///< CG + SSOR(1.2), relative residual linear_tolerance
    } linear_solver = LinearSolver::direct;
    double linear_tolerance = 1e-12;
    /// Under MPI with LinearSolver::direct: systems up to this many dofs are factorized by
    /// MUMPS (through Trilinos Amesos), larger ones solved by CG with ML algebraic multigrid
    /// to linear_tolerance (100 times smaller with a die: the penalty force amplifies the
    /// algebraic error; LinearSolver::cg: always CG + AMG).
    long mpi_direct_max_dofs = 200000;
    /// kappa = penalty_factor * E / h_min. The force error is O(1/kappa): for the paper's die
    /// at L = 5, Q2, |P(1e3) - P(1e4)| = 0.2 N of 192.6 kN (fem_convergence penalty study).
    double penalty_factor = 1e3;
    int max_active_set_iterations = 50;
    int contact_points = 0; ///< Gauss-Lobatto points per die face; 0: p + 1 (nodal)
    /// Unilateral: after the active-set loop, remesh this many times refined around the zones
    /// found (axisymmetric_fem.h, "Dies"), and solve again.
    int edge_fitting_passes = 1;
    /// Dies on outline parts: cells across the contact zone (times 2^L), and the extra
    /// halvings of the cells at each free end of the zone (axisymmetric_fem.h, "Dies").
    int die_zone_cells = 4;
    int die_edge_refinements = 3;
    /// Grading toward every singular vertex of the outline (axisym::singular_vertices: an
    /// exponent with Re lambda < 1; problem/wedge_modes.h): after the global refinements the
    /// cells near the vertex are halved until their size is at most h_L (rho / rho_g)^(1 -
    /// lambda / p) at their distance rho from it (the radical mesh: each annulus then carries
    /// about the same share of the singular term's energy error, and the energy converges at
    /// the nominal order h^2p of a smooth field), down to the smallest cell h_min at the
    /// vertex with (h_min / l)^lambda = (h_L / l)^p (l the outline's size, h_L the level's
    /// nominal size, p the degree, rho_g = vertex_grading_radius l). The vertices where a
    /// traction jumps (axisym::traction_jump_vertices: a stress of degree 0 that depends on
    /// the direction, a rho log rho displacement) are graded as lambda = 1, and so are the
    /// resonant vertices (axisym::resonant_vertices: a rho log rho stress where a temperature
    /// gradient crosses a symmetry line at a right angle to a traction part). false: uniform.
    /// Measured (fem_reference/README.md, "Grading toward singular vertices"): before the
    /// radical law the cells within two diameters of the vertex were halved k times only, and
    /// a shell of cells of size h_L a few h_L from the vertex kept the singular term's error at
    /// h^(2 lambda): the energy's observed order per level was 1.17 on the stepped shaft and
    /// 1.52 on the stepped ring (3.50 and 3.70 now).
    bool grade_toward_vertices = true;
    /// rho_g / l of the radical grading above: the distance from a singular vertex, as a
    /// fraction of the outline's size, beyond which the cells keep the level's size.
    double vertex_grading_radius = 0.25;
    /// Adaptive refinement (issue 25 item 1; problem file "fem.refinement", fem_solve
    /// --adaptive): after the solve on the mesh of level `refinements` (without the grading
    /// toward vertices: the estimator finds them), cycles of: the Kelly estimate of each cell
    /// (the jumps of the displacement gradient across its faces, times sqrt(r) of its centre
    /// for the r-weighted energy), refinement of the cells that carry adaptive_fraction of the
    /// estimate's square (Doerfler marking), solve. It stops when the square of the estimate
    /// relative to the r-weighted gradient norm (a relative energy error) and the energy's
    /// relative change since the mesh had half the DoFs are both below adaptive_tolerance
    /// (Kelly's constant is not known: on the stepped ring the energy's error is 3 times the
    /// estimate's square, the change overestimates it 10 times), or when the next cycle would
    /// pass adaptive_max_dofs, or after adaptive_max_cycles. A die's zone is carried over from
    /// cycle to cycle (its active-set loop starts from it).
    bool adaptive = false;
    /// What the adaptive cycles refine for. `energy`: Kelly's estimate of the solution, the stop
    /// rule above. `samples` (fem.refinement.goal, --adaptive-goal): the stresses at the problem's
    /// samples that have a value (not those at a vertex where the stress has none,
    /// axisym::samples_with_a_value, which the cycles would chase without end; with none left
    /// check_supported rejects the problem), goal-oriented: the dual solution z of a(v, z) = J(v),
    /// with J the mean over the cell around each sample of sum_c s_c sigma_c(v) (s_c the sign of
    /// the current sigma_c there, over the largest sample stress; components below 1e-3 of it left
    /// out), solved with the factorized matrix; each cell's indicator is the product of the
    /// primal's and the dual's Kelly estimates (both times sqrt(r)). It stops when the sample
    /// stresses changed by less than adaptive_tolerance of the largest since the mesh had half the
    /// DoFs.
    enum class AdaptiveGoal
    {
      energy,
      samples
    } adaptive_goal = AdaptiveGoal::energy;
    double adaptive_tolerance = 1e-6;
    long adaptive_max_dofs = 1000000;
    double adaptive_fraction = 0.5;
    int adaptive_max_cycles = 100;
    /// Cells along the shortest outline edge in the base mesh (h0 = its length / this;
    /// outline_mesh.h).
    double outline_cells_on_shortest_edge = 4;
    /// How the arcs are represented. Only `curved` keeps the order of Q_p;
    /// the others exist to study the geometry error.
    enum class OutlineGeometry
    {
      curved,         ///< manifolds on the arcs, transfinite cells, MappingQ(p)
      straight_cells, ///< new vertices on the arcs (manifolds), straight-sided cells (MappingQ1)
      coarse_polygon  ///< no manifolds: refinement keeps the base mesh's chords (MappingQ1)
    } outline_geometry = OutlineGeometry::curved;
    std::string vtu_directory;  ///< write DIR/fem_solution.vtu when not empty
    bool progress = true;       ///< one line on stderr per active-set step

    /// Throws axisym::InputError naming the option, the value and the rule.
    void validate() const;
  };

  FemOptions options_from_problem(const axisym::Problem &problem);

  /// Throws axisym::InputError for what the FEM reference cannot solve: a force-controlled
  /// die with contact.method = "fixed" (a prescribed zone needs the indentation), and the
  /// hollow-cylinder form's die with an outer pressure (the outer side is the die's part).
  void check_supported(const axisym::Problem &problem, const FemOptions &options);

  struct Functionals
  {
    double lagrange = 0, castigliano = 0, reissner = 0; ///< J per radian
    double strain_energy = 0;  ///< U_h = 1/2 int (e - e_th).D (e - e_th) r, J per radian
    double external_work = 0;  ///< W(u_h) = body_force_work + int_St t.u_h r ds
    double body_force_work = 0;     ///< int f.u_h r dr dz (part of external_work)
    double thermal_strain_work = 0; ///< int s_h.e_th r dr dz (in castigliano)
    double penalty_energy = 0; ///< 1/2 kappa int_A g^2 r ds (full body, per radian)
  };

  struct ActiveSetStep
  {
    int pass = 0; ///< mesh pass (0: refined around the estimated zone, k: around pass k-1's)
    int iteration = 0;
    int n_active = 0, n_changed = 0; ///< active quadrature points, changes vs previous step
    double half_width = 0;           ///< c [m] from the gap of this step's solution
    double force = 0, force_trace = 0, force_penalty = 0; ///< [N]
    Functionals functionals;
  };

  struct PressurePoint
  {
    double s = 0; ///< distance from the die's centre along the part [m] (legacy: s = z)
    double r = 0; ///< the point [m]
    double z = 0;
    double p = 0;       ///< penalty traction kappa g_+ (unilateral) or the trace -n.s_h n
    double p_trace = 0; ///< the trace -n.s_h n
    double gap = 0;     ///< u.n - (g0 - delta) [m] (positive = penetration)
  };

  struct ContactResult
  {
    std::string part;         ///< the die's part ("outer" for the legacy die)
    std::string method;       ///< "fixed" (bilateral) or "iterate"/"max-force" (penalty)
    double indentation = 0;   ///< delta [m]: given, or found for the asked force
    /// A die on an outline part whose zone has two free ends: [s_start, s_end] [m] along the
    /// part from the centre (half_width is then half its length); a one-edge zone has none.
    std::optional<std::array<double, 2>> zone;
    bool unilateral = false;
    double half_width = 0;     ///< c [m] (unilateral: square-root law fit at the edge)
    double half_width_gap = 0; ///< c [m] from linear interpolation of the gap (unilateral)
    double force = 0, force_trace = 0, force_penalty = 0; ///< [N], full body
    double penalty = 0, penalty_factor = 0; ///< kappa [Pa/m] and its factor (unilateral)
    double h_min = 0;         ///< smallest face on the die parts [m]
    double max_penetration = 0; ///< max(gap)_+ [m]
    int active_set_iterations = 0; ///< of the last pass
    int edge_fitting_passes = 0;   ///< remeshes at the contact edge actually done
    std::vector<ActiveSetStep> iterations;
    std::vector<PressurePoint> pressure; ///< at the contact points of the part, sorted by s
  };

  /// The force a support part (symmetry or displacement) exerts on the body [N], full 360
  /// degree body: 2 pi times the residual of the discrete equilibrium summed over the dofs
  /// the part holds (a node shared with another support counts for the condition that fixes
  /// that component; the axis is no support). force_r is 2 pi int t_r r ds, as the contact
  /// force P.
  struct PartReaction
  {
    std::string part, condition; ///< "symmetry" or "displacement"
    double force_r = 0, force_z = 0;
  };

  struct FieldSample
  {
    double r = 0, z = 0, u_r = 0, u_z = 0;
    std::array<double, 4> sigma{}; ///< (rr, zz, tt, rz)
  };

  struct FemResult
  {
    bool success = false;
    std::string message;
    int degree = 0, refinements = 0;
    unsigned long n_dofs = 0, n_cells = 0;
    /// MPI ranks that shared the mesh (1 serial), the linear solver of the last solve
    /// ("umfpack", "cg-ssor", "mumps", "cg-amg") and its last iteration count (0: direct).
    unsigned int processes = 1;
    std::string linear_solver;
    unsigned int linear_iterations = 0;
    std::string mesh_generator;
    double base_mesh_size = 0;     ///< h0 [m]
    unsigned long n_base_cells = 0; ///< cells of the gmsh base mesh
    bool base_mesh_subdivided = false; ///< gmsh's all-quad fallback was used
    /// base cells with two boundary faces meeting where the outline is smooth (a
    /// 180 degree corner on the boundary, a singular Jacobian there) that remain after the
    /// generator's retries with more cells (fem_reference/README.md). 0 is the normal case.
    unsigned int base_mesh_flat_corners = 0;
    /// FemOptions::grade_toward_vertices: each singular vertex graded toward, as (r, z,
    /// lambda, extra halvings).
    std::vector<std::array<double, 4>> graded_vertices;
    /// FemOptions::adaptive: one record per solved mesh, the first on the starting mesh.
    struct AdaptiveCycle
    {
      unsigned long n_dofs = 0, n_cells = 0;
      double estimate = 0;        ///< Kelly, relative to the r-weighted gradient norm
      double reissner = 0;        ///< Phi_R [J/rad]
      double change = 0;          ///< |Phi_R - Phi_R at half the DoFs| / |Phi_R| (inf before)
      double force = 0;           ///< the first die's P [N] (0 without a die)
      std::vector<FieldSample> samples; ///< the fields at the problem's samples
      double seconds = 0;         ///< wall time of the cycle (refinement, assembly, solve)
    };
    std::vector<AdaptiveCycle> adaptive_cycles;
    std::string adaptive_stop; ///< why the cycles stopped
    Functionals functionals;
    std::optional<ContactResult> contact; ///< the first die
    std::vector<ContactResult> other_dies; ///< the second and later dies (outline parts)
    std::vector<FieldSample> samples;
    std::vector<PartReaction> reactions; ///< every support part (none for a mirrored body)
    /// r-weighted L2 norms over the full body (per radian), when an exact stress is given:
    /// ||s_h - s|| and ||s|| with the Frobenius norm of the stress tensor (sigma_rz counts
    /// twice, as in verification/lame_errors.h).
    std::optional<double> stress_l2_error, stress_l2_norm;
    /// max |s_h - s| and max |s| over the components and the Gauss-Lobatto points of
    /// every cell (p + 2 per direction, so cell and domain boundaries are included).
    std::optional<double> stress_max_error, stress_max_norm;
    /// r-weighted L2 norms ||u_h - u|| and ||u|| (per radian, as the stress norms), when an
    /// exact displacement is given.
    std::optional<double> displacement_l2_error, displacement_l2_norm;
    double assembly_seconds = 0, solve_seconds = 0, total_seconds = 0;
    /// Peak resident memory [bytes] of this process (rank 0 under MPI) and summed over the
    /// processes, at the end of the run (getrusage's maximum resident set size).
    double peak_memory_bytes = 0, peak_memory_bytes_all_processes = 0;
  };

  /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) at (r, z).
  using StressFunction = std::function<std::array<double, 4>(double r, double z)>;
  /// (u_r, u_z) at (r, z).
  using DisplacementFunction = std::function<std::array<double, 2>(double r, double z)>;

  /// MPI for fem_solve: initializes MPI (and deal.II's parallel libraries) for the lifetime
  /// of the object when the process was started by an MPI launcher (mpirun, mpiexec,
  /// srun: its environment variables), else does nothing, so that a plain run stays serial.
  class MpiSession
  {
  public:
    MpiSession(int &argc, char **&argv);
    ~MpiSession();
    MpiSession(const MpiSession &) = delete;
    MpiSession &operator=(const MpiSession &) = delete;
    /// Whether the environment is that of an MPI launcher.
    static bool launched_by_mpi();
    bool active() const { return active_; }
    unsigned int rank() const { return rank_; }
    unsigned int size() const { return size_; }

  private:
    struct State;
    std::unique_ptr<State> state_;
    bool active_ = false;
    unsigned int rank_ = 0, size_ = 1;
  };

  /// Solves the problem. Numerical failures (singular matrix, CG not converging, active-set
  /// cycle or no convergence) return success = false with a message and whatever history
  /// exists; bad options and unsupported problems (check_supported) throw axisym::InputError.
  FemResult solve(const axisym::Problem &problem, const FemOptions &options,
                  const StressFunction &exact_stress = {},
                  const DisplacementFunction &exact_displacement = {});

  /// A column of a convergence table.
  struct TableColumn
  {
    std::string name;
    std::vector<double> values;
    int precision = 4;
    bool scientific = true;
    bool rates = false; ///< append observed rates log2(e_{k-1}/e_k) (h halves per row)
  };

  /// The columns formatted as a deal.II ConvergenceTable (text).
  std::string format_convergence_table(const std::vector<TableColumn> &columns);
} // namespace fem
