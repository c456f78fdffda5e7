#include "rfm/discrete_space.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rfm
{
  std::vector<std::array<double, 2>> contact_edges(const Section &s)
  {
    std::vector<std::array<double, 2>> edges;
    const double tol = 1e-12 * (s.z_max() - s.z_min());
    for (const auto &p : s.parts())
      if (p.side == Side::outer && p.condition == Condition::contact &&
          p.end < s.z_max() - tol)
        edges.push_back({s.r_max(), p.end});
    return edges;
  }

  DiscreteSpace::DiscreteSpace(const Structures &structures,
                               const DiscretizationOptions &options, const Material &material)
    : structures_(structures)
    , options_((options.validate(), options))
    , basis_(options.degree, structures.section().r_min(), structures.section().r_max(),
             structures.section().z_min(), structures.section().z_max())
  {
    const Section &s = structures_.section();
    bool mirrored = false;
    for (const auto &p : s.parts())
      mirrored |= p.side == Side::bottom && p.condition == Condition::symmetry;
    weight_factor_ = mirrored ? 2.0 : 1.0;

    // 1. Interior quadrature, split and graded where a boundary condition changes.
    const int n_gauss = options_.degree + options_.extra_gauss_points;
    const auto r_cells = section_cells(s.r_min(), s.r_max(), options_.n_cells_r,
                                       s.r_breaks(), options_.n_graded_layers,
                                       options_.grading_ratio);
    const auto z_cells = section_cells(s.z_min(), s.z_max(), options_.n_cells_z,
                                       s.z_breaks(), options_.n_graded_layers,
                                       options_.grading_ratio);
    quadrature_ = tensor_gauss(r_cells, z_cells, n_gauss);
    measure_ = weight_factor_ * quadrature_.weights.cwiseProduct(quadrature_.r);
    basis_values_ = basis_.evaluate(quadrature_.r, quadrature_.z);
    stress_ = structures_.stress(quadrature_.r, quadrature_.z);
    displacement_ = structures_.displacement(quadrature_.r, quadrature_.z);

    // 2. Contact-edge enrichment and its near-edge rule (one edge at most: the half section
    //    of a die problem has the zone [0, c] on its outer side).
    const auto edges = contact_edges(s);
    if (edges.size() > 1)
      throw std::invalid_argument("DiscreteSpace: more than one contact edge is not supported");
    std::vector<double> edge_z;
    if (!edges.empty() && options_.edge_modes > 0)
      {
        const double r_e = edges[0][0], z_e = edges[0][1];
        // The support stays off the inner side and the mid-plane (kinematic there), and
        // off the end z = z_max unless every part of it is a traction part: then it may
        // cross the end, clipped (edge_modes.h), so that an edge near the end keeps a wide
        // cutoff (with a - c = 0.1 a the unclipped rho_0 was 0.018 m).
        bool end_traction = true;
        for (const auto &p : s.parts())
          end_traction &= p.side != Side::top || p.condition == Condition::traction;
        const double room = s.z_max() - z_e;
        const double rho_max = std::min({z_e - s.z_min(), s.r_max() - s.r_min(),
                                         end_traction ? std::numeric_limits<double>::infinity()
                                                      : room});
        std::vector<int> modes;
        for (int k = 0; k < options_.edge_modes; ++k)
          modes.push_back(2 * k + 1);

        const double rho_0 = options_.edge_cutoff * rho_max;
        // The end factor of the stress columns applies whenever the end is free, not only
        // when the support reaches it, so that the space, K(c) and P(c) change smoothly
        // with c (a switch at rho_0 = a - c put a kink into both).
        const double end_z = end_traction ? s.z_max() : std::numeric_limits<double>::infinity();
        enrichment_.emplace(r_e, z_e, rho_0, modes, material, options_.edge_mode_degree, end_z);
        const int n_edge = n_gauss + options_.edge_extra_points;
        edge_quadrature_ =
          half_disc_gauss(r_e, z_e, rho_0, n_edge, n_edge, std::min(end_z, s.z_max()));
        edge_measure_ = weight_factor_ * edge_quadrature_.weights.cwiseProduct(edge_quadrature_.r);
        edge_basis_values_ = basis_.evaluate(edge_quadrature_.r, edge_quadrature_.z);
        edge_stress_ = structures_.stress(edge_quadrature_.r, edge_quadrature_.z);
        edge_displacement_ = structures_.displacement(edge_quadrature_.r, edge_quadrature_.z);
        edge_columns_ = enrichment_->evaluate(edge_quadrature_.r, edge_quadrature_.z);
        edge_z.push_back(z_e);
      }

    // 3. Boundary quadrature on every part, on the same cells along the side; cells that
    //    end at an enriched edge take the t^2 map (the traces behave like sqrt(|z - c|)).
    std::vector<double> rr, zz, ww, nr, nz;
    for (std::size_t i = 0; i < s.parts().size(); ++i)
      {
        const BoundaryPart &p = s.parts()[i];
        const bool radial = p.side == Side::inner || p.side == Side::outer;
        const auto &side_cells = radial ? z_cells : r_cells;
        std::vector<double> cells{p.begin};
        for (const double x : side_cells)
          if (x > p.begin && x < p.end)
            cells.push_back(x);
        cells.push_back(p.end);
        const GaussRule1D g = gauss_on_cells(cells, n_gauss, radial ? edge_z : std::vector<double>{});
        for (Eigen::Index k = 0; k < g.nodes.size(); ++k)
          {
            double r = 0, z = 0, n_r = 0, n_z = 0;
            switch (p.side)
              {
                case Side::inner: r = s.r_min(), z = g.nodes[k], n_r = -1; break;
                case Side::outer: r = s.r_max(), z = g.nodes[k], n_r = 1; break;
                case Side::bottom: r = g.nodes[k], z = s.z_min(), n_z = -1; break;
                case Side::top: r = g.nodes[k], z = s.z_max(), n_z = 1; break;
              }
            rr.push_back(r), zz.push_back(z), nr.push_back(n_r), nz.push_back(n_z);
            ww.push_back(weight_factor_ * g.weights[k] * r);
            boundary_.part.push_back(static_cast<int>(i));
          }
      }
    auto to_vector = [](const std::vector<double> &v) {
      return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
    };
    boundary_.r = to_vector(rr);
    boundary_.z = to_vector(zz);
    boundary_.weights = to_vector(ww);
    boundary_.n_r = to_vector(nr);
    boundary_.n_z = to_vector(nz);
  }
} // namespace rfm
