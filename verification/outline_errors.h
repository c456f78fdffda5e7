// Error measures of a field solved on a section given by its outline, shared by the
// verification drivers: the max over points and stress components of |s_h - s|, relative
// to max |s|, and the observed order of two errors a refinement apart.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>

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
} // namespace verification
