#include "fem_reference/body_loads.h"

#include <cmath>

namespace fem
{
  BodyLoadField::BodyLoadField(const axisym::Problem &problem)
  {
    const axisym::BodyLoads &loads = problem.body_loads;
    if (problem.legacy_cylinder || !loads.any())
      return;
    const double omega = loads.angular_velocity, g = loads.gravity;
    has_force_ = omega != 0.0 || g != 0.0;
    has_thermal_ = loads.temperature[0] != 0.0 || loads.temperature[1] != 0.0 ||
                   loads.temperature[2] != 0.0;
    // parse_problem guarantees the constants; a Problem assembled by hand may not.
    if (has_force_)
      {
        if (!problem.material.density)
          throw axisym::InputError("material.density: missing, needed by loading." +
                                   std::string(omega != 0.0 ? "angular_velocity" : "gravity"));
        density_omega2_ = *problem.material.density * omega * omega;
        density_g_ = *problem.material.density * g;
      }
    if (has_thermal_)
      {
        if (!problem.material.thermal_expansion)
          throw axisym::InputError(
            "material.thermal_expansion: missing, needed by loading.temperature");
        alpha_ = *problem.material.thermal_expansion;
        temperature_ = loads.temperature;
      }
  }
} // namespace fem
