// Matrices for the dense-kernel tests (rfm/solve/dense_cholesky_test.cc, rfm/solve/bordered_cholesky_test.cc).
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>

#include <cmath>

namespace rfm::testing
{
  /// SPD with 1-norm condition number about 10^decades: Q diag(10^(-decades i/(n-1))) Q^T.
  inline Eigen::MatrixXd spd(Eigen::Index n, double decades)
  {
    const Eigen::MatrixXd q = Eigen::MatrixXd::Random(n, n).householderQr().householderQ();
    Eigen::VectorXd l(n);
    for (Eigen::Index i = 0; i < n; ++i)
      l[i] = std::pow(10.0, -decades * static_cast<double>(i) / static_cast<double>(n - 1));
    return q * l.asDiagonal() * q.transpose();
  }
} // namespace rfm::testing
