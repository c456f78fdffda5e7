// Local resolution near a small die zone: coordinate functions supported in nested boxes
// around the die's centre, a column provider beside the global polynomials (issue 23 item 3;
// the "local polynomial columns times a cutoff" of DESIGN.md 4.5).
//
// Why. The global coordinate functions are polynomials of degree <= p on the section's box.
// A contact zone much smaller than the section (a Hertz contact of radius a on an end face 23 a
// wide, a flat punch on 1/20 of a face) puts a field that varies on the scale a, and decays like
// a point load's (stress ~ 1 / rho^2) beyond it, into a space that resolves the scale D / p at
// best: the rounded flat punch's force was 73 % off at p = 8. The remedy of hp finite elements
// is geometric refinement toward the concentration; here it takes the form of L nested boxes
// of half sizes h_l = h_0 2^l about the die's centre, each carrying the tensor Legendre
// polynomials of degree <= d of its own scaled coordinates times a cutoff that vanishes on the
// box's sides inside the body:
//
//   phi_{l,ij}(r, z) = c_l(x, y) P_i(xi(x)) P_j(2 y - 1),   x = (X - X_c) . t / h_l,
//                                                             y = (X - X_c) . n / h_l,
//
// t along the part, n into the body, the box 0 <= y <= 1 and x_lo <= x <= 1 (x_lo = 0 when the
// centre is at the part's end on the axis or a symmetry edge, where the section ends: no cutoff
// there; -1 otherwise), xi mapping [x_lo, 1] onto [-1, 1], and c = (1 - y)(1 - x)(1 + x if
// x_lo = -1): continuous and zero outside the box, so the functions are in H^1 (the
// displacement space) and in L^2 (the stress space, which needs no continuity). The outline
// structures multiply them by the same omega functions as the polynomials (boundary-exact for
// any coefficients) and they enter every block as N more columns per component. On each cell
// of a quadrature rule whose breaks include the boxes' sides (local_breaks) they are
// polynomials, so the rule that integrates the polynomials' products integrates theirs when
// d + 2 <= p.
//
// The span of the nested boxes is nearly dependent where boxes overlap (a polynomial on the
// small box is close to one on the large box times a different cutoff): the model's
// orthonormalizing transform (outline_model.h) drops the dependent directions.
#pragma once

#include "rfm/spaces/basis.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace rfm
{
  /// One box: the centre on the part (r, z) [m], the unit tangent t along the part, the unit
  /// normal n into the body, the half size h [m] and whether the box is one-sided (x >= 0:
  /// the centre at the part's end where the section ends).
  struct LocalPatch
  {
    double r = 0.0, z = 0.0;
    std::array<double, 2> t{{1.0, 0.0}}, n{{0.0, 1.0}};
    double half_size = 0.0;
    bool one_sided = false;
  };

  class LocalBasis
  {
  public:
    LocalBasis() = default;
    /// Precondition: degree >= 0, every half_size > 0, t and n orthonormal.
    LocalBasis(std::vector<LocalPatch> patches, int degree);

    bool empty() const { return patches_.empty(); }
    /// The degree across the part (along n), and along it in a one-sided box.
    int degree() const { return degree_; }
    const std::vector<LocalPatch> &patches() const { return patches_; }
    /// The degree along t in a box whose functions have degree d along n: d in a one-sided
    /// box, 2 d + 1 in a two-sided one. A two-sided box spans twice the length along t, and a
    /// field about a zone with two free ends is neither even nor odd there: with 2 d + 1 its
    /// even and its odd parts each get d + 1 functions, the resolution of a one-sided box of
    /// degree d (measured on the ring die at the FEM's zone: see the closing note of issue 23,
    /// session 5).
    static int t_degree(const LocalPatch &p, const int d) { return p.one_sided ? d : 2 * d + 1; }
    /// Columns of one box with degree d along n: (t_degree + 1)(d + 1).
    static Eigen::Index n_functions(const LocalPatch &p, const int d)
    {
      return static_cast<Eigen::Index>(t_degree(p, d) + 1) * (d + 1);
    }
    /// All boxes' columns with degree d along n.
    Eigen::Index n_functions(int d) const;
    Eigen::Index n_basis_functions() const { return n_functions(degree_); }
    /// Values and first derivatives at points (n_points x n_basis_functions(); zero outside
    /// each box). Ordering: patch by patch, index j (t_degree + 1) + i within a patch (i along
    /// t, j along n).
    BasisValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;

    /// The stress-only columns (outline_model.h): per box, the tensor Legendre polynomials of
    /// degree <= `degree` in the box's coordinates on the box and zero outside, without the
    /// cutoff (stresses need no continuity; the strains of the columns above jump across the
    /// boxes' sides, where every column of evaluate() vanishes). `degree` along n and
    /// t_degree(box, degree) along t. Values only, n_points x n_functions(degree), the same
    /// ordering as evaluate(). A point on a side shared by two cells belongs to the box when
    /// 0 <= y < 1 and x_lo <= x < 1.
    Eigen::MatrixXd piecewise_values(const Eigen::Ref<const Eigen::VectorXd> &r,
                                     const Eigen::Ref<const Eigen::VectorXd> &z, int degree) const;

    /// The r and the z coordinates of the boxes' corners (for the cells of a tensor rule: the
    /// functions are polynomials on every cell between them).
    std::array<std::vector<double>, 2> breaks() const;

  private:
    std::vector<LocalPatch> patches_;
    int degree_ = 0;
  };
} // namespace rfm
