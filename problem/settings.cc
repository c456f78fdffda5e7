#include "problem/settings.h"

#include "problem/input_error.h"

#include <algorithm>
#include <cmath>

namespace axisym
{
  std::string IntRange::rule() const
  {
    std::string s = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (*reason != '\0')
      s += std::string(" (") + reason + ")";
    return s;
  }

  void IntRange::check(const long long x, const std::string &shown_as) const
  {
    if (!contains(x))
      throw InputError(shown_as + " = " + std::to_string(x) + ": must be " + rule());
  }

  void RfmSettings::validate() const
  {
    ranges::rfm_degree.check(degree);
    ranges::rfm_extra_gauss_points.check(extra_gauss_points);
    ranges::rfm_n_cells_r.check(n_cells_r);
    ranges::rfm_n_cells_z.check(n_cells_z);
    ranges::rfm_n_graded_layers.check(n_graded_layers);
    ranges::rfm_edge_modes.check(edge_modes);
    ranges::rfm_edge_extra_points.check(edge_extra_points);
    ranges::rfm_edge_mode_degree.check(edge_mode_degree);
    ranges::rfm_vertex_mode_degree.check(vertex_mode_degree);
    ranges::rfm_vertex_local_degree.check(vertex_local_degree);
    ranges::rfm_vertex_local_displacement_degree.check(vertex_local_displacement_degree);
    if (!(vertex_local_degree_ratio >= min_vertex_local_degree_ratio &&
          vertex_local_degree_ratio <= max_vertex_local_degree_ratio))
      throw InputError("rfm.vertex_local_degree_ratio = " + std::to_string(vertex_local_degree_ratio) +
                       ": must be in [0.25, 1.5] (the vertex's local stress degree over p)");
    ranges::rfm_resonant_displacement_degree.check(resonant_displacement_degree);
    if (!(vertex_max_exponent >= 0.0 && vertex_max_exponent <= 6.0))
      throw InputError("rfm.vertex_max_exponent = " + std::to_string(vertex_max_exponent) +
                       ": must be in [0, 6] (the largest Re lambda of the vertex modes; 0 is off)");
    if (!(vertex_cutoff > 0.0 && vertex_cutoff <= 1.0))
      throw InputError("rfm.vertex_cutoff = " + std::to_string(vertex_cutoff) +
                       ": must be in (0, 1] (a fraction of the room around the vertex)");
    ranges::rfm_max_degree.check(max_degree);
    if (!(z_degree_ratio >= min_z_degree_ratio && z_degree_ratio <= max_z_degree_ratio))
      throw InputError("rfm.z_degree_ratio = " + std::to_string(z_degree_ratio) +
                       ": must be in [0.25, 4] (the degree along z over the degree along r)");
    // The largest p this run may reach: the fixed degree, or the last of the degree sequence.
    const int top_p = degree_given ? degree : std::max(degree, max_degree);
    if (const long long top = std::llround(z_degree_ratio * top_p); top > max_degree_z)
      throw InputError("rfm.z_degree_ratio = " + std::to_string(z_degree_ratio) + ": the degree along z, " +
                       std::to_string(top) + " at p = " + std::to_string(top_p) + ", must stay <= " +
                       std::to_string(max_degree_z) + " (lower it, or rfm.max_degree)");
    ranges::rfm_local_levels.check(local_levels);
    ranges::rfm_local_degree.check(local_degree);
    ranges::rfm_local_stress_degree.check(local_stress_degree);
    if (!(local_first_box > 1.0 && local_first_box <= 10.0))
      throw InputError("rfm.local_first_box = " + std::to_string(local_first_box) +
                       ": must be in (1, 10] (the smallest box must hold the zone)");
    if (!(local_max_box > 0.0 && local_max_box <= 1.0))
      throw InputError("rfm.local_max_box = " + std::to_string(local_max_box) +
                       ": must be in (0, 1] (a fraction of the section's extent along the die's part)");
    if (tolerance && !(*tolerance >= min_tolerance && *tolerance <= 0.1))
      throw InputError("rfm.tolerance = " + std::to_string(*tolerance) +
                       ": must be in [1e-14, 0.1] (the indicator |Phi_L - Phi_C| / |Phi_R| "
                       "does not fall below rounding, about 1e-15)");
    if (!(grading_ratio > 0.0 && grading_ratio < 1.0))
      throw InputError("rfm.grading_ratio = " + std::to_string(grading_ratio) +
                       ": must be in (0, 1)");
    if (!(edge_cutoff > 0.0 && edge_cutoff < 1.0))
      throw InputError("rfm.edge_cutoff = " + std::to_string(edge_cutoff) +
                       ": must be in (0, 1) (a fraction of min(c, a - c, R2 - R1))");
  }
} // namespace axisym
