#include "rfm/assembly/assembly.h"

#include "rfm/hardware.h"
#include "rfm/quadrature/section_quadrature.h"
#include "rfm/structures/outline_structures.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

namespace rfm
{
  namespace
  {
    // The inputs of add_polynomial_blocks for the paper's die at c = 0.12 m (the hollow
    // cylinder's half section with its zone): the tensor Legendre basis and the outline
    // structures at the tensor rule graded toward the zone's end.
    struct Inputs
    {
      Quadrature2D q;
      Eigen::VectorXd mu;
      BasisValues b;
      StressStructureValues s;
      DisplacementStructureValues d;
      Eigen::Index n = 0;
    };
    Inputs make_inputs(const int degree)
    {
      const axisym::Problem p = axisym::parse_problem(nlohmann::json::parse(R"({
        "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
        "die": {"indentation": 1.0e-6}})"));
      const OutlineStructures structures(*p.body, degree, {DieZone{"outer", 0.0, 0.12, 1e-6}});
      Inputs in;
      in.q = rectangle_gauss(structures.body().outline, degree + 4);
      in.mu = 2.0 * in.q.weights.cwiseProduct(in.q.r); // mirrored: both halves
      const TensorLegendreBasis basis(degree, 0.1, 0.2, 0.0, 0.2);
      in.b = basis.evaluate(in.q.r, in.q.z);
      const OutlineStressValues s = structures.stress(in.q.r, in.q.z);
      in.s = {s.omega, s.s0};
      const OutlineDisplacementValues d = structures.displacement(in.q.r, in.q.z);
      in.d = {d.omega, d.omega_r, d.omega_z, d.u0, d.u0_r, d.u0_z};
      in.n = basis.n_basis_functions();
      return in;
    }
    ReissnerSystem assemble(const Inputs &in, const Eigen::Index chunk = 0, const bool full = true)
    {
      ReissnerSystem sys;
      sys.r11.setZero(4 * in.n, 4 * in.n);
      sys.r12.setZero(4 * in.n, 2 * in.n);
      sys.p_s.setZero(4 * in.n);
      sys.p_u.setZero(2 * in.n);
      add_polynomial_blocks(in.mu, in.q.r, in.b, in.s, in.d, Material{}.compliance(), sys, chunk,
                            full);
      return sys;
    }

    // n_e smooth "enrichment" columns at the rule's points, nonzero in the columns `which`
    // (stresses, displacements and the displacements' strains of one field family each).
    EdgeColumns smooth_columns(const Inputs &in, const Eigen::Index n_e, const std::vector<Eigen::Index> &which)
    {
      const Eigen::Index n_p = in.q.n_points();
      EdgeColumns e = EdgeColumns::zero(n_p, n_e);
      for (const Eigen::Index j : which)
        for (Eigen::Index k = 0; k < n_p; ++k)
          {
            const double r = in.q.r[k], z = in.q.z[k], a = 1.0 + j;
            for (int c = 0; c < 4; ++c)
              e.stress[c](k, j) = std::cos(a * r + c * z);
            e.u[0](k, j) = std::sin(a * z) * r, e.u[1](k, j) = std::cos(a * r) * z;
            e.strain[rr](k, j) = std::sin(a * z), e.strain[zz](k, j) = std::cos(a * r);
            e.strain[tt](k, j) = std::sin(a * z);
            e.strain[rz](k, j) = a * std::cos(a * z) * r - a * std::sin(a * r) * z;
          }
      return e;
    }

    // A zero system for N polynomial functions and n_e enrichment columns (no boundary ones).
    ReissnerSystem zero_system(const Eigen::Index n, const Eigen::Index n_e)
    {
      ReissnerSystem sys;
      sys.r11.setZero(4 * n + n_e, 4 * n + n_e);
      sys.r12.setZero(4 * n + n_e, 2 * n + n_e);
      sys.p_s.setZero(4 * n + n_e);
      sys.p_u.setZero(2 * n + n_e);
      return sys;
    }
  } // namespace

  TEST(Assembly, R11IsSymmetricNegativeDefinite)
  {
    const ReissnerSystem sys = assemble(make_inputs(3));
    EXPECT_LT((sys.r11 - sys.r11.transpose()).cwiseAbs().maxCoeff(),
              1e-14 * sys.r11.cwiseAbs().maxCoeff());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(sys.r11);
    EXPECT_LT(es.eigenvalues().maxCoeff(), 0.0);
  }

  // Chunks sum the same integrals in another order: rounding only. Threads own whole
  // blocks, so the thread count changes nothing, bit for bit.
  TEST(Assembly, ChunksAndThreadCountsChangeRoundingOnly)
  {
    const Inputs in = make_inputs(4);
    const Eigen::Index n_q = in.q.n_points();
    ASSERT_GT(n_q, 2 * min_chunk_points);
    const ReissnerSystem one = assemble(in, n_q);
    const ReissnerSystem many = assemble(in, min_chunk_points);
    EXPECT_LT((one.r11 - many.r11).cwiseAbs().maxCoeff(), 1e-14 * one.r11.cwiseAbs().maxCoeff());
    EXPECT_LT((one.r12 - many.r12).cwiseAbs().maxCoeff(), 1e-14 * one.r12.cwiseAbs().maxCoeff());
    EXPECT_LT((one.p_s - many.p_s).cwiseAbs().maxCoeff(), 1e-14 * one.p_s.cwiseAbs().maxCoeff());

    // Threads split every block by columns (the GEMMs of column ranges round differently
    // from the whole block's): other thread counts agree to rounding, the same thread
    // count gives the same bits.
    const int threads = n_threads();
    set_n_threads(1);
    const ReissnerSystem serial = assemble(in, min_chunk_points);
    set_n_threads(3);
    const ReissnerSystem parallel = assemble(in, min_chunk_points);
    const ReissnerSystem again = assemble(in, min_chunk_points);
    set_n_threads(threads);
    EXPECT_LT((serial.r11 - parallel.r11).cwiseAbs().maxCoeff(), 1e-14 * serial.r11.cwiseAbs().maxCoeff());
    EXPECT_LT((serial.r12 - parallel.r12).cwiseAbs().maxCoeff(), 1e-14 * serial.r12.cwiseAbs().maxCoeff());
    EXPECT_TRUE(serial.p_s == parallel.p_s);
    EXPECT_TRUE(serial.p_u == parallel.p_u);
    EXPECT_TRUE(parallel.r11 == again.r11);
    EXPECT_TRUE(parallel.r12 == again.r12);
    const Eigen::Index n_poly = 4 * in.n; // polynomial blocks: mirrored
    const Eigen::MatrixXd poly = parallel.r11.topLeftCorner(n_poly, n_poly);
    EXPECT_TRUE(poly == poly.transpose());
  }

  TEST(Assembly, ChunkFillsHalfOfL2)
  {
    // 4 N doubles per point in half of L2, a multiple of 8, clamped.
    EXPECT_EQ(assembly_chunk_points(121, 1 << 20), 128); // 524288 / 3872 = 135
    EXPECT_EQ(assembly_chunk_points(441, 1 << 20), min_chunk_points);
    EXPECT_EQ(assembly_chunk_points(1, 1L << 30), max_chunk_points);
  }

  // One entry of each R12 block and of p_u by a plain loop over quadrature points with
  // the strain formulas written out: an independent check of the GEMM formulation.
  TEST(Assembly, BlocksMatchScalarLoop)
  {
    const Inputs in = make_inputs(2);
    const ReissnerSystem sys = assemble(in);
    const Eigen::Index n = in.n;
    const auto &q = in.q;
    const auto &b = in.b;
    const auto &s = in.s;
    const auto &d = in.d;
    const Eigen::Matrix4d cm = Material{}.compliance();
    const int j = 4, l = 7; // a stress and a displacement coordinate function
    double rr_ur = 0, tt_ur = 0, rz_ur = 0, zz_uz = 0, rz_uz = 0, m_rr_tt = 0, m_rz_rz = 0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      {
        const double mu = in.mu[k], r = q.r[k];
        const double phi = b.value(k, l);
        const double ur = d.omega(k, 0) * phi;
        const double ur_r = d.omega_r(k, 0) * phi + d.omega(k, 0) * b.d_r(k, l);
        const double ur_z = d.omega_z(k, 0) * phi + d.omega(k, 0) * b.d_z(k, l);
        const double uz_r = d.omega_r(k, 1) * phi + d.omega(k, 1) * b.d_r(k, l);
        const double uz_z = d.omega_z(k, 1) * phi + d.omega(k, 1) * b.d_z(k, l);
        rr_ur += mu * s.omega(k, rr) * b.value(k, j) * ur_r;
        tt_ur += mu * b.value(k, j) * ur / r;
        rz_ur += mu * s.omega(k, rz) * b.value(k, j) * ur_z;
        zz_uz += mu * s.omega(k, zz) * b.value(k, j) * uz_z;
        rz_uz += mu * s.omega(k, rz) * b.value(k, j) * uz_r;
        m_rr_tt -= mu * s.omega(k, rr) * b.value(k, j) * cm(rr, tt) * b.value(k, l);
        m_rz_rz -= mu * s.omega(k, rz) * s.omega(k, rz) * b.value(k, j) * cm(rz, rz) * b.value(k, l);
      }
    // Relative to the largest entry of the matrix: single entries may cancel to ~0.
    const double s11 = sys.r11.cwiseAbs().maxCoeff(), s12 = sys.r12.cwiseAbs().maxCoeff();
    auto near = [&](double x, double y) {
      EXPECT_NEAR(x, y, 1e-13 * s12);
    };
    auto near11 = [&](double x, double y) { EXPECT_NEAR(x, y, 1e-13 * s11); };
    near(sys.r12(rr * n + j, l), rr_ur);
    near(sys.r12(tt * n + j, l), tt_ur);
    near(sys.r12(rz * n + j, l), rz_ur);
    near(sys.r12(zz * n + j, n + l), zz_uz);
    near(sys.r12(rz * n + j, n + l), rz_uz);
    EXPECT_EQ(sys.r12(zz * n + j, l), 0.0); // u_r does no work on sigma_zz
    near11(sys.r11(rr * n + j, tt * n + l), m_rr_tt);
    near11(sys.r11(rz * n + j, rz * n + l), m_rz_rz);
    EXPECT_GT(std::abs(m_rr_tt), 1e-6 * s11); // the compared entries are not trivially 0
    EXPECT_EQ(sys.r11(rr * n + j, rz * n + l), 0.0);
  }

  // full_r11 = false writes the same lower triangle (bitwise) and leaves the strict upper
  // alone; R12 and the loads are the same.
  TEST(Assembly, LowerTriangleOnlyMatchesTheFullAssembly)
  {
    const Inputs in = make_inputs(6);
    const ReissnerSystem full = assemble(in);
    const ReissnerSystem lower = assemble(in, 0, false);
    const Eigen::MatrixXd a = full.r11.triangularView<Eigen::Lower>();
    const Eigen::MatrixXd b = lower.r11.triangularView<Eigen::Lower>();
    EXPECT_TRUE(a == b);
    EXPECT_TRUE(full.r12 == lower.r12);
    EXPECT_TRUE(full.p_s == lower.p_s);
    EXPECT_TRUE(full.p_u == lower.p_u);
  }

  // add_enrichment_blocks with `columns`: the enrichment columns given are placed where the
  // list says, and the result equals the call with all columns where the others are zero
  // (as a vertex's local columns beyond its disc); two blocks of points add up to one call.
  TEST(Assembly, EnrichmentColumnSubsetLandsInItsPlaces)
  {
    const Inputs in = make_inputs(2);
    const Eigen::Index n = in.n, n_p = in.q.n_points(), n_e = 5;
    // Five smooth "enrichment" columns, of which 1 and 3 are zero.
    const EdgeColumns all = smooth_columns(in, n_e, {0, 2, 4});
    const Eigen::Matrix4d c = Material{}.compliance();
    ReissnerSystem full = zero_system(n, n_e), part = zero_system(n, n_e);
    const Eigen::MatrixXd body_force = Eigen::MatrixXd::Constant(n_p, 2, 7.85e4); // so that p_u is not 0
    add_enrichment_blocks(in.mu, in.q.r, in.b, in.s, in.d, all, nullptr, nullptr, &body_force, c, full);
    const std::vector<Eigen::Index> held{0, 2, 4};
    EdgeColumns some = EdgeColumns::zero(n_p, 3);
    for (int k = 0; k < 3; ++k)
      {
        for (int comp = 0; comp < 4; ++comp)
          some.stress[comp].col(k) = all.stress[comp].col(held[k]), some.strain[comp].col(k) = all.strain[comp].col(held[k]);
        for (int m = 0; m < 2; ++m)
          some.u[m].col(k) = all.u[m].col(held[k]);
      }
    // In two blocks of points.
    const Eigen::Index h = n_p / 2;
    auto rows = [](const EdgeColumns &e, const Eigen::Index from, const Eigen::Index count) {
      EdgeColumns out;
      for (int comp = 0; comp < 4; ++comp)
        out.stress[comp] = e.stress[comp].middleRows(from, count), out.strain[comp] = e.strain[comp].middleRows(from, count);
      for (int m = 0; m < 2; ++m)
        out.u[m] = e.u[m].middleRows(from, count);
      return out;
    };
    auto basis_rows = [&](const Eigen::Index from, const Eigen::Index count) {
      return BasisValues{in.b.value.middleRows(from, count), in.b.d_r.middleRows(from, count),
                         in.b.d_z.middleRows(from, count)};
    };
    auto stress_rows = [&](const Eigen::Index from, const Eigen::Index count) {
      return StressStructureValues{in.s.omega.middleRows(from, count), in.s.s0.middleRows(from, count)};
    };
    auto displacement_rows = [&](const Eigen::Index from, const Eigen::Index count) {
      return DisplacementStructureValues{in.d.omega.middleRows(from, count), in.d.omega_r.middleRows(from, count),
                                         in.d.omega_z.middleRows(from, count), in.d.u0.middleRows(from, count),
                                         in.d.u0_r.middleRows(from, count), in.d.u0_z.middleRows(from, count)};
    };
    for (const auto &[from, count] : {std::pair{Eigen::Index{0}, h}, std::pair{h, n_p - h}})
      {
        const Eigen::MatrixXd f = body_force.middleRows(from, count);
        add_enrichment_blocks(in.mu.segment(from, count), in.q.r.segment(from, count), basis_rows(from, count),
                              stress_rows(from, count), displacement_rows(from, count), rows(some, from, count),
                              nullptr, nullptr, &f, c, part, &held);
      }
    const double s11 = full.r11.cwiseAbs().maxCoeff(), s12 = full.r12.cwiseAbs().maxCoeff();
    ASSERT_GT(s11, 0.0);
    EXPECT_LT((full.r11 - part.r11).cwiseAbs().maxCoeff(), 1e-13 * s11);
    EXPECT_LT((full.r12 - part.r12).cwiseAbs().maxCoeff(), 1e-13 * s12);
    EXPECT_LT((full.p_s - part.p_s).cwiseAbs().maxCoeff(), 1e-13 * full.p_s.cwiseAbs().maxCoeff());
    EXPECT_LT((full.p_u - part.p_u).cwiseAbs().maxCoeff(), 1e-13 * full.p_u.cwiseAbs().maxCoeff());
    // The zero columns' rows and columns stay zero; the held ones are not.
    for (const Eigen::Index j : {1, 3})
      {
        EXPECT_EQ(part.r11.col(4 * n + j).cwiseAbs().maxCoeff(), 0.0);
        EXPECT_EQ(part.r12.col(2 * n + j).cwiseAbs().maxCoeff(), 0.0);
      }
    EXPECT_GT(part.r11.col(4 * n + 2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT(part.r12.col(2 * n + 4).cwiseAbs().maxCoeff(), 0.0);
  }

  // Columns with stresses alone (a vertex's local and inner-disc stresses): their products
  // with strains and displacements are skipped. The system equals the one where those
  // columns carry a displacement too, but for that displacement's own rows and columns
  // (R12's and p_u's), which are zero.
  TEST(Assembly, StressOnlyEnrichmentColumnsSkipTheirZeroDisplacements)
  {
    const Inputs in = make_inputs(2);
    const Eigen::Index n = in.n, n_p = in.q.n_points(), n_e = 5;
    const EdgeColumns moving = smooth_columns(in, n_e, {0, 1, 2, 3, 4});
    EdgeColumns still = moving; // columns 1 and 3: stresses alone
    for (const Eigen::Index j : {1, 3})
      {
        for (int c = 0; c < 4; ++c)
          still.strain[c].col(j).setZero();
        for (int m = 0; m < 2; ++m)
          still.u[m].col(j).setZero();
      }
    EXPECT_EQ(still.displacement_columns(), (std::vector<Eigen::Index>{0, 2, 4}));
    EXPECT_EQ(moving.displacement_columns().size(), 5u);
    auto system = [&](const EdgeColumns &e) {
      ReissnerSystem sys = zero_system(n, n_e);
      const Eigen::MatrixXd body_force = Eigen::MatrixXd::Constant(n_p, 2, 7.85e4);
      add_enrichment_blocks(in.mu, in.q.r, in.b, in.s, in.d, e, nullptr, nullptr, &body_force,
                            Material{}.compliance(), sys);
      return sys;
    };
    const ReissnerSystem a = system(still), b = system(moving);
    const double s11 = b.r11.cwiseAbs().maxCoeff(), s12 = b.r12.cwiseAbs().maxCoeff();
    EXPECT_LT((a.r11 - b.r11).cwiseAbs().maxCoeff(), 1e-13 * s11);
    EXPECT_LT((a.p_s - b.p_s).cwiseAbs().maxCoeff(), 1e-13 * b.p_s.cwiseAbs().maxCoeff());
    // R12 and p_u: the same but in the still columns' displacement columns, zero there.
    Eigen::MatrixXd r12 = b.r12;
    Eigen::VectorXd p_u = b.p_u;
    for (const Eigen::Index j : {1, 3})
      {
        EXPECT_GT(b.r12.col(2 * n + j).cwiseAbs().maxCoeff(), 1e-3 * s12);
        EXPECT_EQ(a.r12.col(2 * n + j).cwiseAbs().maxCoeff(), 0.0);
        EXPECT_EQ(a.p_u[2 * n + j], 0.0);
        r12.col(2 * n + j).setZero();
        p_u[2 * n + j] = 0.0;
      }
    EXPECT_LT((a.r12 - r12).cwiseAbs().maxCoeff(), 1e-13 * s12);
    EXPECT_LT((a.p_u - p_u).cwiseAbs().maxCoeff(), 1e-13 * b.p_u.cwiseAbs().maxCoeff());
    // The still columns' stresses still do work on every other displacement.
    EXPECT_GT(a.r12.row(4 * n + 1).cwiseAbs().maxCoeff(), 1e-3 * s12);
  }
} // namespace rfm
