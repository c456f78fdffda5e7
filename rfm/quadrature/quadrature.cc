#include "rfm/quadrature/quadrature.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

namespace rfm
{
  namespace
  {
    // P_n(x) and P_n'(x) by the three-term recurrence; n >= 1, |x| < 1.
    std::pair<double, double> legendre_and_derivative(const int n, const double x)
    {
      double p_prev = 1.0, p = x;
      for (int k = 2; k <= n; ++k)
        {
          const double p_next = ((2.0 * k - 1.0) * x * p - (k - 1.0) * p_prev) / k;
          p_prev = p;
          p = p_next;
        }
      // (1 - x^2) P_n' = n (P_{n-1} - x P_n)
      return {p, n * (p_prev - x * p) / (1.0 - x * x)};
    }
  } // namespace

  GaussRule1D polar_radial_rule(const double rho_0, const int n_points, const int n_layers,
                                const std::vector<double> &breaks, const int n_points_beyond)
  {
    if (n_points < 1 || n_layers < 0)
      throw std::invalid_argument("polar_radial_rule: n_points >= 1 and n_layers >= 0");
    std::vector<double> layers{rho_0};
    for (int i = 0; i < n_layers; ++i)
      layers.push_back(layers.back() * 0.2);
    double lowest_break = rho_0; // the pieces above it take n_points_beyond
    for (const double b : breaks)
      if (b > 0.0 && b < rho_0)
        layers.push_back(b), lowest_break = std::min(lowest_break, b);
    layers.push_back(0.0);
    std::sort(layers.begin(), layers.end(), std::greater<double>());
    layers.erase(std::unique(layers.begin(), layers.end(),
                             [rho_0](const double a, const double b) { return std::abs(a - b) <= 1e-9 * rho_0; }),
                 layers.end());
    const int n_beyond = std::max(n_points, n_points_beyond);
    auto count = [&](const double lo) { return lo >= lowest_break * (1.0 - 1e-12) ? n_beyond : n_points; };
    Eigen::Index total = 0;
    for (std::size_t i = 0; i + 1 < layers.size(); ++i)
      total += count(layers[i + 1]);
    const GaussRule1D g = gauss_legendre(n_points), g_beyond = gauss_legendre(n_beyond);
    GaussRule1D out;
    out.nodes.resize(total);
    out.weights.resize(total);
    Eigen::Index at = 0;
    for (std::size_t i = 0; i + 1 < layers.size(); ++i)
      {
        const double hi = layers[i], lo = layers[i + 1];
        const GaussRule1D &rule = count(lo) == n_points ? g : g_beyond;
        for (Eigen::Index k = 0; k < rule.nodes.size(); ++k, ++at)
          {
            const double s = 0.5 * (rule.nodes[k] + 1.0), ws = 0.5 * rule.weights[k];
            double rho, drho;
            if (lo == 0.0)
              rho = hi * s * s, drho = 2.0 * hi * s;
            else
              rho = lo + (hi - lo) * s, drho = hi - lo;
            out.nodes[at] = rho;
            out.weights[at] = ws * drho * rho;
          }
      }
    return out;
  }

  GaussRule1D gauss_legendre(const int n_points)
  {
    if (n_points < 1)
      throw std::invalid_argument("gauss_legendre: n_points must be >= 1");
    const int n = n_points;
    GaussRule1D rule;
    rule.nodes.resize(n);
    rule.weights.resize(n);
    // The roots are symmetric: Newton's method for the upper half, from the
    // asymptotic guess cos(pi (i + 3/4) / (n + 1/2)).
    for (int i = 0; i < (n + 1) / 2; ++i)
      {
        double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
        for (int iteration = 0; iteration < 100; ++iteration)
          {
            const auto [p, dp] = legendre_and_derivative(n, x);
            const double dx = p / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16)
              break;
          }
        const double dp = legendre_and_derivative(n, x).second;
        const double w = 2.0 / ((1.0 - x * x) * dp * dp);
        rule.nodes[i] = -x;
        rule.nodes[n - 1 - i] = x;
        rule.weights[i] = w;
        rule.weights[n - 1 - i] = w;
      }
    if (n % 2 == 1)
      rule.nodes[n / 2] = 0.0;
    return rule;
  }

  std::vector<double> graded_partition(const double a, const double b,
                                       const std::vector<double> &break_points,
                                       const int n_graded_layers, const double ratio)
  {
    if (!(b > a))
      throw std::invalid_argument("graded_partition: need b > a");
    if (n_graded_layers > 0 && !(ratio > 0.0 && ratio < 1.0))
      throw std::invalid_argument("graded_partition: grading ratio must be in (0, 1)");

    std::vector<double> inner;
    for (const double x : break_points)
      if (x > a && x < b)
        inner.push_back(x);
    std::sort(inner.begin(), inner.end());
    inner.erase(std::unique(inner.begin(), inner.end()), inner.end());

    std::vector<double> ends{a};
    ends.insert(ends.end(), inner.begin(), inner.end());
    ends.push_back(b);

    auto is_graded = [&](const double x) {
      if (n_graded_layers <= 0)
        return false;
      for (const double bp : break_points)
        if (std::abs(bp - x) <= 1e-14 * (b - a))
          return true;
      return false;
    };

    std::vector<double> cells{a};
    for (std::size_t s = 0; s + 1 < ends.size(); ++s)
      {
        const double lo = ends[s], hi = ends[s + 1];
        const bool grade_lo = is_graded(lo), grade_hi = is_graded(hi);
        std::vector<double> points;
        if (grade_lo && grade_hi)
          {
            const double mid = 0.5 * (lo + hi);
            for (int k = n_graded_layers; k >= 1; --k)
              points.push_back(lo + (mid - lo) * std::pow(ratio, k));
            points.push_back(mid);
            for (int k = 1; k <= n_graded_layers; ++k)
              points.push_back(hi - (hi - mid) * std::pow(ratio, k));
          }
        else if (grade_lo)
          for (int k = n_graded_layers; k >= 1; --k)
            points.push_back(lo + (hi - lo) * std::pow(ratio, k));
        else if (grade_hi)
          for (int k = 1; k <= n_graded_layers; ++k)
            points.push_back(hi - (hi - lo) * std::pow(ratio, k));
        cells.insert(cells.end(), points.begin(), points.end());
        cells.push_back(hi);
      }
    return cells;
  }

  GaussRule1D gauss_on_cells(const std::vector<double> &cells, const int n_points,
                             const std::vector<double> &sqrt_points)
  {
    assert(cells.size() >= 2);
    const GaussRule1D ref = gauss_legendre(n_points);
    const Eigen::Index n_cells = static_cast<Eigen::Index>(cells.size()) - 1;
    const double scale = std::abs(cells.back() - cells.front());
    auto singular = [&](const double x) {
      for (const double s : sqrt_points)
        if (std::abs(s - x) <= 1e-14 * scale)
          return true;
      return false;
    };
    GaussRule1D rule;
    rule.nodes.resize(n_cells * n_points);
    rule.weights.resize(n_cells * n_points);
    for (Eigen::Index c = 0; c < n_cells; ++c)
      {
        const double x0 = cells[c], x1 = cells[c + 1];
        const bool s0 = singular(x0), s1 = singular(x1);
        for (int k = 0; k < n_points; ++k)
          {
            const double t = 0.5 * (1.0 + ref.nodes[k]), w = 0.5 * ref.weights[k];
            double x, dx;
            if (s0 || s1)
              {
                // t^2 toward the singular end (the lower one when both are).
                const double xs = s0 ? x0 : x1, xo = s0 ? x1 : x0;
                x = xs + (xo - xs) * t * t;
                dx = 2.0 * std::abs(xo - xs) * t;
              }
            else
              x = x0 + (x1 - x0) * t, dx = x1 - x0;
            rule.nodes[c * n_points + k] = x;
            rule.weights[c * n_points + k] = w * dx;
          }
      }
    return rule;
  }

  Quadrature2D half_disc_gauss(const double r_c, const double z_c, const double rho_0,
                               const int n_radial, const int n_angular, const double z_max)
  {
    const GaussRule1D gs = gauss_legendre(n_radial), gt = gauss_legendre(n_angular);
    // Angular panels [theta_0, theta_1] with the ray length of each: rho_0, or the distance
    // to the line z = z_max beyond the angle where that is shorter.
    struct Panel
    {
      double theta_0, theta_1;
      bool clipped;
    };
    std::vector<Panel> panels{{0.0, 0.5 * M_PI, false}};
    const double room = z_max - z_c;
    if (room < rho_0)
      {
        if (!(room > 0.0))
          throw std::invalid_argument("half_disc_gauss: the centre must lie below z_max");
        const double theta_star = M_PI - std::acos(room / rho_0);
        panels.push_back({0.5 * M_PI, theta_star, false});
        panels.push_back({theta_star, M_PI, true});
      }
    else
      panels.push_back({0.5 * M_PI, M_PI, false});
    Quadrature2D q;
    const Eigen::Index n = static_cast<Eigen::Index>(panels.size()) * n_radial * n_angular;
    q.r.resize(n);
    q.z.resize(n);
    q.weights.resize(n);
    Eigen::Index k = 0;
    for (const Panel &panel : panels)
      for (int j = 0; j < n_angular; ++j)
        {
          const double half = 0.5 * (panel.theta_1 - panel.theta_0);
          const double theta = panel.theta_0 + half * (1.0 + gt.nodes[j]);
          const double w_theta = half * gt.weights[j];
          const double length = panel.clipped ? room / -std::cos(theta) : rho_0;
          for (int i = 0; i < n_radial; ++i, ++k)
            {
              const double s = 0.5 * (1.0 + gs.nodes[i]), w_s = 0.5 * gs.weights[i];
              const double rho = length * s * s;
              q.r[k] = r_c - rho * std::sin(theta);
              q.z[k] = z_c - rho * std::cos(theta);
              // dr dz = rho drho dtheta = L s^2 * 2 L s ds dtheta
              q.weights[k] = 2.0 * length * length * s * s * s * w_s * w_theta;
            }
        }
    return q;
  }

  GaussRule1D gauss_in_square_on_cells(const std::vector<double> &cells, const int n_points)
  {
    assert(cells.size() >= 2 && cells.front() >= 0.0);
    const GaussRule1D ref = gauss_legendre(n_points);
    const Eigen::Index n_cells = static_cast<Eigen::Index>(cells.size()) - 1;
    GaussRule1D rule;
    rule.nodes.resize(n_cells * n_points);
    rule.weights.resize(n_cells * n_points);
    for (Eigen::Index c = 0; c < n_cells; ++c)
      {
        const double s0 = cells[c] * cells[c], s1 = cells[c + 1] * cells[c + 1];
        for (int k = 0; k < n_points; ++k)
          {
            // int f x dx = int f ds / 2 on [s0, s1]: the Gauss weight (s1 - s0) w / 4 of x f.
            const double x = std::sqrt(s0 + 0.5 * (s1 - s0) * (1.0 + ref.nodes[k]));
            rule.nodes[c * n_points + k] = x;
            rule.weights[c * n_points + k] = 0.25 * (s1 - s0) * ref.weights[k] / x;
          }
      }
    return rule;
  }

  Quadrature2D tensor_gauss(const std::vector<double> &r_cells,
                            const std::vector<double> &z_cells, const int n_points,
                            const bool r_in_square)
  {
    const GaussRule1D rr = r_in_square ? gauss_in_square_on_cells(r_cells, n_points)
                                       : gauss_on_cells(r_cells, n_points);
    const GaussRule1D zz = gauss_on_cells(z_cells, n_points);
    Quadrature2D q;
    const Eigen::Index n = rr.nodes.size() * zz.nodes.size();
    q.r.resize(n);
    q.z.resize(n);
    q.weights.resize(n);
    Eigen::Index k = 0;
    for (Eigen::Index j = 0; j < zz.nodes.size(); ++j)
      for (Eigen::Index i = 0; i < rr.nodes.size(); ++i, ++k)
        {
          q.r[k] = rr.nodes[i];
          q.z[k] = zz.nodes[j];
          q.weights[k] = rr.weights[i] * zz.weights[j];
        }
    return q;
  }

  std::vector<double> section_cells(const double a, const double b, const int n_uniform,
                                    const std::vector<double> &break_points,
                                    const int n_graded_layers, const double grading_ratio)
  {
    std::vector<double> ends;
    for (int i = 1; i < n_uniform; ++i)
      ends.push_back(a + (b - a) * i / n_uniform);
    std::vector<double> cells = graded_partition(a, b, break_points, n_graded_layers,
                                                 grading_ratio);
    // Merge the uniform ends into the graded partition (sorted, unique).
    cells.insert(cells.end(), ends.begin(), ends.end());
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end(),
                            [&](double x, double y) { return std::abs(x - y) < 1e-14 * (b - a); }),
                cells.end());
    return cells;
  }

  double disc_partition_step(const double t)
  {
    return t < 1.0 ? t * t * t * t * (35.0 - 84.0 * t + 70.0 * t * t - 20.0 * t * t * t) : 1.0;
  }

  Quadrature2D blend_disc_rules(const Quadrature2D &region, const std::vector<DiscRule> &discs)
  {
    std::vector<double> s(discs.size());
    // 1 + sum_j s_j at (r, z), with the s_j in s.
    auto shares = [&](const double r, const double z) {
      double sum = 1.0;
      for (std::size_t j = 0; j < discs.size(); ++j)
        {
          const double rho = std::hypot(r - discs[j].r_c, z - discs[j].z_c) / discs[j].radius;
          const double step = disc_partition_step(rho * rho);
          s[j] = step < 1e-300 ? 1e300 : (1.0 - step) / step;
          sum += s[j];
        }
      return sum;
    };
    Eigen::Index total = region.n_points();
    for (const DiscRule &d : discs)
      total += d.rule.n_points();
    Quadrature2D out;
    out.r.resize(total), out.z.resize(total), out.weights.resize(total);
    Eigen::Index at = 0;
    for (Eigen::Index k = 0; k < region.n_points(); ++k, ++at)
      {
        out.r[at] = region.r[k], out.z[at] = region.z[k];
        out.weights[at] = region.weights[k] / shares(region.r[k], region.z[k]);
      }
    for (std::size_t j = 0; j < discs.size(); ++j)
      {
        const Quadrature2D &q = discs[j].rule;
        for (Eigen::Index k = 0; k < q.n_points(); ++k, ++at)
          {
            const double sum = shares(q.r[k], q.z[k]);
            out.r[at] = q.r[k], out.z[at] = q.z[k];
            out.weights[at] = q.weights[k] * s[j] / sum;
          }
      }
    return out;
  }
} // namespace rfm
