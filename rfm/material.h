// The material and the stress ordering of the shared problem layer (problem/material.h),
// under the names the RFM code uses.
#pragma once

#include "problem/material.h"

namespace rfm
{
  using axisym::Material;
  using axisym::n_stress_components;
  using axisym::StressComponent;
  using axisym::rr;
  using axisym::rz;
  using axisym::tt;
  using axisym::zz;
} // namespace rfm
