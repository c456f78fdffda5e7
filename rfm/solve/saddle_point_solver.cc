#include "rfm/solve/saddle_point_solver.h"

#include "rfm/hardware.h"

#include "rfm/solve/bordered_cholesky.h"
#include "rfm/solve/dense_cholesky.h"
#include "rfm/solve/symmetric_eigen.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace rfm
{
  namespace
  {
    // From the lower triangle of a (symmetric_eigen reads nothing else).
    double eigen_condition(const Eigen::Ref<const Eigen::MatrixXd> &a)
    {
      const Eigen::VectorXd l = symmetric_eigen(a, false).values;
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
    // Large systems on n_threads() threads (hardware.h); the factors are bitwise the same
    // for every thread count (rfm/solve/bordered_cholesky.h).
    const int threads = n_s + n_u >= parallel_solve_unknowns ? n_threads() : 1;
    // Every BLAS call below is single-threaded, whatever scope encloses this: the
    // parallelism is the factorization's own, and the results do not depend on it.
    const BlasThreadsOff one_blas_thread;

    // 1. The bordered matrix A = [M, B; B^T, 0] in one (n_s + n_u)^2 buffer (lower triangle),
    // M = D (-R11) D and B = D R12 with D the Jacobi scaling of -R11, written by the
    // factorization's threads column tile by column tile.
    const Eigen::VectorXd d = (-sys.r11.diagonal()).cwiseMax(0.0).cwiseSqrt().cwiseInverse();
    if (!d.allFinite())
      {
        summary.message = "R11 has a non-negative diagonal entry: the stress structure has a "
                          "coordinate function that vanishes identically";
        return out;
      }
    // Kept from solve to solve (per thread): above glibc's largest mmap threshold (32 MiB,
    // Lame p >= 18) a fresh matrix is mapped and faulted in again by every solve, which
    // doubled the solve time at p = 18 (rfm/allocator.h).
    thread_local std::vector<double> buffer;
    const Eigen::Index n_a = n_s + n_u;
    if (buffer.size() < static_cast<std::size_t>(n_a * n_a))
      {
        buffer.clear();
        buffer.shrink_to_fit();
        buffer.resize(static_cast<std::size_t>(n_a * n_a));
      }
    Eigen::Map<Eigen::MatrixXd> a(buffer.data(), n_a, n_a);
    Eigen::MatrixXd m_copy(options.compute_diagnostics ? n_s : 0, options.compute_diagnostics ? n_s : 0);
    BorderedCholeskyJobs jobs;
    jobs.load = [&](Eigen::Index c0, Eigen::Index c1) {
      const Eigen::Index w = c1 - c0;
      const auto dc = d.segment(c0, w);
      a.block(c0, c0, w, w).triangularView<Eigen::Lower>() =
        -(dc.asDiagonal() * sys.r11.block(c0, c0, w, w) * dc.asDiagonal());
      a.block(c1, c0, n_s - c1, w) =
        -(d.tail(n_s - c1).asDiagonal() * sys.r11.block(c1, c0, n_s - c1, w) * dc.asDiagonal());
      a.block(n_s, c0, n_u, w) = (dc.asDiagonal() * sys.r12.middleRows(c0, w)).transpose();
      if (m_copy.size() > 0) // the eigenvalue diagnostics need M before it is factorized
        m_copy.block(c0, c0, n_s - c0, w) = a.block(c0, c0, n_s - c0, w);
    };
    // 2. A = L diag(I, -I) L^T: L11 L11^T = M, L21 = (L11^-1 B)^T, L22 L22^T = E K E with
    // K = R12^T (-R11)^-1 R12 the Schur complement and E its Jacobi scaling. M's condition
    // estimate runs on a worker as soon as L11 is final.
    // The same worker also starts the back substitution, which needs only L11 and L21:
    // y_s = L11^-1 D p_s and the right-hand side of K q_u = -(p_u + L21 y_s).
    const auto l11 = a.topLeftCorner(n_s, n_s).triangularView<Eigen::Lower>();
    const auto l21 = a.bottomLeftCorner(n_u, n_s);
    const auto l22 = a.bottomRightCorner(n_u, n_u).triangularView<Eigen::Lower>();
    Eigen::VectorXd y_s, w;
    bool first_block_done = false;
    jobs.after_first_block = [&](double m_norm) {
      summary.rcond_stress = DenseCholesky(a.topLeftCorner(n_s, n_s), m_norm).rcond();
      y_s = d.cwiseProduct(sys.p_s);
      l11.solveInPlace(y_s);
      w = sys.p_u + l21 * y_s;
      first_block_done = true;
    };
    const BorderedCholesky f = factorize_bordered(a, n_s, threads, jobs);
    using Status = BorderedCholesky::Status;
    if (f.status != Status::stress_block_not_positive && !first_block_done) // stopped early
      summary.rcond_stress = DenseCholesky(a.topLeftCorner(n_s, n_s), f.m_l1_norm).rcond();
    if (f.status == Status::stress_block_not_positive ||
        !(summary.rcond_stress >= options.min_rcond))
      {
        std::ostringstream msg;
        msg << "-R11 (stress block) is not numerically positive definite (rcond estimate "
            << summary.rcond_stress << " < " << options.min_rcond << ")";
        summary.message = msg.str();
        return out;
      }
    if (f.status == Status::zero_schur_column)
      {
        summary.message = "R12 has a zero column: a displacement coordinate function does "
                          "no work on any stress (rank loss, inf-sup failure)";
        return out;
      }
    // K's condition estimate, then the rest of the back substitution (discarded if the
    // estimate fails the test): 0.3-0.4 ms at Lame p = 14; on two threads beside each
    // other they took as long.
    if (f.status == Status::ok)
      {
        summary.rcond_schur = DenseCholesky(a.bottomRightCorner(n_u, n_u), f.k_l1_norm).rcond();
        w = -f.e.cwiseProduct(w);
        l22.solveInPlace(w);
        l22.transpose().solveInPlace(w);
        out.q_u = f.e.cwiseProduct(w);
        Eigen::VectorXd t = l21.transpose() * out.q_u + y_s;
        l11.transpose().solveInPlace(t);
        out.q_s = d.cwiseProduct(t);
      }
    if (f.status == Status::schur_not_positive || !(summary.rcond_schur >= options.min_rcond))
      {
        std::ostringstream msg;
        out.q_s.resize(0), out.q_u.resize(0);
        msg << "Schur complement K = R12^T (-R11)^-1 R12 is singular or badly conditioned "
            << "(rcond estimate " << summary.rcond_schur << " < " << options.min_rcond
            << "): R12 lost column rank (discrete inf-sup failure, or a rigid-body mode "
            << "left in the displacement structure)";
        summary.message = msg.str();
        return out;
      }
    if (options.compute_diagnostics)
      {
        const Eigen::MatrixXd l = l22;
        Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n_u, n_u); // E K E = L22 L22^T, lower
        k.selfadjointView<Eigen::Lower>().rankUpdate(l);
        summary.cond_stress = eigen_condition(m_copy);
        summary.cond_schur = eigen_condition(k);
        summary.inf_sup = 1.0 / std::sqrt(summary.cond_schur);
      }

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
