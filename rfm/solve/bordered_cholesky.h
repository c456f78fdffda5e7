// The scaled saddle-point matrix of Reissner's functional factorized in one pass, by tiles,
// on several threads (issue 15, item 3).
//
// With M = D (-R11) D (symmetric positive definite) and B = D R12 (n1 x n2, full column
// rank), the bordered matrix
//
//   A = [ M    B ]  =  [ L11  0   ] [ I  0 ] [ L11^T  L21^T ]
//       [ B^T  0 ]     [ L21  L22 ] [ 0 -I ] [ 0      L22^T ]
//
// is symmetric quasi-definite: L11 L11^T = M, L21 = B^T L11^-T (the Y^T of the Schur
// solve), L22 L22^T = L21 L21^T = K, the Schur complement. Here K is also scaled,
// L22 L22^T = E K E with E = diag(K)^-1/2 (the Jacobi scaling the rcond test reads). It is
// the Schur solve of saddle_point_solver.cc (Cholesky of M, triangular solve, K = Y^T Y,
// Cholesky of K) as one right-looking tiled Cholesky whose updates into the trailing block
// add instead of subtract (the -I).
//
// Why one pass: on two threads the four steps apart ran at 1.31x (Cholesky of M, n = 900),
// 1.91x (triangular solve), 1.56x (K = Y^T Y) and 1.07x (Cholesky of K, n = 450) of one
// thread (Lame p = 14, OpenBLAS threads); as one task graph over the whole matrix the
// threads always have tile work: the factorization 19.6 -> 10.3-11.3 ms at p = 14, and
// the whole solve 1.7-1.9x at p = 14 ... 20 (rfm_benchmark). One thread runs the same
// graph, a little faster than the four steps were (21.2 against 22.8 ms at p = 14, means
// of three runs).
//
// Tasks on tiles (rows and columns of each block cut into tiles of about `tile`, at
// multiples of 8): POTRF(k) factors diagonal tile k, TRSM(i, k) the tiles below it,
// UPDATE(i, j, k) applies column k to tile (i, j), SCALE(i, j) scales a trailing tile by E
// once every first-block update has reached it (and those of its two diagonal tiles, which
// give E). Each worker takes the first ready task of the sequential order. The updates of
// one tile run in the order of k whatever thread runs them, and each task is a
// single-threaded Eigen/OpenBLAS call: the result is bitwise the same for every thread
// count, and from run to run.
#pragma once

#include <Eigen/Core>

#include <functional>

namespace rfm
{
  struct BorderedCholesky
  {
    enum class Status
    {
      ok,
      stress_block_not_positive, ///< a pivot of M <= 0
      zero_schur_column,         ///< K_jj = 0: a column of B does no work
      schur_not_positive         ///< a pivot of E K E <= 0
    } status = Status::ok;
    Eigen::VectorXd e;      ///< the scaling of K, e_j = K_jj^-1/2
    double m_l1_norm = 0.0; ///< |M|_1, for the condition estimate (NaN if stopped first)
    double k_l1_norm = 0.0; ///< |E K E|_1, for the condition estimate
  };

  /// Work the factorization's threads take on beside the tiles.
  struct BorderedCholeskyJobs
  {
    /// Writes columns [c0, c1) of the lower triangle's first block: rows c0 .. n1 - 1 of
    /// M and all n2 rows of B^T. Called once per column tile, from any worker thread.
    std::function<void(Eigen::Index c0, Eigen::Index c1)> load;
    /// Runs once, on a worker thread, when L11 and L21 are final (while the trailing
    /// block is being factorized), with |M|_1; may read them, not write.
    std::function<void(double m_l1_norm)> after_first_block;
  };

  /// Factorizes the bordered matrix in place, its first block written by jobs.load tile by
  /// tile (so that filling it runs in parallel too). The trailing n2 x n2 block of `a`
  /// ((n1 + n2) square) need not be set. On return the lower triangle holds L11, L21 and
  /// L22 (unless the status says otherwise); the strict upper triangle is not touched.
  /// n_threads >= 1 workers (the caller is one). Tiles of about `tile` (192 measured best
  /// of 128, 192, 256 at Lame p = 14, 16, 20).
  BorderedCholesky factorize_bordered(Eigen::Ref<Eigen::MatrixXd> a, Eigen::Index n1,
                                      int n_threads, const BorderedCholeskyJobs &jobs,
                                      Eigen::Index tile = 192);
  /// The same with the first block already in the lower triangle of `a`.
  BorderedCholesky factorize_bordered(Eigen::Ref<Eigen::MatrixXd> a, Eigen::Index n1,
                                      int n_threads, Eigen::Index tile = 192);
} // namespace rfm
