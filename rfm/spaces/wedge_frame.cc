#include "rfm/spaces/wedge_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    double cross(const axisym::Point a, const axisym::Point b) { return a.r * b.z - a.z * b.r; }
    double dot(const axisym::Point a, const axisym::Point b) { return a.r * b.r + a.z * b.z; }
  } // namespace

  WedgeFrame::WedgeFrame(const axisym::OutlineEdge &arriving, const axisym::OutlineEdge &leaving)
    : at_(leaving.start)
  {
    const axisym::Point d0 = leaving.tangent_at(0.0);
    const axisym::Point t1 = arriving.tangent_at(1.0), d1{-t1.r, -t1.z};
    gamma_ = std::atan2(d0.z, d0.r);
    beta_ = std::atan2(cross(d0, d1), dot(d0, d1));
    if (!(beta_ > 1e-12))
      beta_ += 2.0 * pi;
    const axisym::OutlineEdge *edges[2] = {&leaving, &arriving};
    for (int f = 0; f < 2; ++f)
      if (edges[f]->kind == axisym::OutlineEdge::Kind::arc)
        faces_[f] = {edges[f]->center, edges[f]->radius(), edges[f]->sweep() > 0 ? 1 : -1};
  }

  double WedgeFrame::polar_angle(const double r, const double z) const
  {
    const axisym::Point d0{std::cos(gamma_), std::sin(gamma_)}, x{r - at_.r, z - at_.z};
    double theta = std::atan2(cross(d0, x), dot(d0, x));
    if (theta < 0.5 * beta_ - pi)
      theta += 2.0 * pi;
    else if (theta >= 0.5 * beta_ + pi)
      theta -= 2.0 * pi;
    return theta;
  }

  double WedgeFrame::arc_angle(const int face, const double r, const double z) const
  {
    const Face &f = faces_[face];
    if (f.sweep_sign == 0)
      return 0.0;
    const axisym::Point u{at_.r - f.center.r, at_.z - f.center.z}, v{r - f.center.r, z - f.center.z};
    return std::atan2(cross(u, v), dot(u, v));
  }

  std::array<double, 2> WedgeFrame::mapped_angle(const double r, const double z, const double rho_min) const
  {
    if (!(std::hypot(r - at_.r, z - at_.z) > rho_min))
      return {0.5 * beta_, 0.0};
    const double p0 = arc_angle(0, r, z), p1 = arc_angle(1, r, z);
    const double polar = polar_angle(r, z);
    const double w = (polar - 0.5 * p0) / (beta_ + 0.5 * p1 - 0.5 * p0);
    return {polar - 0.5 * ((1.0 - w) * p0 + w * p1), (1.0 - w) * p0 + w * p1};
  }

  Quadrature2D WedgeFrame::near_rule(const double rho_0, const int n_radial, const int n_angular,
                                     const int n_layers, const std::vector<Circle> &rims,
                                     const int n_beyond_rims, const int n_outer) const
  {
    if (n_radial < 1 || n_angular < 1 || n_layers < 0)
      throw std::invalid_argument("WedgeFrame::near_rule: point counts must be positive");
    // The rims' radial breaks: where the rings about v start and stop crossing each rim.
    std::vector<double> radial_breaks;
    for (const Circle &c : rims)
      {
        const double d = std::hypot(c.centre.r - at_.r, c.centre.z - at_.z);
        if (!(d > c.radius))
          throw std::invalid_argument("WedgeFrame::near_rule: a rim's disc contains the vertex");
        for (const double b : {d - c.radius, d + c.radius})
          if (b > 1e-9 * rho_0 && b < (1.0 - 1e-9) * rho_0)
            radial_breaks.push_back(b);
      }
    // The outermost layer with n_outer points: a break where it starts, from which on the
    // rule takes the count beyond the breaks.
    int n_beyond = n_beyond_rims;
    if (n_layers > 0 && n_outer > std::min(n_radial, n_angular))
      {
        radial_breaks.push_back(0.2 * rho_0);
        n_beyond = std::max(n_beyond, n_outer);
      }
    const GaussRule1D radial = polar_radial_rule(rho_0, n_radial, n_layers, radial_breaks, n_beyond),
                      ga_near = gauss_legendre(n_angular),
                      ga_beyond = gauss_legendre(std::max(n_angular, n_beyond));
    const double first_crossing =
      radial_breaks.empty() ? rho_0 : *std::min_element(radial_breaks.begin(), radial_breaks.end());
    std::vector<double> rs, zs, ws;
    for (Eigen::Index k = 0; k < radial.nodes.size(); ++k)
      {
        const double rho = radial.nodes[k], w_rho = radial.weights[k];
        const GaussRule1D &ga = rho > first_crossing ? ga_beyond : ga_near;
        // The faces at this radius: the chord angles of arcs.
        auto chord = [rho](const Face &f) {
          return f.sweep_sign == 0 ? 0.0 : std::asin(std::min(1.0, rho / (2.0 * f.radius)));
        };
        const double theta_lo = faces_[0].sweep_sign * chord(faces_[0]);
        const double theta_hi = beta_ - faces_[1].sweep_sign * chord(faces_[1]);
        std::vector<double> breaks{theta_lo, theta_hi};
        if (beta_ > pi + 1e-12) // the faces' lines continued into the body
          for (const double b : {beta_ - pi, pi})
            if (b > theta_lo && b < theta_hi)
              breaks.push_back(b);
        // Where this ring crosses a rim: |v + rho e - c| = R.
        for (const Circle &c : rims)
          {
            const double dr = c.centre.r - at_.r, dz = c.centre.z - at_.z, d = std::hypot(dr, dz);
            const double cosine = (rho * rho + d * d - c.radius * c.radius) / (2.0 * rho * d);
            if (!(std::abs(cosine) < 1.0))
              continue;
            const double psi = std::atan2(dz, dr), half = std::acos(cosine);
            for (const double phi : {psi - half, psi + half})
              {
                // The polar angle from the leaving face, in [beta / 2 - pi, beta / 2 + pi).
                double theta = phi - gamma_;
                theta -= 2.0 * pi * std::floor((theta - (0.5 * beta_ - pi)) / (2.0 * pi));
                if (theta > theta_lo && theta < theta_hi)
                  breaks.push_back(theta);
              }
          }
        std::sort(breaks.begin(), breaks.end());
        for (std::size_t p = 0; p + 1 < breaks.size(); ++p)
          {
            const double a = breaks[p], b = breaks[p + 1];
            if (!(b - a > 1e-14))
              continue;
            const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / (0.5 * pi) - 1e-9)));
            for (int piece = 0; piece < pieces; ++piece)
              {
                const double pa = a + (b - a) * piece / pieces, pb = a + (b - a) * (piece + 1) / pieces;
                for (Eigen::Index l = 0; l < ga.nodes.size(); ++l)
                  {
                    const double theta = pa + 0.5 * (ga.nodes[l] + 1.0) * (pb - pa);
                    rs.push_back(at_.r + rho * std::cos(gamma_ + theta));
                    zs.push_back(at_.z + rho * std::sin(gamma_ + theta));
                    ws.push_back(w_rho * 0.5 * ga.weights[l] * (pb - pa));
                  }
              }
          }
      }
    Quadrature2D q;
    const Eigen::Index n = static_cast<Eigen::Index>(ws.size());
    q.r = Eigen::Map<const Eigen::VectorXd>(rs.data(), n);
    q.z = Eigen::Map<const Eigen::VectorXd>(zs.data(), n);
    q.weights = Eigen::Map<const Eigen::VectorXd>(ws.data(), n);
    return q;
  }
} // namespace rfm
