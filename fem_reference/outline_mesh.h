// Quadrilateral base meshes of a general meridian section given by its outline of lines and
// circular arcs (DESIGN.md 7.1), built with the gmsh C++ API. No deal.II here: the mesh is
// written as a .msh file that axisymmetric_fem_mesh.cc reads with GridIn::read_msh and then
// refines globally with the arcs represented by manifolds (see axisymmetric_fem.h).
//
// Boundary parts: part k of outline.parts() (order of first appearance) is the gmsh physical
// curve with tag k + 1 and the part's name; that tag is the deal.II boundary id. The section
// is the physical surface 1 named "section".
//
// Base mesh size h0 = (shortest edge length) / cells_on_shortest_edge: every edge is split
// into max(1, ceil(length / h0)) segments, arcs into at least ceil(|sweep| / max_arc_angle)
// so that no coarse chord spans more than 22.5 degrees, and the longest edge gets one more
// segment if the total is odd (a triangulation with an even number of boundary segments
// has an even number of triangles, which the blossom recombination pairs into quadrilaterals).
// The surface is meshed by frontal-Delaunay (Mesh.Algorithm 6; 8, frontal-Delaunay for quads,
// crashes in the installed gmsh 4.8.4) and recombined (blossom); if triangles remain, the
// mesh is rebuilt at twice the size and every element subdivided into quadrilaterals
// (Mesh.SubdivisionAlgorithm 1), which always gives quads.
//
// Why h0 = shortest edge / 4: the shortest edge is the smallest feature the outline names
// (a wall thickness, a flange, a chamfer), and 4 cells across it at level 0 give 8 at L = 1
// and 64 at the default L = 4, the same count as the legacy hollow cylinder's radial lines
// at equal L (4 x 2^L). For the sphere of DESIGN.md 7.1 that is 53 base cells.
#pragma once

#include "problem/outline.h"

#include <string>
#include <vector>

namespace fem
{
  struct OutlineMeshSpec
  {
    /// Cells along the shortest edge of the outline at level 0: the base mesh size is
    /// h0 = shortest edge / this.
    double cells_on_shortest_edge = 4;
    /// Largest angle a coarse boundary segment may span on an arc [rad].
    double max_arc_angle = 3.14159265358979323846 / 8;
    /// Skip the recombination attempt and build the subdivided mesh at once (the fallback;
    /// for tests).
    bool always_subdivide = false;

    /// Throws std::invalid_argument naming the member.
    void validate() const;
    /// h0 [m].
    double base_mesh_size(const axisym::Outline &outline) const;
    /// Segments of edge i at level 0 (before the parity fix of the total).
    int segments(const axisym::OutlineEdge &edge, double h0) const;
  };

  /// 1 + the index of `part` in outline.parts(); throws std::invalid_argument if unknown.
  unsigned int boundary_id_of_part(const axisym::Outline &outline, const std::string &part);

  /// Distance from p to the edge as a curve (segment or arc) [m].
  double distance_to_edge(const axisym::OutlineEdge &edge, axisym::Point p);

  /// The index of the edge of `part` that holds the mesh boundary segment from a to b (both
  /// vertices on it): the edge of that part minimizing max(distance(a), distance(b)).
  /// Throws std::invalid_argument if the part has no edge.
  int edge_of_boundary_segment(const axisym::Outline &outline, const std::string &part,
                               axisym::Point a, axisym::Point b);

  struct OutlineMeshInfo
  {
    double base_mesh_size = 0; ///< h0 [m]
    int n_boundary_segments = 0;
    bool subdivided = false; ///< the all-quad fallback (subdivision) was needed
  };

  /// Builds the quadrilateral mesh of the section with the gmsh API and writes it to
  /// `msh_path` (MSH 4.1 ASCII). Initializes and finalizes gmsh. Throws std::runtime_error if
  /// gmsh fails or the result is not all quadrilaterals.
  OutlineMeshInfo write_outline_gmsh_mesh(const axisym::Outline &outline,
                                          const OutlineMeshSpec &spec,
                                          const std::string &msh_path);
} // namespace fem
