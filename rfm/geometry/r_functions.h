// R-functions in the meridian plane (r, z): values with first derivatives.
//
// An omega function describes a boundary part: omega = 0 on the part and omega > 0 in
// the interior of the section (Rvachev 1982; Shapiro, Acta Numerica 2007). "Normalized
// to first order" means |grad omega| = 1 on the part, so omega behaves like the
// distance to it. Displacement structures are differentiated once, so every function
// here carries its gradient; stress structures use values only.
#pragma once

#include <cmath>

namespace rfm
{
  /// A scalar field value and its gradient at one point.
  struct RValue
  {
    double value = 0.0;
    double d_r = 0.0;
    double d_z = 0.0;
  };

  // 1. Primitives. Each is positive on the side of its part that holds the section.

  /// Half-plane (n_r, n_z) . ((r, z) - (r0, z0)) >= 0 with unit normal n pointing into
  /// the region: normalized (|grad| = 1 everywhere). Precondition: |n| = 1.
  RValue half_plane(double r, double z, double r0, double z0, double n_r, double n_z);

  /// Strip between the parallel lines r = r_lo and r = r_hi (or z, by swapping the
  /// arguments): (x - x_lo)(x_hi - x)/(x_hi - x_lo), normalized on both lines. Its
  /// derivative is returned in d_r; callers working in z swap d_r and d_z.
  RValue strip(double x, double x_lo, double x_hi);

  /// Disk of radius R about (r0, z0): (R^2 - |p - p0|^2) / (2 R), normalized on the circle.
  RValue disk(double r, double z, double r0, double z0, double radius);

  /// Trimmed segment: given f (normalized, f = 0 on the segment's line) and t (t >= 0 on
  /// the segment, t < 0 beyond its ends), both lengths, returns
  ///   w = l w1(f / l, t / l),  w1(f, t) = sqrt(f^2 + ((sqrt(t^2 + f^4) - t) / 2)^2),
  /// which vanishes exactly on the segment, equals |f| near its inside and is not smooth
  /// at its two end points only. f^4 and t^2 are not of one dimension, so the form needs a
  /// length l (> 0) to be the same function of the geometry in any unit of length; the
  /// outline structures take the section's size.
  RValue trimmed_segment(const RValue &f, const RValue &t, double length);

  // 2. R0 operations (sufficient set of the R0 system), with chain-rule gradients.
  //    x AND y = x + y - sqrt(x^2 + y^2), x OR y = x + y + sqrt(x^2 + y^2), NOT x = -x.
  //    Both are smooth away from x = y = 0, where the gradient is set to the limit along
  //    x = y (any value is a subgradient there).
  RValue r_conjunction(const RValue &x, const RValue &y);
  RValue r_disjunction(const RValue &x, const RValue &y);
  RValue r_negation(const RValue &x);

  /// Product x * y: vanishes on the union of the zero sets. For the sides of a
  /// rectangle this is what the structures use (see structures.h: it keeps the
  /// polynomial character of the approximation, which R0's square root destroys).
  RValue product(const RValue &x, const RValue &y);

  /// First-order normalization w / sqrt(w^2 + |grad w|^2): same zero set and sign,
  /// and |grad| = 1 on the zero set. Gradient by the exact chain rule needs second
  /// derivatives of w; we return the gradient exact on the zero set (grad w / |grad w|)
  /// and the first-order term elsewhere, which is what structures need (they use
  /// normalized functions only as values away from the boundary).
  RValue normalize(const RValue &w);
} // namespace rfm
