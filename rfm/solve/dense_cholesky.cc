#include "rfm/solve/dense_cholesky.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

namespace rfm
{
  namespace
  {
    // The recursion of the header comment; false at a non-positive pivot.
    bool factorize_recursive(Eigen::Ref<Eigen::MatrixXd> a)
    {
      const Eigen::Index n = a.rows();
      if (n <= DenseCholesky::leaf_size)
        {
          const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(a);
          return llt.info() == Eigen::Success;
        }
      const Eigen::Index n1 = (n / 2 + 7) / 8 * 8; // a multiple of the kernels' widths
      if (!factorize_recursive(a.topLeftCorner(n1, n1)))
        return false;
      Eigen::Ref<Eigen::MatrixXd> a21 = a.bottomLeftCorner(n - n1, n1);
      a.topLeftCorner(n1, n1).triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(a21);
      a.bottomRightCorner(n - n1, n - n1).selfadjointView<Eigen::Lower>().rankUpdate(a21, -1.0);
      return factorize_recursive(a.bottomRightCorner(n - n1, n - n1));
    }

  } // namespace

  double symmetric_l1_norm(const Eigen::Ref<const Eigen::MatrixXd> &a)
  {
    const Eigen::Index n = a.rows();
    Eigen::VectorXd sums = Eigen::VectorXd::Zero(n);
    for (Eigen::Index j = 0; j < n; ++j)
      {
        const Eigen::Index below = n - j - 1;
        sums[j] += std::abs(a(j, j)) + a.col(j).tail(below).cwiseAbs().sum();
        sums.tail(below) += a.col(j).tail(below).cwiseAbs(); // the mirrored row j
      }
    return n > 0 ? sums.maxCoeff() : 0.0;
  }

  DenseCholesky::DenseCholesky(Eigen::Ref<Eigen::MatrixXd> factor, const double l1_norm)
    : a_(factor)
    , success_(true)
  {
    eigen_assert(factor.rows() == factor.cols());
    rcond_ = Eigen::internal::rcond_estimate_helper(l1_norm, *this);
  }

  DenseCholesky::DenseCholesky(Eigen::Ref<Eigen::MatrixXd> a)
    : a_(a)
  {
    eigen_assert(a.rows() == a.cols());
    const double l1_norm = symmetric_l1_norm(a_);
    success_ = factorize_recursive(a_);
    // Eigen's estimator (the one LLT::rcond uses; LAPACK dpocon's took 1.2 ms at n = 900
    // against 0.5 ms): solves with L and L^T only.
    rcond_ = success_ ? Eigen::internal::rcond_estimate_helper(l1_norm, *this) : 0.0;
  }

  // A single right-hand side goes through Eigen's vector solve (blocked, GEMV updates):
  // as a one-column TRSM through OpenBLAS it took several times longer.
  void DenseCholesky::solve_l_in_place(Eigen::Ref<Eigen::MatrixXd> b) const
  {
    if (b.cols() == 1)
      {
        Eigen::Ref<Eigen::VectorXd> v = b.col(0);
        a_.triangularView<Eigen::Lower>().solveInPlace(v);
      }
    else
      a_.triangularView<Eigen::Lower>().solveInPlace(b);
  }

  void DenseCholesky::solve_lt_in_place(Eigen::Ref<Eigen::MatrixXd> b) const
  {
    if (b.cols() == 1)
      {
        Eigen::Ref<Eigen::VectorXd> v = b.col(0);
        a_.triangularView<Eigen::Lower>().transpose().solveInPlace(v);
      }
    else
      a_.triangularView<Eigen::Lower>().transpose().solveInPlace(b);
  }

  Eigen::MatrixXd DenseCholesky::solve(const Eigen::Ref<const Eigen::MatrixXd> &b) const
  {
    Eigen::MatrixXd x = b;
    solve_l_in_place(x);
    solve_lt_in_place(x);
    return x;
  }
} // namespace rfm
