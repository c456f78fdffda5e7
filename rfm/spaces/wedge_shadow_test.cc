// The hoop shadow (wedge_shadow.h), checked against the axisymmetric equations themselves:
// the mode with its shadow satisfies the axisymmetric equilibrium and the face conditions to
// one power of rho more than the plane-strain mode alone (finite differences of the
// displacement, 3D Hooke's law with e_tt = u_r / r).
#include "rfm/spaces/wedge_shadow.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    struct Vertex
    {
      axisym::Wedge wedge;
      axisym::WedgeMode mode;
      double bisector, r_v, nu;
      WedgeShadow shadow;
      bool with_shadow = true;

      // The real part of the mode (and shadow) displacement in meridian components at (r, z),
      // shear modulus 1; the vertex at (r_v, 0).
      std::array<double, 2> u(const double r, const double z) const
      {
        const double x = r - r_v, y = z, rho = std::hypot(x, y), phi = std::atan2(y, x);
        double theta = phi - bisector;
        theta -= 2.0 * pi * std::round(theta / (2.0 * pi));
        const axisym::WedgeFieldValues v = wedge.evaluate(mode, rho, theta);
        std::complex<double> ur = v.u_r, ut = v.u_t;
        if (with_shadow)
          {
            const WedgeShadow::Values s = shadow.evaluate(rho, theta);
            ur += s.u[0], ut += s.u[1];
          }
        const double c = std::cos(phi), sn = std::sin(phi);
        return {(ur * c - ut * sn).real(), (ur * sn + ut * c).real()};
      }
      // The axisymmetric stresses (rr, zz, tt, rz) by central differences.
      std::array<double, 4> stress(const double r, const double z, const double h) const
      {
        const auto rp = u(r + h, z), rm = u(r - h, z), zp = u(r, z + h), zm = u(r, z - h), c = u(r, z);
        const double e_rr = (rp[0] - rm[0]) / (2 * h), e_zz = (zp[1] - zm[1]) / (2 * h);
        const double g = (zp[0] - zm[0]) / (2 * h) + (rp[1] - rm[1]) / (2 * h), e_tt = c[0] / r;
        const double a = 2 * nu / (1 - 2 * nu), tr = e_rr + e_zz + e_tt;
        return {a * tr + 2 * e_rr, a * tr + 2 * e_zz, a * tr + 2 * e_tt, g};
      }
      // The axisymmetric equilibrium's residual at (r, z).
      double residual(const double r, const double z, const double h) const
      {
        const auto rp = stress(r + h, z, h), rm = stress(r - h, z, h), zp = stress(r, z + h, h),
                   zm = stress(r, z - h, h), c = stress(r, z, h);
        const double f_r = (rp[0] - rm[0]) / (2 * h) + (zp[3] - zm[3]) / (2 * h) + (c[0] - c[2]) / r;
        const double f_z = (rp[3] - rm[3]) / (2 * h) + (zp[1] - zm[1]) / (2 * h) + c[3] / r;
        return std::hypot(f_r, f_z);
      }
    };

    Vertex make(const axisym::WedgeFace minus, const axisym::WedgeFace plus, const double angle,
                const double leaving_direction, const double r_v)
    {
      const double nu = 0.3;
      axisym::Wedge w(angle, minus, plus, nu);
      const axisym::WedgeMode mode = w.modes(1.0).front();
      const double bisector = leaving_direction + 0.5 * angle;
      return {w, mode, bisector, r_v, nu, WedgeShadow(w, mode, bisector, r_v, nu)};
    }
  } // namespace

  // A 270-degree vertex between free faces (the stepped shaft's shoulder): the equilibrium
  // residual of the mode alone falls like rho^(lambda - 2) toward the vertex, with the shadow
  // like rho^(lambda - 1), i.e. by rho / r_v less.
  TEST(WedgeShadow, EquilibriumHoldsToOneMoreOrder)
  {
    // Leaving face along -e_r, arriving along -e_z (the stepped ring's vertex, the body
    // everywhere but the quadrant r < r_v, z > 0).
    Vertex v = make(axisym::WedgeFace::free, axisym::WedgeFace::free, 1.5 * pi, pi, 0.3);
    ASSERT_TRUE(v.shadow.valid());
    EXPECT_LT(v.shadow.residual(), 1e-10);
    // Points inside the body at the distance rho below-right of the vertex.
    for (const double rho : {0.004, 0.002})
      {
        const double r = v.r_v + rho * std::cos(-0.3), z = rho * std::sin(-0.3), h = 1e-3 * rho;
        v.with_shadow = false;
        const double plain = v.residual(r, z, h);
        v.with_shadow = true;
        const double shadowed = v.residual(r, z, h);
        // The mode's stress is of order rho^(lambda - 1); its residual of order
        // rho^(lambda - 1) / r_v. The shadow's leaves rho^lambda / r_v^2.
        EXPECT_LT(shadowed, 3.0 * rho / v.r_v * plain) << "rho " << rho;
        EXPECT_GT(plain, 0.0);
      }
  }

  // On the faces the traction of the shadowed field (with the hoop strain's lambda_L e_tt in
  // the in-plane stresses) vanishes to one order more.
  TEST(WedgeShadow, FacesStayFreeToOneMoreOrder)
  {
    Vertex v = make(axisym::WedgeFace::free, axisym::WedgeFace::free, 1.5 * pi, pi, 0.3);
    for (const double rho : {0.004, 0.002})
      {
        const double h = 1e-4 * rho;
        // The leaving face z = 0, r < r_v (normal -e_z): sigma_zz and sigma_rz; just inside.
        const double r = v.r_v - rho, z = -1e-3 * rho;
        v.with_shadow = false;
        const auto plain = v.stress(r, z, h);
        v.with_shadow = true;
        const auto shadowed = v.stress(r, z, h);
        // sigma_zz: of order rho^lambda / r_v alone, rho^(lambda + 1) / r_v^2 with the shadow
        // (sigma_rz just inside the face is the mode's own, 1e-3 rho off the face).
        EXPECT_LT(std::abs(shadowed[1]), 3.0 * rho / v.r_v * std::abs(plain[1])) << "rho " << rho;
        EXPECT_GT(std::abs(plain[1]), 1e-3 * (std::abs(plain[0]) + std::abs(plain[2])));
      }
  }

  // Clamped and symmetry faces are solved too; a resonant exponent leaves the shadow out.
  TEST(WedgeShadow, ClampedFreeVertex)
  {
    Vertex v = make(axisym::WedgeFace::clamped, axisym::WedgeFace::free, 0.5 * pi, 0.0, 0.2);
    ASSERT_TRUE(v.shadow.valid());
    const double rho = 0.003, r = v.r_v + rho * std::cos(0.7), z = rho * std::sin(0.7), h = 1e-3 * rho;
    v.with_shadow = false;
    const double plain = v.residual(r, z, h);
    v.with_shadow = true;
    EXPECT_LT(v.residual(r, z, h), 3.0 * rho / v.r_v * plain);
  }

  // LogSeriesShadow at a resonance: the half plane y > 0 (free faces at theta = +-pi / 2 about
  // the normal) with the normal stress |x| on its boundary. 2 is an exponent of the half
  // plane and |x| is no polynomial's trace, so the field is rho^2 (V_0 + ln rho V_1). Checked
  // by central differences of its displacement alone: plane-strain Hooke's law gives the
  // stresses evaluate() reports, they are in equilibrium, and they meet the boundary's data.
  TEST(LogSeriesShadow, HalfPlaneWithANonSmoothLoadTakesTheLogLevel)
  {
    const double nu = 0.3;
    const WedgeCollocation c(0.5 * pi, nu, axisym::WedgeFace::free, axisym::WedgeFace::free, 40);
    const int n = c.size(), N = n - 1;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n);
    rhs[0] = rhs[N] = 1.0; // S_thth = rho on both faces, no shear
    const LogSeriesShadow shadow(c, 2.0, {rhs}, {});
    EXPECT_LT(shadow.residual(), 1e-10);
    EXPECT_EQ(shadow.levels(), 2);
    const double a = c.a();
    // The bisector along +y: theta measured from it, positive toward -x.
    auto u = [&](const double x, const double y) {
      const double rho = std::hypot(x, y), phi = std::atan2(y, x), theta = phi - 0.5 * pi;
      const LogSeriesShadow::Values v = shadow.evaluate(rho, theta);
      return std::array<double, 2>{v.u[0] * std::cos(phi) - v.u[1] * std::sin(phi),
                                   v.u[0] * std::sin(phi) + v.u[1] * std::cos(phi)};
    };
    auto stress = [&](const double x, const double y, const double h) {
      const auto xp = u(x + h, y), xm = u(x - h, y), yp = u(x, y + h), ym = u(x, y - h);
      const double e_xx = (xp[0] - xm[0]) / (2 * h), e_yy = (yp[1] - ym[1]) / (2 * h);
      const double g = (yp[0] - ym[0] + xp[1] - xm[1]) / (2 * h);
      return std::array<double, 3>{a * (e_xx + e_yy) + 2 * e_xx, a * (e_xx + e_yy) + 2 * e_yy, g};
    };
    for (const double rho : {0.3, 0.01})
      for (const double angle : {0.2, 1.3, 2.7})
        {
          const double x = rho * std::cos(angle), y = rho * std::sin(angle), h = 1e-4 * rho;
          const auto s = stress(x, y, h);
          // evaluate()'s stresses, turned from polar.
          const LogSeriesShadow::Values v = shadow.evaluate(rho, angle - 0.5 * pi);
          const double cs = std::cos(angle), sn = std::sin(angle);
          const double s_xx = v.s[0] * cs * cs + v.s[1] * sn * sn - 2 * v.s[2] * cs * sn;
          const double s_yy = v.s[0] * sn * sn + v.s[1] * cs * cs + 2 * v.s[2] * cs * sn;
          const double s_xy = (v.s[0] - v.s[1]) * cs * sn + v.s[2] * (cs * cs - sn * sn);
          EXPECT_NEAR(s[0], s_xx, 1e-6 * rho);
          EXPECT_NEAR(s[1], s_yy, 1e-6 * rho);
          EXPECT_NEAR(s[2], s_xy, 1e-6 * rho);
          // Equilibrium: of order rho^0 each term, to the differences' accuracy.
          const double hh = 1e-3 * rho;
          const auto sxp = stress(x + hh, y, h), sxm = stress(x - hh, y, h), syp = stress(x, y + hh, h),
                     sym = stress(x, y - hh, h);
          EXPECT_LT(std::abs((sxp[0] - sxm[0] + syp[2] - sym[2]) / (2 * hh)), 1e-4);
          EXPECT_LT(std::abs((sxp[2] - sxm[2] + syp[1] - sym[1]) / (2 * hh)), 1e-4);
        }
    // The boundary: sigma_yy = |x|, sigma_xy = 0 (just inside, 1e-4 |x| off).
    for (const double x : {-0.2, -0.01, 0.05, 0.4})
      {
        const double y = 1e-4 * std::abs(x);
        const auto s = stress(x, y, 1e-5 * std::abs(x));
        EXPECT_NEAR(s[1], std::abs(x), 1e-3 * std::abs(x)) << "x " << x;
        EXPECT_LT(std::abs(s[2]), 1e-3 * std::abs(x)) << "x " << x;
      }
  }
} // namespace rfm
