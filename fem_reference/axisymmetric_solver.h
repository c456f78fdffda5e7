// The FEM reference's solver class and its pointwise helpers, shared by the translation units
// of fem_reference/ that hold its parts (DESIGN.md 8: mesh, constraints, assembly, active set,
// post-processing). Internal to fem_reference/: the public interface is axisymmetric_fem.h,
// whose comment states the model. deal.II headers compile slowly (about 12 s a unit), so only
// the axisymmetric_fem*.cc units include this.
//
//   axisymmetric_fem.cc                 options, fem::solve, the passes and the active-set loop
//   axisymmetric_fem_mesh.cc            1. the outline mesh and the refinement toward dies
//   axisymmetric_fem_constraints.cc     2. dofs and constraints
//   axisymmetric_fem_assembly.cc        3.-5. assembly, linear solves, penalty, force control,
//                                       the active set
//   axisymmetric_fem_postprocessing.cc  6. functionals, forces, zones, samples, reactions, VTU
#pragma once

#include "fem_reference/axisymmetric_fem.h"

#include "fem_reference/body_loads.h"
#include "fem_reference/outline_mesh.h"

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <functional>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace fem::internal
{
  using namespace dealii;

  constexpr double pi = 3.14159265358979323846;
  using Clock = std::chrono::steady_clock;
  inline double seconds_since(Clock::time_point t0)
  {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  /// Lets `write(path)` write a gmsh .msh file to a temporary path and reads it into
  /// `triangulation`; the file is removed in every case.
  template <typename Write>
  inline void read_through_msh_file(Triangulation<2> &triangulation, const std::string &prefix,
                             Write write)
  {
    static std::atomic<int> counter{0};
    const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      (prefix + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".msh");
    try
      {
        write(path.string());
        GridIn<2> grid_in;
        grid_in.attach_triangulation(triangulation);
        std::ifstream in(path);
        grid_in.read_msh(in);
      }
    catch (...)
      {
        std::filesystem::remove(path);
        throw;
      }
    std::filesystem::remove(path);
  }

  using Stress = std::array<double, 4>; // (rr, zz, tt, rz); strains in the same order

  /// e(u) = (du_r/dr, du_z/dz, u_r/r, du_r/dz + du_z/dr) from u and grad u (grad[i][j] =
  /// du_i/dx_j, x = (r, z)).
  inline Stress strain(double r, double u_r, const Tensor<1, 2> &grad_u_r, const Tensor<1, 2> &grad_u_z)
  {
    // On the axis (r = 0: samples, VTU and Gauss-Lobatto points, never a Gauss point)
    // u_r/r -> du_r/dr. A mapped point on the axis can come out at r ~ 1e-19 with u_r = 0
    // exactly, which would give e_tt = 0 instead of the limit: below 1e-13 m is the axis.
    return {{grad_u_r[0], grad_u_z[1], r > 1e-13 ? u_r / r : grad_u_r[0],
             grad_u_r[1] + grad_u_z[0]}};
  }

  /// Strain of the shape function whose only non-zero component is `component`.
  inline Stress shape_strain(unsigned int component, double r, double phi, const Tensor<1, 2> &grad)
  {
    if (component == 0)
      return {{grad[0], 0.0, phi / r, grad[1]}};
    return {{0.0, grad[1], 0.0, grad[0]}};
  }

  struct Stiffness
  {
    std::array<std::array<double, 4>, 4> d{};
    explicit Stiffness(const axisym::Material &m)
    {
      const Eigen::Matrix4d dm = m.stiffness();
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          d[i][j] = dm(i, j);
    }
    Stress operator*(const Stress &e) const
    {
      Stress s{};
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          s[i] += d[i][j] * e[j];
      return s;
    }
  };

  inline double dot(const Stress &a, const Stress &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  }

  /// The elastic part e(u) - e_th of the strain e at (r, z); e itself without a thermal load.
  inline Stress elastic_strain(const BodyLoadField &loads, double r, double z, const Stress &e)
  {
    if (!loads.has_thermal_strain())
      return e;
    const double e_th = loads.thermal_strain(r, z);
    return {{e[0] - e_th, e[1] - e_th, e[2] - e_th, e[3]}};
  }

  /// The total stress D (e - e_th) that every output reports (DESIGN.md 7.1).
  inline Stress total_stress(const Stiffness &d, const BodyLoadField &loads, double r, double z,
                      const Stress &e)
  {
    return d * elastic_strain(loads, r, z, e);
  }

  /// u and the four stresses for DataOut (x = r is taken from the evaluation points).
  class StressPostprocessor : public DataPostprocessor<2>
  {
  public:
    StressPostprocessor(const Stiffness &d, const BodyLoadField &loads)
      : d_(d), loads_(loads)
    {}
    void evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &in,
                               std::vector<Vector<double>> &out) const override
    {
      for (unsigned int q = 0; q < in.solution_values.size(); ++q)
        {
          const Point<2> &x = in.evaluation_points[q];
          const Stress s =
            total_stress(d_, loads_, x[0], x[1],
                         strain(x[0], in.solution_values[q][0], in.solution_gradients[q][0],
                                in.solution_gradients[q][1]));
          out[q][0] = in.solution_values[q][0];
          out[q][1] = in.solution_values[q][1];
          for (unsigned int k = 0; k < 4; ++k)
            out[q][2 + k] = s[k];
          out[q][6] = in.solution_values[q][0];
          out[q][7] = in.solution_values[q][1];
        }
    }
    // The displacement once more as one vector (x = r, y = z) for ParaView's Warp By Vector.
    std::vector<std::string> get_names() const override
    {
      return {"u_r",      "u_z",      "sigma_rr",     "sigma_zz",
              "sigma_tt", "sigma_rz", "displacement", "displacement"};
    }
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override
    {
      std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
        6, DataComponentInterpretation::component_is_scalar);
      kinds.resize(8, DataComponentInterpretation::component_is_part_of_vector);
      return kinds;
    }
    UpdateFlags get_needed_update_flags() const override
    {
      return update_values | update_gradients | update_quadrature_points;
    }

  private:
    Stiffness d_;
    BodyLoadField loads_;
  };

  /// Everything computed from one solution (one active-set step).
  /// One die on an outline part, from one solution.
  struct DieEvaluation
  {
    double indentation = 0, force = 0, force_trace = 0;
    double half_width = 0, half_width_gap = 0; ///< one-edge zone: centre to free end [m]
    double zone_lo = 0, zone_hi = 0;           ///< the zone along the part [m]
    bool two_edges = false;
    double max_penetration = 0;
    std::vector<PressurePoint> pressure;
  };

  /// The end of a contact zone that starts at s = 0 and runs toward s > 0, from the gap g at
  /// the contact points (s, g) sorted by s: after the last positive sample (sign noise of
  /// g ~ p / kappa inside the zone is ignored), (a) by linear interpolation of g and (b) by
  /// the square-root law of a smooth contact edge, p ~ sqrt(c - s) (DESIGN.md 4.3): p^2 of
  /// the last two samples with positive pressure extrapolated linearly to zero, kept inside
  /// the bracket [last positive, first non-positive]. Returns (b, a); s_end when the zone
  /// reaches the last sample, 0 when even the first sample is open.
  inline std::pair<double, double> zone_end(const std::vector<std::pair<double, double>> &samples,
                                     const double s_end)
  {
    double c = s_end, c_gap = s_end;
    if (samples.empty())
      return {c, c_gap};
    if (samples.front().second <= 0)
      c = c_gap = 0;
    for (std::size_t i = samples.size() - 1; i > 0; --i)
      if (samples[i - 1].second > 0 && samples[i].second <= 0)
        {
          const auto [z0, g0] = samples[i - 1];
          const auto [z1, g1] = samples[i];
          c_gap = z0 + g0 * (z1 - z0) / (g0 - g1);
          c = c_gap;
          std::size_t k = i - 1; // previous positive sample at a distinct s
          while (k > 0 && samples[k - 1].first >= z0)
            --k;
          if (k > 0 && samples[k - 1].second > g0)
            {
              const auto [zm, gm] = samples[k - 1];
              c = std::clamp(z0 + g0 * g0 * (z0 - zm) / (gm * gm - g0 * g0), z0, z1);
            }
          break;
        }
    return {c, c_gap};
  }

  struct Evaluation
  {
    Functionals functionals;
    double force = 0, force_trace = 0, force_penalty = 0, half_width = 0, half_width_gap = 0;
    double max_penetration = 0;
    std::vector<PressurePoint> pressure;
    std::vector<DieEvaluation> dies;
    std::optional<double> error_sq, norm_sq;
    std::optional<double> error_max, norm_max;
    std::optional<double> u_error_sq, u_norm_sq;
  };

  /// The solver of every problem: the section's outline (the hollow-cylinder form is its half
  /// section, Body::mirrored), its conditions per part and its dies.
  class AxisymmetricSolver
  {
  public:
    AxisymmetricSolver(const axisym::Problem &problem, const FemOptions &options,
                       const StressFunction &exact, const DisplacementFunction &exact_u)
      : problem_(problem)
      , body_(*problem.body)
      , options_(options)
      , exact_(exact)
      , exact_u_(exact_u)
      , mirror_(problem.body->mirrored ? 2.0 : 1.0)
      , distributed_(Utilities::MPI::job_supports_mpi())
      , comm_(MPI_COMM_WORLD)
      , root_(!distributed_ || Utilities::MPI::this_mpi_process(comm_) == 0)
      , triangulation_holder_(
          distributed_ ? std::unique_ptr<Triangulation<2>>(
                           std::make_unique<parallel::distributed::Triangulation<2>>(comm_))
                       : std::make_unique<Triangulation<2>>())
      , triangulation_(*triangulation_holder_)
      , fe_(FE_Q<2>(options.degree), 2)
      , dof_handler_(triangulation_)
      , d_(problem.material)
      , loads_(problem)
      , cell_quadrature_(options.degree + 2)
      , face_quadrature_(options.contact_points > 0 ? options.contact_points
                                                    : options.degree + 1)
    {
      const bool fixed = problem.contact.method == "fixed";
      for (const std::string &part : body_.die_parts())
        {
          OutlineDie d;
          d.part = part;
          d.boundary_id = boundary_id_of_part(body_.outline, part);
          d.frame = axisym::die_frame(body_, part);
          d.condition = body_.conditions.at(part).die;
          d.delta = d.condition.indentation.value_or(0.0);
          dies_.push_back(d);
          mode_ = fixed ? Mode::bilateral : Mode::unilateral;
        }
      if (mode_ == Mode::bilateral)
        fix_die_zones();
      else if (!dies_.empty())
        estimate_die_zones();
    }

    FemResult run();

  private:
    /// A die on an outline part: its frame, condition and current state.
    struct OutlineDie
    {
      std::string part;
      types::boundary_id boundary_id = 0;
      axisym::DieFrame frame;
      axisym::DieCondition condition;
      double delta = 0;           ///< the indentation: given, or found for the force
      /// The zone [m along the part]: the one the mesh resolves (unilateral), or the
      /// prescribed one (bilateral, contact.method = "fixed").
      double zone_lo = 0, zone_hi = 0;
    };
    /// One boundary face on a die's part.
    struct ContactFace
    {
      DoFHandler<2>::active_cell_iterator cell;
      unsigned int face = 0, die = 0;
    };
    /// The die's outward normal (that of its straight part).
    Tensor<1, 2> die_normal(unsigned int die) const
    {
      Tensor<1, 2> n;
      n[0] = dies_[die].frame.normal.r, n[1] = dies_[die].frame.normal.z;
      return n;
    }
    /// The target outward displacement u.n at x (+infinity where there is no die surface:
    /// beyond a flat punch's edge).
    double die_target(unsigned int die, const Point<2> &x) const
    {
      const OutlineDie &d = dies_[die];
      const double s = d.frame.coordinate({x[0], x[1]});
      return d.condition.profile.gap(std::abs(s)) - d.delta;
    }
    /// Whether the point at s [m along the part] is in die d's zone (a relative tolerance).
    bool in_zone(const OutlineDie &d, double s) const
    {
      const double tol = 1e-9 * body_.outline.size();
      return s >= d.zone_lo - tol && s <= d.zone_hi + tol;
    }
    /// Pass 0's estimate of each die's zone (see axisymmetric_fem.h, "Dies").
    void estimate_die_zones();
    /// contact.method = "fixed": each die's zone is [centre - c, centre + c] along its part
    /// (clipped to the part; c = contact.half_width, the whole part without it).
    void fix_die_zones();
    /// Refines toward the dies' zones after the global refinements.
    void refine_toward_dies();
    /// FemOptions::grade_toward_vertices; the vertices and their halvings in vertex_grading_.
    void refine_toward_vertices();
    /// Refines the cells `wants` flags, again on the refined mesh, until none is flagged or
    /// after max_rounds rounds (the dies' and the vertices' grading).
    void refine_cells_while(
      const std::function<bool(const Triangulation<2>::active_cell_iterator &)> &wants,
      int max_rounds);
    enum class Mode
    {
      none,
      bilateral,
      unilateral
    };

    void make_mesh();
    /// The mapping of the current mesh (MappingQ(p) cached where the outline has arcs, else
    /// MappingQ1), after make_mesh and after every adaptive refinement.
    void make_mapping();
    /// FemOptions::adaptive: the cycles after the passes (axisymmetric_fem.cc), with the
    /// passes' solve and zone update.
    template <typename Solve, typename Zones>
    void adaptive_cycles(FemResult &result, int first_pass, const Solve &solve_on_mesh,
                         const Zones &zones_from_result);
    /// Kelly's estimate of each active cell for the field u (the jumps of grad u across its
    /// interior faces), times sqrt(r) of the cell's centre: the r-weighted energy's share.
    Vector<float> cell_estimates(const Vector<double> &u) const;
    /// FemOptions::AdaptiveGoal::samples: the dual solution for the sample stresses `now`
    /// (the current ones; see FemOptions::adaptive_goal) of those `aimed` at, with the last
    /// factorization.
    Vector<double> dual_of_samples(const std::vector<FieldSample> &now, const std::vector<bool> &aimed);
    /// sqrt(int |grad u|^2 r dr dz) of the solution: the estimate's scale.
    double gradient_norm() const;
    /// Bilateral: moves the boundary vertex nearest to each free end of a prescribed zone onto
    /// that end.
    void snap_zone_ends();
    void setup_system();
    void add_outline_constraints();
    void add_outline_tractions(const DoFHandler<2>::active_cell_iterator &cell,
                               FEFaceValues<2> &fv, Vector<double> &cell_rhs) const;
    void outline_boundary_terms(double &work, double &b_c, double &b_r) const;
    /// Outline edge of a boundary face (its manifold id - 1, set in make_mesh).
    int edge_of(const TriaIterator<TriaAccessor<1, 2, 2>> &face) const
    {
      return static_cast<int>(face->manifold_id()) - 1;
    }
    const Mapping<2> &mapping() const { return *mapping_; }
    template <typename Finish>
    void active_set_loop(FemResult &result, int pass, const Finish &finish);
    void assemble_base();
    void add_penalty(const std::vector<char> &active);
    /// x = A^-1 rhs with the system matrix: UMFPACK (factorized anew when asked, else the
    /// last factorization) or CG + SSOR; no constraints distributed.
    void solve_system(const Vector<double> &rhs, Vector<double> &x, bool factorize);
    void solve_linear();
    /// Solves the factorized system (solve_linear) for another right-hand side; the
    /// constraints' homogeneous part only (no inhomogeneity).
    Vector<double> solve_homogeneous(const Vector<double> &rhs);
    /// Force control: the indentations of the force-controlled dies that give the asked
    /// forces on the active set, and the solution with them (axisymmetric_fem.h, "Dies").
    void apply_force_control(const std::vector<char> &active);
    /// Per die, over the active points: kappa int (u.n) r ds, kappa int g0 r ds and
    /// kappa int r ds (P = 2 pi (first - second + delta third)).
    std::vector<std::array<double, 3>> penalty_integrals(const Vector<double> &u,
                                                         const std::vector<char> &active) const;
    void evaluate_dies(const std::vector<char> *active, Evaluation &ev, double &b_c,
                       double &b_r, double &penalty_energy) const;
    std::vector<char> active_set() const;
    Evaluation evaluate(const std::vector<char> *active) const;
    std::vector<FieldSample> samples() const;
    /// The residual of the discrete equilibrium, R_i = int s_h.e(phi_i) r - int f.phi_i r -
    /// int_St t.phi_i r ds, per radian, for the conforming basis functions phi_i (the cell
    /// terms of hanging nodes distributed to their masters); meaningful at the dofs of
    /// reaction_dofs_ (0 at the free dofs to the solver's accuracy).
    Vector<double> support_residual() const;
    std::vector<PartReaction> reactions() const;
    void write_vtu() const;

    /// MPI (axisymmetric_fem.h, "MPI"): sums, extrema and concatenations over the ranks; the
    /// value itself in a serial run.
    double all_sum(double x) const
    {
      return distributed_ ? Utilities::MPI::sum(x, comm_) : x;
    }
    double all_max(double x) const
    {
      return distributed_ ? Utilities::MPI::max(x, comm_) : x;
    }
    double all_min(double x) const
    {
      return distributed_ ? Utilities::MPI::min(x, comm_) : x;
    }
    bool all_or(bool x) const
    {
      return distributed_ ? Utilities::MPI::logical_or(x, comm_) : x;
    }
    std::vector<double> all_concat(const std::vector<double> &x) const;
    /// The cell of the mesh around each point and the point in its unit cell: in a
    /// distributed run a rank keeps the points it owns (`here`; one rank for each point).
    struct PointCell
    {
      DoFHandler<2>::active_cell_iterator cell;
      Point<2> unit;
      bool here = false;
    };
    std::vector<PointCell> locate_points(const std::vector<Point<2>> &points) const;
    /// The system matrix and right-hand side set to the base system.
    void reset_system();
    /// solve_system in a distributed run: MUMPS (Amesos) up to FemOptions::mpi_direct_max_dofs
    /// with LinearSolver::direct, else CG + ML algebraic multigrid; `x` receives the solution
    /// with the constraints distributed at the locally relevant dofs.
    void solve_distributed(const Vector<double> &rhs, Vector<double> &x, bool factorize);
    /// Total stress D (e - e_th) at x for the strain e of the solution there.
    Stress stress_at(const Point<2> &x, const Stress &e) const
    {
      return total_stress(d_, loads_, x[0], x[1], e);
    }
    void progress(const std::string &line) const
    {
      if (options_.progress && root_)
        std::cerr << "fem: " << line << '\n';
    }

    const axisym::Problem &problem_;
    const axisym::Body &body_;
    FemOptions options_;
    StressFunction exact_;
    DisplacementFunction exact_u_;
    /// 2 for a mirrored body (the hollow-cylinder form: the half section stands for the
    /// body and its mirror image in z = 0), else 1: the factor of every integral reported.
    double mirror_ = 1.0;
    Mode mode_ = Mode::none;
    int level_ = 0; ///< mesh level of the current pass

    /// Under MPI (fem_solve started by mpirun): a parallel::distributed::Triangulation, each
    /// rank assembling and evaluating its own cells; every Vector<double> below stays
    /// n_dofs long and holds this rank's share: its cells' contributions (right-hand sides)
    /// or the values at its locally relevant dofs (solutions).
    bool distributed_ = false;
    MPI_Comm comm_;
    bool root_ = true; ///< rank 0, or serial: prints and writes
    std::unique_ptr<Triangulation<2>> triangulation_holder_;
    Triangulation<2> &triangulation_;
    FESystem<2> fe_;
    DoFHandler<2> dof_handler_;
    // MappingQ(p) cached after the refinement (MappingQ1 on a polygon and for the
    // straight-cell studies).
    // Declared after the triangulation: the cache listens to its signals.
    std::unique_ptr<Mapping<2>> mapping_;
    double base_mesh_size_ = 0;
    /// The singular vertices graded toward: (r, z, lambda, halvings).
    std::vector<std::array<double, 4>> vertex_grading_;
    unsigned long n_base_cells_ = 0;
    bool base_mesh_subdivided_ = false;
    unsigned int base_mesh_flat_corners_ = 0;
    Stiffness d_;
    BodyLoadField loads_; ///< f and e_th
    QGauss<2> cell_quadrature_;
    QGaussLobatto<1> face_quadrature_; // on the die parts: penalty, active set, traces
    AffineConstraints<double> constraints_;
    /// The hanging-node part of constraints_ alone: residuals in the conforming basis.
    AffineConstraints<double> hanging_node_constraints_;
    SparsityPattern sparsity_;
    SparseMatrix<double> base_matrix_, system_matrix_;
    Vector<double> base_rhs_, system_rhs_, solution_;
    // Faces on the die parts, in cell order; contact quadrature point k * n_q + q.
    std::vector<ContactFace> contact_faces_;
    std::vector<OutlineDie> dies_;
    /// Force control: per force-controlled die, the right-hand side of a unit indentation.
    std::vector<Vector<double>> unit_rhs_;
    /// The dofs whose residual is a support reaction, with the outline edge whose condition
    /// (symmetry, displacement, or a prescribed die zone) holds them and their component (set
    /// in add_outline_constraints).
    struct ReactionDof
    {
      int edge = 0;
      unsigned int component = 0;
    };
    std::map<types::global_dof_index, ReactionDof> reaction_dofs_;
    double h_min_ = 0, kappa_ = 0;
    std::unique_ptr<SparseDirectUMFPACK> umfpack_; ///< the last direct factorization
    // Distributed: the dofs this rank owns and those its cells and ghost cells touch, the
    // Trilinos matrices, and the last factorization or multigrid hierarchy.
    IndexSet owned_dofs_, relevant_dofs_;
    // Held by pointer: a Trilinos object may not even be default-constructed before MPI_Init.
    std::unique_ptr<TrilinosWrappers::SparseMatrix> mpi_base_matrix_, mpi_system_matrix_;
    std::unique_ptr<TrilinosWrappers::SolverDirect> mpi_direct_;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> mpi_amg_;
    SolverControl mpi_direct_control_;
    /// The linear solver of the last solve and its iterations (CG; 0 for a direct solve).
    std::string linear_solver_used_;
    unsigned int linear_iterations_ = 0;
    double assembly_s_ = 0, solve_s_ = 0;
  };
} // namespace fem::internal
