#include "rfm/spaces/section_basis.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rfm
{
  SectionPolynomialBasis::SectionPolynomialBasis(const int degree_r, const int degree_z,
                                                 const double r_min, const double r_max,
                                                 const double z_min, const double z_max,
                                                 const Eigen::Ref<const Eigen::VectorXd> &r,
                                                 const Eigen::Ref<const Eigen::VectorXd> &z,
                                                 const Eigen::Ref<const Eigen::VectorXd> &w,
                                                 const bool even_in_r)
    : degree_r_(degree_r)
    , degree_z_(degree_z)
    , r_mid_(0.5 * (r_min + r_max))
    , r_scale_(2.0 / (r_max - r_min))
    , z_mid_(0.5 * (z_min + z_max))
    , z_scale_(2.0 / (z_max - z_min))
    , even_r_(even_in_r)
    , r_max_(r_max)
  {
    const Eigen::Index n = r.size(), n_f = n_basis_functions();
    if (degree_r < 0 || degree_z < 0 || !(r_max > r_min) || !(z_max > z_min) || z.size() != n ||
        w.size() != n || n < n_f || (even_in_r && r_min != 0.0))
      throw std::invalid_argument("SectionPolynomialBasis: bad degrees, box or sample points");
    const Eigen::ArrayXd xi = even_r_ ? Eigen::ArrayXd(2.0 * (r.array() / r_max_).square() - 1.0)
                                      : Eigen::ArrayXd((r.array() - r_mid_) * r_scale_),
                         eta = (z.array() - z_mid_) * z_scale_;
    // Weighted values sqrt(w) q_k at the samples: the Gram-Schmidt inner products are dot
    // products of these columns.
    Eigen::MatrixXd qw(n, n_f);
    const Eigen::ArrayXd sw = w.array().max(0.0).sqrt();
    q0_ = 1.0 / std::sqrt(w.sum());
    qw.col(0) = q0_ * sw.matrix();
    h_.setZero(n_f, n_f);
    h_(0, 0) = 1.0;
    Eigen::VectorXd v(n), c;
    for (Eigen::Index k = 1; k < n_f; ++k)
      {
        const bool along_r = k <= degree_r_; // j = 0
        const Eigen::Index parent = along_r ? k - 1 : k - (degree_r_ + 1);
        v = ((along_r ? xi : eta) * qw.col(parent).array()).matrix();
        const double norm0 = v.norm();
        // Classical Gram-Schmidt, twice (one pass loses orthogonality when v is nearly in
        // the span already).
        for (int pass = 0; pass < 2; ++pass)
          {
            c.noalias() = qw.leftCols(k).transpose() * v;
            v.noalias() -= qw.leftCols(k) * c;
            h_.col(k).head(k) += c;
          }
        const double hkk = v.norm();
        if (!(hkk > 1e-12 * norm0))
          throw std::runtime_error(
            "SectionPolynomialBasis: function " + std::to_string(k) +
            " is numerically dependent on the ones before it at the sample points (too few "
            "points for degree " + std::to_string(degree_r) + " x " + std::to_string(degree_z) + ")");
        h_(k, k) = hkk;
        qw.col(k) = v / hkk;
      }
    // Self-check: the recurrence evaluated in double at the samples themselves must give
    // the orthonormal columns. Its rounding errors grow with p where the section fills its
    // box only in part (thick sphere, max |G - I|: 5.6e-10 at p = 12, 2.3e-7 at 16, 6.4e-6
    // at 18, 1.8e-4 at 20); above extended_precision_threshold the evaluation runs in
    // double-double (evaluate_double_double, section_basis_dd.cc).
    {
      const Eigen::MatrixXd val = evaluate(r, z, false, Precision::double_precision).value;
      const Eigen::MatrixXd g = val.transpose() * (w.array().max(0.0).matrix().asDiagonal() * val);
      orthonormality_error_ = (g - Eigen::MatrixXd::Identity(n_f, n_f)).cwiseAbs().maxCoeff();
      extended_ = orthonormality_error_ > extended_precision_threshold;
    }
  }

  BasisValues SectionPolynomialBasis::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                               const Eigen::Ref<const Eigen::VectorXd> &z,
                                               const bool derivatives,
                                               const Precision precision) const
  {
    // Chunks of points: a chunk's N columns of one quantity (128 x 441 doubles at p = 20:
    // 0.45 MB) stay in L2 while the recurrence runs over them (64 in double-double: two
    // planes per quantity).
    if (precision == Precision::double_double || (precision == Precision::automatic && extended_))
      return evaluate_double_double(r, z, derivatives, 64);
    if (precision == Precision::long_double)
      return evaluate_in<long double>(r, z, derivatives, 64);
    return evaluate_in<double>(r, z, derivatives, 128);
  }

  // The recurrence in arithmetic T (double, or long double: 64-bit significand, so the
  // rounding noise that the recurrence amplifies is 2^-11 of the double one), chunk points
  // at a time, values and (with derivatives) (x q)' = x' q + x q'.
  //
  // Column k solves q_k h_kk + sum_{j<k} h_jk q_j = x q_parent(k). The first degree_r + 1
  // columns (j = 0) go one at a time (parent k - 1). Beyond them the parent is
  // k - (degree_r + 1), so a block of degree_r + 1 consecutive columns has every parent
  // before the block: the block's right-hand sides x q_parent less the known columns' share
  // (one matrix product) and then a small triangular solve with the block's part of h. The
  // same recurrence as one column at a time, with the sums in another order; the matrix
  // products run at the GEMM rate where the one-column form ran at the GEMV rate (the basis
  // evaluation's share of the sharp flat punch's profile at p = 20 fell from 27 % to 6 %).
  // Only the block's two predecessors enter: eta q_j lies in the blocks up to j's plus one,
  // and q_parent (one block below k's) is orthogonal to them, so h_jk vanishes for j more
  // than two blocks before k (measured: at most 3e-16 of the largest h at p = 8-18, the
  // Gram-Schmidt's rounding), and the products run on that band.
  Eigen::MatrixXd SectionPolynomialBasis::coefficients_of(const SectionPolynomialBasis &sub,
                                                          const Eigen::Ref<const Eigen::VectorXd> &r,
                                                          const Eigen::Ref<const Eigen::VectorXd> &z,
                                                          const Eigen::Ref<const Eigen::VectorXd> &w) const
  {
    if (sub.degree_r_ > degree_r_ || sub.degree_z_ > degree_z_ || sub.even_r_ != even_r_)
      throw std::invalid_argument("SectionPolynomialBasis::coefficients_of: the sub-basis has a "
                                  "higher degree or the other parity");
    const Eigen::VectorXd sw = w.cwiseSqrt();
    const Eigen::MatrixXd a = sw.asDiagonal() * evaluate(r, z, false).value;
    const Eigen::MatrixXd b = sw.asDiagonal() * sub.evaluate(r, z, false).value;
    Eigen::MatrixXd c = a.householderQr().solve(b);
    const double residual = (a * c - b).norm() / b.norm();
    if (!(residual <= max_inclusion_residual))
      throw std::runtime_error("the lowered basis (degrees " + std::to_string(sub.degree_r_) + ", " +
                               std::to_string(sub.degree_z_) + ") is not inside the full one (" +
                               std::to_string(degree_r_) + ", " + std::to_string(degree_z_) +
                               ") at the samples: weighted residual " + std::to_string(residual));
    return c;
  }

  template <typename T>
  BasisValues SectionPolynomialBasis::evaluate_in(const Eigen::Ref<const Eigen::VectorXd> &r,
                                                  const Eigen::Ref<const Eigen::VectorXd> &z,
                                                  const bool derivatives,
                                                  const Eigen::Index chunk) const
  {
    using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
    using Array = Eigen::Array<T, Eigen::Dynamic, 1>;
    const Eigen::Index n = r.size(), n_f = n_basis_functions(), row = degree_r_ + 1;
    const Matrix h = h_.cast<T>();
    BasisValues b;
    b.value.resize(n, n_f);
    if (derivatives)
      b.d_r.resize(n, n_f), b.d_z.resize(n, n_f);
    Matrix q(chunk, n_f), q_r, q_z, rhs(chunk, row);
    if (derivatives)
      q_r.resize(chunk, n_f), q_z.resize(chunk, n_f);
    for (Eigen::Index start = 0; start < n; start += chunk)
      {
        const Eigen::Index m = std::min(chunk, n - start);
        // xi and its derivative d xi / dr.
        const Array rs = r.segment(start, m).cast<T>().array();
        const Array xi = even_r_ ? Array(T(2) * (rs / T(r_max_)).square() - T(1))
                                 : Array((rs - T(r_mid_)) * T(r_scale_)),
                    xi_r = even_r_ ? Array(T(4) / (T(r_max_) * T(r_max_)) * rs)
                                   : Array(Array::Constant(m, T(r_scale_))),
                    eta = (z.segment(start, m).cast<T>().array() - T(z_mid_)) * T(z_scale_);
        auto v = q.topRows(m);
        v.col(0).setConstant(T(q0_));
        if (derivatives)
          q_r.topRows(m).col(0).setZero(), q_z.topRows(m).col(0).setZero();
        // j = 0: one column at a time.
        for (Eigen::Index k = 1; k < std::min(row, n_f); ++k)
          {
            const auto hk = h.col(k).head(k);
            const T inv = T(1) / h(k, k);
            if (derivatives)
              {
                auto vr = q_r.topRows(m), vz = q_z.topRows(m);
                vr.col(k) = (xi * vr.col(k - 1).array() + xi_r * v.col(k - 1).array()).matrix();
                vz.col(k) = (xi * vz.col(k - 1).array()).matrix();
                vr.col(k) = (vr.col(k) - vr.leftCols(k) * hk) * inv;
                vz.col(k) = (vz.col(k) - vz.leftCols(k) * hk) * inv;
              }
            v.col(k) = ((xi * v.col(k - 1).array()).matrix() - v.leftCols(k) * hk) * inv;
          }
        // j >= 1: a block of columns k0 .. k0 + w - 1 at a time (parents k - row < k0).
        for (Eigen::Index k0 = row; k0 < n_f; k0 += row)
          {
            const Eigen::Index w = std::min(row, n_f - k0);
            const Eigen::Index j0 = std::max<Eigen::Index>(0, k0 - 2 * row);
            const auto h_known = h.block(j0, k0, k0 - j0, w);
            const auto h_block = h.block(k0, k0, w, w).template triangularView<Eigen::Upper>();
            auto block = [&](auto &&values, auto &&rhs_of_column) {
              auto x = rhs.topLeftCorner(m, w);
              for (Eigen::Index i = 0; i < w; ++i)
                x.col(i) = rhs_of_column(k0 + i - row);
              x.noalias() -= values.middleCols(j0, k0 - j0) * h_known;
              h_block.template solveInPlace<Eigen::OnTheRight>(x);
              values.middleCols(k0, w) = x;
            };
            if (derivatives)
              {
                auto vr = q_r.topRows(m), vz = q_z.topRows(m);
                block(vr, [&](Eigen::Index parent) {
                  return (eta * vr.col(parent).array()).matrix();
                });
                block(vz, [&](Eigen::Index parent) {
                  return Eigen::Matrix<T, Eigen::Dynamic, 1>(
                    (eta * vz.col(parent).array()).matrix() + T(z_scale_) * v.col(parent));
                });
              }
            block(v, [&](Eigen::Index parent) { return (eta * v.col(parent).array()).matrix(); });
          }
        b.value.middleRows(start, m) = v.template cast<double>();
        if (derivatives)
          {
            b.d_r.middleRows(start, m) = q_r.topRows(m).template cast<double>();
            b.d_z.middleRows(start, m) = q_z.topRows(m).template cast<double>();
          }
      }
    return b;
  }
} // namespace rfm
