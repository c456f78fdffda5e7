// Sneddon's axisymmetric punch on a half-space for any profile (half_space.h).
#include "rfm/contact/half_space.h"

#include "rfm/quadrature/quadrature.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rfm::half_space
{
  namespace
  {
    const GaussRule1D &rule()
    {
      static const GaussRule1D r = gauss_legendre(32);
      return r;
    }

    /// [lo, hi] cut at the kinks strictly inside it.
    std::vector<double> pieces(const axisym::DieProfile &g0, const double lo, const double hi)
    {
      std::vector<double> breaks{lo};
      for (const double k : g0.kinks())
        if (k > lo && k < hi)
          breaks.push_back(k);
      breaks.push_back(hi);
      return breaks;
    }

    /// int_0^(pi/2) f(t sin phi) dphi, split where t sin phi crosses a kink (f jumps or kinks
    /// there; smooth between).
    template <typename F>
    double over_phi(const axisym::DieProfile &g0, const double t, const F &f)
    {
      std::vector<double> phi{0.0};
      for (const double k : g0.kinks())
        if (k < t)
          phi.push_back(std::asin(k / t));
      phi.push_back(0.5 * M_PI);
      double sum = 0.0;
      for (std::size_t j = 0; j + 1 < phi.size(); ++j)
        for (Eigen::Index i = 0; i < rule().nodes.size(); ++i)
          {
            const double p = phi[j] + 0.5 * (rule().nodes[i] + 1.0) * (phi[j + 1] - phi[j]);
            sum += 0.5 * (phi[j + 1] - phi[j]) * rule().weights[i] * f(t * std::sin(p));
          }
      return sum;
    }

    /// int_lo^hi f(t) dt by pieces split at the kinks, t = a + (b - a) u^2 on each piece
    /// [a, b] (psi and psi' have a root singularity at a kink's lower end).
    template <typename F>
    double over_t(const axisym::DieProfile &g0, const double lo, const double hi, const F &f)
    {
      const std::vector<double> b = pieces(g0, lo, hi);
      double sum = 0.0;
      for (std::size_t j = 0; j + 1 < b.size(); ++j)
        for (Eigen::Index i = 0; i < rule().nodes.size(); ++i)
          {
            const double u = 0.5 * (rule().nodes[i] + 1.0);
            sum += 0.5 * rule().weights[i] * 2.0 * u * (b[j + 1] - b[j]) * f(b[j] + (b[j + 1] - b[j]) * u * u);
          }
      return sum;
    }
  } // namespace

  double psi(const axisym::DieProfile &g0, const double t)
  {
    return t * over_phi(g0, t, [&](const double v) { return g0.slope(v); });
  }

  double psi_slope(const axisym::DieProfile &g0, const double t)
  {
    return over_phi(g0, t, [&](const double v) { return g0.slope(v) + v * g0.curvature(v); });
  }

  double indentation(const axisym::DieProfile &g0, const double a) { return psi(g0, a); }

  double force(const axisym::DieProfile &g0, const double a, const double e_star)
  {
    const double psi_a = psi(g0, a);
    return 2.0 * e_star * over_t(g0, 0.0, a, [&](const double t) { return psi_a - psi(g0, t); });
  }

  std::optional<double> contact_radius(const axisym::DieCondition &die, const double e_star,
                                       const double limit)
  {
    const axisym::DieProfile &g0 = die.profile;
    if (g0.sharp_edge() || !(limit > 0.0) || die.indentation.has_value() == die.force.has_value())
      return std::nullopt;
    // delta(a) and P(a) increase with a (g0 convex): bisection on (0, limit].
    auto value = [&](const double a) { return die.indentation ? indentation(g0, a) : force(g0, a, e_star); };
    const double target = die.indentation ? *die.indentation : *die.force;
    if (!(value(limit) > target))
      return std::nullopt;
    double lo = 0.0, hi = limit;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (value(mid) < target ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  double pressure_shape(const axisym::DieProfile &g0, const double a, const double x)
  {
    if (!(a > 0.0) || !(x >= 0.0 && x <= 1.0))
      throw std::invalid_argument("half_space::pressure_shape: needs a > 0 and 0 <= x <= 1");
    // With w = sqrt(t^2 - r^2), dt / sqrt(t^2 - r^2) = dw / t: int psi'(t) / t dw over the
    // pieces of [r, a] in t, w = w_lo + (w_hi - w_lo) u^2 on each (psi' has a root
    // singularity at a kink); divided by sqrt(1 - x^2) = w(a) / a. Each piece's integral is
    // kept as (w_hi - w_lo) times its mean so that x = 1 (one piece of zero length) gives
    // psi'(a).
    // (w as sqrt((t - r)(t + r)): zero at t = r to the bit, where t^2 - r^2 contracted to a
    // fused multiply-add is the rounding error of r^2, and its root 1e-8 r.)
    const double r = x * a;
    auto w_of = [r](const double t) { return std::sqrt(std::max(0.0, (t - r) * (t + r))); };
    const double w_a = w_of(a);
    const std::vector<double> t = pieces(g0, r, a);
    double sum = 0.0;
    for (std::size_t j = 0; j + 1 < t.size(); ++j)
      {
        const double w0 = w_of(t[j]), w1 = w_of(t[j + 1]);
        double mean = 0.0;
        for (Eigen::Index i = 0; i < rule().nodes.size(); ++i)
          {
            const double u = 0.5 * (rule().nodes[i] + 1.0), w = w0 + (w1 - w0) * u * u;
            const double tt = std::sqrt(r * r + w * w);
            mean += 0.5 * rule().weights[i] * 2.0 * u * psi_slope(g0, tt) / tt;
          }
        sum += (w_a > 0.0 ? (w1 - w0) / w_a : 1.0) * a * mean;
      }
    return sum;
  }

  double contact_modulus(const axisym::Problem &problem)
  {
    const double nu = problem.material.poisson_ratio;
    return problem.material.youngs_modulus / (1.0 - nu * nu);
  }
} // namespace rfm::half_space
