// Error measures of the Lame verification, shared by the drivers: the exact solution of
// a problem file, and the relative stress errors of an RFM model against it.
#pragma once

#include "problem/problem.h"
#include "rfm/outline_model.h"
#include "verification/lame_exact.h"

#include <utility>

namespace verification
{
  /// The exact solution for a problem file with `loading` (precondition: loading set).
  LameCylinder exact_of(const axisym::Problem &p);

  /// Relative L2 error of the stress tensor (Frobenius: sigma_rz counted twice, weight r)
  /// on a 4 x 4-cell, 24-point Gauss rule independent of the assembly rule, and the max
  /// component error on a 41 x 41 grid including the boundary, relative to the max
  /// exact stress component.
  std::pair<double, double> stress_errors(const rfm::OutlineModel &model, const LameCylinder &exact);
} // namespace verification
