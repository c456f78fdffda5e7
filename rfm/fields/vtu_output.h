// The RFM fields for people: a VTU file (ParaView) of the solved fields sampled on a fine
// uniform grid of the section, with the field names of the FEM reference's VTU
// (fem_reference/axisymmetric_fem_postprocessing.cc), so that both open side by side and their difference
// can be taken (ParaView: Resample With Dataset, then Python Calculator).
//
// Coordinates are (x, y, 0) = (r, z, 0) [m]. Point data: u_r, u_z [m]; sigma_rr, sigma_zz,
// sigma_tt, sigma_rz [Pa]; displacement = (u_r, u_z, 0) [m] as one vector (Warp By Vector);
// with a density evaluator, also constitutive_error [J/m^3] (rfm_solve: the RFM's
// constitutive-relation error density, OutlineModel::constitutive_error_density: where the
// indicator's gap lies; the FEM's VTU has no such field).
#pragma once

#include "rfm/fields/solution.h"

#include <functional>
#include <string>

namespace rfm
{
  /// The grid: n_r x n_z points on [r_min, r_max] x [z_min, z_max], quadrilateral cells.
  struct VtuGrid
  {
    double r_min = 0, r_max = 1, z_min = 0, z_max = 1;
    int n_r = 101, n_z = 201;
  };

  /// A scalar density at points (r, z) from the fields there.
  using DensityEvaluator =
    std::function<Eigen::VectorXd(const Eigen::Ref<const Eigen::VectorXd> &,
                                  const Eigen::Ref<const Eigen::VectorXd> &, const FieldValues &)>;

  /// The VTU (XML, ASCII) text of the fields on the grid. With `inside`, only the cells whose
  /// four corners are inside are written, and the fields are evaluated at their points only
  /// (the others are written as 0 and belong to no cell). With `constitutive_error`, its
  /// values are written as the point data constitutive_error.
  std::string fields_vtu(const FieldEvaluator &evaluate, const VtuGrid &grid,
                         const std::function<bool(double, double)> &inside = {},
                         const DensityEvaluator &constitutive_error = {});
} // namespace rfm
