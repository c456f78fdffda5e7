// SectionPolynomialBasis::evaluate_double_double (section_basis.h): the recurrence in
// double-double arithmetic. In a file of its own because its error-free transformations need
// every product and sum rounded as written: compiled with -ffp-contract=off (rfm/CMakeLists.txt),
// as GCC would otherwise fuse a product into the next sum and lose the error terms.
#include "rfm/spaces/section_basis.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rfm
{
  namespace
  {
    // Error-free transformations of double-double arithmetic (a value is hi + lo with
    // |lo| <= ulp(hi) / 2): a + b = s + e exactly (Knuth's TwoSum, no condition on the sizes),
    // and a b = p + e exactly (with a fused multiply-add). Written on plain doubles so that
    // the loops over points below vectorize (AVX2 + FMA, 4 points per instruction).
    inline void two_sum(const double a, const double b, double &s, double &e)
    {
      s = a + b;
      const double bb = s - a;
      e = (a - (s - bb)) + (b - bb);
    }

    // One column of the recurrence in double-double, for the points [0, m) of a chunk:
    //   out = (x parent + y other - sum_{j in [j0, k)} h_j col_j) / h_kk,
    // the columns stored as hi / lo planes (column j at hi + j * ld). The sum runs as Ogita,
    // Rump and Oishi's Dot2 (the running sum s and its exact errors' sum c), which is as
    // accurate as the sum in twice the working precision; then one division in double-double.
    // y == nullptr: no second term.
    void dd_column(const Eigen::Index m, const double *x, const double *parent_hi,
                   const double *parent_lo, const double *y, const double *other_hi,
                   const double *other_lo, const double *h, const Eigen::Index j0,
                   const Eigen::Index k, const double h_kk, const double *hi, const double *lo,
                   const Eigen::Index ld, double *out_hi, double *out_lo, double *s, double *c)
    {
      for (Eigen::Index i = 0; i < m; ++i)
        {
          s[i] = x[i] * parent_hi[i];
          c[i] = std::fma(x[i], parent_lo[i], std::fma(x[i], parent_hi[i], -s[i]));
        }
      if (y)
        for (Eigen::Index i = 0; i < m; ++i)
          {
            const double p = y[i] * other_hi[i];
            const double e = std::fma(y[i], other_lo[i], std::fma(y[i], other_hi[i], -p));
            double t, f;
            two_sum(s[i], p, t, f);
            s[i] = t, c[i] += f + e;
          }
      for (Eigen::Index j = j0; j < k; ++j)
        {
          const double g = -h[j];
          if (g == 0.0)
            continue;
          const double *qh = hi + j * ld, *ql = lo + j * ld;
          for (Eigen::Index i = 0; i < m; ++i)
            {
              const double p = g * qh[i];
              const double e = std::fma(g, ql[i], std::fma(g, qh[i], -p));
              double t, f;
              two_sum(s[i], p, t, f);
              s[i] = t, c[i] += f + e;
            }
        }
      for (Eigen::Index i = 0; i < m; ++i)
        {
          double a_hi, a_lo;
          two_sum(s[i], c[i], a_hi, a_lo);
          // (a_hi + a_lo) / h_kk: q1 = a_hi / h_kk, the remainder a - q1 h_kk exactly to first
          // order, q2 = remainder / h_kk.
          const double q1 = a_hi / h_kk;
          const double p_hi = q1 * h_kk, p_lo = std::fma(q1, h_kk, -p_hi);
          const double q2 = (((a_hi - p_hi) - p_lo) + a_lo) / h_kk;
          two_sum(q1, q2, out_hi[i], out_lo[i]);
        }
    }
  } // namespace

  BasisValues SectionPolynomialBasis::evaluate_double_double(const Eigen::Ref<const Eigen::VectorXd> &r,
                                                             const Eigen::Ref<const Eigen::VectorXd> &z,
                                                             const bool derivatives,
                                                             const Eigen::Index chunk) const
  {
    // The same recurrence as evaluate_in, column by column (the blocks' triangular solves
    // are the columns in order), on the same band of h: column k >= row takes the columns
    // from two blocks before its own. xi, eta and d xi / dr stay in double: their rounding
    // moves the point, which the polynomials follow smoothly (values and derivatives alike);
    // it is the recurrence's cancellations that make non-polynomial noise.
    const Eigen::Index n = r.size(), n_f = n_basis_functions(), row = degree_r_ + 1;
    BasisValues b;
    b.value.resize(n, n_f);
    if (derivatives)
      b.d_r.resize(n, n_f), b.d_z.resize(n, n_f);
    const int n_q = derivatives ? 3 : 1; // values, d/dr, d/dz
    // hi and lo planes of each quantity: chunk x n_f, column-major.
    std::vector<Eigen::MatrixXd> hi(n_q, Eigen::MatrixXd(chunk, n_f)), lo(n_q, Eigen::MatrixXd(chunk, n_f));
    Eigen::VectorXd xi(chunk), xi_r(chunk), eta(chunk), s(chunk), c(chunk);
    for (Eigen::Index start = 0; start < n; start += chunk)
      {
        const Eigen::Index m = std::min(chunk, n - start);
        for (Eigen::Index i = 0; i < m; ++i)
          {
            const double ri = r[start + i];
            xi[i] = even_r_ ? 2.0 * (ri / r_max_) * (ri / r_max_) - 1.0 : (ri - r_mid_) * r_scale_;
            xi_r[i] = even_r_ ? 4.0 / (r_max_ * r_max_) * ri : r_scale_;
            eta[i] = (z[start + i] - z_mid_) * z_scale_;
          }
        const Eigen::VectorXd z_scale = Eigen::VectorXd::Constant(m, z_scale_);
        hi[0].col(0).head(m).setConstant(q0_), lo[0].col(0).head(m).setZero();
        for (int q = 1; q < n_q; ++q)
          hi[q].col(0).head(m).setZero(), lo[q].col(0).head(m).setZero();
        auto at = [chunk](Eigen::MatrixXd &plane, Eigen::Index j) { return plane.data() + j * chunk; };
        for (Eigen::Index k = 1; k < n_f; ++k)
          {
            const bool along_r = k < row;
            const Eigen::Index parent = along_r ? k - 1 : k - row;
            const Eigen::Index j0 = along_r ? 0 : std::max<Eigen::Index>(0, (k / row) * row - 2 * row);
            const double *h = h_.col(k).data(), h_kk = h_(k, k);
            const double *x = along_r ? xi.data() : eta.data();
            // Values first: the derivatives' columns take the value of the parent.
            dd_column(m, x, at(hi[0], parent), at(lo[0], parent), nullptr, nullptr, nullptr, h, j0, k,
                      h_kk, hi[0].data(), lo[0].data(), chunk, at(hi[0], k), at(lo[0], k), s.data(),
                      c.data());
            if (!derivatives)
              continue;
            // (x q)' = x q' + x' q: x' is d xi / dr for d/dr along r, dz eta = z_scale for d/dz
            // along z, and 0 otherwise.
            for (int q = 1; q < 3; ++q)
              {
                const bool with_value = along_r ? q == 1 : q == 2;
                const double *y = with_value ? (q == 1 ? xi_r.data() : z_scale.data()) : nullptr;
                dd_column(m, x, at(hi[q], parent), at(lo[q], parent), y, at(hi[0], parent),
                          at(lo[0], parent), h, j0, k, h_kk, hi[q].data(), lo[q].data(), chunk,
                          at(hi[q], k), at(lo[q], k), s.data(), c.data());
              }
          }
        // hi is the double nearest to hi + lo (two_sum normalizes).
        b.value.middleRows(start, m) = hi[0].topRows(m);
        if (derivatives)
          {
            b.d_r.middleRows(start, m) = hi[1].topRows(m);
            b.d_z.middleRows(start, m) = hi[2].topRows(m);
          }
      }
    return b;
  }
} // namespace rfm
