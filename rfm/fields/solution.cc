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
} // namespace rfm
