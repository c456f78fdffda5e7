// Coordinate functions orthonormal on the meridian section: the polynomials of degree
// <= p_r in r and <= p_z in z (the span of the tensor Legendre basis, basis.h), built by
// Arnoldi's process on sample points of the section (the "Vandermonde with Arnoldi" idea
// of Brubeck, Nakatsukasa and Trefethen, SIAM Review 63, 2021, in two variables).
//
// Why. On a section that fills only part of its bounding box (the thick sphere's quarter
// annulus: 59 %) the tensor Legendre polynomials of the box are exponentially close to
// dependent on the section: the condition number of their r-weighted values there is
// 1.1e9 at p = 12, 1.3e12 at p = 16 and 1.5e15 at p = 20 (measured). Every combination a
// solution needs from the small directions then has Legendre coefficients of that size, and
// the orthonormalization of the system (outline_model.h) has to drop them: the thick
// sphere's max stress error stayed between 2e-5 and 8e-5 of max |sigma| from p = 14 on. No change of basis
// computed from Legendre values can fix that (its matrix has the same condition number).
// The functions here are never expanded in another basis: each is evaluated by the
// recurrence that built it, which multiplies an orthonormal function by a bounded one.
//
//   q_0 = 1 / sqrt(sum_k w_k),
//   h_kk q_k = x_k q_{parent(k)} - sum_{i < k} h_ik q_i,
//
// for the index k = j (p_r + 1) + i: x_k = eta (the box coordinate of z, in [-1, 1]) and
// parent(k) = k - (p_r + 1), the function (i, j - 1), when j > 0; x_k = xi and
// parent(k) = k - 1 on the first row j = 0. The parent's span is the monomials r^a z^b
// with b < j - 1, or b = j - 1 and a <= i; times z that is b < j, or b = j and a <= i:
// exactly the span of the indices up to k. (Multiplying (i - 1, j) by r instead would
// leave the space: r times its r^p z^(j-1) part.) The h are the Gram-Schmidt coefficients
// (two passes) at the sample points, stored; the derivatives follow by differentiating
// the recurrence. So q_0..q_k span the same polynomials as the tensor Legendre functions
// 0..k in the same order, and the q are orthonormal in sum_k w_k f g over the samples.
//
// Precision. Where the section fills its box only in part, the recurrence amplifies its
// own rounding errors (the orthonormal functions of the tensor space grow fast outside the
// section, and so do the errors of a forward recurrence): the evaluated functions carry
// non-polynomial noise, with values and derivatives that no longer match. Measured on the
// thick sphere (r-weighted rms of the noise, relative): 3.6e-10 at p = 12, 2.5e-7 at 16,
// 7.4e-6 at 18, 2.0e-4 at 20; at p = 20 it made the RFM's stress error 1.1e-3 instead of
// 4e-7 and the solution depend on the sample points. The constructor therefore evaluates
// the recurrence in double at its own samples and measures max |G - I| (G the Gram matrix
// there, I up to rounding: the Arnoldi vectors are orthonormal); above
// extended_precision_threshold, evaluate() runs the recurrence in double-double arithmetic
// (about 106 bits: error-free products and sums, section_basis_dd.cc), so that the functions
// are the recurrence's polynomials to double rounding. Long double (64-bit significand, 2^11
// times less noise than double) did this before: the sphere's stress error fell from 1.1e-3
// to 4.2e-7 at p = 20, but its noise was back at p = 22 (2.2e-5) and 24 (9.0e-5), and its
// scalar x87 arithmetic took half of the pressed hub's run at p = 16. Double-double, measured
// on the sphere (max stress error on a 41 x 41 polar grid against Lame, relative; one thread):
// p = 20, 22, 24: 9.9e-8, 2.3e-8, 1.9e-9 (long double 2.4e-7, 2.2e-5, 9.0e-5), rfm_solve
// --degree 20 4.7 s (14.5 s); values and derivatives agree with fourth-order central
// differences to 1.3e-11 at p = 22 (long double 5.4e-3, double 7.8). The evaluation takes
// 3.2-3.5 times double's time at p = 16-24, long double 24-31 times (rfm_benchmark's
// BM_SectionBasis: 63, 171, 461 ms against 19, 48, 146 ms in double and 559, 1519, 3537 ms
// in long double for values and derivatives at 5054, 7406, 10206 points).
//
// Evaluation costs about 3 n N^2 flops for n points (values and both derivatives), in
// chunks of points that stay in cache.
//
// Even in r (a section on the axis, r_min = 0; OutlineModel's axis parity, issue 24 item 5).
// The fields of a smooth axisymmetric solution are even or odd in r across the axis:
// sigma_rr, sigma_zz, sigma_tt, u_z are smooth functions of (r^2, z), u_r and sigma_rz r times
// one. Polynomials in r on [0, R], projected in the r-weighted norms of the functionals, are
// weakest exactly there: a weight that vanishes like r at an end point lets the error at that
// end grow about p times faster than inside (measured on the grooved shaft at z = 0.02:
// 2.9e-3 of max |sigma| at r = 0 against 1.4e-4 at r = 0.002, p = 28). With even_in_r the
// recurrence multiplies by xi = 2 (r / r_max)^2 - 1 instead of the box coordinate of r, so the
// functions are the polynomials of degree <= degree_r in r^2 (up to r^(2 degree_r)) and
// <= degree_z in z, the same count as before, and the weight r dr = d(r^2) / 2 is uniform in
// the variable they are polynomials of. Where the section fills only part of its box the
// recurrence's noise (below) is that of polynomials of degree 2 degree_r: fine on a rectangle
// (max |G - I| 2e-15 at degree 24), too much on the thick sphere's quarter annulus beyond
// degree 16 (2.8e-5 at 16, 3.1e-2 at 20), which is why OutlineModel uses it on rectangles only.
#pragma once

#include "rfm/spaces/basis.h"

#include <Eigen/Core>

namespace rfm
{
  class SectionPolynomialBasis
  {
  public:
    /// Orthonormality error of the double recurrence at the samples above which evaluate()
    /// uses double-double (see the header): 1e-6 relative noise in the functions is far
    /// below the accuracy rfm.tolerance asks by default (1e-8 in the indicator, about 1e-4
    /// in stress); the thick sphere at p = 16 (2.3e-7) gives the same stresses either way.
    static constexpr double extended_precision_threshold = 1e-6;

    /// Orthonormal in sum_k w_k f(x_k) g(x_k) over the sample points (r, z, w), which must
    /// determine the polynomials (many more points than functions, spread over the
    /// section; w > 0 except where r = 0). [r_min, r_max] x [z_min, z_max]: the box whose
    /// coordinates xi, eta enter the recurrence (the samples' own box is a good choice).
    /// Throws std::runtime_error if a function is numerically dependent on the ones
    /// before it at the samples (h_kk below 1e-12 of the norm of x_k q_parent).
    /// `even_in_r` (requires r_min = 0): polynomials of degree <= degree_r in r^2 (see the
    /// header); the samples must then determine polynomials of degree 2 degree_r in r.
    SectionPolynomialBasis(int degree_r, int degree_z, double r_min, double r_max, double z_min,
                           double z_max, const Eigen::Ref<const Eigen::VectorXd> &r,
                           const Eigen::Ref<const Eigen::VectorXd> &z,
                           const Eigen::Ref<const Eigen::VectorXd> &w, bool even_in_r = false);

    /// The degree in r, or in r^2 when even_in_r().
    int degree_r() const { return degree_r_; }
    bool even_in_r() const { return even_r_; }
    int degree_z() const { return degree_z_; }
    Eigen::Index n_basis_functions() const
    {
      return static_cast<Eigen::Index>(degree_r_ + 1) * (degree_z_ + 1);
    }

    /// Values and first derivatives at n points (n x N each, as TensorLegendreBasis);
    /// values only (d_r, d_z empty, a third of the work) with derivatives = false.
    /// `precision`: automatic (double-double when extended_precision()), or forced (long
    /// double: the former extended precision, kept for comparison).
    enum class Precision { automatic, double_precision, long_double, double_double };
    BasisValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z, bool derivatives = true,
                         Precision precision = Precision::automatic) const;

    /// The coefficients C (N x N_sub) of the functions of `sub` in this basis,
    /// sub_j = sum_i C_ij q_i, for a basis `sub` of lower degrees (its polynomials inside
    /// this one's): the least-squares fit at points (r, z) with weights w >= 0 (the samples).
    /// Not C = Q^T W S: that formula takes the q as exactly orthonormal at the points, and
    /// the recurrence's coefficients, computed in double, miss that by orthonormality_error()
    /// (3.6e-3 at p = 20 on issue 24's hub section; an extended-precision evaluation does not
    /// change the coefficients), which put components of degree above sub's into the rebuilt
    /// functions (1.3e-2 off there). Throws std::runtime_error when the weighted residual of
    /// the fit exceeds max_inclusion_residual of sub's norm there (sub is not inside this
    /// space: a residual of order 1).
    Eigen::MatrixXd coefficients_of(const SectionPolynomialBasis &sub,
                                    const Eigen::Ref<const Eigen::VectorXd> &r,
                                    const Eigen::Ref<const Eigen::VectorXd> &z,
                                    const Eigen::Ref<const Eigen::VectorXd> &w) const;
    /// The self-check of coefficients_of. The fit's residual is the evaluation's own noise:
    /// measured on the hub, 6e-16 for (p, p - 1) (a prefix of the recurrence); for (p - 1, p)
    /// 2.6e-7 at p = 16 (the lowered basis below the threshold, in double) and 9e-16 at
    /// p = 20 (both in double-double; 2.5e-7 when the extended precision was long double).
    /// 1e-4 leaves room for the double noise and still catches a space that is not inside.
    static constexpr double max_inclusion_residual = 1e-4;

    /// max |G - I| of the double recurrence at the samples (G: their Gram matrix).
    double orthonormality_error() const { return orthonormality_error_; }
    /// Whether evaluate() runs the recurrence in double-double.
    bool extended_precision() const { return extended_; }

  private:
    /// The recurrence in double-double arithmetic (about 106 bits), `chunk` points at a time.
    BasisValues evaluate_double_double(const Eigen::Ref<const Eigen::VectorXd> &r,
                                       const Eigen::Ref<const Eigen::VectorXd> &z, bool derivatives,
                                       Eigen::Index chunk) const;
    template <typename T>
    BasisValues evaluate_in(const Eigen::Ref<const Eigen::VectorXd> &r,
                            const Eigen::Ref<const Eigen::VectorXd> &z, bool derivatives,
                            Eigen::Index chunk) const;
    int degree_r_, degree_z_;
    double r_mid_, r_scale_, z_mid_, z_scale_; ///< xi = (r - r_mid) r_scale, eta likewise
    bool even_r_ = false; ///< xi = 2 (r / r_max)^2 - 1 instead
    double r_max_;
    double q0_;                                ///< the constant q_0
    /// Column k: h_ik for i < k above the diagonal, h_kk on it.
    Eigen::MatrixXd h_;
    double orthonormality_error_ = 0; ///< max |G - I| of the double recurrence at the samples
    bool extended_ = false;           ///< evaluate in double-double (evaluate_double_double)
  };
} // namespace rfm
