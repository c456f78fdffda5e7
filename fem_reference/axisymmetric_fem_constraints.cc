// 2. Degrees of freedom and constraints of the FEM reference (axisymmetric_solver.h).
#include "fem_reference/axisymmetric_solver.h"

namespace fem::internal
{
  // 2. Degrees of freedom and constraints.
  void AxisymmetricSolver::setup_system()
  {
    dof_handler_.distribute_dofs(fe_);
    constraints_.clear();
    hanging_node_constraints_.clear();
    if (distributed_)
      {
        owned_dofs_ = dof_handler_.locally_owned_dofs();
        DoFTools::extract_locally_relevant_dofs(dof_handler_, relevant_dofs_);
        constraints_.reinit(relevant_dofs_);
        hanging_node_constraints_.reinit(relevant_dofs_);
      }
    DoFTools::make_hanging_node_constraints(dof_handler_, constraints_);
    DoFTools::make_hanging_node_constraints(dof_handler_, hanging_node_constraints_);
    hanging_node_constraints_.close();
    // Distributed: each rank constrains the dofs of its cells and ghost cells from the faces
    // it sees, which are all the faces at the dofs of its own cells: the ranks agree on every
    // dof that two of them share (AffineConstraints::make_consistent_in_parallel is not
    // needed, and is quadratic in the constraints).
    add_outline_constraints();
    constraints_.close();

    base_matrix_.clear(); // they refer to the sparsity pattern rebuilt below
    system_matrix_.clear();
    mpi_direct_.reset();
    mpi_amg_.reset();
    if (distributed_)
      {
        DynamicSparsityPattern dsp(relevant_dofs_);
        DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
        SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs_, comm_, relevant_dofs_);
        mpi_base_matrix_ = std::make_unique<TrilinosWrappers::SparseMatrix>();
        mpi_system_matrix_ = std::make_unique<TrilinosWrappers::SparseMatrix>();
        mpi_base_matrix_->reinit(owned_dofs_, owned_dofs_, dsp, comm_);
        mpi_system_matrix_->reinit(owned_dofs_, owned_dofs_, dsp, comm_);
      }
    else
      {
        DynamicSparsityPattern dsp(dof_handler_.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
        sparsity_.copy_from(dsp);
        base_matrix_.reinit(sparsity_);
        system_matrix_.reinit(sparsity_);
      }
    base_rhs_.reinit(dof_handler_.n_dofs());
    system_rhs_.reinit(dof_handler_.n_dofs());
    solution_.reinit(dof_handler_.n_dofs());

    contact_faces_.clear();
    h_min_ = std::numeric_limits<double>::infinity();
    kappa_ = 0;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (!cell->is_locally_owned() || !cell->face(f)->at_boundary())
            continue;
          const types::boundary_id id = cell->face(f)->boundary_id();
          unsigned int die = 0;
          while (die < dies_.size() && dies_[die].boundary_id != id)
            ++die;
          if (die == dies_.size())
            continue;
          contact_faces_.push_back({cell, f, die});
          h_min_ = std::min(h_min_, cell->face(f)->measure());
        }
    h_min_ = all_min(h_min_);
    if (std::isfinite(h_min_))
      kappa_ = options_.penalty_factor * problem_.material.youngs_modulus / h_min_;
  }

  // 2o. Outline constraints. Each boundary node (the pair of u_r and u_z dofs at one support
  // point) collects a_r u_r + a_z u_z = g from every constrained face through it:
  // displacement (1, 0) = u_r*, (0, 1) = u_z*; axis (1, 0) = 0; symmetry n = 0 with the
  // straight edge's normal; a prescribed die zone (bilateral, on the faces inside the zone)
  // n = g0(s) - delta at the node, with the part's normal (as symmetry, whose priority it has). The first (in that order of priority) is kept, with the one
  // most independent of it if their normals are not parallel (then both components are
  // fixed); a single condition constrains its larger component.
  void AxisymmetricSolver::add_outline_constraints()
  {
    using Kind = axisym::PartCondition::Kind;
    const axisym::Body &body = body_;
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
    // The support points of a face, in the order of the base element's face dofs.
    FEFaceValues<2> support(mapping(), fe_,
                            Quadrature<1>(fe_.base_element(0).get_unit_face_support_points()),
                            update_quadrature_points);
    // Distributed: the faces of this rank's cells and of its ghost cells (all faces at the
    // dofs of its own cells); artificial cells have no dofs.
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->is_artificial() || !cell->face(f)->at_boundary())
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
          else if (c.kind == Kind::die && mode_ == Mode::bilateral)
            {
              unsigned int die = 0;
              while (dies_[die].part != body.outline.edges()[edge].part)
                ++die;
              const OutlineDie &d = dies_[die];
              const auto face = cell->face(f);
              const Point<2> a = face->vertex(0), b = face->vertex(1);
              if (!in_zone(d, d.frame.coordinate({a[0], a[1]})) ||
                  !in_zone(d, d.frame.coordinate({b[0], b[1]})))
                continue;
              const double n_r = std::abs(d.frame.normal.r) < 1e-12 ? 0.0 : d.frame.normal.r;
              const double n_z = std::abs(d.frame.normal.z) < 1e-12 ? 0.0 : d.frame.normal.z;
              // g: die_target at each node, set below (kind die: the marker g = NaN).
              add[n_add++] = {n_r, n_z, std::numeric_limits<double>::quiet_NaN(), 2, edge};
              support.reinit(cell, f);
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
                  Condition cond = add[k];
                  if (std::isnan(cond.g)) // a die zone: the target at this node
                    {
                      unsigned int die = 0;
                      while (dies_[die].part != body.outline.edges()[edge].part)
                        ++die;
                      cond.g = die_target(die, support.quadrature_point(index));
                    }
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
} // namespace fem::internal
