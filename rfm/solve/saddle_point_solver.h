// Solution of the symmetric saddle-point system of assembly.h through the Schur
// complement (DESIGN.md section 2):
//
//   M = -R11 (SPD),  K = R12^T M^-1 R12 (SPD iff R12 has full column rank),
//   K q_u = -(p_u + R12^T M^-1 p_s),   q_s = M^-1 (R12 q_u + p_s).
//
// Both M and K are Jacobi-scaled (D A D with D = diag(A)^-1/2) before their Cholesky
// factorizations, so that the reported condition numbers do not depend on the units
// of stress and displacement coefficients.
//
// Numerical outcomes are returned in the summary, never thrown (Ceres Solver::Summary
// style): a failed factorization, or a reciprocal condition estimate below
// min_rcond, sets success = false with a message naming the matrix.
#pragma once

#include "rfm/assembly/assembly.h"

#include <string>

namespace rfm
{
  struct SolverOptions
  {
    /// Smallest accepted LLT reciprocal condition estimate of the scaled M and K.
    double min_rcond = 1e-15;
    /// Compute eigenvalue-based diagnostics (exact condition numbers of scaled M and
    /// K, inf-sup indicator); O(n^3) extra work, off in benchmarks.
    bool compute_diagnostics = true;
  };

  struct SolveSummary
  {
    bool success = false;
    std::string message;
    double rcond_stress = 0.0; ///< LLT rcond estimate of scaled M = -R11
    double rcond_schur = 0.0;  ///< LLT rcond estimate of scaled K
    // Diagnostics (NaN when not computed):
    double cond_stress = 0.0;  ///< lambda_max / lambda_min of scaled M
    double cond_schur = 0.0;   ///< lambda_max / lambda_min of scaled K
    /// Inf-sup indicator: smallest over largest singular value of M^-1/2 R12 E (E the
    /// Jacobi scaling of K) = sqrt(1 / cond_schur). Tends to 0 when R12 loses rank.
    double inf_sup = 0.0;
  };

  struct SaddlePointSolution
  {
    Eigen::VectorXd q_s, q_u;
    SolveSummary summary;
  };

  SaddlePointSolution solve_saddle_point(const ReissnerSystem &system,
                                         const SolverOptions &options = {});
} // namespace rfm
