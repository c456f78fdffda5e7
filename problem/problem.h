// Problem files (JSON, SI units) shared by rfm_solve and fem_solve: DESIGN.md section 7.
// This is the problem layer below both solvers: no RFM and no deal.II in here.
//
//   { "geometry": {"inner_radius": m, "outer_radius": m, "length": m},
//     "material": {"youngs_modulus": Pa, "poisson_ratio": -},
//     "loading":  {"inner_pressure": Pa, "outer_pressure": Pa},          // optional
//     "die":      {"indentation": m, "profile": "parabolic"},            // optional
//     "contact":  {"method": "edge-intensity" | "iterate" | "max-force" | "fixed",
//                  "half_width": m, "curve_points": n},   // n: P(c) and K(c) curve
//     "samples":  [[r, z], ...],
//     "rfm": {"degree": p, "edge_modes": k, "edge_cutoff": f, ...},
//     "fem": {"degree": p, "refinements": L} }
//
// At least one of loading and die. Unknown keys, wrong types, non-finite numbers and
// non-physical values are rejected with InputError naming the field (as a JSON path),
// the value and the rule. The body spans r in [R1, R2], z in [-length/2, length/2].
#pragma once

#include "problem/input_error.h"
#include "problem/material.h"
#include "problem/settings.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace axisym
{
  struct Geometry
  {
    double inner_radius = 0.1, outer_radius = 0.2, length = 0.4; ///< [m]
    double half_length() const { return 0.5 * length; }
  };

  struct Loading
  {
    double inner_pressure = 0.0, outer_pressure = 0.0; ///< [Pa], positive compresses the surface
  };

  /// Smooth rigid die on r = R2 (paper eq. 4.1): r - R2 + delta (1 - 2 z^2 / a^2) = 0,
  /// a = length/2. Linearized normal indentation (eq. 1.6): u_r*(z) = -delta (1 - 2 z^2/a^2).
  struct Die
  {
    double indentation = 1e-6; ///< delta [m], > 0
    std::string profile = "parabolic";
  };

  struct Problem
  {
    Geometry geometry;
    Material material;
    std::optional<Loading> loading;
    std::optional<Die> die;
    ContactSettings contact;
    std::vector<std::array<double, 2>> samples; ///< (r, z) [m]
    RfmSettings rfm;
    FemSettings fem;
    nlohmann::json source; ///< the file as read, echoed into results
  };

  /// Parses and validates; throws InputError.
  Problem parse_problem(const nlohmann::json &j);
  /// Reads a file (InputError if missing or malformed) and parses it.
  Problem read_problem_file(const std::string &path);

  /// Die indentation u_r*(z) and its derivative for the problem's profile.
  double die_u_r(const Die &die, const Geometry &g, double z);
  double die_u_r_derivative(const Die &die, const Geometry &g, double z);
} // namespace axisym
