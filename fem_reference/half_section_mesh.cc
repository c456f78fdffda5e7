#include "fem_reference/half_section_mesh.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fem
{
  std::vector<double> GradedSegment::steps() const
  {
    std::vector<double> h(n_cells);
    double sum = 0, size = 1;
    for (int i = 0; i < n_cells; ++i, size *= growth)
      h[i] = size, sum += size;
    for (double &x : h)
      x *= (end - start) / sum;
    return h;
  }

  std::vector<double> GradedSegment::nodes() const
  {
    std::vector<double> x{start};
    for (const double h : steps())
      x.push_back(x.back() + h);
    x.back() = end; // no rounding drift at the far end: it is a shared vertex
    return x;
  }

  void HalfSectionMeshSpec::validate() const
  {
    auto require = [](bool ok, const std::string &what) {
      if (!ok)
        throw std::invalid_argument("HalfSectionMeshSpec: " + what);
    };
    require(inner_radius > 0 && outer_radius > inner_radius, "need 0 < inner_radius < outer_radius");
    require(half_length > 0, "need half_length > 0");
    require(!split || (*split > 0 && *split <= half_length), "split must be in (0, half_length]");
    require(level >= 0 && level <= 10, "level must be in [0, 10]");
    require(base_cells_r >= 1 && base_cells_z >= 2, "need base_cells_r >= 1, base_cells_z >= 2");
    require(radial_ratio >= 1 && axial_ratio >= 1, "grading ratios must be >= 1");
  }

  bool HalfSectionMeshSpec::is_split() const
  {
    return split && *split < half_length * (1 - 1e-12);
  }

  namespace
  {
    // Per-cell growth at level `level` for a base segment of n0 cells whose largest/smallest
    // cell ratio is `ratio`: q0 = ratio^(1/(n0-1)), q = q0^(1/2^level) (nested refinement).
    double growth_at_level(double ratio, int n0, int level)
    {
      if (n0 <= 1)
        return 1.0;
      const double q0 = std::pow(ratio, 1.0 / (n0 - 1));
      return std::pow(q0, std::ldexp(1.0, -level));
    }
  } // namespace

  GradedSegment HalfSectionMeshSpec::radial_segment() const
  {
    // Smallest cells at R2 (the loaded, contact side): growth < 1 from R1 toward R2.
    const int n = base_cells_r << level;
    return {inner_radius, outer_radius, n,
            1.0 / growth_at_level(radial_ratio, base_cells_r, level)};
  }

  std::vector<GradedSegment> HalfSectionMeshSpec::axial_segments() const
  {
    if (!is_split())
      {
        const double q =
          grade_toward_end ? 1.0 / growth_at_level(axial_ratio, base_cells_z, level) : 1.0;
        return {{0.0, half_length, base_cells_z << level, q}};
      }
    const double c = *split;
    const int n_lower0 =
      std::clamp(static_cast<int>(std::lround(base_cells_z * c / half_length)), 2,
                 std::max(2, base_cells_z - 2));
    const int n_upper0 = std::max(2, base_cells_z - n_lower0);
    // Both blocks have their smallest cells at z = c.
    return {{0.0, c, n_lower0 << level, 1.0 / growth_at_level(axial_ratio, n_lower0, level)},
            {c, half_length, n_upper0 << level, growth_at_level(axial_ratio, n_upper0, level)}};
  }

  void write_gmsh_mesh(const HalfSectionMeshSpec &spec, const std::string &msh_path)
  {
    spec.validate();
    const GradedSegment radial = spec.radial_segment();
    const std::vector<GradedSegment> axial = spec.axial_segments();
    const double r1 = spec.inner_radius, r2 = spec.outer_radius;

    gmsh::initialize();
    try
      {
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.Verbosity", 1);
        gmsh::model::add("half_section");
        namespace geo = gmsh::model::geo;

        // Corner points bottom-up: (R1, z_k), (R2, z_k) for z_0 = 0, [z_1 = c,] z_n = a.
        std::vector<double> z_levels{0.0};
        for (const GradedSegment &s : axial)
          z_levels.push_back(s.end);
        std::vector<int> p_in, p_out;
        for (const double z : z_levels)
          {
            p_in.push_back(geo::addPoint(r1, z, 0));
            p_out.push_back(geo::addPoint(r2, z, 0));
          }
        // Radial lines R1 -> R2 at every z level, all with the radial progression.
        std::vector<int> radial_lines;
        for (std::size_t k = 0; k < z_levels.size(); ++k)
          {
            radial_lines.push_back(geo::addLine(p_in[k], p_out[k]));
          }
        std::vector<int> inner_lines, outer_lines, surfaces;
        for (std::size_t k = 0; k < axial.size(); ++k)
          {
            const int l_out = geo::addLine(p_out[k], p_out[k + 1]); // upward
            const int l_in = geo::addLine(p_in[k], p_in[k + 1]);    // upward
            outer_lines.push_back(l_out);
            inner_lines.push_back(l_in);
            const int loop = geo::addCurveLoop({radial_lines[k], l_out, -radial_lines[k + 1], -l_in});
            surfaces.push_back(geo::addPlaneSurface({loop}));
          }
        geo::synchronize();

        namespace mesh = gmsh::model::mesh;
        for (const int l : radial_lines)
          mesh::setTransfiniteCurve(l, radial.n_cells + 1, "Progression", radial.growth);
        for (std::size_t k = 0; k < axial.size(); ++k)
          {
            mesh::setTransfiniteCurve(outer_lines[k], axial[k].n_cells + 1, "Progression",
                                      axial[k].growth);
            mesh::setTransfiniteCurve(inner_lines[k], axial[k].n_cells + 1, "Progression",
                                      axial[k].growth);
          }
        for (const int s : surfaces)
          {
            mesh::setTransfiniteSurface(s);
            mesh::setRecombine(2, s);
          }

        gmsh::model::addPhysicalGroup(1, inner_lines, inner_boundary);
        gmsh::model::addPhysicalGroup(1, {outer_lines[0]}, outer_contact_boundary);
        if (outer_lines.size() > 1)
          gmsh::model::addPhysicalGroup(1, {outer_lines[1]}, outer_free_boundary);
        gmsh::model::addPhysicalGroup(1, {radial_lines.back()}, end_boundary);
        gmsh::model::addPhysicalGroup(1, {radial_lines.front()}, symmetry_boundary);
        gmsh::model::addPhysicalGroup(2, surfaces, 1);

        mesh::generate(2);
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        gmsh::write(msh_path);
      }
    catch (...)
      {
        gmsh::finalize();
        throw;
      }
    gmsh::finalize();
  }
} // namespace fem
