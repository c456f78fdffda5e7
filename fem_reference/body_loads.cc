#include "fem_reference/body_loads.h"

#include <cmath>

namespace fem
{
  BodyLoadField::BodyLoadField(const axisym::Problem &problem)
    : loads_(problem.body_loads)
    , material_(problem.material)
  {
    if (problem.legacy_cylinder || !loads_.any())
      return;
    has_force_ = loads_.body_force();
    has_thermal_ = loads_.thermal();
    // parse_problem guarantees the constants; a Problem assembled by hand may not.
    if (has_force_ && !material_.density)
      throw axisym::InputError("material.density: missing, needed by loading." +
                               std::string(loads_.angular_velocity != 0.0 ? "angular_velocity"
                                                                          : "gravity"));
    if (has_thermal_ && !material_.thermal_expansion)
      throw axisym::InputError("material.thermal_expansion: missing, needed by loading.temperature");
  }
} // namespace fem
