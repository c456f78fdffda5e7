// The FEM reference's fields at given points, as an rfm::FieldEvaluator: for integrals the
// RFM library evaluates on any field (the interaction integral of rfm/contact/contact.h), with the
// FEM solved once with the integral's points as its samples. Header only (verification).
#pragma once

#include "fem_reference/axisymmetric_fem.h"
#include "rfm/contact/contact.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace verification
{
  /// Appends the interaction rule's points, then the edge point, to `samples` (the order
  /// sampled_interaction_field expects).
  inline void add_interaction_samples(std::vector<std::array<double, 2>> &samples,
                                      const rfm::Quadrature2D &rule, double r_edge, double z_edge)
  {
    for (Eigen::Index k = 0; k < rule.r.size(); ++k)
      samples.push_back({rule.r[k], rule.z[k]});
    samples.push_back({r_edge, z_edge});
  }

  /// The FEM's samples as the field of the interaction integral, which asks for the rule's
  /// points (the samples from `first`, in order) and then for the edge point alone (the
  /// last sample); any other request is a logic error.
  /// `vertex`: the edge point's sample where it is not the last (several vertices' rules).
  inline rfm::FieldEvaluator sampled_interaction_field(const fem::FemResult &fr, std::size_t first = 0,
                                                       std::optional<std::size_t> vertex = std::nullopt)
  {
    return [&fr, first, vertex](const Eigen::Ref<const Eigen::VectorXd> &r,
                                const Eigen::Ref<const Eigen::VectorXd> &z) {
      const bool edge = r.size() == 1;
      const std::size_t from = edge ? vertex.value_or(fr.samples.size() - 1) : first;
      rfm::FieldValues f;
      f.u.resize(r.size(), 2), f.sigma.resize(r.size(), 4), f.strain.setZero(r.size(), 4);
      for (Eigen::Index k = 0; k < r.size(); ++k)
        {
          const fem::FieldSample &s = fr.samples.at(from + k);
          if (std::abs(s.r - r[k]) > 1e-12 || std::abs(s.z - z[k]) > 1e-12)
            throw std::logic_error("FEM sample order differs from the interaction rule's");
          f.u(k, 0) = s.u_r, f.u(k, 1) = s.u_z;
          for (int m = 0; m < 4; ++m)
            f.sigma(k, m) = s.sigma[m];
        }
      return f;
    };
  }
} // namespace verification
