// The meridian section of a solid of revolution: the rectangle
// [r_min, r_max] x [z_min, z_max] with its boundary cut into named parts, each carrying
// one boundary condition, and the omega function of each part (r_functions.h).
//
// Sides and their outward normals: inner r = r_min (-e_r), outer r = r_max (+e_r),
// bottom z = z_min (-e_z), top z = z_max (+e_z). A part is the interval [begin, end] of
// its side's tangential coordinate (z on inner/outer, r on bottom/top).
//
// Conditions (shear traction is zero on every part that is not `displacement`):
//  * traction:     sigma_nn = normal_stress (a constant: -pressure), sigma_ns = 0;
//  * displacement: u_n = normal_displacement(s), u_s = 0 (inner/outer sides only);
//  * symmetry:     u_n = 0, sigma_ns = 0 (a mirror plane; bottom/top sides only);
//  * contact:      smooth rigid die with known zone: u_n = normal_displacement(s),
//                  sigma_ns = 0 (inner/outer sides only; eq. 1.6 gives u_n*).
#pragma once

#include "rfm/r_functions.h"

#include <functional>
#include <string>
#include <vector>

namespace rfm
{
  enum class Side { inner, outer, bottom, top };
  enum class Condition { traction, displacement, symmetry, contact };

  const char *to_string(Side side);
  const char *to_string(Condition condition);

  struct BoundaryPart
  {
    std::string name;
    Side side = Side::outer;
    double begin = 0.0, end = 0.0; ///< interval along the side [m]
    Condition condition = Condition::traction;
    double normal_stress = 0.0; ///< traction parts: sigma_nn [Pa]
    /// displacement/contact parts: outward normal displacement u_n*(s) [m] and its
    /// derivative along the side du_n*/ds [-]
    std::function<double(double)> normal_displacement;
    std::function<double(double)> normal_displacement_derivative;
  };

  class Section
  {
  public:
    /// Throws std::invalid_argument if the box is empty.
    Section(double r_min, double r_max, double z_min, double z_max);

    /// Adds a part. After all parts are added, validate() checks that every side is
    /// covered exactly once and that the conditions fit the side.
    void add_part(BoundaryPart part);
    void validate() const;

    double r_min() const { return r_min_; }
    double r_max() const { return r_max_; }
    double z_min() const { return z_min_; }
    double z_max() const { return z_max_; }
    const std::vector<BoundaryPart> &parts() const { return parts_; }

    /// Omega of one part: zero exactly on it, positive inside the section,
    /// normalized to first order. A whole side gives the half-plane distance; a part
    /// of a side gives a trimmed segment, extended to a ray when the part reaches a
    /// corner so that it is smooth there (non-smooth only at the part's interior end
    /// points, where the boundary condition changes).
    RValue part_omega(const BoundaryPart &part, double r, double z) const
    {
      return interval_omega(part.side, part.begin, part.end, r, z);
    }
    /// The same for any interval [begin, end] of a side.
    RValue interval_omega(Side side, double begin, double end, double r, double z) const;

    /// Points along the side where the condition changes (interior part ends), as
    /// z values (inner/outer) or r values (bottom/top): quadrature splits and grades there.
    std::vector<double> z_breaks() const;
    std::vector<double> r_breaks() const;

  private:
    double side_begin(Side side) const;
    double side_end(Side side) const;
    double r_min_, r_max_, z_min_, z_max_;
    std::vector<BoundaryPart> parts_;
  };
} // namespace rfm
