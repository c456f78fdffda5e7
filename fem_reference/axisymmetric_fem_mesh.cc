// 1. The mesh of the FEM reference (axisymmetric_solver.h): the outline section (the
// hollow-cylinder form's half section is one), and the refinement toward dies.
#include "fem_reference/axisymmetric_solver.h"

#include "problem/wedge_modes.h"

namespace fem::internal
{
  // 1. Mesh: the gmsh base mesh of the outline, the manifold of its edge on every boundary
  // face (PolarManifold about the arc's center, flat for a line), transfinite interpolation on
  // the cells, L global refinements, the refinement toward the dies (and a prescribed zone's
  // ends on vertices), then MappingQ(p) cached once for the refined mesh.
  void AxisymmetricSolver::make_mesh()
  {
    const axisym::Outline &outline = body_.outline;
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
    refine_toward_vertices();
    snap_zone_ends();
    make_mapping();
  }

  void AxisymmetricSolver::make_mapping()
  {
    const std::vector<axisym::OutlineEdge> &edges = body_.outline.edges();
    using Geometry = FemOptions::OutlineGeometry;
    // MappingQ(p) represents the arcs; on a polygon (the hollow cylinder's rectangle, most
    // die problems) every cell is the bilinear image of its vertices (transfinite
    // interpolation of straight edges keeps them straight), which MappingQ1 is, at less
    // cost.
    const bool has_arcs =
      std::any_of(edges.begin(), edges.end(), [](const axisym::OutlineEdge &e) {
        return e.kind == axisym::OutlineEdge::Kind::arc;
      });
    if (options_.outline_geometry == Geometry::curved && has_arcs)
      {
        auto cache = std::make_unique<MappingQCache<2>>(options_.degree);
        cache->initialize(MappingQ<2>(options_.degree), triangulation_);
        mapping_ = std::move(cache);
      }
    else
      mapping_ = std::make_unique<MappingQ1<2>>();
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

  // contact.method = "fixed": the prescribed zone of each die, c = contact.half_width from
  // the centre each way along the part, clipped to it (the whole part without c).
  void AxisymmetricSolver::fix_die_zones()
  {
    for (OutlineDie &d : dies_)
      {
        const std::optional<double> c = problem_.contact.half_width;
        d.zone_lo = c ? std::max(d.frame.s_min, -*c) : d.frame.s_min;
        d.zone_hi = c ? std::min(d.frame.s_max, *c) : d.frame.s_max;
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
    auto refine_while = [&](const auto &wants) { refine_cells_while(wants, 40); };
    const double tol = 1e-9 * body_.outline.size();
    for (const OutlineDie &d : dies_)
      {
        const double w = d.zone_hi - d.zone_lo;
        if (!(w > tol))
          continue;
        const double h = w / (options_.die_zone_cells * std::pow(2.0, level_));
        const axisym::Point pa = d.frame.point_at(d.zone_lo), pb = d.frame.point_at(d.zone_hi);
        const Point<2> a(pa.r, pa.z), b(pb.r, pb.z);
        // A cell's size: its diameter / sqrt 2 (a square's side). A zone that the global
        // refinement already resolves to within a factor 2 of the asked density (h at least
        // half the level's nominal size h0 / 2^L: at least die_zone_cells / 2 * 2^L cells
        // across it; e.g. the hollow cylinder's die, c ~ a / 2, h0 = a / 8) is left as it is:
        // one more halving of a large region would double the cost for little (the base
        // cells' diameters scatter about h0, so `size > 1.01 h` would take most of them).
        // Its free ends are refined below all the same.
        if (h < 0.5 * base_mesh_size_ / std::pow(2.0, level_))
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

  void AxisymmetricSolver::refine_cells_while(
    const std::function<bool(const Triangulation<2>::active_cell_iterator &)> &wants,
    const int max_rounds)
  {
    for (int round = 0; round < max_rounds; ++round)
      {
        bool any = false;
        for (const auto &cell : triangulation_.active_cell_iterators())
          if (cell->is_locally_owned() && wants(cell))
            cell->set_refine_flag(), any = true;
        if (!all_or(any)) // distributed: every rank refines (collectively) or none
          return;
        triangulation_.execute_coarsening_and_refinement();
      }
  }

  void AxisymmetricSolver::refine_toward_vertices()
  {
    vertex_grading_.clear();
    if (!options_.grade_toward_vertices || options_.adaptive)
      return; // adaptive: the estimator finds the vertices
    const double l = body_.outline.size(), h = base_mesh_size_ / std::pow(2.0, level_);
    auto grade_toward = [&](const axisym::Point &at, const double lambda) {
      // The smallest cell, at the vertex: (h_min / l)^lambda = (h / l)^p, log2(h / h_min) =
      // (p / lambda - 1) log2(l / h).
      const double halvings = (options_.degree / lambda - 1.0) * std::log2(l / h);
      const int k = std::clamp(static_cast<int>(std::ceil(halvings)), 0, 40);
      const double h_min = h / std::pow(2.0, k);
      // Away from it the radical law h(rho) = h (rho / rho_g)^(1 - lambda / p), rho_g =
      // vertex_grading_radius l (FemOptions): each annulus then carries about the same share
      // of the singular term's error, which falls as h^2p (FemOptions::grade_toward_vertices).
      const double mu = std::clamp(1.0 - lambda / options_.degree, 0.0, 1.0);
      const double rho_g = options_.vertex_grading_radius * l;
      const Point<2> x(at.r, at.z);
      refine_cells_while(
        [&](const auto &cell) {
          // A lower bound of the cell's distance from the vertex: its centre's, less half its
          // diameter.
          const double rho = std::max(0.0, cell->center().distance(x) - 0.5 * cell->diameter());
          const double target = std::max(h_min, h * std::pow(std::min(1.0, rho / rho_g), mu));
          return cell->diameter() / std::sqrt(2.0) > 1.01 * target;
        },
        k + 4);
      vertex_grading_.push_back({{at.r, at.z, lambda, static_cast<double>(k)}});
    };
    for (const axisym::SingularVertex &v :
         axisym::singular_vertices(body_, problem_.material.poisson_ratio))
      grade_toward(v.at, v.modes.front().lambda.real());
    // Where a traction jumps (axisym::traction_jump_vertices): the displacement's rho log rho
    // term is graded toward as lambda = 1 (the energy's order per level was 1.99 on the
    // pressure band with uniform levels, against 4 for a smooth field with Q2).
    for (const axisym::Point &v : axisym::traction_jump_vertices(body_))
      grade_toward(v, 1.0);
    // Where the loads resonate with the wedge's integer exponents (axisym::resonant_vertices:
    // a symmetry line at a right angle to a traction part, a temperature gradient across the
    // line): the stress's rho log rho term, graded as lambda = 1 too, for the
    // values at and near the vertex.
    for (const axisym::ResonantSite &v : axisym::resonant_vertices(body_, problem_.body_loads))
      grade_toward(v.at, 1.0);
  }

  // A prescribed zone (bilateral) switches from u.n = t to traction free at its free ends:
  // each end must be a mesh vertex, so that the condition and the element traces switch
  // there (DESIGN.md 4.3: the field is singular at the end). The boundary vertex of the die's
  // part nearest to the end is moved onto it, along the straight part. After
  // refine_toward_dies the cells there are die_edge_refinements times finer than across the
  // zone, and the move is at most half a face: a mild distortion of a few small cells.
  void AxisymmetricSolver::snap_zone_ends()
  {
    if (mode_ != Mode::bilateral)
      return;
    const double tol = 1e-9 * body_.outline.size();
    for (const OutlineDie &d : dies_)
      for (const auto &[s_end, free] :
           {std::pair{d.zone_lo, d.zone_lo > d.frame.s_min + tol},
            std::pair{d.zone_hi, d.zone_hi < d.frame.s_max - tol}})
        {
          if (!free)
            continue;
          const axisym::Point pe = d.frame.point_at(s_end);
          const Point<2> e(pe.r, pe.z);
          Point<2> *nearest = nullptr;
          double best = std::numeric_limits<double>::infinity();
          for (const auto &cell : triangulation_.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && face->boundary_id() == d.boundary_id)
                for (unsigned int v = 0; v < 2; ++v)
                  if (face->vertex(v).distance(e) < best)
                    best = face->vertex(v).distance(e), nearest = &face->vertex(v);
          if (nearest)
            *nearest = e;
        }
  }
} // namespace fem::internal
