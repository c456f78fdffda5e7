// Problem files (JSON, SI units) shared by rfm_solve and fem_solve: DESIGN.md section 7
// (the legacy hollow cylinder below) and 7.1 (any section: geometry.outline, boundary).
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
// At least one of loading and die. The body spans r in [R1, R2], z in [-length/2, length/2].
//
// The outline form (DESIGN.md 7.1):
//
//   { "geometry": {"outline": [{"start": [r, z]}, {"line_to": [r, z], "part": name},
//                              {"arc_to": [r, z], "center": [r, z], "part": name}, ...]},
//     "boundary": {name: {"pressure": Pa} | {"traction": [Pa, Pa]} | {"symmetry": true}
//                        | {"displacement": [m, m]}
//                        | {"die": {"indentation": m | "force": N, "center": [r, z],
//                                   "profile": {"shape": "paraboloid", "radius": m}
//                                            | {"shape": "flat_rounded", "flat_radius": m,
//                                               "edge_radius": m}
//                                            | {"shape": "flat", "radius": m}}}, ...},
//     "contact":  {"method": ...},   // optional, with a die (as above)
//     "material": {..., "density": kg/m^3, "thermal_expansion": 1/K},
//     "loading":  {"angular_velocity": rad/s, "gravity": m/s^2,
//                  "temperature": {"field": [T0, T_r, T_z]}},                // optional
//     "samples", "rfm", "fem" as above }
//
// Unknown keys, wrong types, non-finite numbers and non-physical values are rejected with
// InputError naming the field (as a JSON path), the value and the rule.
#pragma once

#include "problem/input_error.h"
#include "problem/material.h"
#include "problem/outline.h"
#include "problem/settings.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <map>
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

  /// A rigid die's shape: its initial gap g0(s) >= 0 [m] to the undeformed part at the
  /// distance s >= 0 [m] from the die's centre along the part (DESIGN.md 7.1).
  struct DieProfile
  {
    enum class Shape
    {
      paraboloid,   ///< g0 = s^2 / (2 radius): Hertz-type
      flat_rounded, ///< g0 = 0 for s <= flat_radius, (s - flat_radius)^2 / (2 edge_radius) beyond
      flat          ///< g0 = 0 for s <= radius; no die beyond (a sharp edge)
    };
    Shape shape = Shape::paraboloid;
    double radius = 0;      ///< paraboloid: R [m]; flat: the punch radius b [m]
    double flat_radius = 0; ///< flat_rounded: b [m]
    double edge_radius = 0; ///< flat_rounded: rho [m]

    /// g0(s) [m] for s >= 0; +infinity beyond a flat punch's edge (no die surface there).
    double gap(double s) const;
    /// g0'(s) and g0''(s) [1/m] for 0 <= s < extent() (at a kink: the values beyond it).
    double slope(double s) const;
    double curvature(double s) const;
    /// The distances s > 0 where g0'' jumps (the rounded punch's flat radius; none for the
    /// paraboloid), increasing: quadratures of g0 split there.
    std::vector<double> kinks() const;
    /// Where the die's surface ends: the flat punch's radius; +infinity otherwise.
    double extent() const;
    /// The die's surface ends at a sharp edge (finite extent): the zone is its face, and
    /// the edge pressure is singular there.
    bool sharp_edge() const { return std::isfinite(extent()); }
  };
  const char *to_string(DieProfile::Shape shape);

  /// Frictionless contact with a rigid die on a straight part (DESIGN.md 7.1). The die moves
  /// by delta along the part's inward normal: in the contact zone the normal displacement into
  /// the body is delta - g0(s) and the shear traction vanishes; outside it the part is traction
  /// free and does not penetrate the die. Exactly one of indentation and force is set.
  struct DieCondition
  {
    std::optional<double> indentation; ///< delta [m], > 0
    std::optional<double> force;       ///< P [N] on the whole body of revolution, > 0
    Point center;                      ///< where the die touches first, on the part [m]
    DieProfile profile;
  };

  /// The condition on one boundary part (DESIGN.md 7.1), SI units, normal n outward.
  struct PartCondition
  {
    enum class Kind
    {
      traction_free, ///< no condition given: sigma . n = 0
      pressure,      ///< sigma . n = -pressure n (positive pushes on the body)
      traction,      ///< sigma . n = (t_r, t_z)
      symmetry,      ///< straight edges only: u . n = 0, shear traction 0
      displacement,  ///< u = (u_r, u_z); [0, 0] clamps
      die,           ///< frictionless rigid die (`die`; the legacy outer side: Problem::die)
      axis           ///< r = 0: u_r = 0, sigma_rz = 0 (implied, never given)
    };
    Kind kind = Kind::traction_free;
    double pressure = 0.0;                      ///< [Pa]; kind die: on the part beyond the zone
                                                ///< (the legacy outer pressure)
    std::array<double, 2> traction{{0.0, 0.0}};   ///< (t_r, t_z) [Pa]
    std::array<double, 2> displacement{{0.0, 0.0}}; ///< (u_r, u_z) [m]
    DieCondition die;                           ///< kind == die
  };
  const char *to_string(PartCondition::Kind kind);

  /// Body loads (DESIGN.md 7.1; the solvers apply them from issue 14 on).
  struct BodyLoads
  {
    double angular_velocity = 0.0;           ///< omega [rad/s]: f_r = density omega^2 r
    double gravity = 0.0;                    ///< g [m/s^2]: f_z = -density g
    std::array<double, 3> temperature{{0, 0, 0}}; ///< T = T0 + T_r r + T_z z [K]
    bool any() const;
    bool body_force() const { return angular_velocity != 0.0 || gravity != 0.0; }
    bool thermal() const;
  };

  /// The load fields of both solvers at (r, z), for a material that has the constants the
  /// loads need (the parser checks that): the body force f = (density omega^2 r,
  /// -density g) [N/m^3], and the free thermal strain alpha T of each normal strain
  /// component (rr, zz, tt) [-]; 0 where the load is off.
  std::array<double, 2> body_force(const BodyLoads &loads, const Material &material, double r,
                                   double z);
  double thermal_strain(const BodyLoads &loads, const Material &material, double r, double z);

  /// The meridian section as an outline with a condition on every part. Both file forms
  /// give one: the legacy hollow cylinder becomes the rectangle [R1, R2] x [0, a] with the
  /// parts mid_plane (symmetry), outer, end and inner, and `mirrored` set (the body is the
  /// section and its mirror image in z = 0, and integrals refer to the whole body).
  struct Body
  {
    Outline outline;
    std::map<std::string, PartCondition> conditions; ///< one entry per part of the outline
    bool mirrored = false;
    /// The condition of the part of edge i.
    const PartCondition &condition_of_edge(int i) const;
    /// The parts that carry a die, in the order of Outline::parts().
    std::vector<std::string> die_parts() const;
  };

  /// The frame of a die on its part (straight: every edge of the part on one line): the
  /// centre, the unit tangent t along the part (the direction of travel of its first edge) and
  /// the outward unit normal n. A point x of the part is at the signed distance
  /// s = (x - center) . t from the centre; the part covers s in [s_min, s_max].
  struct DieFrame
  {
    Point center, tangent, normal;
    double s_min = 0, s_max = 0;
    /// Lengths below this are zero: 1e-9 of the outline's size (die_frame sets it).
    double tolerance = 0;
    /// The part runs on beyond the centre toward +s (-s): the centre is not at that end.
    bool runs_up() const { return s_max > tolerance; }
    bool runs_down() const { return s_min < -tolerance; }
    /// A zone's end s_lo (s_hi) is free, a contact edge where the condition changes, when it
    /// lies inside the part and not at the part's own end (the one rule of every solver).
    bool free_low_end(double s_lo) const { return s_lo > s_min + tolerance; }
    bool free_high_end(double s_hi) const { return s_hi < s_max - tolerance; }
    /// The centre on the axis and the part across it (an end face): the die is an
    /// axisymmetric punch, its zone a disc of radius s_max at most (half_space.h).
    bool about_axis() const { return std::abs(center.r) <= tolerance && std::abs(tangent.z) <= 1e-12; }
    /// The signed distance s of x along the part from the centre [m].
    double coordinate(Point x) const
    {
      return (x.r - center.r) * tangent.r + (x.z - center.z) * tangent.z;
    }
    Point point_at(double s) const { return {center.r + s * tangent.r, center.z + s * tangent.z}; }
  };
  /// Precondition: `part` carries a die (Body::die_parts()); the parser checked it is straight.
  DieFrame die_frame(const Body &body, const std::string &part);

  struct Problem
  {
    /// The legacy form (geometry.inner_radius, ...) or the outline form (geometry.outline).
    bool legacy_cylinder = true;
    Geometry geometry; ///< legacy form only (the hollow cylinder, die and pressures)
    Material material;
    std::optional<Loading> loading;
    std::optional<Die> die;
    ContactSettings contact;
    std::optional<Body> body; ///< always set by parse_problem (both forms)
    BodyLoads body_loads;     ///< outline form only
    std::vector<std::array<double, 2>> samples; ///< (r, z) [m]
    RfmSettings rfm;
    FemSettings fem;
    nlohmann::json source; ///< the file as read, echoed into results
  };

  /// Parses and validates; throws InputError.
  Problem parse_problem(const nlohmann::json &j);
  /// The legacy hollow cylinder's outline Body (the half section z >= 0, mirrored) from its
  /// geometry, loading and die: what parse_problem sets as problem.body for the legacy form.
  /// Code that changes those fields of a parsed problem rebuilds the body with it.
  Body legacy_body(const Problem &p);
  /// Reads a file (InputError if missing or malformed) and parses it.
  Problem read_problem_file(const std::string &path);

  /// Die indentation u_r*(z) and its derivative for the problem's profile.
  double die_u_r(const Die &die, const Geometry &g, double z);
  double die_u_r_derivative(const Die &die, const Geometry &g, double z);
} // namespace axisym
