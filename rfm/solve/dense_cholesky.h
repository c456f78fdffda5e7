// In-place Cholesky factorization A = L L^T of a symmetric positive definite matrix, with
// the reciprocal condition estimate rcond ~ 1 / (|A|_1 |A^-1|_1) (Higham's estimator, as
// LAPACK dpocon and Eigen's LLT::rcond: never below the exact value by more than rounding,
// rarely more than a small factor above it).
//
// Reads the lower triangle of A and overwrites it with L; the strict upper triangle is not
// touched. The factorization is recursive: L11 of the leading half, then
// L21 = A21 L11^-T (one TRSM) and A22 - L21 L21^T (one SYRK), then the trailing half, down
// to leaf_size where Eigen's LLT takes over; rcond by Eigen's estimator. The half-size
// TRSM and SYRK are the largest level-3 calls the factorization can make, so OpenBLAS's
// threads have the most work per call; Eigen's blocked LLT calls them once per 128-wide
// block column. Measured on the project's 2-core machine (OpenBLAS 0.3.21), 1 -> 2
// threads: n = 900 Eigen LLT 5.78 -> 4.72 ms, recursive 5.64 -> 4.04 ms, OpenBLAS dpotrf
// 5.56 -> 4.42 ms; n = 1764: 41.6 -> 26.2, 39.0 -> 22.9, 38.7 -> 23.3 (a standalone
// timing of the factorization alone). Single right-hand sides take the vector solve.
#pragma once

#include <Eigen/Core>
#include <Eigen/Cholesky> // Eigen's condition estimator

namespace rfm
{
  /// |A|_1 (largest column sum of |a_ij|) of the symmetric A from its lower triangle.
  double symmetric_l1_norm(const Eigen::Ref<const Eigen::MatrixXd> &a);

  class DenseCholesky
  {
  public:
    // What Eigen's condition estimator asks of a decomposition.
    using MatrixType = Eigen::MatrixXd;
    using Scalar = double;
    using RealScalar = double;
    Eigen::Index rows() const { return a_.rows(); }
    Eigen::Index cols() const { return a_.cols(); }
    const DenseCholesky &adjoint() const { return *this; } // A is symmetric

    /// Factorizes a in place; a must outlive this object.
    explicit DenseCholesky(Eigen::Ref<Eigen::MatrixXd> a);
    /// A factor computed elsewhere (rfm/solve/bordered_cholesky.h): the lower triangle of
    /// `factor` holds L; rcond() estimates from `l1_norm`, |A|_1 of the matrix factored.
    DenseCholesky(Eigen::Ref<Eigen::MatrixXd> factor, double l1_norm);

    /// False if a is not numerically positive definite (a pivot <= 0).
    bool success() const { return success_; }
    /// Reciprocal condition estimate in the 1-norm; 0 unless success().
    double rcond() const { return rcond_; }

    /// b <- L^-1 b.
    void solve_l_in_place(Eigen::Ref<Eigen::MatrixXd> b) const;
    /// b <- L^-T b.
    void solve_lt_in_place(Eigen::Ref<Eigen::MatrixXd> b) const;
    /// A^-1 b.
    Eigen::MatrixXd solve(const Eigen::Ref<const Eigen::MatrixXd> &b) const;

    /// Below this size the recursion hands over to Eigen's LLT.
    static constexpr Eigen::Index leaf_size = 128;

  private:
    Eigen::Ref<Eigen::MatrixXd> a_;
    bool success_ = false;
    double rcond_ = 0.0;
  };
} // namespace rfm
