#include "rfm/spaces/edge_modes.h"

#include "rfm/quadrature/quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rfm
{
  namespace
  {
    constexpr double r_e = 0.2, z_e = 0.11; // edge at (R2, c)
    const Material steel{2.1e11, 0.3, {}, {}};

    // A point at polar (rho, theta) of the local frame: x = c - z, y = R2 - r.
    std::pair<double, double> at(double rho, double theta)
    {
      return {r_e - rho * std::sin(theta), z_e - rho * std::cos(theta)};
    }
  } // namespace

  // Every mode is an elastic field: the strains of its displacement (central differences)
  // equal the plane-strain compliance times its stresses, and its stresses are in local
  // equilibrium (no hoop terms: the plane-strain field of the edge).
  TEST(EdgeModes, DisplacementGradientsMatchHookeAndEquilibriumHolds)
  {
    for (const int n : {-1, 1, 2, 3, 4, 5})
      for (const double theta : {0.3, 1.2, 2.0, 2.9})
        {
          const auto [r, z] = at(0.01, theta);
          const EdgeModeValue v = edge_mode(n, r, z, r_e, z_e, steel);
          const double h = 1e-7;
          auto f = [&](double dr, double dz) {
            return edge_mode(n, r + dr, z + dz, r_e, z_e, steel);
          };
          const EdgeModeValue pr = f(h, 0), mr = f(-h, 0), pz = f(0, h), mz = f(0, -h);
          const double du_r_dr = (pr.u_r - mr.u_r) / (2 * h), du_r_dz = (pz.u_r - mz.u_r) / (2 * h);
          const double du_z_dr = (pr.u_z - mr.u_z) / (2 * h), du_z_dz = (pz.u_z - mz.u_z) / (2 * h);
          const double scale = v.strain.head<2>().cwiseAbs().maxCoeff() + std::abs(v.strain[rz]);
          const std::string at_ = "n = " + std::to_string(n) + ", theta = " + std::to_string(theta);
          EXPECT_NEAR(du_r_dr, v.strain[rr], 1e-6 * scale) << at_;
          EXPECT_NEAR(du_z_dz, v.strain[zz], 1e-6 * scale) << at_;
          EXPECT_NEAR(du_r_dz + du_z_dr, v.strain[rz], 1e-6 * scale) << at_;
          EXPECT_DOUBLE_EQ(v.strain[tt], v.u_r / r);
          // Equilibrium in the meridian plane without the hoop terms.
          const double s_scale = v.sigma.cwiseAbs().maxCoeff() / 0.01;
          const double div_r = (pr.sigma[rr] - mr.sigma[rr]) / (2 * h) + (pz.sigma[rz] - mz.sigma[rz]) / (2 * h);
          const double div_z = (pr.sigma[rz] - mr.sigma[rz]) / (2 * h) + (pz.sigma[zz] - mz.sigma[zz]) / (2 * h);
          EXPECT_LT(std::abs(div_r), 1e-6 * s_scale) << at_;
          EXPECT_LT(std::abs(div_z), 1e-6 * s_scale) << at_;
          EXPECT_NEAR(v.sigma[tt], steel.poisson_ratio * (v.sigma[rr] + v.sigma[zz]),
                      1e-12 * s_scale * 0.01);
        }
  }

  // Face conditions: frictionless bilateral contact on theta = 0 (u_r = 0, sigma_rz = 0),
  // free face on theta = pi (sigma_rr = sigma_rz = 0); the pressure on the contact face is
  // p(x) = -n x^(n/2 - 1) for odd n and 0 for even n.
  TEST(EdgeModes, FaceConditionsAndContactPressure)
  {
    for (const int n : {1, 2, 3, 4, 5})
      for (const double rho : {1e-4, 3e-3, 0.05})
        {
          const auto [rc, zc] = at(rho, 0.0);
          const EdgeModeValue c = edge_mode(n, rc, zc, r_e, z_e, steel);
          const double s_scale = n * std::pow(rho, 0.5 * n - 1.0);
          EXPECT_LT(std::abs(c.u_r), 1e-14 * std::pow(rho, 0.5 * n) / 1e10);
          EXPECT_LT(std::abs(c.sigma[rz]), 1e-13 * s_scale);
          // Odd modes press on the contact face; even ones (smooth) carry no pressure there.
          const double p = n % 2 == 1 ? -n * std::pow(rho, 0.5 * n - 1.0) : 0.0;
          EXPECT_NEAR(-c.sigma[rr], p, 1e-13 * s_scale);
          const auto [rf, zf] = at(rho, M_PI);
          const EdgeModeValue f = edge_mode(n, rf, zf, r_e, z_e, steel);
          EXPECT_LT(std::abs(f.sigma[rr]), 1e-13 * s_scale);
          EXPECT_LT(std::abs(f.sigma[rz]), 1e-13 * s_scale);
        }
  }

  // The modes in the frame of an edge on any straight part: on an end face z = h with the
  // zone toward the axis (t = -e_r, n = -e_z) and on a bore r = R1 with the zone above
  // (t = +e_z, n = +e_r), each mode satisfies the contact face's conditions (u.n = 0, shear 0)
  // and the free face's (traction 0) in the meridian components, is an elastic field (the
  // strain of its displacement by central differences), and its meridian stresses are the
  // local field rotated: sigma_nn = sigma_yy, sigma_tt' = sigma_xx along the part.
  TEST(EdgeModes, ModesInTheFrameOfAnyStraightPart)
  {
    const EdgeFrame end_face{0.004, 0.02, {{-1.0, 0.0}}, {{0.0, -1.0}}};
    const EdgeFrame bore{0.1, 0.05, {{0.0, 1.0}}, {{1.0, 0.0}}};
    for (const EdgeFrame &f : {end_face, bore})
      for (const int n : {-1, 1, 2, 3})
        for (const double rho : {1e-4, 3e-3})
          {
            const double s_scale = std::abs(n) * std::pow(rho, 0.5 * n - 1.0);
            const double u_scale = std::pow(rho, 0.5 * n) / 1e10;
            // theta = 0: the contact face, (x, y) = (rho, 0).
            const auto c = f.point(rho, 0.0);
            const EdgeModeValue vc = edge_mode(n, c[0], c[1], f, steel);
            const double u_n = vc.u_r * f.n[0] + vc.u_z * f.n[1];
            const double s_nt = vc.sigma[rr] * f.n[0] * f.t[0] + vc.sigma[zz] * f.n[1] * f.t[1] +
                                vc.sigma[rz] * (f.n[0] * f.t[1] + f.n[1] * f.t[0]);
            EXPECT_LT(std::abs(u_n), 1e-14 * u_scale) << n;
            EXPECT_LT(std::abs(s_nt), 1e-13 * s_scale) << n;
            // The same point's local stresses from the legacy frame rotated by hand: the
            // normal stress on the face is sigma_yy.
            const EdgeModeValue legacy = edge_mode(n, r_e - 0.0, z_e - rho, r_e, z_e, steel);
            const double s_nn = vc.sigma[rr] * f.n[0] * f.n[0] + vc.sigma[zz] * f.n[1] * f.n[1] +
                                2 * vc.sigma[rz] * f.n[0] * f.n[1];
            EXPECT_NEAR(s_nn, legacy.sigma[rr], 1e-13 * s_scale) << n; // legacy sigma_rr = s_yy
            // theta = pi: the free face, traction 0.
            const auto fr = f.point(-rho, 0.0);
            const EdgeModeValue vf = edge_mode(n, fr[0], fr[1], f, steel);
            const double t_r = vf.sigma[rr] * f.n[0] + vf.sigma[rz] * f.n[1];
            const double t_z = vf.sigma[rz] * f.n[0] + vf.sigma[zz] * f.n[1];
            EXPECT_LT(std::abs(t_r), 1e-13 * s_scale) << n;
            EXPECT_LT(std::abs(t_z), 1e-13 * s_scale) << n;
            // Inside (theta = 1.1): the strain of the displacement.
            const auto in = f.point(rho * std::cos(1.1), rho * std::sin(1.1));
            const double h = 1e-3 * rho;
            const EdgeModeValue v = edge_mode(n, in[0], in[1], f, steel);
            auto at_ = [&](double dr, double dz) { return edge_mode(n, in[0] + dr, in[1] + dz, f, steel); };
            const EdgeModeValue pr = at_(h, 0), mr = at_(-h, 0), pz = at_(0, h), mz = at_(0, -h);
            const double scale = v.strain.head<2>().cwiseAbs().maxCoeff() + std::abs(v.strain[rz]);
            EXPECT_NEAR((pr.u_r - mr.u_r) / (2 * h), v.strain[rr], 1e-5 * scale) << n;
            EXPECT_NEAR((pz.u_z - mz.u_z) / (2 * h), v.strain[zz], 1e-5 * scale) << n;
            EXPECT_NEAR((pz.u_r - mz.u_r) / (2 * h) + (pr.u_z - mr.u_z) / (2 * h), v.strain[rz],
                        1e-5 * scale)
              << n;
          }
    // The legacy frame gives the legacy values bit for bit.
    const EdgeModeValue a = edge_mode(3, 0.19, 0.1, EdgeFrame::outer_side(r_e, z_e), steel);
    const EdgeModeValue b = edge_mode(3, 0.19, 0.1, r_e, z_e, steel);
    EXPECT_EQ(a.u_r, b.u_r);
    EXPECT_EQ(a.sigma, b.sigma);
    EXPECT_EQ(a.strain, b.strain);
  }

  // On the free face (theta = pi) each mode takes the limit from inside the body, whatever
  // the sign of the zeros in the frame: the end face as the outline builds it has the normal
  // n = (-0, -1), which put face points at theta = -pi (across the branch cut) and flipped
  // u_y there (found when the check of condition 1.3 saw a too-short Hertz zone open a gap).
  // The n = 1 mode with a positive amplitude (a tensile edge) pulls the free face into the
  // body: u . n = (kappa + 1) rho^(1/2) / (2 mu).
  TEST(EdgeModes, FreeFaceIsTheLimitFromTheBody)
  {
    const EdgeFrame end_face{0.004, 0.02, {{-1.0, 0.0}}, {{-0.0, -1.0}}};
    const EdgeFrame end_face_positive_zero{0.004, 0.02, {{-1.0, 0.0}}, {{0.0, -1.0}}};
    const EdgeFrame bore{0.1, 0.05, {{0.0, -1.0}}, {{1.0, -0.0}}};
    const double nu = 0.3, mu = 2.1e11 / (2 * (1 + nu)), kappa = 3 - 4 * nu;
    for (const EdgeFrame &f : {end_face, end_face_positive_zero, bore, EdgeFrame::outer_side(r_e, z_e)})
      for (const int n : {1, 3})
        for (const double rho : {1e-5, 2e-3})
          {
            const auto face = f.point(-rho, 0.0);
            const double eps = 1e-9;
            const auto inside = f.point(-rho * std::cos(eps), rho * std::sin(eps));
            const EdgeModeValue v = edge_mode(n, face[0], face[1], f, steel);
            const EdgeModeValue w = edge_mode(n, inside[0], inside[1], f, steel);
            const double u_scale = std::pow(rho, 0.5 * n) / mu;
            EXPECT_NEAR(v.u_r, w.u_r, 1e-7 * u_scale) << n << " " << rho;
            EXPECT_NEAR(v.u_z, w.u_z, 1e-7 * u_scale) << n << " " << rho;
            if (n == 1)
              {
                EXPECT_NEAR(v.u_r * f.n[0] + v.u_z * f.n[1], (kappa + 1) * std::sqrt(rho) / (2 * mu),
                            1e-12 * u_scale);
              }
          }
  }

  // A support clipped at a traction-free end: the stress columns (every mode and multiplier)
  // carry no traction on the end and stay free on the free face; at the edge they are the
  // unclipped columns.
  TEST(EdgeModes, ClippedColumnsAreFreeOnTheEnd)
  {
    const double end_z = z_e + 0.02, rho_0 = 0.09;
    const EdgeEnrichment clipped(r_e, z_e, rho_0, {1, 3}, steel, 2, end_z);
    const EdgeEnrichment plain(r_e, z_e, rho_0, {1, 3}, steel, 2);
    ASSERT_EQ(clipped.n_columns(), 12);
    const Eigen::VectorXd r_end = Eigen::VectorXd::LinSpaced(9, r_e - 0.08, r_e);
    const EdgeColumns on_end = clipped.evaluate(r_end, Eigen::VectorXd::Constant(9, end_z));
    const Eigen::VectorXd z_free = Eigen::VectorXd::LinSpaced(9, z_e + 1e-3, end_z);
    const EdgeColumns on_free = clipped.evaluate(Eigen::VectorXd::Constant(9, r_e), z_free);
    const double scale = plain.evaluate(Eigen::VectorXd::Constant(1, r_e - 0.01),
                                        Eigen::VectorXd::Constant(1, z_e))
                           .stress[rr]
                           .cwiseAbs()
                           .maxCoeff();
    EXPECT_LT(on_end.stress[zz].cwiseAbs().maxCoeff(), 1e-14 * scale);
    EXPECT_LT(on_end.stress[rz].cwiseAbs().maxCoeff(), 1e-14 * scale);
    EXPECT_GT(on_end.u[0].cwiseAbs().maxCoeff(), 0.0); // displacements are not clipped
    EXPECT_LT(on_free.stress[rr].cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LT(on_free.stress[rz].cwiseAbs().maxCoeff(), 1e-12 * scale);
    // Near the edge (rho = 1e-6) the stress factor is 1 to O(rho).
    const Eigen::VectorXd r1 = Eigen::VectorXd::Constant(1, r_e - 1e-6);
    const Eigen::VectorXd z1 = Eigen::VectorXd::Constant(1, z_e);
    const EdgeColumns a = clipped.evaluate(r1, z1), b = plain.evaluate(r1, z1);
    EXPECT_NEAR(a.stress[rr](0, 0) / b.stress[rr](0, 0), 1.0, 1e-12);
    EXPECT_EQ(a.u[0](0, 0), b.u[0](0, 0));
  }

  TEST(EdgeModes, CutoffIsSmoothStep)
  {
    const double rho_0 = 0.08;
    EXPECT_EQ(edge_cutoff(0.0, rho_0).value, 1.0);
    EXPECT_EQ(edge_cutoff(rho_0, rho_0).value, 0.0);
    EXPECT_EQ(edge_cutoff(2 * rho_0, rho_0).derivative, 0.0);
    for (const double rho : {0.01, 0.04, 0.07})
      {
        const double h = 1e-7;
        const double fd = (edge_cutoff(rho + h, rho_0).value - edge_cutoff(rho - h, rho_0).value) / (2 * h);
        EXPECT_NEAR(edge_cutoff(rho, rho_0).derivative, fd, 1e-7);
      }
  }

  // The enrichment columns are chi times the modes, with the strain of chi u by the
  // product rule: checked against central differences of the column displacements.
  TEST(EdgeModes, ColumnStrainsMatchDifferences)
  {
    const EdgeEnrichment e(r_e, z_e, 0.08, {1, 3}, steel);
    ASSERT_EQ(e.singular_column(), 0);
    const double h = 1e-7;
    Eigen::VectorXd r(5), z(5);
    const auto [r0, z0] = at(0.03, 1.1);
    r << r0, r0 + h, r0 - h, r0, r0;
    z << z0, z0, z0, z0 + h, z0 - h;
    const EdgeColumns c = e.evaluate(r, z);
    for (int j = 0; j < 2; ++j)
      {
        const double e_rr = (c.u[0](1, j) - c.u[0](2, j)) / (2 * h);
        const double e_zz = (c.u[1](3, j) - c.u[1](4, j)) / (2 * h);
        const double g_rz = (c.u[0](3, j) - c.u[0](4, j)) / (2 * h) + (c.u[1](1, j) - c.u[1](2, j)) / (2 * h);
        const double scale = std::abs(c.strain[rr](0, j)) + std::abs(c.strain[zz](0, j)) +
                             std::abs(c.strain[rz](0, j));
        EXPECT_NEAR(c.strain[rr](0, j), e_rr, 1e-6 * scale);
        EXPECT_NEAR(c.strain[zz](0, j), e_zz, 1e-6 * scale);
        EXPECT_NEAR(c.strain[rz](0, j), g_rz, 1e-6 * scale);
        EXPECT_NEAR(c.strain[tt](0, j), c.u[0](0, j) / r0, 1e-15);
      }
    // Nothing beyond the cutoff radius.
    const auto [rf, zf] = at(0.081, 2.0);
    const EdgeColumns far = e.evaluate(Eigen::VectorXd::Constant(1, rf), Eigen::VectorXd::Constant(1, zf));
    EXPECT_EQ(far.stress[rr].cwiseAbs().maxCoeff() + far.u[0].cwiseAbs().maxCoeff(), 0.0);
    EXPECT_THROW(EdgeEnrichment(r_e, z_e, 0.08, {2}, steel), std::invalid_argument);
  }

  // The near-edge rule integrates the singular products of the enrichment to rounding:
  // int over the half disc of (chi sigma_m) . C (chi sigma_n) = int_0^rho_0 chi^2 rho^((m+n)/2 - 1) drho
  // times int_0^pi g(theta) dtheta, both factors computed independently by 1-D Gauss rules
  // with many points (the radial factor is a polynomial times a half-integer power: the
  // t^2 map makes it exact).
  TEST(EdgeModes, NearEdgeRuleIntegratesSingularProductsTo1e12)
  {
    const double rho_0 = 0.08;
    const Eigen::Matrix4d cm = steel.compliance();
    const Quadrature2D q = half_disc_gauss(r_e, z_e, rho_0, 24, 24);
    for (const auto &[m, n] : {std::pair{1, 1}, std::pair{1, 3}, std::pair{3, 3}})
      {
        double quad = 0.0;
        for (Eigen::Index k = 0; k < q.n_points(); ++k)
          {
            const double rho = std::hypot(q.r[k] - r_e, q.z[k] - z_e);
            const double chi = edge_cutoff(rho, rho_0).value;
            const EdgeModeValue a = edge_mode(m, q.r[k], q.z[k], r_e, z_e, steel);
            const EdgeModeValue b = edge_mode(n, q.r[k], q.z[k], r_e, z_e, steel);
            quad += q.weights[k] * chi * chi * a.sigma.dot(cm * b.sigma);
          }
        // Angular factor at rho = 1 (the stresses scale as rho^(n/2 - 1)).
        const GaussRule1D gt = gauss_on_cells({0.0, M_PI / 4, M_PI / 2, 3 * M_PI / 4, M_PI}, 60);
        double angular = 0.0;
        for (Eigen::Index k = 0; k < gt.nodes.size(); ++k)
          {
            const auto [r, z] = at(1.0, gt.nodes[k]);
            const EdgeModeValue a = edge_mode(m, r, z, r_e, z_e, steel);
            const EdgeModeValue b = edge_mode(n, r, z, r_e, z_e, steel);
            angular += gt.weights[k] * a.sigma.dot(cm * b.sigma);
          }
        const GaussRule1D gr = gauss_on_cells({0.0, rho_0}, 40, {0.0});
        double radial = 0.0;
        for (Eigen::Index k = 0; k < gr.nodes.size(); ++k)
          {
            const double chi = edge_cutoff(gr.nodes[k], rho_0).value;
            radial += gr.weights[k] * chi * chi * std::pow(gr.nodes[k], 0.5 * (m + n) - 1.0);
          }
        EXPECT_NEAR(quad, radial * angular, 1e-12 * std::abs(radial * angular))
          << "modes " << m << ", " << n;
      }
  }

  // The assembly drops, block by block of points, the columns that are zero there
  // (outline_model.cc): nonzero_columns finds the columns of the discs that the points reach,
  // and columns() copies exactly those blocks.
  TEST(EdgeColumns, NonzeroColumnsAreThoseOfTheDiscsThePointsReach)
  {
    const EdgeEnrichment near(r_e, z_e, 0.05, {1, 3}, steel);
    const EdgeEnrichment far(r_e, z_e + 0.3, 0.05, {1}, steel);
    const Eigen::Index n_near = near.n_columns(), n_far = far.n_columns();
    auto both = [&](const Eigen::VectorXd &r, const Eigen::VectorXd &z) {
      EdgeColumns c = EdgeColumns::zero(r.size(), n_near + n_far);
      c.set_columns(0, near.evaluate(r, z));
      c.set_columns(n_near, far.evaluate(r, z));
      return c;
    };
    // Points in the first disc only, then in the second only, then in neither.
    Eigen::VectorXd r(3), z(3);
    r << r_e - 0.01, r_e - 0.02, r_e - 0.015;
    z << z_e + 0.01, z_e - 0.02, z_e;
    const EdgeColumns in_near = both(r, z);
    std::vector<Eigen::Index> expected(static_cast<std::size_t>(n_near));
    for (Eigen::Index j = 0; j < n_near; ++j)
      expected[static_cast<std::size_t>(j)] = j;
    EXPECT_EQ(in_near.nonzero_columns(), expected);
    const EdgeColumns in_far = both(r, (z.array() + 0.3).matrix());
    expected.assign(1, n_near);
    EXPECT_EQ(in_far.nonzero_columns(), expected);
    EXPECT_TRUE(both(r, (z.array() + 0.15).matrix()).nonzero_columns().empty());

    const std::vector<Eigen::Index> pick{n_near, 0};
    const EdgeColumns picked = in_near.columns(pick);
    for (int k = 0; k < 4; ++k)
      {
        EXPECT_EQ(picked.stress[k].col(1), in_near.stress[k].col(0));
        EXPECT_EQ(picked.strain[k].col(0), in_near.strain[k].col(n_near));
      }
    for (int m = 0; m < 2; ++m)
      EXPECT_EQ(picked.u[m].col(1), in_near.u[m].col(0));
  }
} // namespace rfm
