// The consistent contact pressure of a die's zone on an outline part (outline_contact.h).
#include "rfm/contact/outline_contact.h"

#include "rfm/contact/half_space.h"
#include "rfm/quadrature/quadrature.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfm
{
  bool consistent_pressure_applies(const axisym::DieFrame &frame, const DieZone &zone)
  {
    return (!frame.runs_down() || frame.free_low_end(zone.s_lo)) &&
           (!frame.runs_up() || frame.free_high_end(zone.s_hi));
  }

  std::vector<double> consistent_die_pressure(const OutlineModel &model, const axisym::Problem &problem,
                                              const DieZone &zone, const std::vector<double> &s,
                                              const int n_moments)
  {
    if (n_moments < 1)
      throw std::invalid_argument("consistent_die_pressure: n_moments must be >= 1");
    const axisym::DieFrame frame = axisym::die_frame(*problem.body, zone.part);
    if (!consistent_pressure_applies(frame, zone))
      return std::vector<double>(s.size(), std::numeric_limits<double>::quiet_NaN());
    const bool sharp = problem.body->conditions.at(zone.part).die.profile.sharp_edge();
    const bool two_ends = frame.runs_up() && frame.runs_down();
    // The zone's coordinate x(s): one free end x = |s| / h, two x = (s - mid) / h.
    const double mid = two_ends ? 0.5 * (zone.s_lo + zone.s_hi) : 0.0;
    const double h = two_ends ? 0.5 * (zone.s_hi - zone.s_lo) : std::max(zone.s_hi, -zone.s_lo);
    const int n_phi = two_ends ? 2 * n_moments - 1 : n_moments;
    auto degree = [two_ends](int k) { return two_ends ? k : 2 * k; };
    const int m_max = degree(n_phi - 1);
    // T_m or U_m at x in [-1, 1] (X_{m+1} = 2 x X_m - X_{m-1}, X_1 = x (T) or 2 x (U)).
    auto chebyshev = [&](double x, std::vector<double> &v) {
      v.assign(m_max + 1, 0.0);
      v[0] = 1.0;
      if (m_max >= 1)
        v[1] = (sharp ? 1.0 : 2.0) * x;
      for (int m = 1; m < m_max; ++m)
        v[m + 1] = 2.0 * x * v[m] - v[m - 1];
    };
    // A die about the axis on an end face (one free end): X_0 is the half-space pressure's
    // shape of its profile (half_space.h) instead of U_0. For the rounded flat punch (c > b)
    // it carries the peak at the flat's end, where g0'' jumps and p has an x log x term that
    // the polynomials smooth out; for the paraboloid it is U_0 times 2 c / R (the same span).
    // The body's finite size adds a smooth part to it. Not where the zone lies inside a flat
    // (psi'(c) = 0: no smooth edge there).
    const axisym::DieProfile &profile = problem.body->conditions.at(zone.part).die.profile;
    const bool shaped = !two_ends && !sharp && frame.about_axis() && h > 0.0 &&
                        half_space::psi_slope(profile, h) > 0.0;
    std::vector<double> kinks;
    if (shaped)
      for (const double k : profile.kinks())
        if (k < h * (1.0 - 1e-9))
          kinks.push_back(k / h);
    std::vector<double> v;
    auto basis = [&](double x, std::vector<double> &values) {
      chebyshev(x, values);
      if (shaped)
        values[0] = half_space::pressure_shape(profile, h, x);
    };
    // The test fields: V_0 = (1 - d / D) n (die_force's: m_0 = P / 2 pi), and for k >= 1 the
    // bumps (1 - x^2)^3 x^e of the zone (C2, zero at its ends and beyond; e = 2 (k - 1) with
    // one free end, k - 1 with two) times the C2 quintic step from 1 at d = 0 to 0 at
    // d = h: supported next to the zone, where the local columns resolve the field, and
    // flat at the zone's ends, where the stresses carry the edge modes' residual singular
    // term. Measured against the finest FEM at p = 8 and three moments, max |p - p_FEM| /
    // p_max on the RFM's points at the searches' zones: Hertz 0.96 % (its peak -0.09 % from
    // Hertz's p0; at the FEM's zone 0.47 % on the FEM's points, the trace 61 % there), the
    // rounded flat punch 11 %, the sharp flat punch 2.4 % of p(0) inside 0.9 b. C1 bumps
    // (1 - x^2)^2 gave 2.1 % (peak +1.9 %), 11.4 % and 3.7 %; (1 - x^2)^4 gave 1.4 % (peak
    // -1.4 %) and 10.8 % on the first two; fading into the body over h instead of h / 2 (then),
    // 2.5 % and 13 %. The hollow cylinder's tests (continued by their
    // end value along the part and linearly through the body, contact.h) gave 5.9 % on Hertz,
    // 37 % with six moments: they kink at the zone's end and vary on the zone's scale across
    // the whole section.
    // The fading depth, session 15 (the defaults then; at the FEM's zones, on the FEM's
    // points): h / 4, h / 2, h, 2 h, 4 h gave 24 %, 8.1 %, 0.31 %, 0.25 %, 0.24 % on the ring
    // die (two free ends: two-sided boxes of degree 8, whose displacement space resolves a
    // step steeper than its depth poorly, and the moments' error is the stress error times
    // that of V_k; degree 9 gave 0.30 % with h / 2; the raw trace was 0.7 % throughout),
    // while Hertz gave 0.35 %, 0.38 %, 0.39 % and the rounded punch 0.32 % with h / 2, h and
    // 2 h. h it is.
    const double depth = model.die_depth(frame);
    const double ell = h;
    const Eigen::VectorXd moments =
      model.die_moments(frame, [&](const Eigen::VectorXd &sq, const Eigen::VectorXd &dq) {
        Eigen::MatrixXd out = Eigen::MatrixXd::Zero(sq.size(), 3 * n_phi);
        for (Eigen::Index q = 0; q < sq.size(); ++q)
          {
            out(q, 0) = 1.0 - dq[q] / depth, out(q, 2 * n_phi) = -1.0 / depth;
            const double x = two_ends ? (sq[q] - mid) / h : std::abs(sq[q]) / h;
            const double dx_ds = two_ends ? 1.0 / h : (sq[q] < 0.0 ? -1.0 : 1.0) / h;
            const double y = dq[q] / ell;
            if (std::abs(x) >= 1.0 || y >= 1.0)
              continue;
            const double yc = std::max(y, 0.0);
            const double chi = 1.0 - yc * yc * yc * (10.0 - 15.0 * yc + 6.0 * yc * yc);
            const double dchi = -30.0 * yc * yc * (1.0 - yc) * (1.0 - yc) / ell;
            const double w2 = (1.0 - x * x) * (1.0 - x * x), bump = w2 * (1.0 - x * x),
                         dbump = -6.0 * x * w2;
            for (int k = 1; k < n_phi; ++k)
              {
                const int e = two_ends ? k - 1 : 2 * (k - 1);
                const double xe = std::pow(x, e), dxe = e > 0 ? e * std::pow(x, e - 1) : 0.0;
                out(q, k) = bump * xe * chi;
                out(q, n_phi + k) = (dbump * xe + bump * dxe) * dx_ds * chi;
                out(q, 2 * n_phi + k) = bump * xe * dchi;
              }
          }
        return out;
      });
    // G_kj = int_zone w X_j phi_k r ds by Gauss-Legendre in theta, x = sin theta: w dx =
    // cos^2 theta d theta (U) or d theta (T), smooth; s = mid + h x (two ends) or on the
    // zone's side of the centre (one).
    const double side = two_ends || zone.s_hi > frame.tolerance ? 1.0 : -1.0;
    const double theta_a = two_ends ? -0.5 * M_PI : 0.0, theta_b = 0.5 * M_PI;
    // (With the half-space shape, in pieces split at the profile's kinks x = k / c.)
    const GaussRule1D rule = gauss_legendre(2 * m_max + 24);
    std::vector<std::array<double, 2>> pieces;
    double theta_lo = theta_a;
    for (const double k : kinks)
      pieces.push_back({theta_lo, std::asin(k)}), theta_lo = std::asin(k);
    pieces.push_back({theta_lo, theta_b});
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n_phi, n_phi);
    for (const auto &[t0, t1] : pieces)
      for (Eigen::Index i = 0; i < rule.nodes.size(); ++i)
        {
          const double theta = t0 + 0.5 * (rule.nodes[i] + 1.0) * (t1 - t0);
          const double x = std::sin(theta), wx = sharp ? 1.0 : std::cos(theta) * std::cos(theta);
          const double r = frame.point_at(two_ends ? mid + h * x : side * h * x).r;
          basis(x, v);
          const double weight =
            0.5 * (t1 - t0) * rule.weights[i] * wx * h * r * (model.mirrored() ? 2.0 : 1.0);
          for (int k = 0; k < n_phi; ++k)
            {
              const int e = two_ends ? k - 1 : 2 * (k - 1);
              const double test = k == 0 ? 1.0 : std::pow(1.0 - x * x, 3) * std::pow(x, e);
              for (int j = 0; j < n_phi; ++j)
                g(k, j) += weight * test * v[degree(j)];
            }
        }
    const Eigen::VectorXd b = g.partialPivLu().solve(moments);
    std::vector<double> p(s.size(), 0.0);
    for (std::size_t i = 0; i < s.size(); ++i)
      {
        const double x = two_ends ? (s[i] - mid) / h : side * s[i] / h;
        if (x < (two_ends ? -1.0 : 0.0) - 1e-12 || x > 1.0 + 1e-12)
          continue;
        // (One free end: x in [0, 1]; a point a rounding error across the centre is at 0.)
        const double xc = std::clamp(x, two_ends ? -1.0 : 0.0, 1.0);
        basis(xc, v);
        double sum = 0.0;
        for (int k = 0; k < n_phi; ++k)
          sum += b[k] * v[degree(k)];
        const double root = std::sqrt(std::max(0.0, 1.0 - xc * xc));
        p[i] = sharp ? (root > 0.0 ? sum / root : std::numeric_limits<double>::infinity()) : root * sum;
      }
    return p;
  }
} // namespace rfm
