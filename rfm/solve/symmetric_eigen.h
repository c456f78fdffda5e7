// Eigenvalues (ascending) and, when asked, eigenvectors of a dense symmetric matrix, from its
// lower triangle.
//
// With OpenBLAS (RFM_OPENBLAS) through LAPACK's dsyevd: blocked tridiagonal reduction and
// divide and conquer, whose level-3 BLAS calls run at the GEMM rate, where Eigen's
// SelfAdjointEigenSolver reduces with level-2 updates and accumulates the QR rotations one at
// a time. Measured on the project's 2-core machine, one thread: the sharp flat punch at
// p = 20 (a 2640-column stress Gram and two 549-column displacement ones) spent 17.9 s in
// its solve phase with Eigen's solver, 12.2 s with dsyevd. Without OpenBLAS, Eigen's
// solver. Both are backward stable; the results agree to rounding.
#pragma once

#include <Eigen/Core>

namespace rfm
{
  struct SymmetricEigen
  {
    Eigen::VectorXd values;  ///< ascending
    Eigen::MatrixXd vectors; ///< column k belongs to values[k]; empty unless asked for
  };

  /// Precondition: a is square (only its lower triangle is read). Throws std::runtime_error
  /// if the iteration fails to converge (LAPACK info > 0).
  SymmetricEigen symmetric_eigen(const Eigen::Ref<const Eigen::MatrixXd> &a, bool with_vectors);
} // namespace rfm
