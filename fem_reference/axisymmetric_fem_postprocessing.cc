// 6. Post-processing of the FEM reference (axisymmetric_solver.h): functionals, forces, the
// dies' zones, samples, support reactions and VTU.
#include "fem_reference/axisymmetric_solver.h"

#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/rtree.h>

namespace fem::internal
{
  // 6. Post-processing of the current solution. `active`: the penalty set used in the solve.
  Evaluation AxisymmetricSolver::evaluate(const std::vector<char> *active) const
  {
    Evaluation ev;

    // Volume: U_h, the work of the body force and the thermal strain, the errors.
    FEValues<2> fe_values(mapping(), fe_, cell_quadrature_,
                          update_values | update_gradients | update_quadrature_points |
                            update_JxW_values);
    const unsigned int n_q = cell_quadrature_.size();
    std::vector<Vector<double>> u(n_q, Vector<double>(2));
    std::vector<std::vector<Tensor<1, 2>>> grad(n_q, std::vector<Tensor<1, 2>>(2));
    double energy = 0, error_sq = 0, norm_sq = 0, u_error_sq = 0, u_norm_sq = 0;
    double body_force_work = 0, thermal_strain_work = 0; // int f.u_h r, int s_h.e_th r
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
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
    energy = all_sum(energy), error_sq = all_sum(error_sq), norm_sq = all_sum(norm_sq);
    u_error_sq = all_sum(u_error_sq), u_norm_sq = all_sum(u_norm_sq);
    body_force_work = all_sum(body_force_work);
    thermal_strain_work = all_sum(thermal_strain_work);
    // A mirrored section stands for the whole body (twice); an outline for itself.
    const double mirror = mirror_;
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
            if (!cell->is_locally_owned())
              continue;
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
        ev.error_max = all_max(error_max), ev.norm_max = all_max(norm_max);
      }

    double work = 0, b_c = 0, b_r = 0, penalty_energy = 0;
    outline_boundary_terms(work, b_c, b_r);
    if (!dies_.empty())
      evaluate_dies(active, ev, b_c, b_r, penalty_energy);
    work = all_sum(work), b_c = all_sum(b_c), b_r = all_sum(b_r);
    penalty_energy = all_sum(penalty_energy);
    // DESIGN.md 3 with the thermal strain as an initial strain (axisymmetric_fem.h):
    // W = int f.u_h r + int_St t.u_h r ds; the Castigliano functional carries
    // -int s_h.e_th r; in Reissner's s.e(u) - 1/2 s.C s - s.e_th = U density for s = s_h.
    // Every term for the whole body: times mirror_.
    Functionals &phi = ev.functionals;
    phi.penalty_energy = mirror * penalty_energy;
    phi.strain_energy = mirror * energy;
    phi.body_force_work = mirror * body_force_work;
    phi.thermal_strain_work = mirror * thermal_strain_work;
    phi.external_work = mirror * work + phi.body_force_work;
    phi.lagrange = phi.strain_energy - phi.external_work;
    phi.castigliano = -phi.strain_energy - phi.thermal_strain_work + mirror * b_c;
    phi.reissner = phi.strain_energy - phi.external_work - mirror * b_r;
    return ev;
  }

  // 6d. Dies on outline parts: at the contact points of each die, the gap g = u.n - t, the
  // penalty pressure kappa g on the active set, the trace -n.s_h n, the forces, the zone ends
  // (zone_end on each side of the centre), and the contact terms of the functionals:
  // b_c += int_A (n.s_h n) t r ds, b_r += int_A (n.s_h n) g r ds (the zone is S_c with u.n = t).
  // A prescribed zone (bilateral): S_c is the faces inside it, the pressure the trace -n.s_h n,
  // the force the reaction of the zone's constrained dofs, the zone the prescribed one.
  // Forces for the whole body (times mirror_).
  void AxisymmetricSolver::evaluate_dies(const std::vector<char> *active, Evaluation &ev,
                                         double &b_c, double &b_r, double &penalty_energy) const
  {
    ev.dies.assign(dies_.size(), DieEvaluation{});
    const bool bilateral = mode_ == Mode::bilateral;
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
        const auto f = face.cell->face(face.face);
        const bool prescribed = bilateral && in_zone(d, d.frame.coordinate({f->vertex(0)[0], f->vertex(0)[1]})) &&
                                in_zone(d, d.frame.coordinate({f->vertex(1)[0], f->vertex(1)[1]}));
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
            const bool penalized = active && (*active)[k * n_q + q];
            const double p = bilateral ? -snn : penalized ? kappa_ * gap : 0.0;
            if (!bilateral)
              de.force += 2 * pi * mirror_ * p * w;
            de.force_trace -= 2 * pi * mirror_ * snn * w;
            if (penalized)
              penalty_energy += 0.5 * kappa_ * gap * gap * w;
            if (penalized || prescribed)
              {
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
    if (distributed_)
      for (std::size_t i = 0; i < dies_.size(); ++i)
        {
          // Each rank has the points of its own faces: the forces summed, the points of all.
          DieEvaluation &de = ev.dies[i];
          de.force = all_sum(de.force);
          de.force_trace = all_sum(de.force_trace);
          de.max_penetration = all_max(de.max_penetration);
          std::vector<double> flat;
          for (const PressurePoint &p : de.pressure)
            flat.insert(flat.end(), {p.s, p.r, p.z, p.p, p.p_trace, p.gap});
          flat = all_concat(flat);
          de.pressure.clear();
          gaps[i].clear();
          for (std::size_t k = 0; k + 5 < flat.size(); k += 6)
            {
              de.pressure.push_back(
                {flat[k], flat[k + 1], flat[k + 2], flat[k + 3], flat[k + 4], flat[k + 5]});
              gaps[i].emplace_back(flat[k], flat[k + 5]);
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
        const double tol = 1e-9 * body_.outline.size();
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
        auto [hi, hi_gap] =
          has_up ? zone_end(up, std::min(d.frame.s_max, extent)) : std::pair{0.0, 0.0};
        auto [lo, lo_gap] =
          has_down ? zone_end(down, std::min(-d.frame.s_min, extent)) : std::pair{0.0, 0.0};
        if (bilateral)
          hi = hi_gap = has_up ? d.zone_hi : 0.0, lo = lo_gap = has_down ? -d.zone_lo : 0.0;
        de.zone_lo = -lo, de.zone_hi = hi;
        de.two_edges = has_up && has_down;
        if (de.two_edges)
          de.half_width = 0.5 * (hi + lo), de.half_width_gap = 0.5 * (hi_gap + lo_gap);
        else
          de.half_width = has_up ? hi : lo, de.half_width_gap = has_up ? hi_gap : lo_gap;
      }
    if (bilateral)
      {
        // The reaction of the zone: P = -2 pi R.n summed over the dofs the die holds (the
        // residual R of a held dof is the support's force on the body, per radian).
        const Vector<double> residual = support_residual();
        for (const auto &[dof, held] : reaction_dofs_)
          {
            const std::string &part = body_.outline.edges()[held.edge].part;
            for (std::size_t i = 0; i < dies_.size(); ++i)
              if (dies_[i].part == part)
                ev.dies[i].force -= 2 * pi * mirror_ * residual(dof) *
                                    (held.component == 0 ? dies_[i].frame.normal.r
                                                         : dies_[i].frame.normal.z);
          }
      }
    if (!ev.dies.empty())
      {
        const DieEvaluation &first = ev.dies.front();
        ev.force = first.force;
        ev.force_penalty = bilateral ? 0.0 : first.force;
        ev.force_trace = first.force_trace;
        ev.half_width = first.half_width, ev.half_width_gap = first.half_width_gap;
        ev.max_penetration = first.max_penetration;
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
          if (!cell->is_locally_owned() || !cell->face(f)->at_boundary())
            continue;
          const axisym::PartCondition &c =
            body_.condition_of_edge(edge_of(cell->face(f)));
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
  Vector<double> AxisymmetricSolver::support_residual() const
  {
    Vector<double> residual(dof_handler_.n_dofs());
    if (reaction_dofs_.empty())
      return residual;
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
    Vector<double> cell_residual(n), cell_load(n);
    // A cell contributes to a held dof directly, or through a hanging node whose masters
    // include it (a coarse face next to finer cells).
    auto reaches = [&](types::global_dof_index i) {
      if (reaction_dofs_.count(i) > 0)
        return true;
      if (const auto *masters = hanging_node_constraints_.get_constraint_entries(i))
        for (const auto &[master, weight] : *masters)
          if (reaction_dofs_.count(master) > 0)
            return true;
      return false;
    };
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(dofs);
        if (std::none_of(dofs.begin(), dofs.end(), reaches))
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
        hanging_node_constraints_.distribute_local_to_global(cell_residual, dofs, residual);
      }
    return residual;
  }

  std::vector<PartReaction> AxisymmetricSolver::reactions() const
  {
    using Kind = axisym::PartCondition::Kind;
    const axisym::Body &body = body_;
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
    const Vector<double> residual = support_residual();
    for (const auto &[dof, held] : reaction_dofs_)
      {
        const auto it = index.find(body.outline.edges()[held.edge].part);
        if (it == index.end())
          continue; // a prescribed die zone: its force is the die's (evaluate_dies)
        PartReaction &reaction = out[it->second];
        (held.component == 0 ? reaction.force_r : reaction.force_z) += 2 * pi * residual(dof);
      }
    // Distributed: each rank's residual holds its cells' shares.
    for (PartReaction &reaction : out)
      reaction.force_r = all_sum(reaction.force_r), reaction.force_z = all_sum(reaction.force_z);
    return out;
  }

  // The cell around each point. A point on an arc may lie just outside the Q_p image of the
  // arc (deal.II 9.4 then returns an invalid cell rather than throwing), so a miss is retried
  // with looser tolerances (unit-cell coordinates) and projected onto the unit cell; with
  // straight-sided cells the nearest boundary cell is taken. Distributed: each rank looks
  // among its own cells nearest to the point, and the rank whose cell is nearest in unit
  // coordinates keeps the point (the lowest rank on a tie: a point on a face between two
  // ranks' cells).
  std::vector<AxisymmetricSolver::PointCell>
  AxisymmetricSolver::locate_points(const std::vector<Point<2>> &points) const
  {
    // The cache holds the vertices and their cells once (without it every search collects
    // the used vertices anew, the whole cost of thousands of samples); the last cell found
    // is the hint for the next point.
    const GridTools::Cache<2> cache(triangulation_, mapping());
    Triangulation<2>::active_cell_iterator hint;
    // (cell, unit point, distance to the unit cell); distance infinity: none found here.
    // Distributed: the own cells whose bounding boxes are nearest to the point (deal.II's
    // search from the nearest vertex would also walk the other ranks' coarse artificial cells,
    // and over the whole mesh where it misses: seconds per point at 1e6 cells).
    const auto locate_own = [&](const Point<2> &x) -> std::pair<PointCell, double> {
      std::vector<std::pair<BoundingBox<2>, Triangulation<2>::active_cell_iterator>> near;
      cache.get_locally_owned_cell_bounding_boxes_rtree().query(
        boost::geometry::index::nearest(x, 8), std::back_inserter(near));
      PointCell best;
      double best_distance = std::numeric_limits<double>::infinity();
      for (const auto &[box, cell] : near)
        try
          {
            const Point<2> u = mapping().transform_real_to_unit_cell(cell, x);
            const double d = GeometryInfo<2>::distance_to_unit_cell(u);
            if (d < best_distance)
              best_distance = d,
              best = {DoFHandler<2>::active_cell_iterator(&triangulation_, cell->level(),
                                                          cell->index(), &dof_handler_),
                      GeometryInfo<2>::project_to_unit_cell(u), true};
          }
        catch (const std::exception &)
          {}
      return {best, best_distance};
    };
    const auto locate = [&](const Point<2> &x) -> std::pair<PointCell, double> {
      if (distributed_)
        return locate_own(x);
      for (const double tolerance : {1e-10, 1e-6, 1e-3})
        {
          try
            {
              const auto [cell, unit] =
                GridTools::find_active_cell_around_point(cache, x, hint, {}, tolerance);
              if (cell.state() == IteratorState::valid)
                {
                  hint = cell;
                  PointCell found{DoFHandler<2>::active_cell_iterator(
                                    &triangulation_, cell->level(), cell->index(), &dof_handler_),
                                  GeometryInfo<2>::project_to_unit_cell(unit), true};
                  return {found, GeometryInfo<2>::distance_to_unit_cell(unit)};
                }
            }
          catch (const std::exception &)
            {
              continue;
            }
        }
      // Still outside (straight-sided studies: a point on an arc lies beyond the chord): the
      // own boundary cell nearest in unit coordinates.
      PointCell best;
      double best_distance = std::numeric_limits<double>::infinity();
      for (const auto &cell : dof_handler_.active_cell_iterators())
        {
          if (!cell->is_locally_owned() || !cell->at_boundary() ||
              cell->center().distance(x) > 2 * cell->diameter())
            continue;
          try
            {
              const Point<2> unit = mapping().transform_real_to_unit_cell(cell, x);
              const double d = GeometryInfo<2>::distance_to_unit_cell(unit);
              if (d < best_distance)
                best_distance = d, best = {cell, GeometryInfo<2>::project_to_unit_cell(unit), true};
            }
          catch (const std::exception &)
            {}
        }
      return {best, best_distance};
    };
    std::vector<PointCell> out;
    std::vector<double> distance;
    for (const Point<2> &x : points)
      {
        const auto [cell, d] = locate(x);
        out.push_back(cell);
        distance.push_back(d);
      }
    if (distributed_)
      {
        const unsigned int rank = Utilities::MPI::this_mpi_process(comm_);
        const std::vector<std::vector<double>> all = Utilities::MPI::all_gather(comm_, distance);
        for (std::size_t k = 0; k < points.size(); ++k)
          {
            unsigned int winner = 0;
            for (unsigned int q = 1; q < all.size(); ++q)
              if (all[q][k] < all[winner][k])
                winner = q;
            distance[k] = all[winner][k];
            out[k].here = winner == rank && std::isfinite(all[winner][k]);
          }
      }
    for (std::size_t k = 0; k < points.size(); ++k)
      if (!std::isfinite(distance[k]))
        throw std::runtime_error("sample (" + std::to_string(points[k][0]) + ", " +
                                 std::to_string(points[k][1]) + ") is not in any cell of the mesh");
    return out;
  }

  std::vector<double> AxisymmetricSolver::all_concat(const std::vector<double> &x) const
  {
    if (!distributed_)
      return x;
    std::vector<double> out;
    for (const std::vector<double> &part : Utilities::MPI::all_gather(comm_, x))
      out.insert(out.end(), part.begin(), part.end());
    return out;
  }

  // Fields at the sample points; a mirrored body's z < 0 by mirroring (u_z and sigma_rz are
  // odd in z). Distributed: the rank that holds a point evaluates it, and the values are
  // summed over the ranks (zeros elsewhere).
  std::vector<FieldSample> AxisymmetricSolver::samples() const
  {
    std::vector<Point<2>> points;
    for (const auto &[r, z] : problem_.samples)
      points.emplace_back(r, body_.mirrored && z < 0 ? -z : z);
    const std::vector<PointCell> cells = locate_points(points);
    std::vector<double> values(6 * points.size(), 0.0);
    for (std::size_t k = 0; k < points.size(); ++k)
      {
        if (!cells[k].here)
          continue;
        const Point<2> &x = points[k];
        const Quadrature<2> point(std::vector<Point<2>>{cells[k].unit});
        FEValues<2> fv(mapping(), fe_, point, update_values | update_gradients);
        fv.reinit(cells[k].cell);
        std::vector<Vector<double>> u(1, Vector<double>(2));
        std::vector<std::vector<Tensor<1, 2>>> grad(1, std::vector<Tensor<1, 2>>(2));
        fv.get_function_values(solution_, u);
        fv.get_function_gradients(solution_, grad);
        const Stress s = stress_at(x, strain(x[0], u[0][0], grad[0][0], grad[0][1]));
        values[6 * k] = u[0][0], values[6 * k + 1] = u[0][1];
        for (int m = 0; m < 4; ++m)
          values[6 * k + 2 + m] = s[m];
      }
    if (distributed_)
      {
        std::vector<double> total(values.size());
        Utilities::MPI::sum(ArrayView<const double>(values.data(), values.size()), comm_,
                            ArrayView<double>(total.data(), total.size()));
        values = std::move(total);
      }
    std::vector<FieldSample> out;
    for (std::size_t k = 0; k < points.size(); ++k)
      {
        const auto [r, z] = problem_.samples[k];
        const double sign = body_.mirrored && z < 0 ? -1.0 : 1.0;
        const double *v = &values[6 * k];
        out.push_back({r, z, v[0], sign * v[1], {{v[2], v[3], v[4], sign * v[5]}}});
      }
    return out;
  }

  void AxisymmetricSolver::write_vtu() const
  {
    const StressPostprocessor post(d_, loads_);
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler_);
    data_out.add_data_vector(solution_, post);
    // Cells next to an arc are curved inside too (transfinite interpolation).
    data_out.build_patches(mapping(), options_.degree, DataOut<2>::curved_inner_cells);
    const std::filesystem::path directory(options_.vtu_directory);
    auto open = [](const std::filesystem::path &path) {
      std::ofstream out(path);
      if (!out)
        throw std::runtime_error("cannot write " + path.string());
      return out;
    };
    if (!distributed_)
      {
        std::filesystem::create_directories(directory);
        std::ofstream out = open(directory / "fem_solution.vtu");
        data_out.write_vtu(out);
        return;
      }
    // One piece per rank (its own cells) and the record that lists them.
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm_);
    const unsigned int n = Utilities::MPI::n_mpi_processes(comm_);
    auto piece = [](unsigned int k) { return "fem_solution." + std::to_string(k) + ".vtu"; };
    if (rank == 0)
      std::filesystem::create_directories(directory);
    MPI_Barrier(comm_);
    std::ofstream out = open(directory / piece(rank));
    data_out.write_vtu(out);
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int k = 0; k < n; ++k)
          pieces.push_back(piece(k));
        std::ofstream record = open(directory / "fem_solution.pvtu");
        data_out.write_pvtu_record(record, pieces);
      }
  }
} // namespace fem::internal
