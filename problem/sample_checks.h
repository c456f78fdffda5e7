// Checks of a problem's sample points that both solvers report in their result file
// (DESIGN.md 7: diagnostics), so that neither gives a number without saying what it is worth
// (issue 24 item 6).
//
// A sample exactly at a vertex where the stress has no value: at a singular vertex
// (Re lambda < 1, singular_vertices) the stress grows like rho^(Re lambda - 1) toward it;
// where a traction jumps at a vertex (traction_jump_vertices) it depends on the direction of
// approach. A solver evaluated there gives a finite number all the same, and not a limit: the
// RFM's global field read sigma_zz = 0 and sigma_rr = 0 at the stepped shaft's re-entrant
// shoulder corner at p = 12 (both omegas vanish there) and the mean of the two tractions at
// the pressure band's end; the FEM gives whichever cell's value holds the point, growing with
// the refinement toward a singular vertex. The vertices are the problem's, whatever columns
// or grading a discretization placed there.
#pragma once

#include "problem/problem.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace axisym
{
  struct SampleAtVertex
  {
    enum class Kind
    {
      singular,     ///< Re lambda < 1
      traction_jump ///< the stress there depends on the direction of approach
    };
    std::size_t sample = 0; ///< index into Problem::samples
    Point at;               ///< the sample's point as given (the vertex within the tolerance)
    Kind kind = Kind::singular;
    double exponent = 0;    ///< singular: the smallest Re lambda of the vertex's wedge
  };

  /// Every sample of the problem that lies on a singular vertex or a traction jump (within
  /// 1e-9 of the section's size), in the samples' order; a sample at a vertex that is both
  /// is listed twice.
  std::vector<SampleAtVertex> samples_at_vertices(const Problem &problem);

  /// For each sample, whether it has a value to converge to: false for those
  /// samples_at_vertices lists (what a goal-oriented refinement or a convergence check of
  /// the samples leaves out).
  std::vector<bool> samples_with_a_value(const Problem &problem);

  /// The result's diagnostics.samples_at_vertices: per entry r, z, kind ("singular" with its
  /// exponent, or "traction_jump").
  nlohmann::json to_json(const std::vector<SampleAtVertex> &at);

  /// The warning's sentence for a solver's diagnostics.message (empty when `at` is).
  std::string samples_at_vertices_warning(const std::vector<SampleAtVertex> &at);
} // namespace axisym
