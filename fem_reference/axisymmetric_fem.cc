// All deal.II code of the FEM reference (one translation unit: deal.II headers compile slowly).
// The story follows deal.II step-8 (elasticity) and step-41 (active sets):
//   1. mesh of the half section (gmsh or structured) with boundary ids,
//   2. degrees of freedom and constraints (symmetry plane, bilateral die zone),
//   3. assembly of the r-weighted axisymmetric stiffness and the pressures,
//   4. linear solve (UMFPACK or CG + SSOR),
//   5. unilateral contact: penalty on the active set at the face quadrature points,
//   6. post-processing: functionals, contact force three ways, half-width, samples, VTU.
// Outline problems (DESIGN.md 7.1) share 2-4 and 6; their mesh (1o) carries manifolds on the
// arcs and their conditions are per part (2o, 3o, 6o).
#include "fem_reference/axisymmetric_fem.h"

#include "fem_reference/body_loads.h"
#include "fem_reference/half_section_mesh.h"
#include "fem_reference/outline_mesh.h"

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
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
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

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

namespace fem
{
  using namespace dealii;

  void FemOptions::validate() const
  {
    auto fail = [](const std::string &field, const std::string &value, const std::string &rule) {
      throw axisym::InputError("FEM option " + field + " = " + value + ": " + rule);
    };
    axisym::ranges::fem_degree.check(degree, "FEM option degree (fem.degree, --degree)");
    axisym::ranges::fem_refinements.check(
      refinements, "FEM option refinements (fem.refinements, --refinements)");
    if (!(penalty_factor > 0) || !std::isfinite(penalty_factor))
      fail("penalty_factor (--penalty-factor)", std::to_string(penalty_factor),
           "must be a finite number > 0");
    if (contact_points < 0 || contact_points == 1 || contact_points > 12)
      fail("contact_points", std::to_string(contact_points), "must be 0 (p + 1) or in [2, 12]");
    if (edge_fitting_passes < 0 || edge_fitting_passes > 5)
      fail("edge_fitting_passes (--edge-fitting-passes)", std::to_string(edge_fitting_passes),
           "must be in [0, 5]");
    if (max_active_set_iterations < 1)
      fail("max_active_set_iterations", std::to_string(max_active_set_iterations), "must be >= 1");
    if (!(linear_tolerance > 0 && linear_tolerance < 1e-2))
      fail("linear_tolerance", std::to_string(linear_tolerance), "must be in (0, 1e-2)");
    if (base_cells_r < 1 || base_cells_z < 2)
      fail("base_cells_r/base_cells_z", std::to_string(base_cells_r) + "/" +
                                          std::to_string(base_cells_z),
           "need base_cells_r >= 1, base_cells_z >= 2");
    if (!(radial_grading >= 1 && axial_grading >= 1))
      fail("radial_grading/axial_grading", std::to_string(radial_grading), "must be >= 1");
    if (!(outline_cells_on_shortest_edge >= 1 && outline_cells_on_shortest_edge <= 64))
      fail("outline_cells_on_shortest_edge", std::to_string(outline_cells_on_shortest_edge),
           "must be in [1, 64]");
  }

  void check_supported(const axisym::Problem &problem, const FemOptions &options)
  {
    if (problem.legacy_cylinder)
      return;
    if (!problem.body)
      throw axisym::InputError("problem: an outline problem without its body (parser bug?)");
    if (!problem.body->die_parts().empty() && problem.contact.method == "fixed")
      throw axisym::InputError("contact.method = \"fixed\": a prescribed zone is only for the "
                               "hollow-cylinder form's die so far; a die on an outline part is "
                               "solved for its zone (penalty active set)");
    if (options.mesh == FemOptions::MeshGenerator::structured)
      throw axisym::InputError("FEM option mesh (--mesh) = structured: only for the "
                               "hollow-cylinder form (an outline section is meshed by gmsh)");
  }

  FemOptions options_from_problem(const axisym::Problem &problem)
  {
    FemOptions o;
    o.degree = problem.fem.degree;
    o.refinements = problem.fem.refinements;
    return o;
  }

  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    using Clock = std::chrono::steady_clock;
    double seconds_since(Clock::time_point t0)
    {
      return std::chrono::duration<double>(Clock::now() - t0).count();
    }

    /// Lets `write(path)` write a gmsh .msh file to a temporary path and reads it into
    /// `triangulation`; the file is removed in every case.
    template <typename Write>
    void read_through_msh_file(Triangulation<2> &triangulation, const std::string &prefix,
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
    Stress strain(double r, double u_r, const Tensor<1, 2> &grad_u_r, const Tensor<1, 2> &grad_u_z)
    {
      // On the axis (r = 0: samples, VTU and Gauss-Lobatto points, never a Gauss point)
      // u_r/r -> du_r/dr. A mapped point on the axis can come out at r ~ 1e-19 with u_r = 0
      // exactly, which would give e_tt = 0 instead of the limit: below 1e-13 m is the axis.
      return {{grad_u_r[0], grad_u_z[1], r > 1e-13 ? u_r / r : grad_u_r[0],
               grad_u_r[1] + grad_u_z[0]}};
    }

    /// Strain of the shape function whose only non-zero component is `component`.
    Stress shape_strain(unsigned int component, double r, double phi, const Tensor<1, 2> &grad)
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

    double dot(const Stress &a, const Stress &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    }

    /// The elastic part e(u) - e_th of the strain e at (r, z); e itself without a thermal load.
    Stress elastic_strain(const BodyLoadField &loads, double r, double z, const Stress &e)
    {
      if (!loads.has_thermal_strain())
        return e;
      const double e_th = loads.thermal_strain(r, z);
      return {{e[0] - e_th, e[1] - e_th, e[2] - e_th, e[3]}};
    }

    /// The total stress D (e - e_th) that every output reports (DESIGN.md 7.1).
    Stress total_stress(const Stiffness &d, const BodyLoadField &loads, double r, double z,
                        const Stress &e)
    {
      return d * elastic_strain(loads, r, z, e);
    }

    /// u_r* on the contact zone as a 2-component function (u_z unconstrained: masked out).
    class DieDisplacement : public Function<2>
    {
    public:
      DieDisplacement(const axisym::Die &die, const axisym::Geometry &g)
        : Function<2>(2), die_(die), geometry_(g)
      {}
      double value(const Point<2> &p, unsigned int component) const override
      {
        return component == 0 ? axisym::die_u_r(die_, geometry_, p[1]) : 0.0;
      }

    private:
      axisym::Die die_;
      axisym::Geometry geometry_;
    };

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
    std::pair<double, double> zone_end(const std::vector<std::pair<double, double>> &samples,
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
      std::vector<DieEvaluation> dies; ///< outline dies
      std::optional<double> error_sq, norm_sq;
      std::optional<double> error_max, norm_max;
      std::optional<double> u_error_sq, u_norm_sq;
    };

    class AxisymmetricSolver
    {
    public:
      AxisymmetricSolver(const axisym::Problem &problem, const FemOptions &options,
                         const StressFunction &exact, const DisplacementFunction &exact_u)
        : problem_(problem)
        , options_(options)
        , exact_(exact)
        , exact_u_(exact_u)
        , outline_(!problem.legacy_cylinder)
        , fe_(FE_Q<2>(options.degree), 2)
        , dof_handler_(triangulation_)
        , d_(problem.material)
        , loads_(problem)
        , cell_quadrature_(options.degree + 2)
        , face_quadrature_(options.contact_points > 0 ? options.contact_points
                                                      : options.degree + 1)
      {
        if (!outline_)
          mapping_ = std::make_unique<MappingQ1<2>>();
        const double a = problem.geometry.half_length();
        if (outline_)
          for (const std::string &part : problem.body->die_parts())
            {
              OutlineDie d;
              d.part = part;
              d.boundary_id = boundary_id_of_part(problem.body->outline, part);
              d.frame = axisym::die_frame(*problem.body, part);
              d.condition = problem.body->conditions.at(part).die;
              d.delta = d.condition.indentation.value_or(0.0);
              dies_.push_back(d);
              mode_ = Mode::unilateral;
            }
        if (!dies_.empty())
          estimate_die_zones();
        if (problem.die)
          {
            mode_ = problem.contact.method == "fixed" ? Mode::bilateral : Mode::unilateral;
            half_width_ = mode_ == Mode::bilateral ? problem.contact.half_width.value_or(a) : a;
            if (mode_ == Mode::bilateral)
              split_ = half_width_;
          }
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
        double zone_lo = 0, zone_hi = 0; ///< the zone [m along the part] the mesh resolves
      };
      /// One boundary face on a die's part (legacy: r = R2, die 0).
      struct ContactFace
      {
        DoFHandler<2>::active_cell_iterator cell;
        unsigned int face = 0, die = 0;
      };
      /// The die's outward normal and the target outward displacement u.n at x (+infinity
      /// where there is no die surface: beyond a flat punch's edge).
      Tensor<1, 2> die_normal(unsigned int die) const
      {
        Tensor<1, 2> n;
        if (outline_)
          n[0] = dies_[die].frame.normal.r, n[1] = dies_[die].frame.normal.z;
        else
          n[0] = 1.0;
        return n;
      }
      double die_target(unsigned int die, const Point<2> &x) const
      {
        if (!outline_)
          return axisym::die_u_r(*problem_.die, problem_.geometry, x[1]);
        const OutlineDie &d = dies_[die];
        const double s = d.frame.coordinate({x[0], x[1]});
        return d.condition.profile.gap(std::abs(s)) - d.delta;
      }
      /// Pass 0's estimate of each die's zone (see axisymmetric_fem.h, "Dies").
      void estimate_die_zones();
      /// Refines toward the dies' zones after the global refinements.
      void refine_toward_dies();
      enum class Mode
      {
        none,
        bilateral,
        unilateral
      };

      void make_mesh();
      void make_outline_mesh();
      void setup_system();
      void add_outline_constraints();
      void add_outline_tractions(const DoFHandler<2>::active_cell_iterator &cell,
                                 FEFaceValues<2> &fv, Vector<double> &cell_rhs) const;
      void outline_boundary_terms(double &work, double &b_c, double &b_r) const;
      /// Outline edge of a boundary face (its manifold id - 1, set in make_outline_mesh).
      int edge_of(const TriaIterator<TriaAccessor<1, 2, 2>> &face) const
      {
        return static_cast<int>(face->manifold_id()) - 1;
      }
      const Mapping<2> &mapping() const { return *mapping_; }
      template <typename Finish>
      void active_set_loop(FemResult &result, int pass, const Finish &finish);
      void assemble_base();
      void add_penalty(const std::vector<char> &active);
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
      std::vector<PartReaction> reactions() const;
      void write_vtu() const;
      /// Total stress D (e - e_th) at x for the strain e of the solution there.
      Stress stress_at(const Point<2> &x, const Stress &e) const
      {
        return total_stress(d_, loads_, x[0], x[1], e);
      }
      void progress(const std::string &line) const
      {
        if (options_.progress)
          std::cerr << "fem: " << line << '\n';
      }
      bool is_outer(unsigned int id) const
      {
        return id == outer_contact_boundary || id == outer_free_boundary;
      }

      const axisym::Problem &problem_;
      FemOptions options_;
      StressFunction exact_;
      DisplacementFunction exact_u_;
      bool outline_ = false; ///< an outline problem (DESIGN.md 7.1): the section as given
      Mode mode_ = Mode::none;
      double half_width_ = 0;
      std::optional<double> split_; ///< z where the outer line is split (contact edge)
      int level_ = 0;               ///< mesh level of the current pass

      Triangulation<2> triangulation_;
      FESystem<2> fe_;
      DoFHandler<2> dof_handler_;
      // MappingQ1 for the legacy rectangle; for an outline MappingQ(p) cached after the
      // refinement. Declared after the triangulation: the cache listens to its signals.
      std::unique_ptr<Mapping<2>> mapping_;
      double base_mesh_size_ = 0;
      unsigned long n_base_cells_ = 0;
      bool base_mesh_subdivided_ = false;
      unsigned int base_mesh_flat_corners_ = 0;
      Stiffness d_;
      BodyLoadField loads_; ///< f and e_th (outline problems; none for the legacy form)
      QGauss<2> cell_quadrature_;
      QGaussLobatto<1> face_quadrature_; // on r = R2: penalty, active set, traces
      AffineConstraints<double> constraints_;
      SparsityPattern sparsity_;
      SparseMatrix<double> base_matrix_, system_matrix_;
      Vector<double> base_rhs_, system_rhs_, solution_;
      // Faces on r = R2, in cell order; contact quadrature point k * n_q + q.
      std::vector<ContactFace> contact_faces_;
      std::vector<OutlineDie> dies_; ///< outline problems
      /// Force control: per force-controlled die, the right-hand side of a unit indentation.
      std::vector<Vector<double>> unit_rhs_;
      /// Outline: the dofs whose residual is a support reaction, with the outline edge whose
      /// condition (symmetry or displacement) holds them and their component (set in
      /// add_outline_constraints).
      struct ReactionDof
      {
        int edge = 0;
        unsigned int component = 0;
      };
      std::map<types::global_dof_index, ReactionDof> reaction_dofs_;
      double h_min_ = 0, kappa_ = 0;
      std::unique_ptr<SparseDirectUMFPACK> umfpack_; ///< the last direct factorization
      double assembly_s_ = 0, solve_s_ = 0;
    };

    // 1. Mesh.
    void AxisymmetricSolver::make_mesh()
    {
      if (outline_)
        {
          make_outline_mesh();
          return;
        }
      const axisym::Geometry &g = problem_.geometry;
      HalfSectionMeshSpec spec;
      spec.inner_radius = g.inner_radius;
      spec.outer_radius = g.outer_radius;
      spec.half_length = g.half_length();
      spec.level = level_;
      spec.base_cells_r = options_.base_cells_r;
      spec.base_cells_z = options_.base_cells_z;
      spec.radial_ratio = options_.radial_grading;
      spec.axial_ratio = options_.axial_grading;
      if (split_)
        {
          // Grade toward the contact edge z = c (a corner when c = a).
          spec.split = split_;
          spec.grade_toward_end = !spec.is_split();
        }

      if (options_.mesh == FemOptions::MeshGenerator::gmsh)
        {
          read_through_msh_file(triangulation_, "rfm_fem_", [&](const std::string &path) {
            write_gmsh_mesh(spec, path);
          });
        }
      else
        {
          std::vector<std::vector<double>> steps(2);
          steps[0] = spec.radial_segment().steps();
          for (const GradedSegment &s : spec.axial_segments())
            for (const double h : s.steps())
              steps[1].push_back(h);
          GridGenerator::subdivided_hyper_rectangle(triangulation_, steps,
                                                    Point<2>(g.inner_radius, 0.0),
                                                    Point<2>(g.outer_radius, g.half_length()));
          const double tol = 1e-9 * g.outer_radius;
          const double split = spec.is_split() ? *spec.split : g.half_length();
          for (const auto &cell : triangulation_.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  const Point<2> x = face->center();
                  if (std::abs(x[0] - g.inner_radius) < tol)
                    face->set_boundary_id(inner_boundary);
                  else if (std::abs(x[0] - g.outer_radius) < tol)
                    face->set_boundary_id(x[1] < split ? outer_contact_boundary
                                                       : outer_free_boundary);
                  else if (std::abs(x[1]) < tol)
                    face->set_boundary_id(symmetry_boundary);
                  else
                    face->set_boundary_id(end_boundary);
                }
        }

      // Every boundary face must carry one of our ids (a gmsh group lost would be silent).
      for (const auto &cell : triangulation_.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              (face->boundary_id() < inner_boundary || face->boundary_id() > symmetry_boundary))
            throw std::runtime_error("mesh: boundary face at (" + std::to_string(face->center()[0]) +
                                     ", " + std::to_string(face->center()[1]) +
                                     ") has no physical group (id " +
                                     std::to_string(face->boundary_id()) + ")");
    }

    // 1o. Outline mesh: the gmsh base mesh, the manifold of its edge on every boundary face
    // (PolarManifold about the arc's center, flat for a line), transfinite interpolation on
    // the cells, L global refinements, then MappingQ(p) cached once for the refined mesh.
    void AxisymmetricSolver::make_outline_mesh()
    {
      const axisym::Outline &outline = problem_.body->outline;
      const std::vector<axisym::OutlineEdge> &edges = outline.edges();
      const std::vector<std::string> parts = outline.parts();
      const types::manifold_id cell_manifold = static_cast<types::manifold_id>(edges.size() + 1);
      // A base-mesh cell with two boundary faces that meet where the outline is smooth (on
      // one edge, or where two edges join with the same tangent) has a corner of 180
      // degrees once the faces are curved: its Jacobian is singular at that vertex, and the
      // stress there is not the field's (0.16 of max |sigma| at L = 3 on a ring whose two
      // arcs join at the top). Such a mesh is made again with one more cell on the shortest
      // edge, up to four times; what remains is counted and reported.
      auto count_flat_corners = [&]() {
        const std::size_t n = edges.size();
        auto smooth_join = [&](std::size_t a, std::size_t b) {
          if (a == b)
            return true;
          if (b != (a + 1) % n)
            std::swap(a, b);
          if (b != (a + 1) % n)
            return false;
          const axisym::Point ta = edges[a].tangent_at(1.0), tb = edges[b].tangent_at(0.0);
          return ta.r * tb.r + ta.z * tb.z > std::cos(5.0 * M_PI / 180.0);
        };
        unsigned int flat = 0;
        for (const auto &cell : triangulation_.active_cell_iterators())
          {
            bool found = false;
            for (unsigned int f = 0; f < 4 && !found; ++f)
              for (unsigned int g = f + 1; g < 4 && !found; ++g)
                {
                  const auto fa = cell->face(f), fb = cell->face(g);
                  if (!fa->at_boundary() || !fb->at_boundary())
                    continue;
                  // Adjacent faces share a vertex (opposite faces of a quad do not).
                  bool share = false;
                  for (unsigned int i = 0; i < 2; ++i)
                    for (unsigned int j = 0; j < 2; ++j)
                      share |= fa->vertex_index(i) == fb->vertex_index(j);
                  found = share && smooth_join(fa->manifold_id() - 1, fb->manifold_id() - 1);
                }
            flat += found;
          }
        return flat;
      };
      const double tol = 1e-6 * outline.size();
      OutlineMeshInfo info;
      for (int attempt = 0; attempt < 5; ++attempt)
        {
          OutlineMeshSpec spec;
          spec.cells_on_shortest_edge = options_.outline_cells_on_shortest_edge + attempt;
          triangulation_.clear();
          read_through_msh_file(triangulation_, "rfm_fem_outline_", [&](const std::string &path) {
            info = write_outline_gmsh_mesh(outline, spec, path);
          });
          // Manifold ids: edge i -> i + 1 on its boundary faces, the cells (and interior faces)
          // -> n_edges + 1 (transfinite interpolation).
          triangulation_.set_all_manifold_ids(cell_manifold);
          for (const auto &cell : triangulation_.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  const unsigned int id = face->boundary_id();
                  const Point<2> a = face->vertex(0), b = face->vertex(1);
                  if (id < 1 || id > parts.size())
                    throw std::runtime_error("mesh: boundary face at (" + std::to_string(a[0]) +
                                             ", " + std::to_string(a[1]) +
                                             ") has no part (id " + std::to_string(id) + ")");
                  const int edge =
                    edge_of_boundary_segment(outline, parts[id - 1], {a[0], a[1]}, {b[0], b[1]});
                  const double off = std::max(distance_to_edge(edges[edge], {a[0], a[1]}),
                                              distance_to_edge(edges[edge], {b[0], b[1]}));
                  if (off > tol)
                    throw std::runtime_error("mesh: boundary face at (" + std::to_string(a[0]) +
                                             ", " + std::to_string(a[1]) + ") is " +
                                             std::to_string(off) + " m off its part " +
                                             parts[id - 1]);
                  face->set_manifold_id(static_cast<types::manifold_id>(edge + 1));
                }
          base_mesh_flat_corners_ = count_flat_corners();
          if (base_mesh_flat_corners_ == 0)
            break;
        }
      base_mesh_size_ = info.base_mesh_size;
      base_mesh_subdivided_ = info.subdivided;
      n_base_cells_ = triangulation_.n_active_cells();

      using Geometry = FemOptions::OutlineGeometry;
      const bool curved = options_.outline_geometry != Geometry::coarse_polygon;
      for (std::size_t i = 0; i < edges.size(); ++i)
        {
          const auto id = static_cast<types::manifold_id>(i + 1);
          if (curved && edges[i].kind == axisym::OutlineEdge::Kind::arc)
            triangulation_.set_manifold(
              id, PolarManifold<2>(Point<2>(edges[i].center.r, edges[i].center.z)));
          else
            triangulation_.set_manifold(id, FlatManifold<2>());
        }
      if (curved)
        {
          TransfiniteInterpolationManifold<2> transfinite;
          transfinite.initialize(triangulation_);
          triangulation_.set_manifold(cell_manifold, transfinite);
        }
      else
        triangulation_.set_manifold(cell_manifold, FlatManifold<2>());
      triangulation_.refine_global(level_);
      refine_toward_dies();

      if (options_.outline_geometry == Geometry::curved)
        {
          auto cache = std::make_unique<MappingQCache<2>>(options_.degree);
          cache->initialize(MappingQ<2>(options_.degree), triangulation_);
          mapping_ = std::move(cache);
        }
      else
        mapping_ = std::make_unique<MappingQ1<2>>();
    }

    // 2. Degrees of freedom and constraints.
    void AxisymmetricSolver::setup_system()
    {
      dof_handler_.distribute_dofs(fe_);
      constraints_.clear();
      DoFTools::make_hanging_node_constraints(dof_handler_, constraints_);
      const FEValuesExtractors::Scalar u_r(0), u_z(1);
      if (outline_)
        add_outline_constraints();
      else
        {
          VectorTools::interpolate_boundary_values(mapping(), dof_handler_, symmetry_boundary,
                                                   Functions::ZeroFunction<2>(2), constraints_,
                                                   fe_.component_mask(u_z));
          if (mode_ == Mode::bilateral)
            VectorTools::interpolate_boundary_values(
              mapping(), dof_handler_, outer_contact_boundary,
              DieDisplacement(*problem_.die, problem_.geometry), constraints_,
              fe_.component_mask(u_r));
        }
      constraints_.close();

      base_matrix_.clear(); // they refer to the sparsity pattern rebuilt below
      system_matrix_.clear();
      DynamicSparsityPattern dsp(dof_handler_.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
      sparsity_.copy_from(dsp);
      base_matrix_.reinit(sparsity_);
      system_matrix_.reinit(sparsity_);
      base_rhs_.reinit(dof_handler_.n_dofs());
      system_rhs_.reinit(dof_handler_.n_dofs());
      solution_.reinit(dof_handler_.n_dofs());

      contact_faces_.clear();
      h_min_ = std::numeric_limits<double>::infinity();
      kappa_ = 0;
      for (const auto &cell : dof_handler_.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const types::boundary_id id = cell->face(f)->boundary_id();
            unsigned int die = 0;
            if (outline_)
              {
                while (die < dies_.size() && dies_[die].boundary_id != id)
                  ++die;
                if (die == dies_.size())
                  continue;
              }
            else if (!problem_.die || !is_outer(id))
              continue;
            contact_faces_.push_back({cell, f, die});
            h_min_ = std::min(h_min_, cell->face(f)->measure());
          }
      if (!contact_faces_.empty())
        kappa_ = options_.penalty_factor * problem_.material.youngs_modulus / h_min_;
    }

    // 2o. Outline constraints. Each boundary node (the pair of u_r and u_z dofs at one support
    // point) collects a_r u_r + a_z u_z = g from every constrained face through it:
    // displacement (1, 0) = u_r*, (0, 1) = u_z*; axis (1, 0) = 0; symmetry n = 0 with the
    // straight edge's normal. The first (in that order of priority) is kept, with the one
    // most independent of it if their normals are not parallel (then both components are
    // fixed); a single condition constrains its larger component.
    void AxisymmetricSolver::add_outline_constraints()
    {
      using Kind = axisym::PartCondition::Kind;
      const axisym::Body &body = *problem_.body;
      struct Condition
      {
        double a_r, a_z, g;
        int priority, edge;
      };
      struct Node
      {
        types::global_dof_index dof_z = 0;
        std::vector<Condition> conditions;
      };
      std::map<types::global_dof_index, Node> nodes; // by the u_r dof
      reaction_dofs_.clear();
      const unsigned int n_face_dofs = fe_.n_dofs_per_face();
      std::vector<types::global_dof_index> face_dofs(n_face_dofs);
      for (const auto &cell : dof_handler_.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const int edge = edge_of(cell->face(f));
            const axisym::PartCondition &c = body.condition_of_edge(edge);
            std::array<Condition, 2> add{};
            unsigned int n_add = 0;
            if (c.kind == Kind::displacement)
              {
                add[n_add++] = {1, 0, c.displacement[0], 0, edge};
                add[n_add++] = {0, 1, c.displacement[1], 0, edge};
              }
            else if (c.kind == Kind::axis)
              add[n_add++] = {1, 0, 0, 1, edge};
            else if (c.kind == Kind::symmetry)
              {
                const axisym::Point n = body.outline.edges()[edge].outward_normal_at(0.5);
                // Exact zeros for edges along e_r or e_z (a single-component constraint).
                const double n_r = std::abs(n.r) < 1e-12 ? 0.0 : n.r;
                const double n_z = std::abs(n.z) < 1e-12 ? 0.0 : n.z;
                add[n_add++] = {n_r, n_z, 0, 2, edge};
              }
            else
              continue;
            cell->face(f)->get_dof_indices(face_dofs);
            // Pair the two components of each support point of the face.
            std::map<unsigned int, std::array<types::global_dof_index, 2>> pairs;
            for (unsigned int i = 0; i < n_face_dofs; ++i)
              {
                const auto [component, index] = fe_.face_system_to_component_index(i);
                pairs[index][component] = face_dofs[i];
              }
            for (const auto &[index, dofs] : pairs)
              {
                Node &node = nodes[dofs[0]];
                node.dof_z = dofs[1];
                for (unsigned int k = 0; k < n_add; ++k)
                  {
                    const Condition &cond = add[k];
                    const bool seen =
                      std::any_of(node.conditions.begin(), node.conditions.end(),
                                  [&](const Condition &o) {
                                    return o.edge == cond.edge && o.a_r == cond.a_r &&
                                           o.a_z == cond.a_z;
                                  });
                    if (!seen)
                      node.conditions.push_back(cond);
                  }
              }
          }

      for (auto &[dof_r, node] : nodes)
        {
          std::stable_sort(node.conditions.begin(), node.conditions.end(),
                           [](const Condition &a, const Condition &b) {
                             return a.priority < b.priority;
                           });
          const Condition &first = node.conditions.front();
          const Condition *second = nullptr;
          double best = 0;
          for (const Condition &c : node.conditions)
            {
              const double cross = std::abs(first.a_r * c.a_z - first.a_z * c.a_r);
              if (cross > 1e-6 && cross > best)
                best = cross, second = &c;
            }
          const types::global_dof_index dof_z = node.dof_z;
          // The residual of a constrained dof is the reaction of the support that holds it;
          // the axis is no support (its exact reaction vanishes with r).
          auto own = [&](types::global_dof_index dof, const Condition &by) {
            if (body.condition_of_edge(by.edge).kind != Kind::axis)
              reaction_dofs_[dof] = {by.edge, dof == dof_z ? 1u : 0u};
          };
          auto fix = [&](types::global_dof_index dof, double value, const Condition &by) {
            if (constraints_.is_constrained(dof))
              return;
            constraints_.add_line(dof);
            constraints_.set_inhomogeneity(dof, value);
            own(dof, by);
          };
          if (second)
            {
              // Solve [a1; a2] u = [g1; g2]. u_r belongs to the condition that weighs it
              // more (the first on a tie), u_z to the other.
              const double det = first.a_r * second->a_z - first.a_z * second->a_r;
              const bool first_has_r = std::abs(first.a_r) >= std::abs(second->a_r);
              fix(dof_r, (first.g * second->a_z - second->g * first.a_z) / det,
                  first_has_r ? first : *second);
              fix(dof_z, (first.a_r * second->g - second->a_r * first.g) / det,
                  first_has_r ? *second : first);
            }
          else
            {
              const bool on_r = std::abs(first.a_r) >= std::abs(first.a_z);
              const types::global_dof_index dof = on_r ? dof_r : dof_z;
              const types::global_dof_index other = on_r ? dof_z : dof_r;
              const double a = on_r ? first.a_r : first.a_z, b = on_r ? first.a_z : first.a_r;
              if (constraints_.is_constrained(dof))
                continue;
              constraints_.add_line(dof);
              own(dof, first);
              if (b != 0) // an inclined edge: the node's reaction (both components) is along n
                constraints_.add_entry(dof, other, -b / a), own(other, first);
              constraints_.set_inhomogeneity(dof, first.g / a);
            }
        }
    }

    // 3o. Pressure and traction parts: int t.v r ds with t = -p n (n of the mapped face at
    // the quadrature point) or t = (t_r, t_z).
    void
    AxisymmetricSolver::add_outline_tractions(const DoFHandler<2>::active_cell_iterator &cell,
                                              FEFaceValues<2> &fv, Vector<double> &cell_rhs) const
    {
      using Kind = axisym::PartCondition::Kind;
      for (const unsigned int f : cell->face_indices())
        {
          if (!cell->face(f)->at_boundary())
            continue;
          const axisym::PartCondition &c =
            problem_.body->condition_of_edge(edge_of(cell->face(f)));
          if (c.kind != Kind::pressure && c.kind != Kind::traction)
            continue;
          fv.reinit(cell, f);
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const Tensor<1, 2> n = fv.normal_vector(q);
              const std::array<double, 2> t =
                c.kind == Kind::pressure
                  ? std::array<double, 2>{{-c.pressure * n[0], -c.pressure * n[1]}}
                  : c.traction;
              const double w = fv.quadrature_point(q)[0] * fv.JxW(q);
              for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i)
                cell_rhs(i) +=
                  t[fe_.system_to_component_index(i).first] * fv.shape_value(i, q) * w;
            }
        }
    }

    // 3. Assembly: int e(v).D e(u) r dr dz, int t.v r ds for the pressures and tractions, and
    // for the body loads int f.v r dr dz + int e(v).D e_th r dr dz.
    void AxisymmetricSolver::assemble_base()
    {
      const auto t0 = Clock::now();
      FEValues<2> fe_values(mapping(), fe_, cell_quadrature_,
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
      FEFaceValues<2> fe_face_values(mapping(), fe_, QGauss<1>(options_.degree + 1),
                                     update_values | update_quadrature_points |
                                       update_JxW_values);
      FEFaceValues<2> outline_face_values(mapping(), fe_, QGauss<1>(options_.degree + 1),
                                          update_values | update_quadrature_points |
                                            update_normal_vectors | update_JxW_values);
      const unsigned int n = fe_.n_dofs_per_cell();
      FullMatrix<double> cell_matrix(n, n);
      Vector<double> cell_rhs(n);
      std::vector<types::global_dof_index> dofs(n);
      std::vector<Stress> b(n), db(n);
      const double p_in = problem_.loading ? problem_.loading->inner_pressure : 0.0;
      const double p_out = problem_.loading ? problem_.loading->outer_pressure : 0.0;

      base_matrix_ = 0;
      base_rhs_ = 0;
      for (const auto &cell : dof_handler_.active_cell_iterators())
        {
          cell_matrix = 0;
          cell_rhs = 0;
          fe_values.reinit(cell);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double r = fe_values.quadrature_point(q)[0];
              const double w = r * fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c = fe_.system_to_component_index(i).first;
                  b[i] = shape_strain(c, r, fe_values.shape_value_component(i, q, c),
                                      fe_values.shape_grad_component(i, q, c));
                  db[i] = d_ * b[i];
                }
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j <= i; ++j)
                  cell_matrix(i, j) += dot(b[i], db[j]) * w;
              // Body loads: int f.v r + int e(v).D e_th r (the thermal strain as an initial
              // strain: the stress is D (e(u) - e_th)).
              if (loads_.any())
                {
                  const Point<2> &x = fe_values.quadrature_point(q);
                  const std::array<double, 2> f = loads_.force(x[0], x[1]);
                  const double e_th = loads_.thermal_strain(x[0], x[1]);
                  const Stress s_th = d_ * Stress{{e_th, e_th, e_th, 0.0}};
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int c = fe_.system_to_component_index(i).first;
                      cell_rhs(i) +=
                        (f[c] * fe_values.shape_value_component(i, q, c) + dot(b[i], s_th)) * w;
                    }
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = i + 1; j < n; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);

          if (outline_)
            add_outline_tractions(cell, outline_face_values, cell_rhs);
          // Legacy: pressure p on a face with outward normal n: t = -p n, t.v = -p n_r v_r.
          for (const unsigned int f : cell->face_indices())
            {
              if (outline_ || !cell->face(f)->at_boundary())
                continue;
              const unsigned int id = cell->face(f)->boundary_id();
              double pressure = 0, normal_r = 0;
              if (id == inner_boundary)
                pressure = p_in, normal_r = -1;
              else if (is_outer(id))
                pressure = p_out, normal_r = 1;
              if (pressure == 0)
                continue;
              fe_face_values.reinit(cell, f);
              for (const unsigned int q : fe_face_values.quadrature_point_indices())
                {
                  const double r = fe_face_values.quadrature_point(q)[0];
                  for (unsigned int i = 0; i < n; ++i)
                    if (fe_.system_to_component_index(i).first == 0)
                      cell_rhs(i) += -pressure * normal_r * fe_face_values.shape_value(i, q) * r *
                                     fe_face_values.JxW(q);
                }
            }
          cell->get_dof_indices(dofs);
          constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dofs, base_matrix_,
                                                  base_rhs_);
        }
      assembly_s_ += seconds_since(t0);
    }

    // 5a. Penalty kappa int_A (u.n - t) v.n r ds added to a copy of the base system, t the
    // target outward displacement (legacy: n = e_r, t = u_r*). Force-controlled dies enter with
    // delta = 0, and unit_rhs_[k] receives the right-hand side of a unit indentation of the
    // k-th of them (t = g0 - delta: -kappa int_A v.n r ds per unit delta).
    void AxisymmetricSolver::add_penalty(const std::vector<char> &active)
    {
      const auto t0 = Clock::now();
      system_matrix_.copy_from(base_matrix_);
      system_rhs_ = base_rhs_;
      std::vector<int> force_index(dies_.size(), -1);
      int n_force = 0;
      for (std::size_t d = 0; d < dies_.size(); ++d)
        if (dies_[d].condition.force)
          {
            force_index[d] = n_force++;
            dies_[d].delta = 0;
          }
      unit_rhs_.assign(n_force, Vector<double>(dof_handler_.n_dofs()));
      FEFaceValues<2> fv(mapping(), fe_, face_quadrature_,
                         update_values | update_quadrature_points | update_JxW_values);
      const unsigned int n = fe_.n_dofs_per_cell(), n_q = face_quadrature_.size();
      FullMatrix<double> m(n, n);
      Vector<double> rhs(n), unit(n);
      std::vector<types::global_dof_index> dofs(n);
      for (std::size_t k = 0; k < contact_faces_.size(); ++k)
        {
          bool any = false;
          for (unsigned int q = 0; q < n_q; ++q)
            any = any || active[k * n_q + q];
          if (!any)
            continue;
          const ContactFace &face = contact_faces_[k];
          const Tensor<1, 2> normal = die_normal(face.die);
          fv.reinit(face.cell, face.face);
          m = 0;
          rhs = 0;
          unit = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              if (!active[k * n_q + q])
                continue;
              const Point<2> x = fv.quadrature_point(q);
              const double w = kappa_ * x[0] * fv.JxW(q);
              const double target = die_target(face.die, x);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const double n_i = normal[fe_.system_to_component_index(i).first];
                  if (n_i == 0.0)
                    continue;
                  const double phi_i = fv.shape_value(i, q) * n_i;
                  rhs(i) += w * target * phi_i;
                  unit(i) -= w * phi_i;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const double n_j = normal[fe_.system_to_component_index(j).first];
                      if (n_j != 0.0)
                        m(i, j) += w * phi_i * fv.shape_value(j, q) * n_j;
                    }
                }
            }
          face.cell->get_dof_indices(dofs);
          constraints_.distribute_local_to_global(m, rhs, dofs, system_matrix_, system_rhs_);
          if (outline_ && force_index[face.die] >= 0)
            constraints_.distribute_local_to_global(unit, dofs, unit_rhs_[force_index[face.die]]);
        }
      assembly_s_ += seconds_since(t0);
    }

    // 4. Linear solve; throws on failure (the caller turns it into a numerical outcome).
    void AxisymmetricSolver::solve_linear()
    {
      const auto t0 = Clock::now();
      if (options_.linear_solver == FemOptions::LinearSolver::direct)
        {
          umfpack_ = std::make_unique<SparseDirectUMFPACK>();
          umfpack_->initialize(system_matrix_);
          umfpack_->vmult(solution_, system_rhs_);
        }
      else
        {
          SolverControl control(20 * dof_handler_.n_dofs() + 100,
                                options_.linear_tolerance * system_rhs_.l2_norm());
          SolverCG<Vector<double>> cg(control);
          PreconditionSSOR<SparseMatrix<double>> ssor;
          ssor.initialize(system_matrix_, 1.2);
          cg.solve(system_matrix_, solution_, system_rhs_, ssor);
        }
      constraints_.distribute(solution_);
      for (const double x : solution_)
        if (!std::isfinite(x))
          throw std::runtime_error("linear solve produced non-finite values (singular matrix?)");
      solve_s_ += seconds_since(t0);
    }

    Vector<double> AxisymmetricSolver::solve_homogeneous(const Vector<double> &rhs)
    {
      const auto t0 = Clock::now();
      Vector<double> x(dof_handler_.n_dofs()), zero(dof_handler_.n_dofs());
      if (options_.linear_solver == FemOptions::LinearSolver::direct)
        umfpack_->vmult(x, rhs);
      else
        {
          SolverControl control(20 * dof_handler_.n_dofs() + 100,
                                options_.linear_tolerance * rhs.l2_norm());
          SolverCG<Vector<double>> cg(control);
          PreconditionSSOR<SparseMatrix<double>> ssor;
          ssor.initialize(system_matrix_, 1.2);
          cg.solve(system_matrix_, x, rhs, ssor);
        }
      constraints_.distribute(x);
      constraints_.distribute(zero); // the inhomogeneities alone
      x -= zero;
      solve_s_ += seconds_since(t0);
      return x;
    }

    std::vector<std::array<double, 3>>
    AxisymmetricSolver::penalty_integrals(const Vector<double> &u,
                                          const std::vector<char> &active) const
    {
      std::vector<std::array<double, 3>> out(dies_.size(), {{0.0, 0.0, 0.0}});
      FEFaceValues<2> fv(mapping(), fe_, face_quadrature_,
                         update_values | update_quadrature_points | update_JxW_values);
      const unsigned int n_q = face_quadrature_.size();
      std::vector<Vector<double>> uq(n_q, Vector<double>(2));
      for (std::size_t k = 0; k < contact_faces_.size(); ++k)
        {
          const ContactFace &face = contact_faces_[k];
          const OutlineDie &d = dies_[face.die];
          fv.reinit(face.cell, face.face);
          fv.get_function_values(u, uq);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              if (!active[k * n_q + q])
                continue;
              const Point<2> x = fv.quadrature_point(q);
              const double w = kappa_ * x[0] * fv.JxW(q);
              const double un = uq[q][0] * d.frame.normal.r + uq[q][1] * d.frame.normal.z;
              const double g0 = d.condition.profile.gap(std::abs(d.frame.coordinate({x[0], x[1]})));
              out[face.die][0] += w * un;
              out[face.die][1] += w * g0;
              out[face.die][2] += w;
            }
        }
      return out;
    }

    // 5d. Force control. On a fixed active set, P_i = 2 pi (A_i(u) - G_i + delta_i W_i) with
    // u = u_0 + sum_k delta_k u_k (penalty_integrals: A, G, W); u_0 is the solution with the
    // force-controlled deltas at 0 (add_penalty), u_k the response to a unit delta_k.
    void AxisymmetricSolver::apply_force_control(const std::vector<char> &active)
    {
      std::vector<unsigned int> force_dies;
      for (unsigned int d = 0; d < dies_.size(); ++d)
        if (dies_[d].condition.force)
          force_dies.push_back(d);
      if (force_dies.empty())
        return;
      const std::size_t m = force_dies.size();
      std::vector<Vector<double>> unit(m);
      for (std::size_t k = 0; k < m; ++k)
        unit[k] = solve_homogeneous(unit_rhs_[k]);
      const auto base = penalty_integrals(solution_, active);
      FullMatrix<double> a(m, m);
      Vector<double> b(m), delta(m);
      for (std::size_t i = 0; i < m; ++i)
        {
          const unsigned int di = force_dies[i];
          b(i) = *dies_[di].condition.force / (2 * pi) - (base[di][0] - base[di][1]);
        }
      for (std::size_t k = 0; k < m; ++k)
        {
          const auto response = penalty_integrals(unit[k], active);
          for (std::size_t i = 0; i < m; ++i)
            a(i, k) = response[force_dies[i]][0] + (i == k ? base[force_dies[i]][2] : 0.0);
        }
      // A die with no active point cannot carry its force: the set is wrong, not the system.
      for (std::size_t i = 0; i < m; ++i)
        if (!(base[force_dies[i]][2] > 0))
          throw std::runtime_error("force control: die on part " + dies_[force_dies[i]].part +
                                   " has no point in contact");
      a.gauss_jordan();
      a.vmult(delta, b);
      for (std::size_t k = 0; k < m; ++k)
        {
          dies_[force_dies[k]].delta = delta(k);
          solution_.add(delta(k), unit[k]);
        }
    }

    // 5b. The active set of the current solution: g = u.n - t > 0 at the contact points.
    std::vector<char> AxisymmetricSolver::active_set() const
    {
      FEFaceValues<2> fv(mapping(), fe_, face_quadrature_, update_values | update_quadrature_points);
      const unsigned int n_q = face_quadrature_.size();
      std::vector<char> active(contact_faces_.size() * n_q);
      std::vector<Vector<double>> u(n_q, Vector<double>(2));
      for (std::size_t k = 0; k < contact_faces_.size(); ++k)
        {
          const ContactFace &face = contact_faces_[k];
          const Tensor<1, 2> n = die_normal(face.die);
          fv.reinit(face.cell, face.face);
          fv.get_function_values(solution_, u);
          for (unsigned int q = 0; q < n_q; ++q)
            active[k * n_q + q] =
              u[q][0] * n[0] + u[q][1] * n[1] - die_target(face.die, fv.quadrature_point(q)) > 0.0;
        }
      return active;
    }

    // 6. Post-processing of the current solution. `active`: the penalty set used in the solve.
    Evaluation AxisymmetricSolver::evaluate(const std::vector<char> *active) const
    {
      Evaluation ev;
      const axisym::Geometry &g = problem_.geometry;
      const double r1 = g.inner_radius, r2 = g.outer_radius;

      // Volume: U_h, the consistent reaction int s.e(v) r with v = (psi, 0), the stress error.
      FEValues<2> fe_values(mapping(), fe_, cell_quadrature_,
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
      const unsigned int n_q = cell_quadrature_.size();
      std::vector<Vector<double>> u(n_q, Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> grad(n_q, std::vector<Tensor<1, 2>>(2));
      double energy = 0, reaction = 0, error_sq = 0, norm_sq = 0, u_error_sq = 0, u_norm_sq = 0;
      double body_force_work = 0, thermal_strain_work = 0; // int f.u_h r, int s_h.e_th r
      for (const auto &cell : dof_handler_.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(solution_, u);
          fe_values.get_function_gradients(solution_, grad);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<2> x = fe_values.quadrature_point(q);
              const double w = x[0] * fe_values.JxW(q);
              // e = e(u_h) - e_th, s = D e the total stress, U_h = 1/2 int e.D e r.
              const Stress e = elastic_strain(loads_, x[0], x[1],
                                              strain(x[0], u[q][0], grad[q][0], grad[q][1]));
              const Stress s = d_ * e;
              energy += 0.5 * dot(e, s) * w;
              if (loads_.has_force())
                {
                  const std::array<double, 2> f = loads_.force(x[0], x[1]);
                  body_force_work += (f[0] * u[q][0] + f[1] * u[q][1]) * w;
                }
              if (loads_.has_thermal_strain())
                thermal_strain_work +=
                  loads_.thermal_strain(x[0], x[1]) * (s[0] + s[1] + s[2]) * w;
              if (!outline_)
                {
                  const double psi = (x[0] - r1) / (r2 - r1);
                  reaction += (s[0] / (r2 - r1) + s[2] * psi / x[0]) * w;
                }
              if (exact_u_)
                {
                  const std::array<double, 2> ue = exact_u_(x[0], x[1]);
                  for (unsigned int k = 0; k < 2; ++k)
                    {
                      u_error_sq += (u[q][k] - ue[k]) * (u[q][k] - ue[k]) * w;
                      u_norm_sq += ue[k] * ue[k] * w;
                    }
                }
              if (exact_)
                {
                  // Frobenius norm of the stress tensor: sigma_rz counts twice, as
                  // in the RFM verification (verification/lame_errors.h).
                  const Stress se = exact_(x[0], x[1]);
                  for (int k = 0; k < 4; ++k)
                    {
                      const double f = k == 3 ? 2.0 : 1.0;
                      error_sq += f * (s[k] - se[k]) * (s[k] - se[k]) * w;
                      norm_sq += f * se[k] * se[k] * w;
                    }
                }
            }
        }
      // The legacy half section stands for the whole body (twice); an outline for itself.
      const double mirror = outline_ ? 1.0 : 2.0;
      if (exact_u_)
        ev.u_error_sq = mirror * u_error_sq, ev.u_norm_sq = mirror * u_norm_sq;
      if (exact_)
        {
          ev.error_sq = mirror * error_sq, ev.norm_sq = mirror * norm_sq;
          // Max norm at the Gauss-Lobatto points of every cell (they include the cell and
          // domain boundaries, where the FEM stress error peaks); the discontinuous s_h is
          // taken from each cell in turn.
          const QGaussLobatto<2> nodes(options_.degree + 2);
          FEValues<2> fe_nodes(mapping(), fe_, nodes,
                               update_values | update_gradients | update_quadrature_points);
          std::vector<Vector<double>> un(nodes.size(), Vector<double>(2));
          std::vector<std::vector<Tensor<1, 2>>> gradn(nodes.size(),
                                                       std::vector<Tensor<1, 2>>(2));
          double error_max = 0, norm_max = 0;
          for (const auto &cell : dof_handler_.active_cell_iterators())
            {
              fe_nodes.reinit(cell);
              fe_nodes.get_function_values(solution_, un);
              fe_nodes.get_function_gradients(solution_, gradn);
              for (unsigned int q = 0; q < nodes.size(); ++q)
                {
                  const Point<2> x = fe_nodes.quadrature_point(q);
                  const Stress s =
                    stress_at(x, strain(x[0], un[q][0], gradn[q][0], gradn[q][1]));
                  const Stress se = exact_(x[0], x[1]);
                  for (int k = 0; k < 4; ++k)
                    {
                      error_max = std::max(error_max, std::abs(s[k] - se[k]));
                      norm_max = std::max(norm_max, std::abs(se[k]));
                    }
                }
            }
          ev.error_max = error_max, ev.norm_max = norm_max;
        }

      if (outline_)
        {
          double work = 0, b_c = 0, b_r = 0, penalty_energy = 0;
          outline_boundary_terms(work, b_c, b_r);
          if (!dies_.empty())
            evaluate_dies(active, ev, b_c, b_r, penalty_energy);
          ev.functionals.penalty_energy = penalty_energy;
          // DESIGN.md 3 with the thermal strain as an initial strain (axisymmetric_fem.h):
          // W = int f.u_h r + int_St t.u_h r ds; the Castigliano functional carries
          // -int s_h.e_th r; in Reissner's s.e(u) - 1/2 s.C s - s.e_th = U density for s = s_h.
          Functionals &phi = ev.functionals;
          phi.strain_energy = energy;
          phi.body_force_work = body_force_work;
          phi.thermal_strain_work = thermal_strain_work;
          phi.external_work = work + body_force_work;
          phi.lagrange = phi.strain_energy - phi.external_work;
          phi.castigliano = -phi.strain_energy - thermal_strain_work + b_c;
          phi.reissner = phi.strain_energy - phi.external_work - b_r;
          return ev;
        }

      // Boundary: work of the pressures; on r = R2 the traces, gap and contact terms.
      const double p_in = problem_.loading ? problem_.loading->inner_pressure : 0.0;
      const double p_out = problem_.loading ? problem_.loading->outer_pressure : 0.0;
      FEFaceValues<2> fv(mapping(), fe_, face_quadrature_,
                         update_values | update_gradients | update_quadrature_points |
                           update_JxW_values);
      const unsigned int n_fq = face_quadrature_.size();
      std::vector<Vector<double>> uf(n_fq, Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> gradf(n_fq, std::vector<Tensor<1, 2>>(2));
      double work = 0, trace = 0, penalty_force = 0, penalty_energy = 0, b_c = 0, b_r = 0;
      std::vector<std::pair<double, double>> gap_samples; // (z, g)
      for (const auto &cell : dof_handler_.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const unsigned int id = cell->face(f)->boundary_id();
            if (id != inner_boundary && !is_outer(id))
              continue;
            fv.reinit(cell, f);
            fv.get_function_values(solution_, uf);
            for (unsigned int q = 0; q < n_fq; ++q)
              {
                const double r = fv.quadrature_point(q)[0];
                work += (id == inner_boundary ? p_in : -p_out) * uf[q][0] * r * fv.JxW(q);
              }
          }
      if (problem_.die)
        {
          for (std::size_t k = 0; k < contact_faces_.size(); ++k)
            {
              const auto &[cell, f, die] = contact_faces_[k];
              fv.reinit(cell, f);
              fv.get_function_values(solution_, uf);
              fv.get_function_gradients(solution_, gradf);
              const bool prescribed_face = mode_ == Mode::bilateral &&
                                           cell->face(f)->boundary_id() == outer_contact_boundary;
              for (unsigned int q = 0; q < n_fq; ++q)
                {
                  const Point<2> x = fv.quadrature_point(q);
                  const double w = x[0] * fv.JxW(q); // r ds with r = R2
                  const double target = axisym::die_u_r(*problem_.die, g, x[1]);
                  const double gap = uf[q][0] - target;
                  const Stress s =
                    stress_at(x, strain(x[0], uf[q][0], gradf[q][0], gradf[q][1]));
                  trace += s[0] * fv.JxW(q);
                  const bool in_zone =
                    active ? static_cast<bool>((*active)[k * n_fq + q]) : prescribed_face;
                  double p = -s[0];
                  if (active)
                    {
                      p = in_zone ? kappa_ * gap : 0.0;
                      penalty_force += p * fv.JxW(q);
                      if (in_zone)
                        penalty_energy += 0.5 * kappa_ * gap * gap * w;
                    }
                  if (in_zone)
                    b_c += s[0] * target * w, b_r += s[0] * gap * w;
                  ev.max_penetration = std::max(ev.max_penetration, gap);
                  ev.pressure.push_back({x[1], x[0], x[1], p, -s[0], gap});
                  gap_samples.emplace_back(x[1], gap);
                }
            }
          std::stable_sort(ev.pressure.begin(), ev.pressure.end(),
                           [](const PressurePoint &a, const PressurePoint &b) { return a.z < b.z; });
          std::stable_sort(gap_samples.begin(), gap_samples.end());
        }

      // Full body: twice the half section; forces also times 2 pi.
      Functionals &phi = ev.functionals;
      phi.strain_energy = 2 * energy;
      phi.external_work = 2 * work;
      phi.penalty_energy = 2 * penalty_energy;
      phi.lagrange = phi.strain_energy - phi.external_work;
      phi.castigliano = -phi.strain_energy + 2 * b_c;
      phi.reissner = phi.strain_energy - phi.external_work - 2 * b_r;
      ev.force = -2 * pi * 2 * reaction;
      ev.force_trace = -2 * pi * r2 * 2 * trace;
      ev.force_penalty = 2 * pi * r2 * 2 * penalty_force;

      // Half-width (unilateral): zone_end from z = 0; (b) is the reported half_width.
      ev.half_width = ev.half_width_gap = half_width_;
      if (mode_ == Mode::unilateral && !gap_samples.empty())
        std::tie(ev.half_width, ev.half_width_gap) = zone_end(gap_samples, g.half_length());
      return ev;
    }

    // 6d. Dies on outline parts: at the contact points of each die, the gap g = u.n - t, the
    // penalty pressure kappa g on the active set, the trace -n.s_h n, the forces, the zone ends
    // (zone_end on each side of the centre), and the contact terms of the functionals:
    // b_c += int_A (n.s_h n) t r ds, b_r += int_A (n.s_h n) g r ds (the zone is S_c with u.n = t).
    void AxisymmetricSolver::evaluate_dies(const std::vector<char> *active, Evaluation &ev,
                                           double &b_c, double &b_r, double &penalty_energy) const
    {
      ev.dies.assign(dies_.size(), DieEvaluation{});
      FEFaceValues<2> fv(mapping(), fe_, face_quadrature_,
                         update_values | update_gradients | update_quadrature_points |
                           update_JxW_values);
      const unsigned int n_q = face_quadrature_.size();
      std::vector<Vector<double>> u(n_q, Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> grad(n_q, std::vector<Tensor<1, 2>>(2));
      std::vector<std::vector<std::pair<double, double>>> gaps(dies_.size()); // (s, g)
      for (std::size_t k = 0; k < contact_faces_.size(); ++k)
        {
          const ContactFace &face = contact_faces_[k];
          const OutlineDie &d = dies_[face.die];
          DieEvaluation &de = ev.dies[face.die];
          const Tensor<1, 2> n = die_normal(face.die);
          fv.reinit(face.cell, face.face);
          fv.get_function_values(solution_, u);
          fv.get_function_gradients(solution_, grad);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<2> x = fv.quadrature_point(q);
              const double w = x[0] * fv.JxW(q);
              if (!(w > 0))
                continue; // a point on the axis: no weight r ds, no penalty, no pressure
              const double target = die_target(face.die, x);
              const double gap = u[q][0] * n[0] + u[q][1] * n[1] - target;
              const Stress st = stress_at(x, strain(x[0], u[q][0], grad[q][0], grad[q][1]));
              const double snn = st[0] * n[0] * n[0] + 2 * st[3] * n[0] * n[1] + st[1] * n[1] * n[1];
              const bool in_zone = active && (*active)[k * n_q + q];
              const double p = in_zone ? kappa_ * gap : 0.0;
              de.force += 2 * pi * p * w;
              de.force_trace -= 2 * pi * snn * w;
              if (in_zone)
                {
                  penalty_energy += 0.5 * kappa_ * gap * gap * w;
                  b_c += snn * target * w;
                  b_r += snn * gap * w;
                }
              if (std::isfinite(gap))
                de.max_penetration = std::max(de.max_penetration, gap);
              const double s = d.frame.coordinate({x[0], x[1]});
              de.pressure.push_back({s, x[0], x[1], p, -snn, gap});
              gaps[face.die].emplace_back(s, gap);
            }
        }
      for (std::size_t i = 0; i < dies_.size(); ++i)
        {
          const OutlineDie &d = dies_[i];
          DieEvaluation &de = ev.dies[i];
          de.indentation = d.delta;
          std::stable_sort(de.pressure.begin(), de.pressure.end(),
                           [](const PressurePoint &a, const PressurePoint &b) { return a.s < b.s; });
          // Each side of the centre as a zone from s = 0 outward (the gap beyond a flat
          // punch is -infinity: an open point).
          const double tol = 1e-9 * problem_.body->outline.size();
          std::vector<std::pair<double, double>> up, down;
          // Points beyond a flat punch's edge (no die surface: infinite gap) are left out, and
          // a zone that reaches the edge ends there.
          const double extent = d.condition.profile.extent();
          for (const auto &[si, gi] : gaps[i])
            {
              if (!std::isfinite(gi))
                continue;
              if (si >= -tol)
                up.emplace_back(std::max(si, 0.0), gi);
              if (si <= tol)
                down.emplace_back(std::max(-si, 0.0), gi);
            }
          std::stable_sort(up.begin(), up.end());
          std::stable_sort(down.begin(), down.end());
          const bool has_up = d.frame.s_max > tol, has_down = d.frame.s_min < -tol;
          const auto [hi, hi_gap] =
            has_up ? zone_end(up, std::min(d.frame.s_max, extent)) : std::pair{0.0, 0.0};
          const auto [lo, lo_gap] =
            has_down ? zone_end(down, std::min(-d.frame.s_min, extent)) : std::pair{0.0, 0.0};
          de.zone_lo = -lo, de.zone_hi = hi;
          de.two_edges = has_up && has_down;
          if (de.two_edges)
            de.half_width = 0.5 * (hi + lo), de.half_width_gap = 0.5 * (hi_gap + lo_gap);
          else
            de.half_width = has_up ? hi : lo, de.half_width_gap = has_up ? hi_gap : lo_gap;
        }
      if (!ev.dies.empty())
        {
          const DieEvaluation &first = ev.dies.front();
          ev.force = ev.force_penalty = first.force;
          ev.force_trace = first.force_trace;
          ev.half_width = first.half_width, ev.half_width_gap = first.half_width_gap;
          ev.max_penetration = first.max_penetration;
        }
    }

    // Pass 0's zones: where g0 < delta (indentation) or Hertz's contact radius
    // a = (3 P R / 4 E*)^(1/3), E* = E / (1 - nu^2) (force), and at least the flat face.
    void AxisymmetricSolver::estimate_die_zones()
    {
      const double e_star = problem_.material.youngs_modulus /
                            (1 - problem_.material.poisson_ratio * problem_.material.poisson_ratio);
      for (OutlineDie &d : dies_)
        {
          const axisym::DieProfile &pr = d.condition.profile;
          using Shape = axisym::DieProfile::Shape;
          const double flat = pr.shape == Shape::flat           ? pr.radius
                              : pr.shape == Shape::flat_rounded ? pr.flat_radius
                                                                : 0.0;
          const double curvature_radius =
            pr.shape == Shape::paraboloid ? pr.radius : pr.edge_radius;
          double reach = flat;
          if (pr.shape != Shape::flat)
            reach += d.condition.indentation
                       ? std::sqrt(2 * curvature_radius * *d.condition.indentation)
                       : std::cbrt(3 * *d.condition.force * curvature_radius / (4 * e_star));
          d.zone_lo = std::max(d.frame.s_min, -reach);
          d.zone_hi = std::min(d.frame.s_max, reach);
        }
    }

    // Refinement toward the dies' zones (axisymmetric_fem.h, "Dies"): the cells near the zone
    // to die_zone_cells * 2^L across it, then each free end die_edge_refinements times more.
    void AxisymmetricSolver::refine_toward_dies()
    {
      auto distance_to_segment = [](const Point<2> &x, const Point<2> &a, const Point<2> &b) {
        const Tensor<1, 2> ab = b - a;
        const double t = ab.norm_square() > 0
                           ? std::clamp((x - a) * ab / ab.norm_square(), 0.0, 1.0)
                           : 0.0;
        return x.distance(a + t * ab);
      };
      auto refine_while = [&](const auto &wants) {
        for (int round = 0; round < 40; ++round)
          {
            bool any = false;
            for (const auto &cell : triangulation_.active_cell_iterators())
              if (wants(cell))
                cell->set_refine_flag(), any = true;
            if (!any)
              return;
            triangulation_.execute_coarsening_and_refinement();
          }
      };
      const double tol = 1e-9 * problem_.body->outline.size();
      for (const OutlineDie &d : dies_)
        {
          const double w = d.zone_hi - d.zone_lo;
          if (!(w > tol))
            continue;
          const double h = w / (options_.die_zone_cells * std::pow(2.0, level_));
          const axisym::Point pa = d.frame.point_at(d.zone_lo), pb = d.frame.point_at(d.zone_hi);
          const Point<2> a(pa.r, pa.z), b(pb.r, pb.z);
          // A cell's size: its diameter / sqrt 2 (a square's side).
          refine_while([&](const auto &cell) {
            const double size = cell->diameter() / std::sqrt(2.0);
            return size > 1.01 * h &&
                   distance_to_segment(cell->center(), a, b) < 0.5 * w + cell->diameter();
          });
          for (const auto &[s_end, free] :
               {std::pair{d.zone_lo, d.zone_lo > d.frame.s_min + tol},
                std::pair{d.zone_hi, d.zone_hi < d.frame.s_max - tol}})
            {
              if (!free)
                continue;
              const axisym::Point pe = d.frame.point_at(s_end);
              const Point<2> e(pe.r, pe.z);
              for (int j = 1; j <= options_.die_edge_refinements; ++j)
                {
                  const double hj = h / std::pow(2.0, j);
                  refine_while([&](const auto &cell) {
                    return cell->diameter() / std::sqrt(2.0) > 1.01 * hj &&
                           cell->center().distance(e) < 2.0 * cell->diameter();
                  });
                }
            }
        }
    }

    // 6o. Boundary terms of an outline problem: the work W = int t.u_h r ds of the pressure
    // and traction parts, and on the displacement parts b_c = int (s_h n).u* r ds and
    // b_r = int (s_h n).(u_h - u*) r ds (s_h n the element trace).
    void AxisymmetricSolver::outline_boundary_terms(double &work, double &b_c, double &b_r) const
    {
      using Kind = axisym::PartCondition::Kind;
      const QGauss<1> quadrature(options_.degree + 2);
      FEFaceValues<2> fv(mapping(), fe_, quadrature,
                         update_values | update_gradients | update_quadrature_points |
                           update_normal_vectors | update_JxW_values);
      const unsigned int n_q = quadrature.size();
      std::vector<Vector<double>> u(n_q, Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> grad(n_q, std::vector<Tensor<1, 2>>(2));
      for (const auto &cell : dof_handler_.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const axisym::PartCondition &c =
              problem_.body->condition_of_edge(edge_of(cell->face(f)));
            if (c.kind != Kind::pressure && c.kind != Kind::traction &&
                c.kind != Kind::displacement)
              continue;
            fv.reinit(cell, f);
            fv.get_function_values(solution_, u);
            if (c.kind == Kind::displacement)
              fv.get_function_gradients(solution_, grad);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const Point<2> x = fv.quadrature_point(q);
                const Tensor<1, 2> n = fv.normal_vector(q);
                const double w = x[0] * fv.JxW(q);
                if (c.kind == Kind::displacement)
                  {
                    const Stress s = stress_at(x, strain(x[0], u[q][0], grad[q][0], grad[q][1]));
                    const double t_r = s[0] * n[0] + s[3] * n[1];
                    const double t_z = s[3] * n[0] + s[1] * n[1];
                    b_c += (t_r * c.displacement[0] + t_z * c.displacement[1]) * w;
                    b_r += (t_r * (u[q][0] - c.displacement[0]) +
                            t_z * (u[q][1] - c.displacement[1])) *
                           w;
                    continue;
                  }
                const double t_r = c.kind == Kind::pressure ? -c.pressure * n[0] : c.traction[0];
                const double t_z = c.kind == Kind::pressure ? -c.pressure * n[1] : c.traction[1];
                work += (t_r * u[q][0] + t_z * u[q][1]) * w;
              }
          }
    }

    // 6r. Support reactions of an outline problem. The residual of the discrete equilibrium,
    // R_i = int s_h.e(phi_i) r dr dz - int f.phi_i r dr dz - int_St t.phi_i r ds, vanishes at
    // the free dofs (to the solver's accuracy); at a dof held by a symmetry or displacement
    // part it is the force that part exerts on the body (per radian). Summed per part and
    // component and times 2 pi: N for the full body. Taking v = e_z everywhere (e(v) = 0)
    // gives the global balance: the z reactions sum to minus the applied z load.
    std::vector<PartReaction> AxisymmetricSolver::reactions() const
    {
      using Kind = axisym::PartCondition::Kind;
      const axisym::Body &body = *problem_.body;
      std::vector<PartReaction> out;
      std::map<std::string, std::size_t> index;
      for (const std::string &part : body.outline.parts())
        {
          const Kind kind = body.conditions.at(part).kind;
          if (kind != Kind::symmetry && kind != Kind::displacement)
            continue;
          index[part] = out.size();
          PartReaction reaction;
          reaction.part = part;
          reaction.condition = axisym::to_string(kind);
          out.push_back(reaction);
        }
      if (reaction_dofs_.empty())
        return out;

      FEValues<2> fe_values(mapping(), fe_, cell_quadrature_,
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
      // The face rule and flags of the assembly (3o), so that R is the discrete residual.
      FEFaceValues<2> face_values(mapping(), fe_, QGauss<1>(options_.degree + 1),
                                  update_values | update_quadrature_points |
                                    update_normal_vectors | update_JxW_values);
      const unsigned int n = fe_.n_dofs_per_cell(), n_q = cell_quadrature_.size();
      std::vector<Vector<double>> u(n_q, Vector<double>(2));
      std::vector<std::vector<Tensor<1, 2>>> grad(n_q, std::vector<Tensor<1, 2>>(2));
      std::vector<types::global_dof_index> dofs(n);
      Vector<double> cell_residual(n), cell_load(n), residual(dof_handler_.n_dofs());
      for (const auto &cell : dof_handler_.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          if (std::none_of(dofs.begin(), dofs.end(), [&](types::global_dof_index i) {
                return reaction_dofs_.count(i) > 0;
              }))
            continue;
          fe_values.reinit(cell);
          fe_values.get_function_values(solution_, u);
          fe_values.get_function_gradients(solution_, grad);
          cell_residual = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<2> x = fe_values.quadrature_point(q);
              const double w = x[0] * fe_values.JxW(q);
              const Stress s = stress_at(x, strain(x[0], u[q][0], grad[q][0], grad[q][1]));
              const std::array<double, 2> f = loads_.force(x[0], x[1]);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c = fe_.system_to_component_index(i).first;
                  const double phi = fe_values.shape_value_component(i, q, c);
                  const Stress b =
                    shape_strain(c, x[0], phi, fe_values.shape_grad_component(i, q, c));
                  cell_residual(i) += (dot(b, s) - f[c] * phi) * w;
                }
            }
          cell_load = 0;
          add_outline_tractions(cell, face_values, cell_load);
          cell_residual -= cell_load;
          for (unsigned int i = 0; i < n; ++i)
            residual(dofs[i]) += cell_residual(i);
        }
      for (const auto &[dof, held] : reaction_dofs_)
        {
          PartReaction &reaction =
            out[index.at(body.outline.edges()[held.edge].part)];
          (held.component == 0 ? reaction.force_r : reaction.force_z) += 2 * pi * residual(dof);
        }
      return out;
    }

    // Fields at the sample points; legacy: z < 0 mirrored (u_z and sigma_rz are odd in z).
    // Outline: as given. A sample on an arc may lie just outside the Q_p image of the arc
    // (deal.II 9.4 then returns an invalid cell rather than throwing), so a miss is retried
    // with looser tolerances (unit-cell coordinates) and projected onto the unit cell; with
    // straight-sided cells the nearest boundary cell is taken.
    std::vector<FieldSample> AxisymmetricSolver::samples() const
    {
      using Found = std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>;
      const auto locate = [&](const Point<2> &x) -> Found {
        if (!outline_)
          return GridTools::find_active_cell_around_point(mapping(), dof_handler_, x);
        for (const double tolerance : {1e-10, 1e-6, 1e-3})
          {
            Found found;
            try
              {
                found = GridTools::find_active_cell_around_point(mapping(), dof_handler_, x,
                                                                 {}, tolerance);
              }
            catch (const std::exception &)
              {
                continue;
              }
            if (found.first.state() == IteratorState::valid)
              {
                found.second = GeometryInfo<2>::project_to_unit_cell(found.second);
                return found;
              }
          }
        // Still outside (straight-sided studies: a sample on an arc lies beyond the chord):
        // the boundary cell nearest in unit coordinates, the point projected onto it.
        Found best;
        double best_distance = std::numeric_limits<double>::infinity();
        for (const auto &cell : dof_handler_.active_cell_iterators())
          {
            if (!cell->at_boundary() || cell->center().distance(x) > 2 * cell->diameter())
              continue;
            try
              {
                const Point<2> unit = mapping().transform_real_to_unit_cell(cell, x);
                const double d = GeometryInfo<2>::distance_to_unit_cell(unit);
                if (d < best_distance)
                  best_distance = d, best = {cell, GeometryInfo<2>::project_to_unit_cell(unit)};
              }
            catch (const std::exception &)
              {}
          }
        if (best.first.state() != IteratorState::valid)
          throw std::runtime_error("sample (" + std::to_string(x[0]) + ", " +
                                   std::to_string(x[1]) + ") is not in any cell of the mesh");
        return best;
      };
      std::vector<FieldSample> out;
      for (const auto &[r, z] : problem_.samples)
        {
          const Point<2> x(r, outline_ ? z : std::abs(z));
          const Found found = locate(x);
          const Quadrature<2> point(std::vector<Point<2>>{found.second});
          FEValues<2> fv(mapping(), fe_, point, update_values | update_gradients);
          fv.reinit(found.first);
          std::vector<Vector<double>> u(1, Vector<double>(2));
          std::vector<std::vector<Tensor<1, 2>>> grad(1, std::vector<Tensor<1, 2>>(2));
          fv.get_function_values(solution_, u);
          fv.get_function_gradients(solution_, grad);
          const Stress s = stress_at(x, strain(r, u[0][0], grad[0][0], grad[0][1]));
          const double sign = !outline_ && z < 0 ? -1.0 : 1.0;
          out.push_back({r, z, u[0][0], sign * u[0][1], {{s[0], s[1], s[2], sign * s[3]}}});
        }
      return out;
    }

    void AxisymmetricSolver::write_vtu() const
    {
      const StressPostprocessor post(d_, loads_);
      DataOut<2> data_out;
      data_out.attach_dof_handler(dof_handler_);
      data_out.add_data_vector(solution_, post);
      if (outline_) // cells next to an arc are curved inside too (transfinite interpolation)
        data_out.build_patches(mapping(), options_.degree, DataOut<2>::curved_inner_cells);
      else
        data_out.build_patches(mapping(), options_.degree);
      std::filesystem::create_directories(options_.vtu_directory);
      const std::filesystem::path path =
        std::filesystem::path(options_.vtu_directory) / "fem_solution.vtu";
      std::ofstream out(path);
      if (!out)
        throw std::runtime_error("cannot write " + path.string());
      data_out.write_vtu(out);
    }

    FemResult AxisymmetricSolver::run()
    {
      const auto t_start = Clock::now();
      FemResult result;
      result.degree = options_.degree;
      result.refinements = options_.refinements;
      result.mesh_generator =
        options_.mesh == FemOptions::MeshGenerator::gmsh ? "gmsh" : "structured";
      result.outline = outline_;
      if (problem_.die || !dies_.empty())
        {
          result.contact.emplace();
          result.contact->part = outline_ ? dies_.front().part : "outer";
          result.contact->method = problem_.contact.method;
          result.contact->unilateral = mode_ == Mode::unilateral;
          if (problem_.die)
            result.contact->indentation = problem_.die->indentation;
        }

      auto finish = [&](const Evaluation &ev) {
        result.functionals = ev.functionals;
        if (ev.error_sq)
          result.stress_l2_error = std::sqrt(*ev.error_sq),
          result.stress_l2_norm = std::sqrt(*ev.norm_sq);
        if (ev.error_max)
          result.stress_max_error = *ev.error_max, result.stress_max_norm = *ev.norm_max;
        if (ev.u_error_sq)
          result.displacement_l2_error = std::sqrt(*ev.u_error_sq),
          result.displacement_l2_norm = std::sqrt(*ev.u_norm_sq);
        if (result.contact)
          {
            ContactResult &c = *result.contact;
            c.half_width = ev.half_width;
            c.half_width_gap = ev.half_width_gap;
            c.force = ev.force;
            c.force_trace = ev.force_trace;
            c.force_penalty = ev.force_penalty;
            c.max_penetration = ev.max_penetration;
            c.pressure = ev.pressure;
            result.other_dies.clear();
            for (std::size_t d = 0; d < ev.dies.size(); ++d)
              {
                const DieEvaluation &de = ev.dies[d];
                ContactResult &x = d == 0 ? c : result.other_dies.emplace_back(c);
                x.part = dies_[d].part;
                x.indentation = de.indentation;
                x.half_width = de.half_width;
                x.half_width_gap = de.half_width_gap;
                x.force = x.force_penalty = de.force;
                x.force_trace = de.force_trace;
                x.max_penetration = de.max_penetration;
                x.pressure = de.pressure;
                x.zone.reset();
                if (de.two_edges)
                  x.zone = std::array<double, 2>{{de.zone_lo, de.zone_hi}};
                if (d > 0)
                  x.iterations.clear(); // the steps are the first die's record
              }
          }
        result.assembly_seconds = assembly_s_;
        result.solve_seconds = solve_s_;
        result.total_seconds = seconds_since(t_start);
      };

      // Unilateral: pass 0 on a mesh without a split; each further pass remeshes with the
      // outer line split (and graded) at the half-width found by the previous pass.
      const double a = problem_.geometry.half_length();
      const int n_passes = mode_ == Mode::unilateral ? 1 + options_.edge_fitting_passes : 1;
      try
        {
          for (int pass = 0; pass < n_passes; ++pass)
            {
              if (pass > 0 && outline_)
                {
                  // Refine around the zones found (a lost contact keeps the estimate).
                  for (std::size_t d = 0; d < dies_.size(); ++d)
                    {
                      const ContactResult &x = d == 0 ? *result.contact : result.other_dies[d - 1];
                      const double lo = x.zone ? (*x.zone)[0]
                                        : dies_[d].frame.s_max > 0 ? 0.0
                                                                   : -x.half_width;
                      const double hi = x.zone ? (*x.zone)[1]
                                        : dies_[d].frame.s_max > 0 ? x.half_width
                                                                   : 0.0;
                      if (hi > lo)
                        dies_[d].zone_lo = lo, dies_[d].zone_hi = hi;
                    }
                  dof_handler_.clear();
                  triangulation_.clear();
                }
              else if (pass > 0)
                {
                  const double c = result.contact->half_width;
                  if (!(c > 1e-3 * a && c < a * (1 - 1e-3)))
                    break; // no interior edge to fit
                  split_ = c;
                  dof_handler_.clear();
                  triangulation_.clear();
                }
              // Passes before the last one only locate the edge: one level coarser each.
              level_ = std::max(0, options_.refinements - (n_passes - 1 - pass));
              const auto t0 = Clock::now();
              make_mesh();
              setup_system();
              assembly_s_ += seconds_since(t0);
              assemble_base();
              result.n_dofs = dof_handler_.n_dofs();
              result.n_cells = triangulation_.n_active_cells();
              result.base_mesh_size = base_mesh_size_;
              result.n_base_cells = n_base_cells_;
              result.base_mesh_subdivided = base_mesh_subdivided_;
              result.base_mesh_flat_corners = base_mesh_flat_corners_;
              std::ostringstream line;
              line.precision(6);
              if (outline_)
                line << "outline section: base mesh " << n_base_cells_ << " cells (h0 = "
                     << base_mesh_size_ << " m" << (base_mesh_subdivided_ ? ", subdivided" : "")
                     << "), ";
              if (outline_ && base_mesh_flat_corners_ > 0)
                progress("warning: " + std::to_string(base_mesh_flat_corners_) +
                         " base cell(s) with two faces on one outline edge (a 180 degree "
                         "corner): the stress next to that boundary vertex converges slowly");
              line << "pass " << pass << ", L = " << level_ << ", Q" << options_.degree << ": "
                   << result.n_cells << " cells, " << result.n_dofs << " dofs ("
                   << result.mesh_generator << " mesh";
              if (split_)
                line << ", outer side split at z = " << *split_ << " = " << *split_ / a << " a";
              progress(line.str() + ")");
              if (result.contact)
                result.contact->h_min = h_min_;

              if (mode_ != Mode::unilateral)
                {
                  system_matrix_.copy_from(base_matrix_);
                  system_rhs_ = base_rhs_;
                  solve_linear();
                  finish(evaluate(nullptr));
                  result.success = true;
                }
              else
                {
                  result.contact->penalty = kappa_;
                  result.contact->penalty_factor = options_.penalty_factor;
                  result.contact->edge_fitting_passes = pass;
                  result.success = false;
                  active_set_loop(result, pass, finish);
                  if (!result.success)
                    break;
                }
            }
          if (result.success)
            result.samples = samples();
          if (result.success && outline_)
            result.reactions = reactions();
        }
      catch (const std::exception &e)
        {
          result.success = false;
          result.message = std::string("numerical failure: ") + e.what();
        }
      if (!options_.vtu_directory.empty() && result.success)
        write_vtu();
      result.total_seconds = seconds_since(t_start);
      return result;
    }

    // 5c. Active-set loop, from the whole outer side in contact (paper iteration 0), until the
    // set repeats its previous state; a repeat of an older state is a cycle (failure).
    template <typename Finish>
    void AxisymmetricSolver::active_set_loop(FemResult &result, int pass, const Finish &finish)
    {
      ContactResult &contact = *result.contact;
      // Start: all in contact (pass 0), or z < c of the previous pass (the split point).
      // Outline dies: the zone the mesh was refined for, where the die has a surface.
      std::vector<char> start(contact_faces_.size() * face_quadrature_.size(), 1);
      if ((pass > 0 && split_) || outline_)
        {
          FEFaceValues<2> fv(mapping(), fe_, face_quadrature_, update_quadrature_points);
          const unsigned int n_q = face_quadrature_.size();
          for (std::size_t k = 0; k < contact_faces_.size(); ++k)
            {
              const ContactFace &face = contact_faces_[k];
              fv.reinit(face.cell, face.face);
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const Point<2> x = fv.quadrature_point(q);
                  if (!outline_)
                    start[k * n_q + q] = x[1] < *split_;
                  else
                    {
                      const OutlineDie &d = dies_[face.die];
                      const double s = d.frame.coordinate({x[0], x[1]});
                      start[k * n_q + q] = s >= d.zone_lo && s <= d.zone_hi &&
                                           std::isfinite(d.condition.profile.gap(std::abs(s)));
                    }
                }
            }
        }
      std::vector<std::vector<char>> history{start};
      for (int it = 0;; ++it)
        {
          const std::vector<char> &active = history.back();
          add_penalty(active);
          solve_linear();
          apply_force_control(active);
          const Evaluation ev = evaluate(&active);
          std::vector<char> next = active_set();
          ActiveSetStep step;
          step.pass = pass;
          step.iteration = it;
          step.n_active = static_cast<int>(std::count(active.begin(), active.end(), 1));
          for (std::size_t i = 0; i < next.size(); ++i)
            step.n_changed += next[i] != active[i];
          step.half_width = ev.half_width;
          step.force = ev.force;
          step.force_trace = ev.force_trace;
          step.force_penalty = ev.force_penalty;
          step.functionals = ev.functionals;
          contact.iterations.push_back(step);
          contact.active_set_iterations = it + 1;
          std::ostringstream line;
          line.precision(6);
          line << "pass " << pass << ", active-set step " << it << ": |A| = " << step.n_active
               << " of " << active.size() << ", changed " << step.n_changed;
          if (outline_)
            for (std::size_t d = 0; d < ev.dies.size(); ++d)
              line << "; " << dies_[d].part << ": c = " << ev.dies[d].half_width
                   << " m, delta = " << ev.dies[d].indentation << " m, P = " << ev.dies[d].force
                   << " N (trace " << ev.dies[d].force_trace << ")";
          else
            line << ", c/a = " << ev.half_width / problem_.geometry.half_length()
                 << ", P = " << ev.force << " N (trace " << ev.force_trace << ")";
          progress(line.str());
          finish(ev);
          if (step.n_changed == 0)
            {
              result.success = true;
              return;
            }
          const auto seen = std::find(history.begin(), history.end(), next);
          if (seen != history.end())
            {
              result.message = "active set cycles: step " + std::to_string(it + 1) +
                               " would repeat step " + std::to_string(seen - history.begin()) +
                               " (pass " + std::to_string(pass) + ")";
              return;
            }
          if (it + 1 >= options_.max_active_set_iterations)
            {
              result.message = "active set not converged in " +
                               std::to_string(options_.max_active_set_iterations) +
                               " iterations (pass " + std::to_string(pass) + ")";
              return;
            }
          history.push_back(std::move(next));
        }
    }
  } // namespace

  FemResult solve(const axisym::Problem &problem, const FemOptions &options,
                  const StressFunction &exact_stress,
                  const DisplacementFunction &exact_displacement)
  {
    options.validate();
    check_supported(problem, options);
    AxisymmetricSolver solver(problem, options, exact_stress, exact_displacement);
    return solver.run();
  }

  std::string format_convergence_table(const std::vector<TableColumn> &columns)
  {
    ConvergenceTable table;
    std::size_t n_rows = 0;
    for (const TableColumn &c : columns)
      n_rows = std::max(n_rows, c.values.size());
    for (std::size_t row = 0; row < n_rows; ++row)
      for (const TableColumn &c : columns)
        if (row < c.values.size())
          table.add_value(c.name, c.values[row]);
    for (const TableColumn &c : columns)
      {
        table.set_precision(c.name, c.precision);
        table.set_scientific(c.name, c.scientific);
        if (c.rates)
          table.evaluate_convergence_rates(c.name, ConvergenceTable::reduction_rate_log2);
      }
    std::ostringstream out;
    table.write_text(out);
    return out.str();
  }
} // namespace fem
