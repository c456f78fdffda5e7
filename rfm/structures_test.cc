#include "rfm/structures.h"

#include "rfm/discrete_space.h"
#include "rfm/solution.h"
#include "rfm/test_sections.h"

#include <gtest/gtest.h>

namespace rfm
{
  using namespace rfm::testing;

  // Structures satisfy every boundary condition identically: random coefficients,
  // points on each part.
  TEST(Structures, BoundaryConditionsHoldForRandomCoefficients)
  {
    const Structures structures(die_section());
    DiscretizationOptions options;
    options.degree = 4;
    const DiscreteSpace space(structures, options, Material{});
    // The die section has a contact edge at z = c: the n = 1, 3 edge modes, each times the
    // 6 monomials of degree <= 2, are columns of both spaces and get random coefficients too.
    ASSERT_EQ(options.edge_mode_degree, 2);
    ASSERT_EQ(space.n_edge_columns(), 2 * 6);
    std::srand(7);
    const RfmSolution sol(space, Material{}, 1e7 * Eigen::VectorXd::Random(space.n_stress_unknowns()),
                          1e-5 * Eigen::VectorXd::Random(space.n_displacement_unknowns()));

    const int m = 25;
    auto along = [&](double lo, double hi) {
      return Eigen::VectorXd::LinSpaced(m, lo, hi);
    };
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m);
    const double tol_s = 1e-7 * 1e7, tol_u = 1e-12;

    // Inner side: sigma_rr = -p_in, sigma_rz = 0.
    FieldValues f = sol.evaluate(r1 * ones, along(0, a));
    EXPECT_LT((f.sigma.col(rr).array() + p_in).abs().maxCoeff(), tol_s);
    EXPECT_LT(f.sigma.col(rz).cwiseAbs().maxCoeff(), tol_s);
    // Contact part: u_r = u*, sigma_rz = 0.
    const Eigen::VectorXd zc = along(0, c);
    f = sol.evaluate(r2 * ones, zc);
    for (int k = 0; k < m; ++k)
      EXPECT_NEAR(f.u(k, 0), u_star(zc[k]), tol_u);
    EXPECT_LT(f.sigma.col(rz).cwiseAbs().maxCoeff(), tol_s);
    // Free outer part: sigma_rr = -p_out, sigma_rz = 0.
    f = sol.evaluate(r2 * ones, along(c, a));
    EXPECT_LT((f.sigma.col(rr).array() + p_out).abs().maxCoeff(), tol_s);
    EXPECT_LT(f.sigma.col(rz).cwiseAbs().maxCoeff(), tol_s);
    // Symmetry plane: u_z = 0, sigma_rz = 0.
    f = sol.evaluate(along(r1, r2), 0 * ones);
    EXPECT_LT(f.u.col(1).cwiseAbs().maxCoeff(), tol_u);
    EXPECT_LT(f.sigma.col(rz).cwiseAbs().maxCoeff(), tol_s);
    // Free end: sigma_zz = 0, sigma_rz = 0.
    f = sol.evaluate(along(r1, r2), a * ones);
    EXPECT_LT(f.sigma.col(zz).cwiseAbs().maxCoeff(), tol_s);
    EXPECT_LT(f.sigma.col(rz).cwiseAbs().maxCoeff(), tol_s);

    // ...and the coefficients do act inside: the fields are not trivially zero
    // (omega_rz is a product of four distances of about 0.05 m: 1e7 * 0.05^4 = 60).
    f = sol.evaluate(0.15 * ones, along(0.01, 0.19));
    EXPECT_GT(f.sigma.col(rz).cwiseAbs().maxCoeff(), 10.0);
    EXPECT_GT(f.u.col(1).cwiseAbs().maxCoeff(), 1e-9);
    // The enrichment acts near the edge (rho = 1 mm): its stresses are not small.
    const FieldValues fe = sol.evaluate(Eigen::VectorXd::Constant(1, r2 - 1e-3),
                                        Eigen::VectorXd::Constant(1, c), FieldPart::enrichment);
    EXPECT_GT(fe.sigma.cwiseAbs().maxCoeff(), 1e6);
  }

  TEST(Structures, RejectsFreeRigidTranslation)
  {
    Section s(r1, r2, 0.0, a);
    s.add_part({"inner", Side::inner, 0.0, a, Condition::traction, 0.0, {}, {}});
    s.add_part({"outer", Side::outer, 0.0, a, Condition::traction, 0.0, {}, {}});
    s.add_part({"bottom", Side::bottom, r1, r2, Condition::traction, 0.0, {}, {}});
    s.add_part({"top", Side::top, r1, r2, Condition::traction, 0.0, {}, {}});
    try
      {
        Structures st(s);
        FAIL() << "expected std::invalid_argument";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("rigid translation in z"), std::string::npos);
      }
  }
} // namespace rfm
