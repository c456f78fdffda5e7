#include "fem_reference/outline_mesh.h"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace fem
{
  namespace
  {
    using axisym::Outline;
    using axisym::OutlineEdge;

    OutlineEdge line_to(double r, double z, const std::string &part)
    {
      OutlineEdge e;
      e.end = {r, z};
      e.part = part;
      return e;
    }
    OutlineEdge arc_to(double r, double z, double rc, double zc, const std::string &part)
    {
      OutlineEdge e = line_to(r, z, part);
      e.kind = OutlineEdge::Kind::arc;
      e.center = {rc, zc};
      return e;
    }

    // The thick sphere of DESIGN.md 7.1 (a = 0.1, b = 0.2): quarter annulus.
    Outline sphere()
    {
      return Outline({0.1, 0.0}, {line_to(0.2, 0.0, "equator"), arc_to(0.0, 0.2, 0, 0, "outer"),
                                  line_to(0.0, 0.1, "axis"), arc_to(0.1, 0.0, 0, 0, "inner")});
    }

    // A flanged ring: an inclined edge, a concave fillet arc, two edges sharing a part.
    Outline flanged_ring()
    {
      return Outline({0.1, 0.0},
                     {line_to(0.25, 0.0, "bottom"), line_to(0.25, 0.03, "flange"),
                      line_to(0.17, 0.03, "flange"), arc_to(0.15, 0.05, 0.17, 0.05, "fillet"),
                      line_to(0.14, 0.2, "neck"), line_to(0.1, 0.2, "top"),
                      line_to(0.1, 0.0, "bore")});
    }

    struct ReadBack
    {
      std::vector<double> coords;          // node coordinates, 3 per node
      std::map<int, std::size_t> elements; // element type -> count (dim 2)
      std::map<int, std::string> names;    // physical curve tag -> name
      std::map<int, std::vector<std::size_t>> group_nodes; // physical curve tag -> node tags
      std::map<std::size_t, std::size_t> node_index;       // node tag -> index
    };

    ReadBack mesh_and_read(const Outline &outline, const OutlineMeshSpec &spec,
                           OutlineMeshInfo *info = nullptr)
    {
      const std::string path = (std::filesystem::temp_directory_path() /
                                ("outline_mesh_test_" + std::to_string(::getpid()) + ".msh"))
                                 .string();
      const OutlineMeshInfo i = write_outline_gmsh_mesh(outline, spec, path);
      if (info)
        *info = i;
      ReadBack rb;
      gmsh::initialize();
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::open(path);
      std::vector<std::size_t> tags;
      std::vector<double> parametric;
      gmsh::model::mesh::getNodes(tags, rb.coords, parametric);
      for (std::size_t k = 0; k < tags.size(); ++k)
        rb.node_index[tags[k]] = k;
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, 2);
      for (std::size_t k = 0; k < types.size(); ++k)
        rb.elements[types[k]] = element_tags[k].size();
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, 1);
      for (const auto &[dim, tag] : groups)
        {
          gmsh::model::getPhysicalName(dim, tag, rb.names[tag]);
          std::vector<double> c;
          gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, rb.group_nodes[tag], c);
        }
      gmsh::finalize();
      std::filesystem::remove(path);
      return rb;
    }
  } // namespace

  TEST(OutlineMeshSpec, BaseSizeFromTheShortestEdgeAndArcAngles)
  {
    const Outline s = sphere();
    OutlineMeshSpec spec;
    const double h0 = spec.base_mesh_size(s);
    EXPECT_NEAR(h0, 0.1 / 4, 1e-15); // equator and axis are the shortest edges, 0.1
    EXPECT_EQ(spec.segments(s.edges()[0], h0), 4);
    // Outer arc: length 0.2 pi / 2 = 0.314 -> 13 segments; inner 0.157 -> 7, but 90 degrees
    // at 22.5 degrees per segment needs 4 at least.
    EXPECT_EQ(spec.segments(s.edges()[1], h0), 13);
    EXPECT_EQ(spec.segments(s.edges()[3], h0), 7);
    spec.cells_on_shortest_edge = 1;
    EXPECT_EQ(spec.segments(s.edges()[3], spec.base_mesh_size(s)), 4);
    EXPECT_EQ(boundary_id_of_part(s, "equator"), 1u);
    EXPECT_EQ(boundary_id_of_part(s, "inner"), 4u);
    EXPECT_THROW(boundary_id_of_part(s, "lid"), std::invalid_argument);
  }

  TEST(DistanceToEdge, LinesAndArcsInsideAndBeyondTheirEnds)
  {
    const Outline s = sphere();
    const OutlineEdge &equator = s.edges()[0], &outer = s.edges()[1], &inner = s.edges()[3];
    EXPECT_NEAR(distance_to_edge(equator, {0.15, 0.01}), 0.01, 1e-15);
    EXPECT_NEAR(distance_to_edge(equator, {0.23, 0.04}), 0.05, 1e-15); // beyond the end
    EXPECT_NEAR(distance_to_edge(outer, {0.1, 0.1}), 0.2 - std::sqrt(0.02), 1e-14);
    EXPECT_NEAR(distance_to_edge(outer, {0.3, -0.1}), std::hypot(0.1, 0.1), 1e-14);
    // The inner arc runs clockwise (negative sweep) from (0, 0.1) to (0.1, 0).
    EXPECT_LT(inner.sweep(), 0);
    EXPECT_NEAR(distance_to_edge(inner, {0.06, 0.06}), 0.1 - std::sqrt(0.0072), 1e-14);
    EXPECT_NEAR(distance_to_edge(inner, {-0.05, 0.0}), std::hypot(0.05, 0.1), 1e-14);
  }

  TEST(EdgeOfBoundarySegment, PicksTheEdgeOfThePartThatHoldsBothVertices)
  {
    const Outline f = flanged_ring();
    // Part flange: edges 1 (r = 0.25) and 2 (z = 0.03); a segment at their shared corner.
    EXPECT_EQ(edge_of_boundary_segment(f, "flange", {0.25, 0.03}, {0.23, 0.03}), 2);
    EXPECT_EQ(edge_of_boundary_segment(f, "flange", {0.25, 0.01}, {0.25, 0.03}), 1);
    EXPECT_EQ(edge_of_boundary_segment(f, "fillet", {0.17, 0.03}, {0.15, 0.05}), 3);
    EXPECT_THROW(edge_of_boundary_segment(f, "lid", {0, 0}, {1, 1}), std::invalid_argument);
  }

  // All quadrilaterals, one named physical curve per part (tag = 1 + index in parts()), and
  // every node of an arc's group on its circle.
  TEST(WriteOutlineGmshMesh, AllQuadrilateralsWithNamedPartsAndNodesOnTheArcs)
  {
    for (const Outline &outline : {sphere(), flanged_ring()})
      for (const double n : {1.0, 4.0, 8.0})
        for (const bool subdivide : {false, true})
        {
          OutlineMeshSpec spec;
          spec.cells_on_shortest_edge = n;
          spec.always_subdivide = subdivide;
          OutlineMeshInfo info;
          const ReadBack rb = mesh_and_read(outline, spec, &info);
          EXPECT_EQ(info.subdivided, subdivide);
          EXPECT_EQ(rb.elements.count(2), 0u) << "triangles left, n = " << n;
          ASSERT_EQ(rb.elements.count(3), 1u);
          EXPECT_GT(rb.elements.at(3), 0u);
          const std::vector<std::string> parts = outline.parts();
          ASSERT_EQ(rb.names.size(), parts.size());
          for (std::size_t k = 0; k < parts.size(); ++k)
            EXPECT_EQ(rb.names.at(static_cast<int>(k) + 1), parts[k]);
          for (const OutlineEdge &e : outline.edges())
            {
              if (e.kind != OutlineEdge::Kind::arc)
                continue;
              const int tag = static_cast<int>(boundary_id_of_part(outline, e.part));
              for (const std::size_t node : rb.group_nodes.at(tag))
                {
                  const std::size_t i = rb.node_index.at(node);
                  const double dr = rb.coords[3 * i] - e.center.r,
                               dz = rb.coords[3 * i + 1] - e.center.z;
                  EXPECT_NEAR(std::hypot(dr, dz), e.radius(), 1e-12 * e.radius());
                }
            }
          // Each boundary node count: the segments (closed loop: as many nodes as segments).
          std::size_t on_boundary = 0;
          for (const auto &[tag, nodes] : rb.group_nodes)
            on_boundary += nodes.size();
          EXPECT_GE(on_boundary, static_cast<std::size_t>(info.n_boundary_segments));
        }
  }
} // namespace fem
