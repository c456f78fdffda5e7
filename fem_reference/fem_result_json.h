// Result JSON of the FEM reference (DESIGN.md section 7), the same keys as rfm_solve's.
#pragma once

#include "fem_reference/axisymmetric_fem.h"

#include <nlohmann/json.hpp>

namespace fem
{
  /// {"solver": "fem", "problem", "discretization", "functionals", "contact", "samples",
  ///  "reactions", "diagnostics", "timing"}; "functionals" and "contact" only when the solve
  ///  produced them, "reactions" (support parts, N for the full body) for outline problems.
  ///  The meaning of every key: fem_reference/README.md.
  nlohmann::json result_to_json(const axisym::Problem &problem, const FemOptions &options,
                                const FemResult &result);
} // namespace fem
