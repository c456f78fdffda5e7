// Error measures of a field solved on a section given by its outline, shared by the
// verification drivers: the max over points and stress components of |s_h - s|, relative
// to max |s|, and the observed order of two errors a refinement apart; the samples of a
// problem, their scale, and their differences on the axis and off it.
#pragma once

#include "problem/problem.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace verification
{
  /// Model: anything with evaluate(r, z) returning fields with a sigma matrix (n x 4);
  /// Exact: (r, z) -> std::array<double, 4> (rr, zz, tt, rz) [Pa].
  template <typename Model, typename Exact>
  double max_stress_error(const Model &m, const Eigen::VectorXd &r, const Eigen::VectorXd &z,
                          const Exact &exact)
  {
    const auto f = m.evaluate(r, z);
    double err = 0, max = 0;
    for (Eigen::Index k = 0; k < r.size(); ++k)
      {
        const std::array<double, 4> s = exact(r[k], z[k]);
        for (int c = 0; c < 4; ++c)
          err = std::max(err, std::abs(f.sigma(k, c) - s[c])), max = std::max(max, std::abs(s[c]));
      }
    return err / max;
  }

  /// log2(e_coarse / e_fine): the order of a method under one halving of h.
  inline double observed_order(double e_coarse, double e_fine) { return std::log2(e_coarse / e_fine); }

  /// The problem's sample points, (r, z).
  inline std::array<Eigen::VectorXd, 2> sample_points(const axisym::Problem &problem)
  {
    const Eigen::Index n = static_cast<Eigen::Index>(problem.samples.size());
    std::array<Eigen::VectorXd, 2> x{Eigen::VectorXd(n), Eigen::VectorXd(n)};
    for (Eigen::Index k = 0; k < n; ++k)
      x[0][k] = problem.samples[static_cast<std::size_t>(k)][0], x[1][k] = problem.samples[static_cast<std::size_t>(k)][1];
    return x;
  }

  /// The samples' scale: the largest stress component at any sample.
  inline double largest_component(const std::vector<std::array<double, 4>> &samples)
  {
    double scale = 0.0;
    for (const auto &s : samples)
      for (const double x : s)
        scale = std::max(scale, std::abs(x));
    return scale;
  }

  /// The largest |sigma(k, c) - reference[k][c]| over the stress components, at the samples
  /// on the axis (r[k] = 0) and at the others apart (issue 24 item 5): {on the axis, off it}.
  template <typename Sigma>
  std::array<double, 2> axis_and_off_axis_differences(const Eigen::VectorXd &r,
                                                      const std::vector<std::array<double, 4>> &reference,
                                                      const Sigma &sigma)
  {
    std::array<double, 2> e{0.0, 0.0};
    for (Eigen::Index k = 0; k < r.size(); ++k)
      for (int c = 0; c < 4; ++c)
        {
          double &x = e[r[k] == 0.0 ? 0 : 1];
          x = std::max(x, std::abs(sigma(k, c) - reference[static_cast<std::size_t>(k)][c]));
        }
    return e;
  }
} // namespace verification
