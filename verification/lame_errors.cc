#include "verification/lame_errors.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace verification
{
  LameCylinder exact_of(const axisym::Problem &p)
  {
    return {p.geometry.inner_radius,   p.geometry.outer_radius,   p.geometry.length,
            p.material.youngs_modulus, p.material.poisson_ratio,  p.loading->inner_pressure,
            p.loading->outer_pressure};
  }

  std::pair<double, double> stress_errors(const rfm::OutlineModel &model,
                                          const LameCylinder &exact)
  {
    const double a = 0.5 * exact.length;
    std::vector<double> rc, zc;
    for (int i = 0; i <= 4; ++i)
      rc.push_back(exact.inner_radius + (exact.outer_radius - exact.inner_radius) * i / 4.0),
        zc.push_back(a * i / 4.0);
    const rfm::Quadrature2D q = rfm::tensor_gauss(rc, zc, 24);
    const rfm::FieldValues f = model.evaluate(q.r, q.z);
    double err2 = 0.0, ref2 = 0.0;
    for (Eigen::Index k = 0; k < q.n_points(); ++k)
      {
        const auto s = exact.stress(q.r[k], q.z[k]);
        const double w = q.weights[k] * q.r[k];
        for (int c = 0; c < 4; ++c)
          {
            const double factor = c == rfm::rz ? 2.0 : 1.0;
            const double d = f.sigma(k, c) - s[c];
            err2 += w * factor * d * d;
            ref2 += w * factor * s[c] * s[c];
          }
      }
    // Max error on a grid including the boundary, relative to the max exact stress.
    const int m = 41;
    Eigen::VectorXd r(m * m), z(m * m);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        r[j * m + i] = exact.inner_radius + (exact.outer_radius - exact.inner_radius) * i / (m - 1.0),
                  z[j * m + i] = a * j / (m - 1.0);
    const rfm::FieldValues g = model.evaluate(r, z);
    double max_err = 0.0, max_ref = 0.0;
    for (int k = 0; k < m * m; ++k)
      {
        const auto s = exact.stress(r[k], z[k]);
        for (int c = 0; c < 4; ++c)
          {
            max_err = std::max(max_err, std::abs(g.sigma(k, c) - s[c]));
            max_ref = std::max(max_ref, std::abs(s[c]));
          }
      }
    return {std::sqrt(err2 / ref2), max_err / max_ref};
  }
} // namespace verification
