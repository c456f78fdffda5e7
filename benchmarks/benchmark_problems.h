// The two problems every benchmark times: the paper's Lame cylinder (p_in = 10 MPa) and
// the paper's die problem at a fixed contact zone c = 0.53 a (bilateral, one linear solve).
#pragma once

#include "problem/problem.h"

namespace benchmarks
{
  inline axisym::Problem make_problem(bool die)
  {
    nlohmann::json j = {
      {"geometry", {{"inner_radius", 0.1}, {"outer_radius", 0.2}, {"length", 0.4}}},
      {"material", {{"youngs_modulus", 2.1e11}, {"poisson_ratio", 0.3}}}};
    if (die)
      j["die"] = {{"indentation", 1e-6}}, j["contact"] = {{"method", "fixed"}, {"half_width", 0.106}};
    else
      j["loading"] = {{"inner_pressure", 1e7}};
    return axisym::parse_problem(j);
  }
} // namespace benchmarks
