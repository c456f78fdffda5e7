// The FEM reference (axisymmetric_fem.h): its options, fem::solve, and the passes and the
// active-set loop that drive the solver's parts (axisymmetric_solver.h lists the units).
// The story follows deal.II step-8 (elasticity) and step-41 (active sets):
//   1. the gmsh mesh of the section's outline (the hollow-cylinder form: its half section),
//      manifolds on the arcs, refinement toward the dies,
//   2. degrees of freedom and constraints per part (symmetry, displacement, axis, a
//      prescribed die zone),
//   3. assembly of the r-weighted axisymmetric stiffness, pressures, tractions, body loads,
//   4. linear solve (UMFPACK or CG + SSOR),
//   5. unilateral contact: penalty on the active set at the face quadrature points,
//   6. post-processing: functionals, contact forces, zones, samples, reactions, VTU.
#include "fem_reference/axisymmetric_fem.h"

#include "fem_reference/axisymmetric_solver.h"
#include "problem/sample_checks.h"

#include <deal.II/base/convergence_table.h>

#include <algorithm>
#include <cstdlib>
#include <sys/resource.h>
#include <iomanip>
#include <limits>

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
    if (!(adaptive_tolerance >= 1e-12 && adaptive_tolerance <= 1e-1))
      fail("adaptive_tolerance (fem.refinement.tolerance, --adaptive-tolerance)",
           std::to_string(adaptive_tolerance), "must be in [1e-12, 1e-1]");
    if (!(adaptive_max_dofs >= 100 && adaptive_max_dofs <= 100000000))
      fail("adaptive_max_dofs (fem.refinement.max_dofs, --max-dofs)", std::to_string(adaptive_max_dofs),
           "must be in [100, 1e8]");
    if (!(adaptive_fraction > 0 && adaptive_fraction < 1))
      fail("adaptive_fraction", std::to_string(adaptive_fraction), "must be in (0, 1)");
    if (adaptive_max_cycles < 1)
      fail("adaptive_max_cycles", std::to_string(adaptive_max_cycles), "must be >= 1");
    if (!(outline_cells_on_shortest_edge >= 1 && outline_cells_on_shortest_edge <= 64))
      fail("outline_cells_on_shortest_edge", std::to_string(outline_cells_on_shortest_edge),
           "must be in [1, 64]");
  }

  struct MpiSession::State
  {
    std::unique_ptr<Utilities::MPI::MPI_InitFinalize> mpi;
  };

  MpiSession::MpiSession(int &argc, char **&argv)
    : state_(std::make_unique<State>())
  {
    if (!launched_by_mpi())
      return;
    // One thread per rank: the ranks are the parallelism.
    state_->mpi = std::make_unique<Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
    active_ = true;
    rank_ = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    size_ = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  }

  MpiSession::~MpiSession() = default;

  bool MpiSession::launched_by_mpi()
  {
    // Open MPI's mpirun, MPICH's and Intel's hydra (PMI), PMIx launchers, Slurm's srun.
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }

  void check_supported(const axisym::Problem &problem, const FemOptions &options)
  {
    if (!problem.body)
      throw axisym::InputError("problem: no body (parser bug?)");
    // The goal-oriented cycles leave out the samples at a vertex where the stress has no
    // value (adaptive_cycles); with nothing left there is no goal.
    if (options.adaptive && options.adaptive_goal == FemOptions::AdaptiveGoal::samples &&
        !problem.samples.empty())
      {
        const std::vector<bool> with_a_value = axisym::samples_with_a_value(problem);
        if (std::count(with_a_value.begin(), with_a_value.end(), true) == 0)
          throw axisym::InputError("fem.refinement.goal = \"samples\" (--adaptive-goal samples): "
                                   "every sample lies at a vertex where the stress has no value "
                                   "(problem/sample_checks.h), which the refinement would chase "
                                   "without end; give a sample away from the vertices, or refine "
                                   "for the energy");
      }
    if (Utilities::MPI::job_supports_mpi() && problem.contact.method == "fixed" &&
        !problem.body->die_parts().empty())
      throw axisym::InputError("contact.method = \"fixed\" under MPI: a prescribed zone moves "
                               "mesh vertices onto its ends, which the distributed mesh does "
                               "not do; run fem_solve without mpirun");
    if (problem.contact.method == "fixed")
      for (const std::string &part : problem.body->die_parts())
        if (problem.body->conditions.at(part).die.force)
          throw axisym::InputError("boundary." + part + ".die.force with contact.method = "
                                   "\"fixed\": a prescribed zone needs the die's indentation "
                                   "(force control is for the unilateral problem)");
    // The hollow-cylinder form's outer side is the die's part: it carries no pressure too.
    if (problem.legacy_cylinder && problem.die && problem.loading &&
        problem.loading->outer_pressure != 0)
      throw axisym::InputError("loading.outer_pressure = " +
                               std::to_string(problem.loading->outer_pressure) +
                               " with a die: the outer side r = R2 is the die's part, which "
                               "carries no pressure besides (set outer_pressure to 0)");
  }

  FemOptions options_from_problem(const axisym::Problem &problem)
  {
    FemOptions o;
    o.degree = problem.fem.degree;
    o.refinements = problem.fem.refinements;
    o.adaptive = problem.fem.adaptive;
    o.adaptive_tolerance = problem.fem.adaptive_tolerance;
    o.adaptive_max_dofs = problem.fem.adaptive_max_dofs;
    o.adaptive_goal = problem.fem.adaptive_goal_samples ? FemOptions::AdaptiveGoal::samples
                                                        : FemOptions::AdaptiveGoal::energy;
    return o;
  }

  namespace internal
  {
    FemResult AxisymmetricSolver::run()
    {
      const auto t_start = Clock::now();
      FemResult result;
      result.degree = options_.degree;
      result.refinements = options_.refinements;
      result.mesh_generator = "gmsh";
      if (!dies_.empty())
        {
          result.contact.emplace();
          result.contact->part = dies_.front().part;
          result.contact->method = problem_.contact.method;
          result.contact->unilateral = mode_ == Mode::unilateral;
          result.contact->indentation = dies_.front().delta;
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
        result.linear_solver = linear_solver_used_;
        result.linear_iterations = linear_iterations_;
        result.total_seconds = seconds_since(t_start);
      };

      // The dies' zones that the last solve found (a lost contact keeps the estimate): the
      // next pass refines around them, the next adaptive cycle's active set starts from them.
      auto zones_from_result = [&]() {
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
      };
      // Dofs, assembly and the solve (the active-set loop with a unilateral die) on the
      // current mesh; `what` names the mesh in the progress line. False on failure.
      auto solve_on_mesh = [&](const int pass, const std::string &what) {
        const auto t0 = Clock::now();
        setup_system();
        assembly_s_ += seconds_since(t0);
        assemble_base();
        result.n_dofs = dof_handler_.n_dofs();
        result.n_cells = triangulation_.n_global_active_cells();
        result.processes = distributed_ ? Utilities::MPI::n_mpi_processes(comm_) : 1;
        result.base_mesh_size = base_mesh_size_;
        result.n_base_cells = n_base_cells_;
        result.base_mesh_subdivided = base_mesh_subdivided_;
        result.base_mesh_flat_corners = base_mesh_flat_corners_;
        result.graded_vertices = vertex_grading_;
        std::ostringstream line;
        line.precision(6);
        line << (body_.mirrored ? "half section (mirrored)" : "outline section")
             << ": base mesh " << n_base_cells_ << " cells (h0 = " << base_mesh_size_
             << " m" << (base_mesh_subdivided_ ? ", subdivided" : "") << "), " << what << ", Q"
             << options_.degree << ": " << result.n_cells << " cells, " << result.n_dofs
             << " dofs (" << result.mesh_generator << " mesh)";
        progress(line.str());
        if (result.contact)
          result.contact->h_min = h_min_;
        if (mode_ != Mode::unilateral)
          {
            reset_system();
            solve_linear();
            const auto t_evaluate = Clock::now();
            finish(evaluate(nullptr));
            std::ostringstream line;
            line.precision(3);
            line << "functionals and errors " << seconds_since(t_evaluate) << " s";
            progress(line.str());
            result.success = true;
          }
        else
          {
            result.contact->penalty = kappa_;
            result.contact->penalty_factor = options_.penalty_factor;
            // An adaptive cycle counts as a pass in the steps' history, not here.
            result.contact->edge_fitting_passes = std::min(pass, options_.edge_fitting_passes);
            result.success = false;
            active_set_loop(result, pass, finish);
          }
        return result.success;
      };

      // Unilateral: pass 0 on the mesh refined around the estimated zones; each further pass
      // remeshes, refined around the zones the previous pass found.
      const int n_passes = mode_ == Mode::unilateral ? 1 + options_.edge_fitting_passes : 1;
      try
        {
          for (int pass = 0; pass < n_passes; ++pass)
            {
              if (pass > 0)
                {
                  zones_from_result();
                  dof_handler_.clear();
                  triangulation_.clear();
                }
              // Passes before the last one only locate the edge: one level coarser each.
              level_ = std::max(0, options_.refinements - (n_passes - 1 - pass));
              const auto t0 = Clock::now();
              make_mesh();
              assembly_s_ += seconds_since(t0);
              if (base_mesh_flat_corners_ > 0)
                progress("warning: " + std::to_string(base_mesh_flat_corners_) +
                         " base cell(s) with two faces on one outline edge (a 180 degree "
                         "corner): the stress next to that boundary vertex converges slowly");
              if (!solve_on_mesh(pass, "pass " + std::to_string(pass) + ", L = " + std::to_string(level_)))
                break;
            }
          if (result.success && options_.adaptive)
            adaptive_cycles(result, n_passes, solve_on_mesh, zones_from_result);
          const auto t_post = Clock::now();
          // The last adaptive cycle recorded the samples on this mesh.
          if (result.success)
            result.samples = !result.adaptive_cycles.empty() && !problem_.samples.empty()
                               ? result.adaptive_cycles.back().samples
                               : samples();
          const double samples_s = seconds_since(t_post);
          // A mirrored section's mid-plane is no support of the body: no reactions.
          if (result.success && !body_.mirrored)
            result.reactions = reactions();
          std::ostringstream line;
          line.precision(3);
          line << "samples " << samples_s << " s, reactions " << seconds_since(t_post) - samples_s
               << " s";
          progress(line.str());
        }
      catch (const std::exception &e)
        {
          result.success = false;
          result.message = std::string("numerical failure: ") + e.what();
        }
      if (!options_.vtu_directory.empty() && result.success)
        write_vtu();
      result.total_seconds = seconds_since(t_start);
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      result.peak_memory_bytes = 1024.0 * static_cast<double>(usage.ru_maxrss); // ru_maxrss: KiB
      result.peak_memory_bytes_all_processes = all_sum(result.peak_memory_bytes);
      return result;
    }

    // Adaptive refinement (FemOptions::adaptive, issue 25 item 1): after the passes, record
    // the mesh's solution, stop or mark the cells carrying adaptive_fraction of the squared
    // estimate (Doerfler), refine them and solve again.
    template <typename Solve, typename Zones>
    void AxisymmetricSolver::adaptive_cycles(FemResult &result, const int first_pass,
                                             const Solve &solve_on_mesh, const Zones &zones_from_result)
    {
      auto t_cycle = Clock::now();
      std::vector<FemResult::AdaptiveCycle> &cycles = result.adaptive_cycles;
      // The samples the goal aims at: not those at a vertex where the stress has no value (a
      // sample at the stepped ring's 270-degree corner drew all 100 cycles toward it, its
      // sigma_zz from -9 to -7.4e5 MPa, and left a sample 1.4 cm away at -2.035 MPa, 2.5 %
      // off the graded meshes' -2.088).
      const std::vector<bool> aimed = axisym::samples_with_a_value(problem_);
      const bool goal = options_.adaptive_goal == FemOptions::AdaptiveGoal::samples &&
                        std::count(aimed.begin(), aimed.end(), true) > 0;
      for (int cycle = 0;; ++cycle)
        {
          Vector<float> eta = cell_estimates(solution_);
          FemResult::AdaptiveCycle rec;
          rec.n_dofs = result.n_dofs, rec.n_cells = result.n_cells;
          const double scale = gradient_norm();
          const double eta_norm = std::sqrt(all_sum(eta.norm_sqr()));
          rec.estimate = scale > 0 ? eta_norm / scale : 0.0;
          rec.reissner = result.functionals.reissner;
          // The change since the mesh had half the dofs (a cycle refines few cells where a
          // singularity dominates: the change from the previous cycle alone would stop early):
          // of the energy, or of the sample stresses over the largest of them (goal).
          if (goal)
            {
              rec.samples = samples();
              const Vector<double> z = dual_of_samples(rec.samples, aimed);
              const Vector<float> eta_z = cell_estimates(z);
              for (unsigned int i = 0; i < eta.size(); ++i)
                eta[i] *= eta_z[i];
            }
          rec.change = std::numeric_limits<double>::infinity();
          for (std::size_t c = cycles.size(); c-- > 0;)
            if (2 * cycles[c].n_dofs <= rec.n_dofs)
              {
                if (!goal)
                  rec.change = std::abs(rec.reissner - cycles[c].reissner) / std::abs(rec.reissner);
                else
                  {
                    double largest = 0, change = 0;
                    for (std::size_t k = 0; k < rec.samples.size(); ++k)
                      for (int m = 0; m < 4 && aimed[k]; ++m)
                        {
                          largest = std::max(largest, std::abs(rec.samples[k].sigma[m]));
                          change = std::max(change, std::abs(rec.samples[k].sigma[m] - cycles[c].samples[k].sigma[m]));
                        }
                    rec.change = largest > 0 ? change / largest : 0.0;
                  }
                break;
              }
          rec.force = result.contact ? result.contact->force : 0.0;
          if (!goal && !problem_.samples.empty())
            rec.samples = samples();
          rec.seconds = seconds_since(t_cycle);
          cycles.push_back(rec);
          std::ostringstream line;
          line.precision(6);
          line << "adaptive cycle " << cycle << ": " << rec.n_dofs << " dofs, estimate "
               << rec.estimate << ", Phi_R " << std::setprecision(12) << rec.reissner
               << std::setprecision(3) << ", change since half the dofs " << rec.change;
          progress(line.str());
          // Both on the energy's scale (the estimate is a relative energy-norm error), and both
          // must hold: Kelly's constant is not known (the stepped ring: the energy's error 3
          // times the estimate's square), the change since half the dofs overestimates (10
          // times there).
          const double tol = options_.adaptive_tolerance;
          if (goal && rec.change < tol)
            {
              result.adaptive_stop = "the sample stresses' change since half the dofs is below "
                                     "the tolerance";
              return;
            }
          if (!goal && rec.estimate * rec.estimate < tol && rec.change < tol)
            {
              result.adaptive_stop = "the estimate squared and the energy's change since half "
                                     "the dofs are below the tolerance";
              return;
            }
          if (cycle + 1 >= options_.adaptive_max_cycles)
            {
              result.adaptive_stop = "adaptive_max_cycles reached";
              return;
            }
          if (distributed_)
            parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
              dynamic_cast<parallel::distributed::Triangulation<2> &>(triangulation_), eta,
              options_.adaptive_fraction, 0.0, VectorTools::NormType::L2_norm);
          else
            GridRefinement::refine_and_coarsen_fixed_fraction(
              triangulation_, eta, options_.adaptive_fraction, 0.0,
              std::numeric_limits<unsigned int>::max(), VectorTools::NormType::L2_norm);
          // Each refined quadrilateral becomes four: about 3 n_dofs / n_cells more dofs each.
          double marked = 0;
          for (const auto &cell : triangulation_.active_cell_iterators())
            marked += cell->is_locally_owned() && cell->refine_flag_set() ? 1 : 0;
          marked = all_sum(marked);
          const double next = static_cast<double>(result.n_dofs) *
                              (1.0 + 3.0 * static_cast<double>(marked) / static_cast<double>(result.n_cells));
          if (next > static_cast<double>(options_.adaptive_max_dofs))
            {
              for (const auto &cell : triangulation_.active_cell_iterators())
                cell->clear_refine_flag();
              result.adaptive_stop = "the next cycle would pass adaptive_max_dofs";
              return;
            }
          t_cycle = Clock::now();
          const auto t0 = Clock::now();
          triangulation_.execute_coarsening_and_refinement();
          make_mapping();
          assembly_s_ += seconds_since(t0);
          if (mode_ == Mode::unilateral)
            zones_from_result();
          result.success = false;
          if (!solve_on_mesh(first_pass + cycle, "adaptive cycle " + std::to_string(cycle + 1)))
            return;
        }
    }

    Vector<double> AxisymmetricSolver::dual_of_samples(const std::vector<FieldSample> &now,
                                                       const std::vector<bool> &aimed)
    {
      double largest = 0;
      for (std::size_t k = 0; k < now.size(); ++k)
        for (int m = 0; m < 4 && aimed[k]; ++m)
          largest = std::max(largest, std::abs(now[k].sigma[m]));
      Vector<double> rhs(dof_handler_.n_dofs());
      if (!(largest > 0))
        return rhs;
      FEValues<2> fv(mapping(), fe_, cell_quadrature_,
                     update_values | update_gradients | update_quadrature_points | update_JxW_values);
      const unsigned int n = fe_.n_dofs_per_cell();
      Vector<double> local(n);
      std::vector<types::global_dof_index> dofs(n);
      // The cell around each sample (a mirrored body's image point in z > 0).
      std::vector<Point<2>> points;
      for (const FieldSample &s : now)
        points.emplace_back(s.r, std::abs(s.z));
      const std::vector<PointCell> cells = locate_points(points);
      for (std::size_t k = 0; k < now.size(); ++k)
        {
          const FieldSample &s = now[k];
          if (!cells[k].here || !aimed[k])
            continue;
          const DoFHandler<2>::active_cell_iterator cell = cells[k].cell;
          std::array<double, 4> weight{};
          for (int m = 0; m < 4; ++m)
            weight[m] = std::abs(s.sigma[m]) > 1e-3 * largest ? (s.sigma[m] > 0 ? 1.0 : -1.0) / largest : 0.0;
          fv.reinit(cell);
          double area = 0;
          for (const unsigned int q : fv.quadrature_point_indices())
            area += fv.JxW(q);
          local = 0;
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const double r = fv.quadrature_point(q)[0];
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c = fe_.system_to_component_index(i).first;
                  const Stress st =
                    d_ * shape_strain(c, r, fv.shape_value_component(i, q, c), fv.shape_grad_component(i, q, c));
                  double j = 0;
                  for (int m = 0; m < 4; ++m)
                    j += weight[m] * st[m];
                  local[i] += j * fv.JxW(q) / area;
                }
            }
          cell->get_dof_indices(dofs);
          constraints_.distribute_local_to_global(local, dofs, rhs);
        }
      return solve_homogeneous(rhs);
    }

    Vector<float> AxisymmetricSolver::cell_estimates(const Vector<double> &u) const
    {
      Vector<float> eta(triangulation_.n_active_cells());
      KellyErrorEstimator<2>::estimate(mapping(), dof_handler_, QGauss<1>(options_.degree + 1),
                                       std::map<types::boundary_id, const Function<2> *>(),
                                       u, eta);
      for (const auto &cell : triangulation_.active_cell_iterators())
        eta[cell->active_cell_index()] =
          cell->is_locally_owned()
            ? eta[cell->active_cell_index()] * static_cast<float>(std::sqrt(std::max(0.0, cell->center()[0])))
            : 0.0f;
      return eta;
    }

    double AxisymmetricSolver::gradient_norm() const
    {
      FEValues<2> fv(mapping(), fe_, cell_quadrature_,
                     update_gradients | update_quadrature_points | update_JxW_values);
      std::vector<std::vector<Tensor<1, 2>>> grads(cell_quadrature_.size(), std::vector<Tensor<1, 2>>(2));
      double sum = 0;
      for (const auto &cell : dof_handler_.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          fv.reinit(cell);
          fv.get_function_gradients(solution_, grads);
          for (unsigned int q = 0; q < cell_quadrature_.size(); ++q)
            sum += (grads[q][0].norm_square() + grads[q][1].norm_square()) * fv.quadrature_point(q)[0] *
                   fv.JxW(q);
        }
      return std::sqrt(all_sum(sum));
    }

    // 5c. Active-set loop, from the whole outer side in contact (paper iteration 0), until the
    // set repeats its previous state; a repeat of an older state is a cycle (failure).
    template <typename Finish>
    void AxisymmetricSolver::active_set_loop(FemResult &result, int pass, const Finish &finish)
    {
      ContactResult &contact = *result.contact;
      // Start: the zone the mesh was refined for, where the die has a surface.
      std::vector<char> start(contact_faces_.size() * face_quadrature_.size(), 1);
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
                const OutlineDie &d = dies_[face.die];
                const double s = d.frame.coordinate({x[0], x[1]});
                start[k * n_q + q] = s >= d.zone_lo && s <= d.zone_hi &&
                                     std::isfinite(d.condition.profile.gap(std::abs(s)));
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
          // Each rank holds the points of its own faces: counts are summed.
          step.n_active = static_cast<int>(
            all_sum(static_cast<double>(std::count(active.begin(), active.end(), 1))));
          int changed = 0;
          for (std::size_t i = 0; i < next.size(); ++i)
            changed += next[i] != active[i];
          step.n_changed = static_cast<int>(all_sum(changed));
          const double n_points = all_sum(static_cast<double>(active.size()));
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
               << " of " << n_points << ", changed " << step.n_changed;
          for (std::size_t d = 0; d < ev.dies.size(); ++d)
            line << "; " << dies_[d].part << ": c = " << ev.dies[d].half_width
                 << " m, delta = " << ev.dies[d].indentation << " m, P = " << ev.dies[d].force
                 << " N (trace " << ev.dies[d].force_trace << ")";
          progress(line.str());
          finish(ev);
          if (step.n_changed == 0)
            {
              result.success = true;
              return;
            }
          // The first earlier set equal to the next one on every rank.
          std::size_t seen = history.size();
          for (std::size_t h = 0; h < history.size() && seen == history.size(); ++h)
            if (!all_or(history[h] != next))
              seen = h;
          if (seen != history.size())
            {
              result.message = "active set cycles: step " + std::to_string(it + 1) +
                               " would repeat step " + std::to_string(seen) +
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
  } // namespace internal

  FemResult solve(const axisym::Problem &problem, const FemOptions &options,
                  const StressFunction &exact_stress,
                  const DisplacementFunction &exact_displacement)
  {
    options.validate();
    check_supported(problem, options);
    internal::AxisymmetricSolver solver(problem, options, exact_stress, exact_displacement);
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
