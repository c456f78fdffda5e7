#include "fem_reference/outline_mesh.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fem
{
  void OutlineMeshSpec::validate() const
  {
    if (!(cells_on_shortest_edge >= 1 && cells_on_shortest_edge <= 64))
      throw std::invalid_argument("OutlineMeshSpec: cells_on_shortest_edge must be in [1, 64]");
    if (!(max_arc_angle > 0.01 && max_arc_angle <= 3.14159265358979323846 / 2))
      throw std::invalid_argument("OutlineMeshSpec: max_arc_angle must be in (0.01, pi/2]");
  }

  double OutlineMeshSpec::base_mesh_size(const axisym::Outline &outline) const
  {
    double shortest = outline.edges().front().length();
    for (const axisym::OutlineEdge &e : outline.edges())
      shortest = std::min(shortest, e.length());
    return shortest / cells_on_shortest_edge;
  }

  int OutlineMeshSpec::segments(const axisym::OutlineEdge &edge, double h0) const
  {
    // The small allowance keeps an edge of exactly k h0 at k segments despite rounding.
    int n = std::max(1, static_cast<int>(std::ceil(edge.length() / h0 - 1e-9)));
    if (edge.kind == axisym::OutlineEdge::Kind::arc)
      n = std::max(n, static_cast<int>(std::ceil(std::abs(edge.sweep()) / max_arc_angle - 1e-9)));
    return n;
  }

  unsigned int boundary_id_of_part(const axisym::Outline &outline, const std::string &part)
  {
    const std::vector<std::string> parts = outline.parts();
    const auto it = std::find(parts.begin(), parts.end(), part);
    if (it == parts.end())
      throw std::invalid_argument("boundary_id_of_part: no part " + part + " in the outline");
    return static_cast<unsigned int>(it - parts.begin()) + 1;
  }

  double distance_to_edge(const axisym::OutlineEdge &e, const axisym::Point p)
  {
    return e.distance_to(p);
  }


  int edge_of_boundary_segment(const axisym::Outline &outline, const std::string &part,
                               const axisym::Point a, const axisym::Point b)
  {
    int best = -1;
    double best_distance = 0;
    for (std::size_t i = 0; i < outline.edges().size(); ++i)
      {
        const axisym::OutlineEdge &e = outline.edges()[i];
        if (e.part != part)
          continue;
        const double d = std::max(distance_to_edge(e, a), distance_to_edge(e, b));
        if (best < 0 || d < best_distance)
          best = static_cast<int>(i), best_distance = d;
      }
    if (best < 0)
      throw std::invalid_argument("edge_of_boundary_segment: no edge of part " + part);
    return best;
  }

  namespace
  {
    // Number of 2-D elements of gmsh element type `type` in the current model.
    std::size_t count_elements(int type)
    {
      std::vector<std::size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(type, tags, nodes, -1);
      return tags.size();
    }
  } // namespace

  OutlineMeshInfo write_outline_gmsh_mesh(const axisym::Outline &outline,
                                          const OutlineMeshSpec &spec,
                                          const std::string &msh_path)
  {
    spec.validate();
    const std::vector<axisym::OutlineEdge> &edges = outline.edges();
    const std::vector<std::string> parts = outline.parts();
    OutlineMeshInfo info;
    info.base_mesh_size = spec.base_mesh_size(outline);
    const double h0 = info.base_mesh_size;

    std::vector<int> n_segments(edges.size());
    for (std::size_t i = 0; i < edges.size(); ++i)
      n_segments[i] = spec.segments(edges[i], h0);
    int total = 0;
    for (const int n : n_segments)
      total += n;
    if (total % 2 == 1)
      {
        std::size_t longest = 0;
        for (std::size_t i = 1; i < edges.size(); ++i)
          if (edges[i].length() > edges[longest].length())
            longest = i;
        ++n_segments[longest];
        ++total;
      }
    info.n_boundary_segments = total;

    gmsh::initialize();
    try
      {
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.Verbosity", 1);
        gmsh::model::add("outline_section");
        namespace geo = gmsh::model::geo;

        // Vertex i is the start of edge i (the outline is closed: edge i ends at vertex i+1).
        std::vector<int> vertices;
        for (const axisym::OutlineEdge &e : edges)
          vertices.push_back(geo::addPoint(e.start.r, e.start.z, 0, h0));
        std::vector<int> curves;
        for (std::size_t i = 0; i < edges.size(); ++i)
          {
            const axisym::OutlineEdge &e = edges[i];
            const int a = vertices[i], b = vertices[(i + 1) % edges.size()];
            if (e.kind == axisym::OutlineEdge::Kind::line)
              curves.push_back(geo::addLine(a, b));
            else
              {
                const int center = geo::addPoint(e.center.r, e.center.z, 0, h0);
                curves.push_back(geo::addCircleArc(a, center, b));
              }
          }
        const int loop = geo::addCurveLoop(curves);
        const int surface = geo::addPlaneSurface({loop});
        geo::synchronize();

        for (std::size_t k = 0; k < parts.size(); ++k)
          {
            std::vector<int> members;
            for (std::size_t i = 0; i < edges.size(); ++i)
              if (edges[i].part == parts[k])
                members.push_back(curves[i]);
            const int tag = static_cast<int>(k) + 1;
            gmsh::model::addPhysicalGroup(1, members, tag);
            gmsh::model::setPhysicalName(1, tag, parts[k]);
          }
        gmsh::model::addPhysicalGroup(2, {surface}, 1);
        gmsh::model::setPhysicalName(2, 1, "section");

        namespace mesh = gmsh::model::mesh;
        // Frontal-Delaunay (6). Frontal-Delaunay for quads (8) crashes in gmsh 4.8.4 (segfault
        // in its background-mesh cross field), so it is not used.
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1); // blossom
        gmsh::option::setNumber("Mesh.MeshSizeMax", h0);
        mesh::setRecombine(2, surface);
        for (std::size_t i = 0; i < edges.size(); ++i)
          mesh::setTransfiniteCurve(curves[i], n_segments[i] + 1);
        if (!spec.always_subdivide)
          mesh::generate(2);

        // Triangles left: subdivide a mesh twice as coarse.
        if (spec.always_subdivide || count_elements(2) > 0)
          {
            info.subdivided = true;
            mesh::clear();
            gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
            gmsh::option::setNumber("Mesh.MeshSizeMax", 2 * h0);
            for (std::size_t i = 0; i < edges.size(); ++i)
              mesh::setTransfiniteCurve(curves[i], (n_segments[i] + 1) / 2 + 1);
            mesh::generate(2);
          }
        if (count_elements(2) > 0 || count_elements(3) == 0)
          throw std::runtime_error("gmsh: the outline mesh is not all quadrilaterals (" +
                                   std::to_string(count_elements(2)) + " triangles, " +
                                   std::to_string(count_elements(3)) + " quadrilaterals)");
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        gmsh::write(msh_path);
      }
    catch (...)
      {
        gmsh::finalize();
        throw;
      }
    gmsh::finalize();
    return info;
  }
} // namespace fem
