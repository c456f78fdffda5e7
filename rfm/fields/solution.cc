#include "rfm/fields/solution.h"

#include <cmath>

namespace rfm
{
  void add_enrichment_fields(const EdgeColumns &e, const Eigen::Ref<const Eigen::VectorXd> &q_s,
                             const Eigen::Ref<const Eigen::VectorXd> &q_u, FieldValues &f)
  {
    for (int k = 0; k < n_stress_components; ++k)
      {
        f.sigma.col(k) += e.stress[k] * q_s;
        f.strain.col(k) += e.strain[k] * q_u;
      }
    for (int m = 0; m < 2; ++m)
      f.u.col(m) += e.u[m] * q_u;
  }

  double Functionals::indicator() const
  {
    return std::abs(lagrange - castigliano) / std::abs(reissner);
  }

  double Functionals::error_measure() const
  {
    // E within 0.1 % of the indicator (no fixed part: equal to the rules' rounding) leaves
    // the indicator, so that such problems read exactly what they read before.
    const double e = constitutive_error / std::abs(reissner), i = indicator();
    return std::isfinite(e) && e > 1.001 * i ? e : i;
  }
} // namespace rfm
