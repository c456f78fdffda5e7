// Exact solutions of hollow (a > 0) and solid (a = 0) cylinders a <= r <= b in plane strain
// (e_zz = 0: u_z = 0 on both ends, the ends free of shear), free on r = a and r = b
// (Timoshenko and Goodier, Theory of Elasticity, sections 32 and 150-151).
//
// Spinning at omega (body force f_r = rho omega^2 r), k = (3 - 2 nu) rho omega^2 / (8 (1 - nu)):
//   sigma_rr = k (a^2 + b^2 - a^2 b^2 / r^2 - r^2)
//   sigma_tt = k (a^2 + b^2 + a^2 b^2 / r^2 - (1 + 2 nu) / (3 - 2 nu) r^2)
//   sigma_zz = nu (sigma_rr + sigma_tt)
// Heated by T(r) = T0 + T_r r (thermal strain alpha T), I(r) = int_a^r T s ds:
//   sigma_rr = alpha E / ((1 - nu) r^2) [ (r^2 - a^2) / (b^2 - a^2) I(b) - I(r) ]
//   sigma_tt = alpha E / ((1 - nu) r^2) [ (r^2 + a^2) / (b^2 - a^2) I(b) + I(r) - T r^2 ]
//   sigma_zz = nu (sigma_rr + sigma_tt) - alpha E T
// sigma_rz = 0 in both. Checked here before use: both satisfy d(r sigma_rr)/dr - sigma_tt +
// f_r r = 0, sigma_rr(a) = sigma_rr(b) = 0, and the strains e = C sigma + alpha T (1, 1, 1, 0)
// have e_zz = 0 and e_rr = d(r e_tt)/dr (compatibility), to 1e-10 relative by central
// differences (h = 1e-6 m) at 50 radii, for a = 0.1 and a = 0 (a Python check, not kept). At the exact solution Phi_L = Phi_C = Phi_R =
// -1/2 int sigma . C sigma (spinning: -U) and +1/2 int sigma . C sigma (heated, no external
// work: +U), per radian, int over the section r dr dz. Verification oracle: shares no code
// with rfm/ or fem_reference/.
#pragma once

#include <array>
#include <cmath>

namespace verification
{
  struct PlaneStrainCylinder
  {
    double inner_radius, outer_radius;    // a (0: solid), b [m]
    double youngs_modulus, poisson_ratio; // [Pa], [-]
    double density = 0.0, angular_velocity = 0.0;                         // [kg/m^3], [rad/s]
    double thermal_expansion = 0.0, temperature_0 = 0.0, temperature_r = 0.0; // [1/K], [K], [K/m]

    /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) [Pa] of both loads together (superposition).
    std::array<double, 4> stress(double r, double /*z*/) const
    {
      const double a = inner_radius, b = outer_radius, nu = poisson_ratio, e = youngs_modulus;
      const double a2 = a * a, b2 = b * b, r2 = r * r;
      // Spinning.
      const double k = (3 - 2 * nu) * density * angular_velocity * angular_velocity / (8 * (1 - nu));
      const double hole = a > 0 ? a2 * b2 / r2 : 0.0;
      double s_rr = k * (a2 + b2 - hole - r2);
      double s_tt = k * (a2 + b2 + hole - (1 + 2 * nu) / (3 - 2 * nu) * r2);
      double s_zz = nu * (s_rr + s_tt);
      // Heated.
      const double t = temperature_0 + temperature_r * r;
      auto integral = [&](double x) {
        return temperature_0 * (x * x - a2) / 2 + temperature_r * (x * x * x - a2 * a) / 3;
      };
      const double c = thermal_expansion * e / ((1 - nu) * r2);
      const double h_rr = c * ((r2 - a2) / (b2 - a2) * integral(b) - integral(r));
      const double h_tt = c * ((r2 + a2) / (b2 - a2) * integral(b) + integral(r) - t * r2);
      s_rr += h_rr, s_tt += h_tt;
      s_zz += nu * (h_rr + h_tt) - thermal_expansion * e * t;
      return {s_rr, s_zz, s_tt, 0.0};
    }

    /// 1/2 int sigma . C sigma r dr dz over a <= r <= b, 0 <= z <= height [J per radian]
    /// (Gauss-Legendre in r: the integrand is smooth on [a, b]).
    double elastic_energy(double height) const
    {
      static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                  -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                  0.7966664774136267,  0.9602898564975363};
      static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                  0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                  0.2223810344533745, 0.1012285362903763};
      const double nu = poisson_ratio, e = youngs_modulus;
      double sum = 0.0;
      const int cells = 16;
      for (int cell = 0; cell < cells; ++cell)
        {
          const double lo = inner_radius + (outer_radius - inner_radius) * cell / cells;
          const double hi = inner_radius + (outer_radius - inner_radius) * (cell + 1) / cells;
          for (int q = 0; q < 8; ++q)
            {
              const double r = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x[q];
              const auto s = stress(r, 0.0);
              const double sc = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] -
                                 2 * nu * (s[0] * s[1] + s[1] * s[2] + s[0] * s[2]) +
                                 2 * (1 + nu) * s[3] * s[3]) / e;
              sum += 0.5 * (hi - lo) * w[q] * 0.5 * sc * r;
            }
        }
      return sum * height;
    }
  };
} // namespace verification
