// Quadrilateral meshes of the meridian half section r in [R1, R2], z in [0, a] (a = length/2;
// the body is symmetric about z = 0, DESIGN.md section 4), graded toward the outer side and
// toward the contact edge (R2, c). No deal.II here: the gmsh C++ API writes a .msh file, and
// the same 1-D node distributions feed deal.II's subdivided_hyper_rectangle fallback, so both
// generators give the same vertices.
//
// Node distributions are geometric: a segment of n cells with per-cell growth factor q has
// cell sizes h0, h0 q, ..., h0 q^(n-1). Refinement level L multiplies n by 2^L and takes
// q^(1/2^L), which inserts one node in every cell: the meshes are nested (mesh-size halving
// with the grading preserved), and level L is what `--refinements L` means.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fem
{
  /// Boundary ids of the half section (gmsh physical group tags = deal.II boundary ids).
  enum BoundaryId : unsigned int
  {
    inner_boundary = 1,         ///< r = R1
    outer_contact_boundary = 2, ///< r = R2, z in [0, c] (the whole outer side when not split)
    outer_free_boundary = 3,    ///< r = R2, z in [c, a]
    end_boundary = 4,           ///< z = a
    symmetry_boundary = 5       ///< z = 0
  };

  /// One graded 1-D segment [start, end].
  struct GradedSegment
  {
    double start = 0, end = 1;
    int n_cells = 1;
    double growth = 1; ///< size ratio of neighbouring cells, from start toward end (> 0)

    /// n_cells + 1 node coordinates from start to end.
    std::vector<double> nodes() const;
    /// Cell sizes (sum = end - start).
    std::vector<double> steps() const;
  };

  struct HalfSectionMeshSpec
  {
    double inner_radius = 0.1, outer_radius = 0.2, half_length = 0.2; ///< R1, R2, a [m]
    /// z = c becomes a vertex of the outer line (the outer side splits into the contact part
    /// [0, c] and the free part [c, a]). nullopt or c = a: no split, grading toward z = a
    /// only if grade_toward_end.
    std::optional<double> split;
    bool grade_toward_end = false;
    int level = 0;             ///< refinement level L
    int base_cells_r = 4;      ///< cells across the wall at level 0
    int base_cells_z = 8;      ///< cells along [0, a] at level 0
    double radial_ratio = 3.0; ///< largest / smallest radial cell at level 0 (smallest at R2)
    double axial_ratio = 3.0;  ///< largest / smallest axial cell per block at level 0

    /// Throws std::invalid_argument naming the member when inconsistent.
    void validate() const;
    GradedSegment radial_segment() const;
    /// One segment when not split, else [0, c] (graded toward c) and [c, a] (graded away from c).
    std::vector<GradedSegment> axial_segments() const;
    bool is_split() const;
  };

  /// Builds the mesh with the gmsh API (geo kernel, transfinite curves with the progressions
  /// of the spec, recombined to quadrilaterals, physical groups tagged by BoundaryId, surface
  /// group 1) and writes it to `msh_path` (MSH 4.1 ASCII). Initializes and finalizes gmsh.
  void write_gmsh_mesh(const HalfSectionMeshSpec &spec, const std::string &msh_path);
} // namespace fem
