// 3.-5. Assembly, linear solves, penalty, force control and the active set of the FEM reference
// (axisymmetric_solver.h).
#include "fem_reference/axisymmetric_solver.h"

// The constraints' distribution into a Trilinos matrix with a deal.II right-hand side (the
// distributed assembly) is not among deal.II's precompiled combinations.
#include <deal.II/lac/affine_constraints.templates.h>

namespace fem::internal
{
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
          body_.condition_of_edge(edge_of(cell->face(f)));
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
    FEFaceValues<2> outline_face_values(mapping(), fe_, QGauss<1>(options_.degree + 1),
                                        update_values | update_quadrature_points |
                                          update_normal_vectors | update_JxW_values);
    const unsigned int n = fe_.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double> cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<Stress> b(n), db(n);

    if (distributed_)
      *mpi_base_matrix_ = 0;
    else
      base_matrix_ = 0;
    base_rhs_ = 0;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
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

        add_outline_tractions(cell, outline_face_values, cell_rhs);
        cell->get_dof_indices(dofs);
        if (distributed_)
          constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dofs, *mpi_base_matrix_,
                                                  base_rhs_);
        else
          constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dofs, base_matrix_,
                                                  base_rhs_);
      }
    if (distributed_)
      mpi_base_matrix_->compress(VectorOperation::add);
    assembly_s_ += seconds_since(t0);
  }

  void AxisymmetricSolver::reset_system()
  {
    if (distributed_)
      mpi_system_matrix_->copy_from(*mpi_base_matrix_);
    else
      system_matrix_.copy_from(base_matrix_);
    system_rhs_ = base_rhs_;
  }

  // 5a. Penalty kappa int_A (u.n - t) v.n r ds added to a copy of the base system, t the
  // target outward displacement. Force-controlled dies enter with
  // delta = 0, and unit_rhs_[k] receives the right-hand side of a unit indentation of the
  // k-th of them (t = g0 - delta: -kappa int_A v.n r ds per unit delta).
  void AxisymmetricSolver::add_penalty(const std::vector<char> &active)
  {
    const auto t0 = Clock::now();
    reset_system();
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
        if (distributed_)
          constraints_.distribute_local_to_global(m, rhs, dofs, *mpi_system_matrix_, system_rhs_);
        else
          constraints_.distribute_local_to_global(m, rhs, dofs, system_matrix_, system_rhs_);
        if (force_index[face.die] >= 0)
          constraints_.distribute_local_to_global(unit, dofs, unit_rhs_[force_index[face.die]]);
      }
    if (distributed_)
      mpi_system_matrix_->compress(VectorOperation::add);
    assembly_s_ += seconds_since(t0);
  }

  // 4. Linear solve; throws on failure (the caller turns it into a numerical outcome).
  void AxisymmetricSolver::solve_system(const Vector<double> &rhs, Vector<double> &x,
                                        const bool factorize)
  {
    linear_iterations_ = 0;
    if (distributed_)
      {
        solve_distributed(rhs, x, factorize);
        return;
      }
    if (options_.linear_solver == FemOptions::LinearSolver::direct)
      {
        if (factorize || !umfpack_)
          {
            umfpack_ = std::make_unique<SparseDirectUMFPACK>();
            umfpack_->initialize(system_matrix_);
          }
        umfpack_->vmult(x, rhs);
        linear_solver_used_ = "umfpack";
        return;
      }
    SolverControl control(20 * dof_handler_.n_dofs() + 100, options_.linear_tolerance * rhs.l2_norm());
    SolverCG<Vector<double>> cg(control);
    PreconditionSSOR<SparseMatrix<double>> ssor;
    ssor.initialize(system_matrix_, 1.2);
    cg.solve(system_matrix_, x, rhs, ssor);
    linear_solver_used_ = "cg-ssor";
    linear_iterations_ = control.last_step();
  }

  void AxisymmetricSolver::solve_distributed(const Vector<double> &rhs, Vector<double> &x,
                                             const bool factorize)
  {
    // The ranks' contributions (at their relevant dofs) summed into the owners' entries.
    TrilinosWrappers::MPI::Vector b;
    b.reinit(owned_dofs_, relevant_dofs_, comm_, true);
    for (const types::global_dof_index i : relevant_dofs_)
      if (rhs(i) != 0.0)
        b(i) += rhs(i);
    b.compress(VectorOperation::add);
    TrilinosWrappers::MPI::Vector u(owned_dofs_, comm_);
    const bool direct = options_.linear_solver == FemOptions::LinearSolver::direct &&
                        static_cast<long>(dof_handler_.n_dofs()) <= options_.mpi_direct_max_dofs;
    if (direct)
      {
        if (factorize || !mpi_direct_)
          {
            mpi_amg_.reset();
            mpi_direct_ = std::make_unique<TrilinosWrappers::SolverDirect>(
              mpi_direct_control_, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
            mpi_direct_->initialize(*mpi_system_matrix_);
          }
        mpi_direct_->solve(u, b);
        linear_solver_used_ = "mumps";
      }
    else
      {
        const auto t_setup = Clock::now();
        if (factorize || !mpi_amg_)
          {
            mpi_direct_.reset();
            // Near-null space: a constant u_r and a constant u_z (the axial translation is
            // the true null mode; u_r = const carries the hoop strain u_r / r, but is smooth,
            // which is what the aggregates need).
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            data.elliptic = true;
            data.higher_order_elements = options_.degree > 1;
            // Two Chebyshev sweeps, aggregation threshold 1e-4: 85 iterations to 1e-12 on the
            // Lame cylinder at 337 k dofs (0.02: 117; 0.1: 375; one sweep: 134, no faster).
            data.smoother_sweeps = 2;
            data.aggregation_threshold = 1e-4;
            DoFTools::extract_constant_modes(dof_handler_, ComponentMask(), data.constant_modes);
            mpi_amg_ = std::make_unique<TrilinosWrappers::PreconditionAMG>();
            mpi_amg_->initialize(*mpi_system_matrix_, data);
          }
        const double setup_s = seconds_since(t_setup);
        const auto t_cg = Clock::now();
        // With a penalty the force is kappa int (u.n - t) r ds: an algebraic error in u.n
        // comes back times kappa (penalty_factor E / h_min). On the paper's die at level 5
        // the relative residual 1e-10, 1e-12, 1e-13, 1e-14 left P off UMFPACK's by 1.8e-6,
        // 6.7e-8, 9.3e-9, 6.1e-10: with dies the residual asked is 100 times smaller.
        const double tolerance = options_.linear_tolerance * (kappa_ > 0 ? 1e-2 : 1.0);
        SolverControl control(20 * dof_handler_.n_dofs() + 100, tolerance * b.l2_norm());
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(*mpi_system_matrix_, u, b, *mpi_amg_);
        linear_solver_used_ = "cg-amg";
        linear_iterations_ = control.last_step();
        std::ostringstream line;
        line.precision(3);
        line << "CG + AMG: " << linear_iterations_ << " iterations in " << seconds_since(t_cg)
             << " s (multigrid set up in " << setup_s << " s)";
        progress(line.str());
      }
    constraints_.distribute(u);
    TrilinosWrappers::MPI::Vector ghosted(owned_dofs_, relevant_dofs_, comm_);
    ghosted = u;
    x = 0;
    for (const types::global_dof_index i : relevant_dofs_)
      x(i) = ghosted(i);
  }

  void AxisymmetricSolver::solve_linear()
  {
    const auto t0 = Clock::now();
    solve_system(system_rhs_, solution_, true);
    if (!distributed_) // solve_distributed distributes on the owned entries
      constraints_.distribute(solution_);
    bool finite = true;
    for (const double x : solution_)
      finite = finite && std::isfinite(x);
    if (all_or(!finite))
      throw std::runtime_error("linear solve produced non-finite values (singular matrix?)");
    solve_s_ += seconds_since(t0);
  }

  Vector<double> AxisymmetricSolver::solve_homogeneous(const Vector<double> &rhs)
  {
    const auto t0 = Clock::now();
    Vector<double> x(dof_handler_.n_dofs()), zero(dof_handler_.n_dofs());
    solve_system(rhs, x, false); // the factorization of solve_linear
    if (!distributed_)
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
    for (auto &die : out)
      for (double &v : die)
        v = all_sum(v);
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
        // The asked force is the whole body's: a mirrored section carries 1 / mirror_ of it.
        b(i) = *dies_[di].condition.force / (2 * pi * mirror_) - (base[di][0] - base[di][1]);
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
} // namespace fem::internal
