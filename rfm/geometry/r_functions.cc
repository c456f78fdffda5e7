#include "rfm/geometry/r_functions.h"

namespace rfm
{
  RValue half_plane(const double r, const double z, const double r0, const double z0,
                    const double n_r, const double n_z)
  {
    return {n_r * (r - r0) + n_z * (z - z0), n_r, n_z};
  }

  RValue strip(const double x, const double x_lo, const double x_hi)
  {
    const double h = x_hi - x_lo;
    return {(x - x_lo) * (x_hi - x) / h, (x_hi + x_lo - 2.0 * x) / h, 0.0};
  }

  RValue disk(const double r, const double z, const double r0, const double z0,
              const double radius)
  {
    const double dr = r - r0, dz = z - z0;
    return {(radius * radius - dr * dr - dz * dz) / (2.0 * radius), -dr / radius,
            -dz / radius};
  }

  RValue trimmed_segment(const RValue &f_length, const RValue &t_length, const double length)
  {
    // In units of length: f = f_length / l, t = t_length / l, and w_length = l w, whose
    // gradient is l times w's (f's and t's gradients are over l too).
    const double l = length;
    const RValue f{f_length.value / l, f_length.d_r / l, f_length.d_z / l};
    const RValue t{t_length.value / l, t_length.d_r / l, t_length.d_z / l};
    // w^2 = f^2 + g^2 with g = (s - t)/2, s = sqrt(t^2 + f^4).
    const double f2 = f.value * f.value;
    const double s = std::sqrt(t.value * t.value + f2 * f2);
    const double g = 0.5 * (s - t.value);
    const double w = std::sqrt(f2 + g * g);
    if (w == 0.0)
      return {0.0, 0.0, 0.0}; // on the segment: w is not differentiable across it
    // ds = (t dt + 2 f^3 df) / s; at s = 0 (t = f = 0, an end point) take ds = 0.
    auto ds = [&](const double dt, const double df) {
      return s > 0.0 ? (t.value * dt + 2.0 * f2 * f.value * df) / s : 0.0;
    };
    const double dg_r = 0.5 * (ds(t.d_r, f.d_r) - t.d_r);
    const double dg_z = 0.5 * (ds(t.d_z, f.d_z) - t.d_z);
    return {l * w, l * (f.value * f.d_r + g * dg_r) / w, l * (f.value * f.d_z + g * dg_z) / w};
  }

  namespace
  {
    // x + y + sign * sqrt(x^2 + y^2) and its gradient.
    RValue r0_combine(const RValue &x, const RValue &y, const double sign)
    {
      const double rho = std::sqrt(x.value * x.value + y.value * y.value);
      if (rho == 0.0)
        {
          // Limit along x = y: d rho = (dx + dy) / sqrt(2).
          const double c = sign / std::sqrt(2.0);
          return {0.0, x.d_r + y.d_r + c * (x.d_r + y.d_r),
                  x.d_z + y.d_z + c * (x.d_z + y.d_z)};
        }
      return {x.value + y.value + sign * rho,
              x.d_r + y.d_r + sign * (x.value * x.d_r + y.value * y.d_r) / rho,
              x.d_z + y.d_z + sign * (x.value * x.d_z + y.value * y.d_z) / rho};
    }
  } // namespace

  RValue r_conjunction(const RValue &x, const RValue &y) { return r0_combine(x, y, -1.0); }

  RValue r_disjunction(const RValue &x, const RValue &y) { return r0_combine(x, y, +1.0); }

  RValue r_negation(const RValue &x) { return {-x.value, -x.d_r, -x.d_z}; }

  RValue product(const RValue &x, const RValue &y)
  {
    return {x.value * y.value, x.d_r * y.value + x.value * y.d_r,
            x.d_z * y.value + x.value * y.d_z};
  }

  RValue normalize(const RValue &w)
  {
    const double g2 = w.d_r * w.d_r + w.d_z * w.d_z;
    const double q = std::sqrt(w.value * w.value + g2);
    if (q == 0.0)
      return {0.0, 0.0, 0.0};
    // d(w/q) = dw/q - w dq/q^2; dq involves the Hessian of w, which is not carried, so
    // the second term is dropped: exact wherever w = 0, first-order accurate near it.
    return {w.value / q, w.d_r / q, w.d_z / q};
  }
} // namespace rfm
