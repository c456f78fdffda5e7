// The section-orthonormal polynomial basis (section_basis.h): orthonormal at its samples,
// the same span as the tensor Legendre functions, derivatives consistent with the values,
// and evaluated in long double where the double recurrence is too noisy.
#include "rfm/spaces/section_basis.h"

#include "problem/outline.h"
#include "problem/problem.h"
#include "problem/test_problems.h"
#include "rfm/quadrature/section_quadrature.h"
#include "rfm/spaces/basis.h"

#include <gtest/gtest.h>

#include <Eigen/QR>

#include <vector>

namespace
{
  // The thick sphere's quarter annulus (0.1 <= rho <= 0.2, r, z >= 0): 59 % of its box.
  axisym::Outline quarter_annulus()
  {
    return axisym::parse_problem(axisym::testing::thick_sphere()).body->outline;
  }

  struct BasisCase
  {
    rfm::Quadrature2D samples, fine;
    Eigen::VectorXd w, w_fine;
    rfm::SectionPolynomialBasis basis;
    rfm::TensorLegendreBasis legendre;
  };
  BasisCase make(int p)
  {
    const axisym::Outline outline = quarter_annulus();
    const axisym::BoundingBox b = outline.bounding_box();
    rfm::SectionQuadratureOptions qo;
    qo.n_points = p + 2;
    rfm::Quadrature2D s = rfm::section_gauss(outline, qo);
    qo.n_points = p + 3; // other points than the samples
    rfm::Quadrature2D f = rfm::section_gauss(outline, qo);
    const Eigen::VectorXd w = s.weights.cwiseProduct(s.r), wf = f.weights.cwiseProduct(f.r);
    rfm::SectionPolynomialBasis basis(p, p, b.r_min, b.r_max, b.z_min, b.z_max, s.r, s.z, w);
    return {s, f, w, wf, basis, rfm::TensorLegendreBasis(p, b.r_min, b.r_max, b.z_min, b.z_max)};
  }

  // Largest residual, relative to the largest value, of the tensor Legendre functions
  // (values and both derivatives) fitted by the basis at the fine points (least squares on
  // the values, the same coefficients for the derivatives).
  std::vector<double> span_residuals(const BasisCase &s, bool derivatives = true)
  {
    const rfm::BasisValues v = s.basis.evaluate(s.fine.r, s.fine.z, derivatives);
    const rfm::BasisValues l = s.legendre.evaluate(s.fine.r, s.fine.z);
    const Eigen::VectorXd sw = s.w_fine.cwiseSqrt();
    const Eigen::MatrixXd c =
      (sw.asDiagonal() * v.value).householderQr().solve(sw.asDiagonal() * l.value);
    std::vector<double> out{(v.value * c - l.value).cwiseAbs().maxCoeff() / l.value.cwiseAbs().maxCoeff()};
    if (derivatives)
      {
        out.push_back((v.d_r * c - l.d_r).cwiseAbs().maxCoeff() / l.d_r.cwiseAbs().maxCoeff());
        out.push_back((v.d_z * c - l.d_z).cwiseAbs().maxCoeff() / l.d_z.cwiseAbs().maxCoeff());
      }
    return out;
  }
} // namespace

TEST(SectionBasis, OrthonormalAtItsSamplesAndSpansTheTensorPolynomials)
{
  const BasisCase s = make(8);
  EXPECT_FALSE(s.basis.extended_precision());
  const Eigen::MatrixXd v = s.basis.evaluate(s.samples.r, s.samples.z).value;
  const Eigen::MatrixXd g = v.transpose() * s.w.asDiagonal() * v;
  // The recurrence's rounding at p = 8: 1.2e-12 in the ASan build (no x86-64-v3, no
  // OpenBLAS), below 1e-12 in the release build.
  EXPECT_LT((g - Eigen::MatrixXd::Identity(g.rows(), g.cols())).cwiseAbs().maxCoeff(), 1e-11);
  for (const double res : span_residuals(s))
    EXPECT_LT(res, 1e-11);
}

TEST(SectionBasis, DerivativesMatchCentralDifferences)
{
  const BasisCase s = make(6);
  Eigen::VectorXd r(3), z(3);
  r << 0.13, 0.02, 0.15;
  z << 0.07, 0.15, 0.01;
  const double h = 1e-6;
  const rfm::BasisValues b = s.basis.evaluate(r, z);
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(3);
  const rfm::BasisValues rp = s.basis.evaluate(r + h * one, z), rm = s.basis.evaluate(r - h * one, z);
  const rfm::BasisValues zp = s.basis.evaluate(r, z + h * one), zm = s.basis.evaluate(r, z - h * one);
  const Eigen::MatrixXd dr = (rp.value - rm.value) / (2 * h), dz = (zp.value - zm.value) / (2 * h);
  EXPECT_LT((dr - b.d_r).cwiseAbs().maxCoeff(), 1e-6 * b.d_r.cwiseAbs().maxCoeff());
  EXPECT_LT((dz - b.d_z).cwiseAbs().maxCoeff(), 1e-6 * b.d_z.cwiseAbs().maxCoeff());
}

TEST(SectionBasis, HighDegreeSwitchesToLongDoubleAndStaysAPolynomialSpace)
{
  // At p = 18 on the quarter annulus the double recurrence's own orthonormality error is
  // 6.4e-6 (measured): long double. The functions must then still reproduce the tensor
  // Legendre functions with their derivatives, values and derivatives alike (the double
  // recurrence's noise there is about 7e-6, with derivatives that do not match).
  const BasisCase s = make(18);
  EXPECT_TRUE(s.basis.extended_precision());
  EXPECT_GT(s.basis.orthonormality_error(), rfm::SectionPolynomialBasis::extended_precision_threshold);
  // (Values only here: the derivatives' recurrence is the same code, checked at p = 8 and
  // by central differences; this keeps the test short under ASan.)
  for (const double res : span_residuals(s, false))
    EXPECT_LT(res, 1e-8);
  // The double recurrence's noise is real: long double and double evaluations of the same
  // recurrence differ visibly here (measured 1.3e-5 of the largest value at the other
  // points), and agree to rounding at p = 8 (1.4e-12).
  using P = rfm::SectionPolynomialBasis::Precision;
  auto difference = [](const BasisCase &c) {
    const Eigen::MatrixXd a = c.basis.evaluate(c.fine.r, c.fine.z, false, P::double_precision).value;
    const Eigen::MatrixXd b = c.basis.evaluate(c.fine.r, c.fine.z, false, P::long_double).value;
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
  };
  EXPECT_GT(difference(s), 1e-7);
  EXPECT_LT(difference(make(8)), 1e-11);
}
