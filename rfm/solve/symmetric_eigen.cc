#include "rfm/solve/symmetric_eigen.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#if defined(RFM_OPENBLAS)
extern "C"
{
  // LAPACK (in OpenBLAS), Fortran calling convention.
  void dsyevd_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
               double *w, double *work, const int *lwork, int *iwork, const int *liwork,
               int *info);
}
#endif

namespace rfm
{
  SymmetricEigen symmetric_eigen(const Eigen::Ref<const Eigen::MatrixXd> &a, const bool with_vectors)
  {
    if (a.rows() != a.cols())
      throw std::invalid_argument("symmetric_eigen: the matrix is not square");
    SymmetricEigen out;
#if defined(RFM_OPENBLAS)
    const int n = static_cast<int>(a.rows());
    Eigen::MatrixXd work_a = a; // overwritten by the eigenvectors
    out.values.resize(n);
    if (n == 0)
      return out;
    const char jobz = with_vectors ? 'V' : 'N', uplo = 'L';
    int info = 0, lwork = -1, liwork = -1, iwork_query = 0;
    double work_query = 0;
    dsyevd_(&jobz, &uplo, &n, work_a.data(), &n, out.values.data(), &work_query, &lwork,
            &iwork_query, &liwork, &info);
    lwork = static_cast<int>(work_query);
    liwork = iwork_query;
    std::vector<double> work(static_cast<std::size_t>(std::max(1, lwork)));
    std::vector<int> iwork(static_cast<std::size_t>(std::max(1, liwork)));
    dsyevd_(&jobz, &uplo, &n, work_a.data(), &n, out.values.data(), work.data(), &lwork,
            iwork.data(), &liwork, &info);
    if (info != 0)
      throw std::runtime_error("symmetric_eigen: LAPACK dsyevd returned info = " +
                               std::to_string(info));
    if (with_vectors)
      out.vectors = std::move(work_a);
#else
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(
      a, with_vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
    if (es.info() != Eigen::Success)
      throw std::runtime_error("symmetric_eigen: Eigen's solver did not converge");
    out.values = es.eigenvalues();
    if (with_vectors)
      out.vectors = es.eigenvectors();
#endif
    return out;
  }
} // namespace rfm
