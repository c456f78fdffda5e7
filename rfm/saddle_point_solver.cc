#include "rfm/saddle_point_solver.h"

#include "rfm/hardware.h"

#include "rfm/dense_cholesky.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <sstream>

namespace rfm
{
  namespace
  {
    // From the lower triangle of a (SelfAdjointEigenSolver reads nothing else).
    double eigen_condition(const Eigen::MatrixXd &a)
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(a, Eigen::EigenvaluesOnly);
      const Eigen::VectorXd &l = es.eigenvalues();
      return l.minCoeff() > 0 ? l.maxCoeff() / l.minCoeff()
                              : std::numeric_limits<double>::infinity();
    }
  } // namespace

  SaddlePointSolution solve_saddle_point(const ReissnerSystem &sys, const SolverOptions &options)
  {
    SaddlePointSolution out;
    SolveSummary &summary = out.summary;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    summary.cond_stress = summary.cond_schur = summary.inf_sup = nan;
    const Eigen::Index n_s = sys.r11.rows(), n_u = sys.r12.cols();
    // Large systems: the factorizations and solves on n_threads() threads (hardware.h).
    const BlasThreadsOn parallel(n_s + n_u >= parallel_solve_unknowns);

    // Three n x n-sized buffers in all (M, Y, K): each factorization overwrites its
    // matrix (DenseCholesky), only lower triangles are formed, nothing large is copied twice.
    // 1. M = -R11, scaled (lower triangle), Cholesky in place (DenseCholesky).
    const Eigen::VectorXd d = (-sys.r11.diagonal()).cwiseMax(0.0).cwiseSqrt().cwiseInverse();
    if (!d.allFinite())
      {
        summary.message = "R11 has a non-negative diagonal entry: the stress structure has a "
                          "coordinate function that vanishes identically";
        return out;
      }
    Eigen::MatrixXd m(n_s, n_s);
    m.triangularView<Eigen::Lower>() = -(d.asDiagonal() * sys.r11 * d.asDiagonal());
    // The eigenvalue diagnostics read the lower triangle before it is factorized.
    const double cond_stress = options.compute_diagnostics ? eigen_condition(m) : nan;
    const DenseCholesky llt_m(m);
    summary.rcond_stress = llt_m.rcond();
    if (!llt_m.success() || !(summary.rcond_stress >= options.min_rcond))
      {
        std::ostringstream msg;
        msg << "-R11 (stress block) is not numerically positive definite (rcond estimate "
            << summary.rcond_stress << " < " << options.min_rcond << ")";
        summary.message = msg.str();
        return out;
      }

    // 2. Y = L^-1 D R12, K = Y^T Y (lower triangle), scaled by E in place.
    Eigen::MatrixXd y = d.asDiagonal() * sys.r12;
    llt_m.solve_l_in_place(y);
    Eigen::VectorXd y_s = d.cwiseProduct(sys.p_s);
    llt_m.solve_l_in_place(y_s);
    Eigen::MatrixXd k(n_u, n_u);
    k.triangularView<Eigen::Lower>() = y.transpose() * y;
    const Eigen::VectorXd e = k.diagonal().cwiseMax(0.0).cwiseSqrt().cwiseInverse();
    if (!e.allFinite())
      {
        summary.message = "R12 has a zero column: a displacement coordinate function does "
                          "no work on any stress (rank loss, inf-sup failure)";
        return out;
      }
    k.triangularView<Eigen::Lower>() = e.asDiagonal() * k * e.asDiagonal();
    if (options.compute_diagnostics)
      {
        summary.cond_stress = cond_stress;
        summary.cond_schur = eigen_condition(k);
        summary.inf_sup = 1.0 / std::sqrt(summary.cond_schur);
      }
    const DenseCholesky llt_k(k);
    summary.rcond_schur = llt_k.rcond();
    if (!llt_k.success() || !(summary.rcond_schur >= options.min_rcond))
      {
        std::ostringstream msg;
        msg << "Schur complement K = R12^T (-R11)^-1 R12 is singular or badly conditioned "
            << "(rcond estimate " << summary.rcond_schur << " < " << options.min_rcond
            << "): R12 lost column rank (discrete inf-sup failure, or a rigid-body mode "
            << "left in the displacement structure)";
        summary.message = msg.str();
        return out;
      }

    // 3. Back substitution.
    const Eigen::VectorXd rhs = -(sys.p_u + y.transpose() * y_s);
    out.q_u = e.cwiseProduct(llt_k.solve(e.cwiseProduct(rhs)));
    Eigen::VectorXd t = y * out.q_u + y_s;
    llt_m.solve_lt_in_place(t);
    out.q_s = d.cwiseProduct(t);
    if (!out.q_u.allFinite() || !out.q_s.allFinite())
      {
        summary.message = "solution has non-finite coefficients";
        return out;
      }
    summary.success = true;
    summary.message = "ok";
    return out;
  }
} // namespace rfm
