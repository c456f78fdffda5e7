#include "rfm/spaces/resonant_vertex.h"

#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using axisym::OutlineEdge;
  using axisym::Point;
  using rfm::ResonantVertex;
  constexpr double pi = 3.14159265358979323846;
  constexpr double nu = 0.3, young = 2.1e11, mu = young / (2 * (1 + nu));

  using axisym::testing::arc;
  using axisym::testing::line;
  rfm::Material steel()
  {
    rfm::Material m;
    m.youngs_modulus = young;
    m.poisson_ratio = nu;
    return m;
  }

  // The frame field: equilibrium, plane-strain Hooke's law against the displacement's
  // derivatives (central differences), and the conditions on both faces.
  TEST(ResonantVertex, FrameFieldIsAnElasticFieldWithTheHalfPlanesLoad)
  {
    const double h = 1e-5;
    for (const auto &[x, y] : {std::pair{0.3, 0.2}, std::pair{0.05, 0.7}, std::pair{0.6, 0.01}, std::pair{0.2, 0.9}})
      {
        auto f = [](const double a, const double b) { return ResonantVertex::frame_field(a, b, nu); };
        auto dx = [&](auto get) { return (get(f(x + h, y)) - get(f(x - h, y))) / (2 * h); };
        auto dy = [&](auto get) { return (get(f(x, y + h)) - get(f(x, y - h))) / (2 * h); };
        auto sxx = [](const auto &v) { return v.s[0]; };
        auto syy = [](const auto &v) { return v.s[1]; };
        auto sxy = [](const auto &v) { return v.s[2]; };
        auto ux = [](const auto &v) { return v.u[0]; };
        auto uy = [](const auto &v) { return v.u[1]; };
        EXPECT_NEAR(dx(sxx) + dy(sxy), 0.0, 1e-8);
        EXPECT_NEAR(dx(sxy) + dy(syy), 0.0, 1e-8);
        // 2 e = s - nu tr s (mu = 1).
        const auto v = f(x, y);
        const double tr = nu * (v.s[0] + v.s[1]);
        EXPECT_NEAR(dx(ux), (v.s[0] - tr) / 2, 1e-8);
        EXPECT_NEAR(dy(uy), (v.s[1] - tr) / 2, 1e-8);
        EXPECT_NEAR(dy(ux) + dx(uy), v.s[2], 1e-8);
      }
    for (const double t : {0.1, 0.5, 2.0})
      {
        const auto on_line = ResonantVertex::frame_field(t, 0.0, nu), on_face = ResonantVertex::frame_field(0.0, t, nu);
        EXPECT_NEAR(on_line.u[1], 0.0, 1e-15);
        EXPECT_NEAR(on_line.s[2], 0.0, 1e-15);
        EXPECT_NEAR(on_face.s[0], 0.5 * pi * t, 1e-14);
        EXPECT_NEAR(on_face.s[2], 0.0, 1e-15);
        // The log term: sigma_yy on the line is -2 x log x - 2 x / 3.
        EXPECT_NEAR(on_line.s[1], -2 * t * std::log(t) - 2 * t / 3, 1e-14);
      }
  }

  // Columns at a symmetry line z = 0 meeting a traction face: the leaving face (a line along
  // r, or the hub's inner arc about the origin).
  struct Case
  {
    OutlineEdge arriving, leaving;
    bool symmetry_leaves;
  };

  void check_columns(const Case &c, const double rho_0)
  {
    const ResonantVertex v(c.arriving, c.leaving, c.symmetry_leaves, rho_0, steel(), 2, 2);
    ASSERT_EQ(v.n_columns(), 6);
    const OutlineEdge &face = c.symmetry_leaves ? c.arriving : c.leaving;
    const OutlineEdge &sym = c.symmetry_leaves ? c.leaving : c.arriving;
    // The traction face: sigma n = 0 at points within the support.
    double worst_t = 0, scale = 0, worst_u = 0, worst_s = 0, u_scale = 0;
    for (int k = 1; k <= 20; ++k)
      {
        const double s = 0.04 * k * rho_0 / face.length();
        const double t = c.symmetry_leaves ? 1.0 - s : s;
        const Point x = face.point_at(t), n = face.outward_normal_at(t);
        const rfm::EdgeColumns col = v.evaluate(Eigen::VectorXd::Constant(1, x.r), Eigen::VectorXd::Constant(1, x.z));
        for (Eigen::Index j = 0; j < v.n_columns(); ++j)
          {
            const double srr = col.stress[rfm::rr](0, j), szz = col.stress[rfm::zz](0, j), srz = col.stress[rfm::rz](0, j);
            worst_t = std::max({worst_t, std::abs(srr * n.r + srz * n.z), std::abs(srz * n.r + szz * n.z)});
            scale = std::max({scale, std::abs(srr), std::abs(szz), std::abs(srz)});
          }
        const double ts = c.symmetry_leaves ? s : 1.0 - s;
        const Point y = sym.point_at(ts), m = sym.outward_normal_at(ts);
        const rfm::EdgeColumns cs = v.evaluate(Eigen::VectorXd::Constant(1, y.r), Eigen::VectorXd::Constant(1, y.z));
        for (Eigen::Index j = 0; j < v.n_columns(); ++j)
          {
            // Symmetry: u . n = 0 and no shear.
            const double srr = cs.stress[rfm::rr](0, j), szz = cs.stress[rfm::zz](0, j), srz = cs.stress[rfm::rz](0, j);
            const double tr = srr * m.r + srz * m.z, tz = srz * m.r + szz * m.z;
            worst_s = std::max(worst_s, std::abs(tr * m.z - tz * m.r));
            worst_u = std::max(worst_u, std::abs(cs.u[0](0, j) * m.r + cs.u[1](0, j) * m.z));
            u_scale = std::max({u_scale, std::abs(cs.u[0](0, j)), std::abs(cs.u[1](0, j))});
          }
      }
    EXPECT_GT(scale, 1e-3);
    EXPECT_GT(u_scale, 1e-16);
    EXPECT_LT(worst_t, 1e-13 * scale);
    EXPECT_LT(worst_s, 1e-13 * scale);
    EXPECT_LT(worst_u, 1e-13 * u_scale);
  }

  TEST(ResonantVertex, ColumnsMeetBothFacesConditions)
  {
    // Symmetry line z = 0 leaving (0.8, 0) toward r = 1.2; the face arriving from above.
    check_columns({line({0.8, 0.5}, {0.8, 0.0}), line({0.8, 0.0}, {1.2, 0.0}), true}, 0.2);
    check_columns({arc({0.55, 0.5809475019311126}, {0.8, 0.0}, {0.0, 0.0}), line({0.8, 0.0}, {1.2, 0.0}), true}, 0.2);
    // The symmetry line arriving: z = 1.6 from (0.85, 1.6) to (0.55, 1.6), the face leaving
    // downward along r = 0.55.
    check_columns({line({0.85, 1.6}, {0.55, 1.6}), line({0.55, 1.6}, {0.55, 0.9}), false}, 0.2);
  }

  // Strains are the displacement columns' derivatives (central differences), e_tt = u_r / r.
  TEST(ResonantVertex, StrainsAreTheDerivativesOfTheDisplacementColumns)
  {
    const ResonantVertex v(arc({0.55, 0.5809475019311126}, {0.8, 0.0}, {0.0, 0.0}), line({0.8, 0.0}, {1.2, 0.0}),
                           true, 0.2, steel(), 2, 2);
    const double h = 1e-6;
    for (const auto &[r, z] : {std::pair{0.9, 0.05}, std::pair{0.85, 0.12}, std::pair{0.95, 0.02}})
      {
        auto at = [&](const double a, const double b) {
          return v.evaluate(Eigen::VectorXd::Constant(1, a), Eigen::VectorXd::Constant(1, b));
        };
        const rfm::EdgeColumns c = at(r, z), rp = at(r + h, z), rm = at(r - h, z), zp = at(r, z + h), zm = at(r, z - h);
        for (Eigen::Index j = 0; j < v.n_columns(); ++j)
          {
            const double s = std::max(std::abs(c.strain[rfm::rr](0, j)), std::abs(c.strain[rfm::rz](0, j))) + 1e-300;
            EXPECT_NEAR((rp.u[0](0, j) - rm.u[0](0, j)) / (2 * h), c.strain[rfm::rr](0, j), 1e-6 * s);
            EXPECT_NEAR((zp.u[1](0, j) - zm.u[1](0, j)) / (2 * h), c.strain[rfm::zz](0, j), 1e-6 * s);
            EXPECT_NEAR((zp.u[0](0, j) - zm.u[0](0, j) + rp.u[1](0, j) - rm.u[1](0, j)) / (2 * h),
                        c.strain[rfm::rz](0, j), 1e-6 * s);
            EXPECT_NEAR(c.u[0](0, j) / r, c.strain[rfm::tt](0, j), 1e-14 * s);
          }
      }
  }

  TEST(ResonantVertex, RejectsWhatItCannotTake)
  {
    const OutlineEdge face = line({0.8, 0.5}, {0.8, 0.0}), sym = line({0.8, 0.0}, {1.2, 0.0});
    EXPECT_THROW(ResonantVertex(face, sym, true, 0.0, steel(), 1, 1), std::invalid_argument);
    EXPECT_THROW(ResonantVertex(face, sym, true, 0.1, steel(), -1, -1), std::invalid_argument);
    // 135 degrees.
    EXPECT_THROW(ResonantVertex(line({0.3, 0.5}, {0.8, 0.0}), sym, true, 0.1, steel(), 1, 1), std::invalid_argument);
    // The symmetry face an arc.
    EXPECT_THROW(ResonantVertex(line({1.2, 0.5}, {0.8, 0.0}), arc({0.8, 0.0}, {0.0, 0.8}, {0.0, 0.0}), true, 0.1,
                                steel(), 1, 1),
                 std::invalid_argument);
    // Displacement columns beyond the stress columns' degree.
    EXPECT_THROW(ResonantVertex(face, sym, true, 0.1, steel(), 1, 2), std::invalid_argument);
    EXPECT_THROW(ResonantVertex(face, sym, true, 0.1, steel(), 1, -2), std::invalid_argument);
  }

  // Displacement columns of a lower degree: the columns beyond it have a zero displacement
  // part and the same stress part.
  TEST(ResonantVertex, ColumnsBeyondTheDisplacementDegreeHaveNoDisplacement)
  {
    const OutlineEdge face = line({0.8, 0.5}, {0.8, 0.0}), sym = line({0.8, 0.0}, {1.2, 0.0});
    const ResonantVertex full(face, sym, true, 0.2, steel(), 2, 2), stress_only(face, sym, true, 0.2, steel(), 2, -1),
      low(face, sym, true, 0.2, steel(), 2, 0);
    const Eigen::VectorXd r = Eigen::Vector2d(0.9, 0.85), z = Eigen::Vector2d(0.05, 0.1);
    const rfm::EdgeColumns a = full.evaluate(r, z), b = stress_only.evaluate(r, z), c = low.evaluate(r, z);
    for (int k = 0; k < 4; ++k)
      {
        EXPECT_EQ((a.stress[k] - b.stress[k]).norm(), 0.0);
        EXPECT_EQ((a.stress[k] - c.stress[k]).norm(), 0.0);
        EXPECT_EQ(b.strain[k].norm(), 0.0);
        EXPECT_GT(c.strain[k].col(0).norm(), 0.0);
        EXPECT_EQ(c.strain[k].rightCols(5).norm(), 0.0);
      }
    for (int m = 0; m < 2; ++m)
      {
        EXPECT_EQ(b.u[m].norm(), 0.0);
        EXPECT_EQ((a.u[m].col(0) - c.u[m].col(0)).norm(), 0.0);
        EXPECT_EQ(c.u[m].rightCols(5).norm(), 0.0);
      }
  }
} // namespace
